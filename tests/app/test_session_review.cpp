// A session loaded for review: its recording turned into plots that agree with the stored
// metrics, and every way the recording or the task can be missing said plainly, naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "recorded_session.hpp"
#include "tests/support/test_paths.hpp"
#include "training/sessions/session_review.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = test::output_dir() / "session_review" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

class SessionReviewTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::process_folder(test::output_dir() / "session_review" / "good");
    good_ = test::record_session(dir_ / "sessions.db");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static inline fs::path dir_;
  static inline test::RecordedSession good_;
};

TEST_F(SessionReviewTest, RecordingBecomesPlotsThatAgreeWithTheStoredMetrics) {
  SessionStore store(dir_ / "sessions.db");
  const SessionReview r = load_session_review(store, dir_ / "sessions.db", good_.id);
  ASSERT_TRUE(r.has_recording()) << r.recording_problem;
  EXPECT_EQ(r.recording_file, good_.recording);
  ASSERT_TRUE(r.task.has_value()) << r.task_problem;
  EXPECT_EQ(r.stored.info.task_source, r.task->source);
  ASSERT_EQ(r.states.size(), good_.samples);
  for (const Plot* p : r.plots.all()) {
    ASSERT_EQ(p->lines.size() > 0, true) << p->title << ": " << p->missing;
    EXPECT_EQ(p->lines[0].v.size(), good_.samples) << p->title;
  }
  // The force plot's peak (the force at the hand) is the session's scored peak; the lateral plot's
  // trapezoid integral is its lateral load (docs/SCORING.md).
  const Series& force = r.plots.force.lines[0];
  EXPECT_NEAR(*std::max_element(force.v.begin(), force.v.end()), r.stored.overall.peak_hand_force_N, 1e-12);
  const Series& lateral = r.plots.lateral.lines[0];
  double integral = 0.0;
  for (size_t k = 1; k < lateral.v.size(); ++k)
    integral += 0.5 * (lateral.v[k] + lateral.v[k - 1]) * (lateral.t[k] - lateral.t[k - 1]);
  EXPECT_NEAR(integral, r.stored.overall.lateral_load_Ns, 1e-9 + 1e-9 * integral);
  EXPECT_GT(integral, 0.0);
  // The depth reaches the insert step's band while that step completes.
  const Series& depth = r.plots.depth.lines[0];
  EXPECT_GE(*std::max_element(depth.v.begin(), depth.v.end()), 25.0);
  EXPECT_DOUBLE_EQ(r.start_s(), r.states.front().time_s);
}

TEST_F(SessionReviewTest, MissingAndUnreadableRecordingsAreNamed) {
  const fs::path dir = fresh_dir("broken");
  const test::RecordedSession s = test::record_session(dir / "sessions.db", {"rigid_sphere", "good", "bo", true});
  SessionStore store(dir / "sessions.db");
  std::ofstream(s.recording) << "hello";
  SessionReview r = load_session_review(store, dir / "sessions.db", s.id);
  EXPECT_FALSE(r.has_recording());
  EXPECT_NE(r.recording_problem.find(s.recording.string()), std::string::npos) << r.recording_problem;
  EXPECT_NE(r.recording_problem.find("not a needle-sim session recording"), std::string::npos) << r.recording_problem;
  EXPECT_TRUE(r.states.empty());
  EXPECT_TRUE(r.stored.info.complete);  // the metrics are still there
  EXPECT_EQ(r.stored.steps.size(), 4u);
  for (const Plot* p : r.plots.all()) EXPECT_EQ(p->missing, r.recording_problem);

  fs::remove(s.recording);
  r = load_session_review(store, dir / "sessions.db", s.id);
  EXPECT_EQ(r.recording_problem, s.recording.string() + ": recording not found");
}

TEST_F(SessionReviewTest, SessionWithoutRecordingOrTaskFile) {
  const fs::path dir = fresh_dir("old");
  SessionStore store(dir / "sessions.db");
  Task task = load_task(test::source_dir() / "assets/tasks/rigid_sphere.json");
  task.source = (dir / "moved_away.json").string();
  const int64_t id = store.begin_session("cy", task, "sim", "");
  const SessionReview r = load_session_review(store, dir / "sessions.db", id);
  EXPECT_EQ(r.recording_problem, "no recording (the session was stored without one)");
  EXPECT_TRUE(r.recording_file.empty());
  EXPECT_FALSE(r.task.has_value());
  EXPECT_NE(r.task_problem.find("moved_away.json"), std::string::npos) << r.task_problem;
  EXPECT_FALSE(r.stored.info.complete);
  EXPECT_THROW(load_session_review(store, dir / "sessions.db", id + 1), SessionStoreError);
}

TEST(ResolveRecording, RelativeToTheDatabaseFolder) {
  EXPECT_EQ(resolve_recording("/data/needle/sessions.db", "/elsewhere/a.nrec"), fs::path("/elsewhere/a.nrec"));
  EXPECT_EQ(resolve_recording("/data/needle/sessions.db", "recordings/session_3.nrec"),
            fs::path("/data/needle/recordings/session_3.nrec"));
}

}  // namespace
}  // namespace needle::training
