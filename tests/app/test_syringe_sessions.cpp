// The epidural tasks with their loss-of-resistance syringe (saline, continuous; air, intermittent),
// done by their scripted operators through the product's TaskSession: the good operator's thumb
// feels the plunger give and the hand stops within 2 mm of the loss; the sloppy one goes on into
// the dura. The metrics are checked against the recording's own ticks, and a replay of the
// recording reproduces the syringe and the score bit for bit.
#include <gtest/gtest.h>

#include <cstring>

#include "haptics/recording/session_format.hpp"
#include "haptics/syringe/syringe_model.hpp"
#include "recorded_session.hpp"

namespace needle::test {
namespace {

using training::operator-;  // the task geometry's plain-array arithmetic

class SyringeSessions : public testing::TestWithParam<const char*> {};

// The first tick whose flow into the epidural space began under the thumb (the loss), from the
// recording itself; the tip's furthest advance along the needle after it until the task ended (its
// last step's end: the score judges the session up to there).
struct LossInRecording {
  size_t tick = 0;
  double advance_m = -1.0;
};
LossInRecording loss_in(const haptics::Session& recording, int space, double end_s) {
  LossInRecording out;
  bool flowing = false, found = false;
  training::Vec3 tip{}, axis{};
  for (size_t k = 0; k < recording.records.size() && recording.records[k].state.time_s <= end_s; ++k) {
    const haptics::ToolSnapshot& s = recording.records[k].state;
    const bool now = s.syringe.flow_m3_per_s > 5e-8 && s.syringe.thumb_force_N > 0.0;
    if (!found && now && !flowing && s.syringe.layer == space) {
      found = true;
      out.tick = k;
      tip = training::vec3(s.needle_tip_m);
      const auto a = haptics::needle_axis(s);
      axis = {a[0], a[1], a[2]};
    }
    flowing = now;
    if (found) out.advance_m = std::max(out.advance_m, training::dot(training::vec3(s.needle_tip_m) - tip, axis));
  }
  return out;
}

TEST_P(SyringeSessions, GoodStopsWithinTwoMillimetresOfTheLossSloppyGoesOnIntoTheDura) {
  const std::filesystem::path dir = process_folder(output_dir() / "syringe_sessions" / GetParam());
  const RecordedSession good = record_session(dir / "sessions.db", {GetParam(), "good", "ana", true});
  const RecordedSession sloppy = record_session(dir / "sessions.db", {GetParam(), "sloppy", "bo", true});
  const training::Task task = training::load_task(source_dir() / "assets/tasks" / (std::string(GetParam()) + ".json"));
  ASSERT_TRUE(task.syringe.has_value());
  const int space = task.syringe->space;

  // Good: the loss found in the epidural space, the advance after it within 2 mm, every step done.
  const haptics::Session good_ticks = haptics::read_session(good.recording.string());
  const LossInRecording g = loss_in(good_ticks, space, good.result.steps.back().record.end_s);
  ASSERT_GE(g.advance_m, 0.0) << "no loss of resistance in the recording";
  EXPECT_LE(g.advance_m, 0.002);
  EXPECT_NEAR(good.result.overall.advance_after_loss_m, g.advance_m, 1e-12);
  EXPECT_EQ(good.result.overall.false_losses, 0.0);
  for (const training::StepResult& s : good.result.steps)
    EXPECT_EQ(s.record.outcome, training::StepOutcome::kCompleted) << s.id;
  EXPECT_TRUE(good.result.score.passed);
  // Before the loss the thumb held the plunger in the flavum at its 11 N over the plunger's area.
  const double held = 11.0 / haptics::SyringeParams{}.plunger_area_m2;
  EXPECT_NEAR(good.result.overall.loss_pressure_before_Pa, held, 1e-6 * held);
  EXPECT_LT(good.result.overall.loss_pressure_after_Pa, held);
  EXPECT_GT(good.result.overall.pressure_applied_s, 1.0);
  // The syringe's state is in every tick of the recording: the fluid the task names, the plunger
  // still until the loss, moving after.
  EXPECT_EQ(good_ticks.header.payload_version, haptics::kPayloadVersion);
  const haptics::SyringeSnapshot& before = good_ticks.records[g.tick - 1].state.syringe;
  EXPECT_EQ(before.fluid, uint32_t(task.syringe->fluid));
  EXPECT_EQ(before.flow_m3_per_s, 0.0);
  EXPECT_GT(good_ticks.records[g.tick + 20].state.syringe.travel_m, before.travel_m);

  // Sloppy: on past the loss, the step failed for it, the dura punctured.
  const LossInRecording s =
      loss_in(haptics::read_session(sloppy.recording.string()), space, sloppy.result.steps.back().record.end_s);
  EXPECT_GE(s.advance_m, 0.008);
  EXPECT_NEAR(sloppy.result.overall.advance_after_loss_m, s.advance_m, 1e-12);
  EXPECT_FALSE(sloppy.result.score.passed);
  const auto step = std::find_if(sloppy.result.steps.begin(), sloppy.result.steps.end(),
                                 [](const training::StepResult& r) { return r.id == "loss_of_resistance"; });
  ASSERT_NE(step, sloppy.result.steps.end());
  EXPECT_EQ(step->record.outcome, training::StepOutcome::kAdvancedPastLoss);
  EXPECT_GT(step->record.advanced_m, 0.004);
  EXPECT_TRUE(std::any_of(sloppy.result.punctures.begin(), sloppy.result.punctures.end(),
                          [](const training::PunctureResult& p) { return p.layer == "dura"; }));
  // The score pays for how soon the trainee stopped: the loss-of-resistance component.
  const auto component = [](const training::Score& score) {
    for (const training::ScoreComponent& c : score.components)
      if (c.name == "loss_of_resistance") return c.value;
    return -1.0;
  };
  EXPECT_GT(component(good.result.score), component(sloppy.result.score));
  EXPECT_NEAR(component(good.result.score), 1.0 - g.advance_m / task.scoring.references.loss_advance_m, 1e-12);
}

TEST_P(SyringeSessions, AReplayReproducesTheSyringeAndTheScoreBitForBit) {
  const std::filesystem::path dir = process_folder(output_dir() / "syringe_replay" / GetParam());
  const RecordedSession live = record_session(dir / "sessions.db", {GetParam(), "good", "ana", true});
  app::TaskSessionOptions options;
  options.task = source_dir() / "assets/tasks" / (std::string(GetParam()) + ".json");
  options.rig.device = haptics::DeviceSpec::parse("replay:" + live.recording.string());
  options.trainee = "ana";
  options.db = dir / "sessions.db";
  options.out_dir = dir / "replay";
  app::TaskSession replay(options);
  replay.run_offline([](size_t) {});
  const training::SessionResult again = *replay.finish();
  EXPECT_EQ(again.score.total, live.result.score.total);
  EXPECT_EQ(again.overall.advance_after_loss_m, live.result.overall.advance_after_loss_m);
  EXPECT_EQ(again.overall.loss_pressure_after_Pa, live.result.overall.loss_pressure_after_Pa);
  EXPECT_EQ(again.overall.pressure_applied_s, live.result.overall.pressure_applied_s);
  const haptics::Session a = haptics::read_session(live.recording.string());
  const haptics::Session b = haptics::read_session(replay.recording_path().string());
  ASSERT_EQ(a.records.size(), b.records.size());
  int differing = 0;
  for (size_t k = 0; k < a.records.size(); ++k)
    differing +=
        std::memcmp(&a.records[k].state.syringe, &b.records[k].state.syringe, sizeof(haptics::SyringeSnapshot)) != 0;
  EXPECT_EQ(differing, 0);
}

INSTANTIATE_TEST_SUITE_P(EpiduralTasks, SyringeSessions, testing::Values("epidural", "epidural_air"));

}  // namespace
}  // namespace needle::test
