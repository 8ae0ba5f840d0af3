#include "haptics/sim/thumb_script.hpp"

#include <algorithm>
#include <cmath>

#include "haptics/sim/scenario.hpp"
#include "io/strict_json.hpp"

namespace needle::haptics {
namespace {

// The thumb's force: up to 100 N (a strong thumb's pinch; the loss-of-resistance syringe is pressed
// with 11 N, vaughan2012); a press's rise, a tap's press and release within a minute, a reaction
// within 5 s (design values: past them a number is a typo, not an operator).
constexpr io::Range kThumbForce{0.0, 100.0, false, "N"};
constexpr io::Range kRise{0.0, 10.0, true, "s"};
constexpr io::Range kTap{0.0, 60.0, true, "s"};
constexpr io::Range kReaction{0.0, 5.0, false, "s"};

}  // namespace

double scheduled_thumb_force(const ThumbScript& s, double t) {
  if (t < s.from_s || t >= s.until_s) return 0.0;
  double since = t - s.from_s;
  if (s.press_s > 0.0) {
    since = std::fmod(since, s.press_s + s.release_s);
    if (since >= s.press_s) return 0.0;
  }
  return s.force_N * std::min(1.0, since / s.rise_s);
}

ThumbScript read_thumb(const nlohmann::json& j, const std::string& file, const std::string& at,
                       const Eigen::Vector3d& base_in_world) {
  const io::StrictJsonReader<ScenarioError> r(file);
  r.object(j, at, {"force_N", "from_s", "until_s", "rise_s", "press_s", "release_s", "on_loss"});
  ThumbScript s;
  s.force_N = r.in_range(r.member(j, at, "force_N"), at + "/force_N", kThumbForce);
  s.from_s = r.in_range(r.member(j, at, "from_s"), at + "/from_s", io::kSessionTimeRange);
  if (j.contains("until_s")) {
    s.until_s = r.in_range(j["until_s"], at + "/until_s", io::kSessionTimeRange);
    if (!(s.until_s > s.from_s)) r.fail(at + "/until_s", "must be after from_s");
  }
  if (j.contains("rise_s")) s.rise_s = r.in_range(j["rise_s"], at + "/rise_s", kRise);
  if (j.contains("press_s") != j.contains("release_s"))
    r.fail(at + (j.contains("press_s") ? "/release_s" : "/press_s"), "missing: taps need both press_s and release_s");
  if (j.contains("press_s")) {
    s.press_s = r.in_range(j["press_s"], at + "/press_s", kTap);
    s.release_s = r.in_range(j["release_s"], at + "/release_s", kTap);
  }
  if (j.contains("on_loss")) {
    const nlohmann::json& l = j["on_loss"];
    const std::string where = at + "/on_loss";
    r.object(l, where, {"reaction_s", "hold_s", "waypoints"});
    LossReaction reaction;
    reaction.reaction_s = r.in_range(r.member(l, where, "reaction_s"), where + "/reaction_s", kReaction);
    if (l.contains("hold_s")) reaction.hold_s = r.in_range(l["hold_s"], where + "/hold_s", io::kSessionTimeRange);
    reaction.waypoints = read_waypoints(r.member(l, where, "waypoints"), file, where + "/waypoints", base_in_world);
    if (!(reaction.waypoints.front().t > reaction.hold_s))
      r.fail(where + "/waypoints/0/t", "must be after hold_s: the hand first holds where it is when it reacts");
    s.on_loss = std::move(reaction);
  }
  return s;
}

ScriptedThumb::ScriptedThumb(const ThumbScript& script) : script_(script) {
  if (!script_.on_loss) return;
  std::vector<HandWaypoint> waypoints{HandWaypoint{}};  // where the hand is when it reacts, set then
  if (script_.on_loss->hold_s > 0.0)
    waypoints.push_back(
        {script_.on_loss->hold_s, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()});  // and still there
  waypoints.insert(waypoints.end(), script_.on_loss->waypoints.begin(), script_.on_loss->waypoints.end());
  reaction_ = HandTrajectory(std::move(waypoints));
}

void ScriptedThumb::reset() {
  reacting_ = felt_ = false;
  felt_at_ = fast_for_ = last_travel_ = 0.0;
}

double ScriptedThumb::force(double t) const { return reacting_ ? 0.0 : scheduled_thumb_force(script_, t); }

void ScriptedThumb::feel(double t, double travel_m, double dt) {
  const double speed = (travel_m - last_travel_) / dt;
  last_travel_ = travel_m;
  if (felt_) return;
  fast_for_ = speed > kGiveSpeed_mps && force(t) > 0.0 ? fast_for_ + dt : 0.0;
  if (fast_for_ >= kGiveTime_s - 1e-12) {
    felt_ = true;
    felt_at_ = t + dt;
  }
}

bool ScriptedThumb::reaction_due(double t) const {
  return felt_ && !reacting_ && script_.on_loss && t >= felt_at_ + script_.on_loss->reaction_s - 1e-12;
}

void ScriptedThumb::begin_reaction(double t, const Eigen::Vector3d& tip, const Eigen::Vector3d& direction) noexcept {
  reaction_.restart(t, tip, direction, script_.on_loss->hold_s > 0.0 ? 2 : 1);
  reacting_ = true;
}

}  // namespace needle::haptics
