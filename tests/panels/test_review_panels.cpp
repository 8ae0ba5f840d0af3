// The instructor's review panels drawn headless, against goldens: the session table (with its
// sessions' checks against their recordings), a session's detail with its plots, a single plot, two sessions compared,
// and a replay frame of the recorded session in the 3D view. The sessions are recorded closed-loop runs of the
// penetrable task (good and sloppy operators) with their dates fixed, so the pictures are too; and
// the layered tasks' force–depth plot of their recorded runs.
#include <gtest/gtest.h>

#include "app/replay_cursor.hpp"
#include "engine/gpu_device.hpp"
#include "image_compare.hpp"
#include "tests/app/recorded_session.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/panel_picture.hpp"
#include "ui/review_panels.hpp"
#include "ui/review_replay.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;

ui::PanelRect whole(engine::Extent e) { return {ImVec2(0, 0), ImVec2(float(e.width), float(e.height))}; }

class ReviewPanels : public VulkanTest {
 protected:
  static void SetUpTestSuite() {
    VulkanTest::SetUpTestSuite();
    dir_ = process_folder(test::output_dir() / "review_panels");
    db_ = dir_ / "sessions.db";
    good_ = record_session(db_, {"penetrable_sphere", "good", "ana", true});
    sloppy_ = record_session(db_, {"penetrable_sphere", "sloppy", "bo", true});
    training::SessionStore store(db_);
    const training::Task rigid = training::load_task(test::source_dir() / "assets/tasks/rigid_sphere.json");
    store.begin_session("cy", rigid, "sim", "");  // died mid-task, before recordings were kept
    // The instructor's checks against the recordings (needle-sim verify): ana's verified, bo's not
    // what its replay gives; the table marks each, the detail says when and by whom.
    const training::StoredSession good = store.load(good_.id), sloppy = store.load(sloppy_.id);
    store.record_check({good_.id, training::CheckOutcome::kVerified, good.info.score, training::result_digest(good), "",
                        "2026-03-05T09:00:00Z", "dr-lee"});
    store.record_check({sloppy_.id, training::CheckOutcome::kMismatch, sloppy.info.score,
                        training::result_digest(sloppy), "score: stored 90, replay 38.6", "2026-03-05T09:00:00Z",
                        "dr-lee"});
  }
  // The session as the panels show it, with the clock's fields fixed for the picture.
  static training::SessionReview review(int64_t id) {
    training::SessionStore store(db_);
    training::SessionReview r = training::load_session_review(store, db_, id);
    fix_dates(r.stored.info);
    return r;
  }
  static void fix_dates(training::SessionInfo& s) {
    s.started_at = "2026-03-0" + std::to_string(s.id) + "T10:00:00Z";
    s.ended_at = s.complete ? "2026-03-0" + std::to_string(s.id) + "T10:01:00Z" : "";
  }
  static void TearDownTestSuite() {
    fs::remove_all(dir_);
    VulkanTest::TearDownTestSuite();
  }
  static inline fs::path dir_, db_;
  static inline RecordedSession good_, sloppy_;
};

TEST_F(ReviewPanels, SessionTableMatchesGolden) {
  std::vector<training::SessionInfo> sessions = training::SessionStore(db_).sessions();
  ASSERT_EQ(sessions.size(), 3u);
  for (training::SessionInfo& s : sessions) fix_dates(s);
  ui::SessionTableState table;
  table.selected = good_.id;
  table.compared = sloppy_.id;
  const engine::Extent size{760, 200};
  EXPECT_TRUE(
      matches_golden(ui::panel_picture(device(), size, [&] { ui::draw_session_table(sessions, table, whole(size)); }),
                     "panel_review_table"));
}

TEST_F(ReviewPanels, SessionDetailWithPlotsMatchesGolden) {
  const training::SessionReview r = review(good_.id);
  ASSERT_TRUE(r.has_recording());
  const engine::Extent size{720, 1340};
  EXPECT_TRUE(matches_golden(ui::panel_picture(device(), size,
                                               [&] {
                                                 ui::draw_session_detail(r, {12.0, false, ""}, whole(size));
                                               }),
                             "panel_review_detail"));
}

// Zoomed into two seconds: the time axes read 10 to 12 s, each y axis is scaled to the lines in
// them (the force's 3 N safe limit no longer flattens the 0.3 N the hand feels), and the row above
// the plots shows the range.
TEST_F(ReviewPanels, SessionDetailZoomedIntoTwoSecondsMatchesGolden) {
  const training::SessionReview r = review(good_.id);
  ASSERT_TRUE(r.has_recording());
  ui::TimeSpan span{10.0, 12.0};
  const engine::Extent size{720, 1340};
  EXPECT_TRUE(matches_golden(ui::panel_picture(device(), size,
                                               [&] {
                                                 ui::draw_session_detail(r, {11.0, false, "", &span}, whole(size));
                                               }),
                             "panel_review_detail_zoomed"));
  EXPECT_DOUBLE_EQ(span.lo, 10.0);  // no pointer over the plots: the range is as it was
  EXPECT_DOUBLE_EQ(span.hi, 12.0);
}

TEST_F(ReviewPanels, SessionWithoutRecordingSaysSo) {
  const training::SessionReview r = review(3);
  EXPECT_FALSE(r.has_recording());
  const engine::Extent size{600, 300};
  EXPECT_TRUE(matches_golden(ui::panel_picture(device(), size, [&] { ui::draw_session_detail(r, {}, whole(size)); }),
                             "panel_review_no_recording"));
}

