// The good and sloppy operator scripts of each shipped task, run through the closed-loop
// simulation of the task's scenario (the hand replaced by the script) and scored: the good one
// passes and scores higher; the sloppy one fails the pass threshold.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "haptics/sim/closed_loop.hpp"
#include "ui/scoring/session_scorer.hpp"

namespace needle::ui {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kTasks = fs::path(NEEDLE_SOURCE_DIR) / "assets/tasks";

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// The task's scenario with its hand replaced by the script's, run until the script's end + 4 s.
haptics::Scenario scenario_with_operator(const Task& task, const std::string& script) {
  json scenario = read_json(task.scenario);
  const json operator_script = read_json(kTasks / (task.name + "_" + script + ".json"));
  scenario["hand"] = operator_script.at("hand");
  scenario["duration_s"] = operator_script["hand"]["waypoints"].back()["t"].get<double>() + 4.0;
  for (const char* key : {"master_urdf", "virtual_urdf"})  // the merged file lives elsewhere
    scenario[key] = (task.scenario.parent_path() / scenario[key].get<std::string>()).string();
  const fs::path merged = fs::path(NEEDLE_TEST_OUTPUT_DIR) / "operators" / (task.name + "_" + script + ".json");
  fs::create_directories(merged.parent_path());
  std::ofstream(merged) << scenario.dump(2);
  return haptics::load_scenario(merged.string());
}

// The state the haptic loop would publish for one simulated tick.
haptics::ToolSnapshot snapshot(const haptics::TickRecord& r) {
  haptics::ToolSnapshot s;
  s.time_s = r.t;
  for (int i = 0; i < 3; ++i) {
    s.needle_tip_m[i] = r.x_v[i];
    s.environment_force_n[i] = r.force_v[i];
  }
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), r.needle_v);
  s.needle_orientation[0] = q.w(), s.needle_orientation[1] = q.x();
  s.needle_orientation[2] = q.y(), s.needle_orientation[3] = q.z();
  using haptics::ContactMode, haptics::ContactState;
  s.contact = r.mode == ContactMode::Free        ? ContactState::kFree
              : r.mode == ContactMode::Holonomic ? ContactState::kRigidSurface
                                                 : ContactState::kTissue;
  s.multiplier_count = r.mode == ContactMode::Free ? 0 : r.mode == ContactMode::Holonomic ? 1 : 2;
  s.multipliers[0] = r.lambda_v[0], s.multipliers[1] = r.lambda_v[1];
  return s;
}

SessionResult run(const Task& task, const std::string& script) {
  const haptics::Scenario scenario = scenario_with_operator(task, script);
  SessionScorer scorer(task);
  haptics::TickSample sample;
  haptics::run_closed_loop(scenario, false, [&](const haptics::TickRecord& r) {
    sample.state = snapshot(r);
    scorer.feed(sample);
  });
  return scorer.result();
}

std::string report(const SessionResult& r) {
  std::string out = "score " + std::to_string(r.score.total) + ";";
  for (const StepResult& s : r.steps) out += " " + s.id + "=" + step_outcome_name(s.record.outcome);
  for (const ScoreComponent& c : r.score.components) out += " " + c.name + ":" + std::to_string(c.value).substr(0, 4);
  for (const std::string& why : r.score.reasons_failed) out += "; " + why;
  return out;
}

class OperatorScripts : public testing::TestWithParam<const char*> {};

TEST_P(OperatorScripts, GoodPassesAndOutscoresSloppyWhichFails) {
  const Task task = load_task(kTasks / (std::string(GetParam()) + ".json"));
  const SessionResult good = run(task, "good");
  const SessionResult sloppy = run(task, "sloppy");
  EXPECT_TRUE(good.score.passed) << report(good);
  EXPECT_FALSE(sloppy.score.passed) << report(sloppy);
  EXPECT_LT(sloppy.score.total, task.scoring.pass_score) << report(sloppy);
  EXPECT_GT(good.score.total, sloppy.score.total + 10.0) << report(good) << "\n" << report(sloppy);
  std::cout << GetParam() << " good: " << report(good) << "\n" << GetParam() << " sloppy: " << report(sloppy) << "\n";
}

INSTANTIATE_TEST_SUITE_P(ShippedTasks, OperatorScripts, testing::Values("rigid_sphere", "penetrable_sphere"));

}  // namespace
}  // namespace needle::ui
