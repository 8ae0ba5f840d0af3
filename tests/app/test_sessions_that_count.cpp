// Which sessions the store keeps (docs/SESSIONS.md, "Sessions that count") and practice runs
// (docs/TASKS.md, "Practice"), through the product's own TaskSession, headless.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/session_rig.hpp"
#include "app/task_session.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;

app::TaskSessionOptions options_in(const fs::path& dir, const std::string& task, const std::string& operator_spec) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  app::TaskSessionOptions o;
  o.task = source_dir() / "assets/tasks" / (task + ".json");
  o.rig.operator_spec = operator_spec;
  o.trainee = "ana";
  o.db = dir / "sessions.db";
  o.out_dir = dir / "out";
  return o;
}

// A session closed before its first step ended is no session: nothing stored, its recording gone.
// Asked to (--store), it is stored from its start and stays incomplete.
TEST(SessionsThatCount, ASessionClosedBeforeItsFirstStepEndedIsNotStoredUnlessAsked) {
  const fs::path dir = process_folder(output_dir() / "sessions_that_count");
  app::TaskSessionOptions o = options_in(dir, "penetrable_sphere", "good");
  fs::path recording;
  {
    app::TaskSession session(o);
    recording = session.recording_path();
    EXPECT_TRUE(fs::exists(recording));
    EXPECT_FALSE(session.store_once_under_way()) << "no tick has run: not under way";
    EXPECT_EQ(session.session_id(), 0);
  }
  EXPECT_FALSE(fs::exists(recording)) << "a session that never happened leaves no recording";
  EXPECT_TRUE(training::SessionStore(o.db.string()).sessions().empty());

  o.store = app::StoreWhen::kAlways;
  {
    app::TaskSession session(o);
    recording = session.recording_path();
    EXPECT_NE(session.session_id(), 0);
  }
  const std::vector<training::SessionInfo> sessions = training::SessionStore(o.db.string()).sessions();
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_FALSE(sessions[0].complete);
  EXPECT_EQ(sessions[0].recording_path, recording.string());
  EXPECT_TRUE(fs::exists(recording));
}

// Once its first step has ended the session is stored (headless, after that tick); a run that ends is
// stored complete.
TEST(SessionsThatCount, ASessionIsStoredOnceItsFirstStepHasEnded) {
  const fs::path dir = process_folder(output_dir() / "sessions_under_way");
  const app::TaskSessionOptions o = options_in(dir, "rigid_sphere", "good");
  app::TaskSession session(o);
  bool stored_at_first_end = false;
  session.run_offline([&](size_t step) {
    if (step == 0) stored_at_first_end = session.session_id() == 0;  // the store follows right after this tick
  });
  EXPECT_TRUE(stored_at_first_end);
  EXPECT_NE(session.session_id(), 0);
  ASSERT_NE(session.finish(), nullptr);
  const std::vector<training::SessionInfo> sessions = training::SessionStore(o.db.string()).sessions();
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_TRUE(sessions[0].complete);
}

// Practice: the task's steps without their time limits. The sloppy rigid-sphere operator's align
// step times out at 20 s in the task; in practice it never does. The store says practice, and the
// recording replays (and verifies) as practice.
TEST(SessionsThatCount, APracticeRunIsUntimedStoredAsPracticeAndReplaysAsPractice) {
  const fs::path dir = process_folder(output_dir() / "practice");
  app::TaskSessionOptions o = options_in(dir, "rigid_sphere", "sloppy");
  o.practice = true;
  app::TaskSession session(o);
  ASSERT_TRUE(session.task().practice);
  for (const training::Step& step : session.task().steps) EXPECT_EQ(step.time_limit_s, 0.0) << step.id;
  session.run_offline([](size_t) {});
  const training::SessionResult* result = session.finish();
  ASSERT_NE(result, nullptr);
  for (const training::StepResult& step : result->steps)
    EXPECT_NE(step.record.outcome, training::StepOutcome::kTimedOut) << step.id;
  const std::vector<training::SessionInfo> sessions = training::SessionStore(o.db.string()).sessions();
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_EQ(sessions[0].device, "sim (rigid_sphere_sloppy) (practice)");

  const training::Task replayed =
      app::session_task({}, haptics::DeviceSpec::parse("replay:" + session.recording_path().string()));
  EXPECT_TRUE(replayed.practice);
  for (const training::Step& step : replayed.steps) EXPECT_EQ(step.time_limit_s, 0.0) << step.id;

  // The same operator on the timed task: its align step runs out of time.
  app::TaskSessionOptions timed = options_in(dir / "timed", "rigid_sphere", "sloppy");
  app::TaskSession timed_session(timed);
  timed_session.run_offline([](size_t) {});
  const training::SessionResult* timed_result = timed_session.finish();
  ASSERT_NE(timed_result, nullptr);
  EXPECT_EQ(timed_result->steps[1].record.outcome, training::StepOutcome::kTimedOut);
}

}  // namespace
}  // namespace needle::test