TEST_F(ReviewPanels, ComparisonMatchesGolden) {
  const training::SessionReview a = review(good_.id), b = review(sloppy_.id);
  const engine::Extent size{720, 1080};
  EXPECT_TRUE(matches_golden(ui::panel_picture(device(), size, [&] { ui::draw_comparison(a, b, whole(size)); }),
                             "panel_review_compare"));
}

// The recorded needle 12 s in (pivoting in the tissue), the scene framed right of where the
// review's panels stand, the replay bar below.
TEST_F(ReviewPanels, ReplayFrameMatchesGolden) {
  const training::SessionReview r = review(good_.id);
  ASSERT_TRUE(r.task.has_value());
  app::ReplayCursor cursor;
  double t = 12.0;
  ui::PictureScene scene{engine::load_scene(r.task->scene), cursor.at(r.states, t), 0.3f};
  const engine::Extent size{640, 360};
  EXPECT_TRUE(matches_golden(ui::panel_picture(
                                 device(), size,
                                 [&] {
                                   ui::draw_replay_bar(r, t, false, {ImVec2(0, 300), ImVec2(640, 60)});
                                 },
                                 &scene, 4),
                             "panel_review_replay"));
}

// The layered tasks' force–depth plot, from recorded closed-loop runs: the layered
// target's good run alone (its boundaries skin, fat, muscle and its punctures), and the epidural's
// good run (A) against its sloppy one (B).
class ReviewPanelsLayered : public VulkanTest {
 protected:
  static void SetUpTestSuite() {
    VulkanTest::SetUpTestSuite();
    dir_ = process_folder(test::output_dir() / "review_panels_layered");
    db_ = dir_ / "sessions.db";
    target_ = record_session(db_, {"layered_target", "good", "ana", true});
    epidural_good_ = record_session(db_, {"epidural", "good", "ana", true});
    epidural_sloppy_ = record_session(db_, {"epidural", "sloppy", "bo", true});
  }
  static training::SessionReview review(int64_t id) {
    training::SessionStore store(db_);
    return training::load_session_review(store, db_, id);
  }
  static void TearDownTestSuite() {
    fs::remove_all(dir_);
    VulkanTest::TearDownTestSuite();
  }
  static inline fs::path dir_, db_;
  static inline RecordedSession target_, epidural_good_, epidural_sloppy_;
};

TEST_F(ReviewPanelsLayered, ForceDepthOfTheLayeredTargetMatchesGolden) {
  const training::SessionReview r = review(target_.id);
  ASSERT_TRUE(r.layered());
  ASSERT_FALSE(r.force_depth.plot.lines.empty()) << r.force_depth.plot.missing;
  // The punctures are the ones the run scored, in order.
  ASSERT_EQ(r.force_depth.puncture_list.size(), target_.result.punctures.size());
  for (size_t k = 0; k < r.force_depth.puncture_list.size(); ++k) {
    EXPECT_EQ(r.force_depth.puncture_list[k].layer, target_.result.punctures[k].layer);
    EXPECT_DOUBLE_EQ(r.force_depth.puncture_list[k].peak_force_N, target_.result.punctures[k].peak_force_N);
  }
  const engine::Extent size{900, 320};
  EXPECT_TRUE(matches_golden(
      ui::panel_picture(device(), size, [&] { ui::draw_force_depth_window(r.force_depth, nullptr, whole(size)); }),
      "panel_force_depth_layered_target"));
}

TEST_F(ReviewPanelsLayered, ForceDepthOfTwoEpiduralSessionsComparedMatchesGolden) {
  const training::SessionReview a = review(epidural_good_.id), b = review(epidural_sloppy_.id);
  const engine::Extent size{900, 320};
  EXPECT_TRUE(matches_golden(
      ui::panel_picture(device(), size,
                        [&] { ui::draw_force_depth_window(a.force_depth, &b.force_depth, whole(size)); }),
      "panel_force_depth_compare_epidural"));
}

// The epidural's syringe beside its force–depth plot: the plunger's pressure against the same depth
// for the good run (A) and the sloppy one (B), each loss of resistance ringed at the pressure held
// before it. The losses are the recording's: the first in the epidural space, where the axial force
// drops at the flavum's far face.
TEST_F(ReviewPanelsLayered, PlungerPressureOfTwoEpiduralSessionsComparedMatchesGolden) {
  const training::SessionReview a = review(epidural_good_.id), b = review(epidural_sloppy_.id);
  ASSERT_TRUE(a.has_syringe());
  ASSERT_FALSE(a.force_depth.pressure.lines.empty()) << a.force_depth.pressure.missing;
  ASSERT_FALSE(a.force_depth.losses.empty());
  EXPECT_EQ(a.force_depth.losses.front().label, "epidural space");
  EXPECT_NEAR(a.force_depth.losses.front().y, 1e-3 * a.stored.overall.loss_pressure_before_Pa, 1e-9);
  // The loss is where the flavum gave way and the tip entered the epidural space (the boundary the
  // force-depth plot marks), within a tick's travel (at most 0.1 mm at the good run's speed).
  const auto space = std::find_if(a.force_depth.boundaries.begin(), a.force_depth.boundaries.end(),
                                  [](const training::PlotMark& m) { return m.label == "epidural space"; });
  ASSERT_NE(space, a.force_depth.boundaries.end());
  EXPECT_NEAR(a.force_depth.losses.front().x, space->x, 0.1);
  const engine::Extent size{900, 320};
  EXPECT_TRUE(matches_golden(
      ui::panel_picture(device(), size,
                        [&] { ui::draw_plunger_pressure_window(a.force_depth, &b.force_depth, whole(size)); }),
      "panel_plunger_pressure_compare_epidural"));
}

}  // namespace
}  // namespace needle::test
