// The review window's Class tab (ui/cohort_panel.hpp) on a seeded store of four trainees, two
// tasks, two stations and seven complete sessions (one more left incomplete): the filters against
// counts, learning curves, failed steps and percentiles worked out by hand below, the view kept
// through a half-typed date and computed again when a session completes, and the panel drawn
// headless against goldens (tests/README.md's tolerance: 8 counts, 0.2% of the pixels).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/gpu_device.hpp"
#include "image_compare.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/stored_sessions.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/cohort_panel.hpp"
#include "ui/panel_picture.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;
using training::CohortView;

constexpr double kNotReached = std::numeric_limits<double>::quiet_NaN();

// a_result's two steps (insert completes; pivot, whose tip error applies, ends at `reached_s`
// completed, or as the tip moved when NaN): the time to target is `reached_s`.
training::SessionResult scored(double score, bool passed, double reached_s) {
  training::SessionResult r = a_result();
  r.score.total = score;
  r.score.passed = passed;
  if (!std::isnan(reached_s)) {
    r.steps[1].record.outcome = training::StepOutcome::kCompleted;
    r.steps[1].record.end_s = reached_s;
  }
  return r;
}

// The cohort, as the hand counts below read it:
//   id trainee task          station  day    score passed  time to target
//   1  ana     pivot_drill   st-1     11-01  40    no      -
//   2  ana     pivot_drill   st-1     11-03  70    yes     12 s
//   3  ana     pivot_drill   st-2     11-05  85    yes     9 s
//   4  ben     pivot_drill   st-2     11-02  90    yes     8 s
//   5  ben     pivot_drill   st-2     11-04  60    no      -
//   6  cyd     rigid_sphere  st-1     11-03  55    no      -
//   7  cyd     rigid_sphere  st-1     11-06  75    yes     10 s
//   8  dee     pivot_drill   st-3     11-06  (incomplete: never counted, offered by no filter)
// A session that did not reach the target failed its pivot step; insert never fails.
class Cohort {
 public:
  explicit Cohort(const fs::path& file) : store(file.string()) {
    add("ana", "pivot_drill", "st-1", "2026-11-01T09:00:00Z", scored(40, false, kNotReached));
    add("ana", "pivot_drill", "st-1", "2026-11-03T09:00:00Z", scored(70, true, 12.0));
    add("ana", "pivot_drill", "st-2", "2026-11-05T09:00:00Z", scored(85, true, 9.0));
    add("ben", "pivot_drill", "st-2", "2026-11-02T10:00:00Z", scored(90, true, 8.0));
    add("ben", "pivot_drill", "st-2", "2026-11-04T10:00:00Z", scored(60, false, kNotReached));
    add("cyd", "rigid_sphere", "st-1", "2026-11-03T11:00:00Z", scored(55, false, kNotReached));
    add("cyd", "rigid_sphere", "st-1", "2026-11-06T11:00:00Z", scored(75, true, 10.0));
    store.begin_session({"dee", "pivot_drill", "pivot_drill", "", "sim", "", "st-3", "", "2026-11-06T12:00:00Z"});
  }
  void add(const std::string& trainee, const std::string& task, const std::string& station, const std::string& at,
           const training::SessionResult& result) {
    store.finish_session(store.begin_session({trainee, task, task, "", "sim", "", station, "", at}), result);
  }
  training::SessionStore store;
};

const training::Percentiles& percentiles(const CohortView& v, const std::string& task, const std::string& metric) {
  for (const training::Percentiles& p : v.percentiles)
    if (p.task == task && p.metric == metric) return p;
  throw std::runtime_error("no percentiles of " + task + " " + metric);
}

std::vector<double> scores(const training::LearningCurve& c) {
  std::vector<double> out;
  for (const training::Attempt& a : c.attempts) out.push_back(a.score);
  return out;
}

fs::path folder() { return test::output_dir() / "cohort_panel" / std::to_string(::getpid()); }

// An empty database file in this process's folder (made anew).
fs::path fresh_db(const std::string& name) {
  const fs::path dir = process_folder(test::output_dir() / "cohort_panel");
  const fs::path file = dir / (name + ".db");
  for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(file.string() + suffix);
  return file;
}

class CohortPanelFilters : public testing::Test {
 protected:
  void SetUp() override {
    cohort_ = std::make_unique<Cohort>(fresh_db(testing::UnitTest::GetInstance()->current_test_info()->name()));
  }
  void TearDown() override {
    cohort_.reset();
    fs::remove_all(folder());
  }
  // The panel after the instructor set `state`'s filters.
  ui::CohortPanel panel_with(const ui::CohortPanelState& state) {
    ui::CohortPanel panel;
    panel.state = state;
    EXPECT_TRUE(panel.update(cohort_->store, cohort_->store.sessions()));
    return panel;
  }
  std::unique_ptr<Cohort> cohort_;
};

TEST_F(CohortPanelFilters, NoFilterShowsEveryCompleteSession) {
  const ui::CohortPanel p = panel_with({});
  EXPECT_EQ(p.view.sessions, 7u);
  ASSERT_EQ(p.view.curves.size(), 3u);  // by task, then trainee
  EXPECT_EQ(p.view.curves[0].trainee, "ana");
  EXPECT_EQ(scores(p.view.curves[0]), (std::vector<double>{40, 70, 85}));
  EXPECT_FALSE(p.view.curves[0].first_pass);
  EXPECT_EQ(p.view.curves[0].attempts_to_pass, 2);
  EXPECT_TRUE(std::isnan(p.view.curves[0].attempts[0].time_to_target_s));
  EXPECT_EQ(p.view.curves[0].attempts[2].time_to_target_s, 9.0);
  EXPECT_EQ(scores(p.view.curves[1]), (std::vector<double>{90, 60}));  // ben: passed first, then not
  EXPECT_TRUE(p.view.curves[1].first_pass);
  EXPECT_EQ(p.view.curves[1].attempts_to_pass, 1);
  EXPECT_EQ(p.view.curves[2].task, "rigid_sphere");
  EXPECT_EQ(p.view.curves[2].attempts_to_pass, 2);
  // pivot failed in sessions 1 and 5 of pivot_drill's five, and in 6 of rigid_sphere's two.
  ASSERT_EQ(p.view.most_failed.size(), 2u);
  EXPECT_EQ(p.view.most_failed[0].task, "pivot_drill");
  EXPECT_EQ(p.view.most_failed[0].failed, 2);
  EXPECT_EQ(p.view.most_failed[0].attempts, 5);
  EXPECT_EQ(p.view.most_failed[1].task, "rigid_sphere");
  EXPECT_EQ(p.view.most_failed[1].failed, 1);
  EXPECT_EQ(p.view.most_failed[1].attempts, 2);
  // pivot_drill's scores sorted 40 60 70 85 90; R-7: rank p/100 * 4, linear between neighbours.
  const training::Percentiles& score = percentiles(p.view, "pivot_drill", "score");
  EXPECT_EQ(score.n, 5u);
  EXPECT_DOUBLE_EQ(score.p10, 48.0);  // rank 0.4: 40 + 0.4 * 20
  EXPECT_DOUBLE_EQ(score.p25, 60.0);
  EXPECT_DOUBLE_EQ(score.p50, 70.0);
  EXPECT_DOUBLE_EQ(score.p75, 85.0);
  EXPECT_DOUBLE_EQ(score.p90, 88.0);  // rank 3.6: 85 + 0.6 * 5
  // Its times to target 8 9 12 (rank p/100 * 2).
  const training::Percentiles& reach = percentiles(p.view, "pivot_drill", "time_to_target_s");
  EXPECT_EQ(reach.n, 3u);
  EXPECT_DOUBLE_EQ(reach.p10, 8.2);
  EXPECT_DOUBLE_EQ(reach.p50, 9.0);
  EXPECT_DOUBLE_EQ(reach.p90, 11.4);
  EXPECT_TRUE(p.state.error.empty());
}

TEST_F(CohortPanelFilters, OffersTheNamesOfCompleteSessionsOnly) {
  const ui::CohortPanel p = panel_with({});
  EXPECT_EQ(p.state.choices.tasks, (std::vector<std::string>{"pivot_drill", "rigid_sphere"}));
  EXPECT_EQ(p.state.choices.trainees, (std::vector<std::string>{"ana", "ben", "cyd"}));  // dee's is incomplete
  EXPECT_EQ(p.state.choices.stations, (std::vector<std::string>{"st-1", "st-2"}));
}

TEST_F(CohortPanelFilters, StationKeepsItsSessionsAndCountsAttemptsWithinThem) {
  ui::CohortPanelState state;
  state.station = "st-2";  // sessions 3, 4, 5
  const ui::CohortPanel p = panel_with(state);
  EXPECT_EQ(p.view.sessions, 3u);
  ASSERT_EQ(p.view.curves.size(), 2u);
  EXPECT_EQ(scores(p.view.curves[0]), (std::vector<double>{85}));  // ana's one attempt there passed
  EXPECT_TRUE(p.view.curves[0].first_pass);
  EXPECT_EQ(scores(p.view.curves[1]), (std::vector<double>{90, 60}));
  ASSERT_EQ(p.view.most_failed.size(), 1u);  // session 5
  EXPECT_EQ(p.view.most_failed[0].failed, 1);
  EXPECT_EQ(p.view.most_failed[0].attempts, 3);
  const training::Percentiles& score = percentiles(p.view, "pivot_drill", "score");  // 60 85 90
  EXPECT_DOUBLE_EQ(score.p25, 72.5);                                                 // rank 0.5
  EXPECT_DOUBLE_EQ(score.p50, 85.0);
}

TEST_F(CohortPanelFilters, TraineeAndDateRangeBothEndsIncluded) {
  ui::CohortPanelState state;
  state.trainee = "ana";
  std::snprintf(state.since, sizeof state.since, "2026-11-03");
  std::snprintf(state.until, sizeof state.until, "2026-11-05");
  const ui::CohortPanel p = panel_with(state);  // sessions 2 (11-03) and 3 (11-05)
  EXPECT_EQ(p.view.sessions, 2u);
  ASSERT_EQ(p.view.curves.size(), 1u);
  EXPECT_EQ(scores(p.view.curves[0]), (std::vector<double>{70, 85}));
  EXPECT_TRUE(p.view.curves[0].first_pass);
  EXPECT_EQ(p.view.curves[0].attempts[0].time_to_target_s, 12.0);
  EXPECT_TRUE(p.view.most_failed.empty());
}

TEST_F(CohortPanelFilters, TaskAndOpenEndedDates) {
  ui::CohortPanelState state;
  state.task = "rigid_sphere";
  ui::CohortPanel p = panel_with(state);
  EXPECT_EQ(p.view.sessions, 2u);
  ASSERT_EQ(p.view.curves.size(), 1u);
  EXPECT_EQ(p.view.curves[0].trainee, "cyd");
  for (const training::Percentiles& q : p.view.percentiles) EXPECT_EQ(q.task, "rigid_sphere");
  EXPECT_DOUBLE_EQ(percentiles(p.view, "rigid_sphere", "score").p50, 65.0);  // 55 and 75

  state = {};
  std::snprintf(state.since, sizeof state.since, "2026-11-05");  // sessions 3 and 7
  p = panel_with(state);
  EXPECT_EQ(p.view.sessions, 2u);
  ASSERT_EQ(p.view.curves.size(), 2u);
  EXPECT_EQ(scores(p.view.curves[0]), (std::vector<double>{85}));
  EXPECT_EQ(scores(p.view.curves[1]), (std::vector<double>{75}));
}

TEST_F(CohortPanelFilters, HalfTypedDateKeepsTheLastViewAndSaysWhy) {
  ui::CohortPanel p = panel_with({});
  std::snprintf(p.state.until, sizeof p.state.until, "2026-11-0");
  EXPECT_FALSE(p.update(cohort_->store, cohort_->store.sessions()));
  EXPECT_EQ(p.view.sessions, 7u);
  EXPECT_NE(p.state.error.find("expected a date YYYY-MM-DD, got '2026-11-0'"), std::string::npos) << p.state.error;
  std::snprintf(p.state.until, sizeof p.state.until, "2026-11-02");  // sessions 1 and 4
  EXPECT_TRUE(p.update(cohort_->store, cohort_->store.sessions()));
  EXPECT_EQ(p.view.sessions, 2u);
  EXPECT_TRUE(p.state.error.empty());
}

TEST_F(CohortPanelFilters, ComputedAgainOnlyWhenASessionCompletes) {
  ui::CohortPanel p = panel_with({});
  EXPECT_FALSE(p.update(cohort_->store, cohort_->store.sessions()));  // nothing changed
  cohort_->store.finish_session(8, scored(50, false, kNotReached));   // dee's session completes
  EXPECT_TRUE(p.update(cohort_->store, cohort_->store.sessions()));
  EXPECT_EQ(p.view.sessions, 8u);
  EXPECT_EQ(p.state.choices.stations, (std::vector<std::string>{"st-1", "st-2", "st-3"}));
  EXPECT_EQ(p.view.most_failed[0].failed, 3);  // pivot_drill's pivot: sessions 1, 5 and 8
  EXPECT_EQ(p.view.most_failed[0].attempts, 6);
}

class CohortPanelPicture : public VulkanTest {
 protected:
  static void SetUpTestSuite() {
    VulkanTest::SetUpTestSuite();
    cohort_ = std::make_unique<Cohort>(fresh_db("picture"));
  }
  static void TearDownTestSuite() {
    cohort_.reset();
    fs::remove_all(folder());
    VulkanTest::TearDownTestSuite();
  }
  static engine::RgbaImage picture(ui::CohortPanel& panel, engine::Extent size) {
    panel.update(cohort_->store, cohort_->store.sessions());
    return ui::panel_picture(device(), size, [&] {
      ui::draw_cohort_panel(panel.view, panel.state, {ImVec2(0, 0), ImVec2(float(size.width), float(size.height))});
    });
  }
  static const engine::GpuDevice& device() { return *device_; }
  static inline std::unique_ptr<Cohort> cohort_;
};

// The whole cohort: the tables left, each task's score and time to target over attempts right
// (ana's three attempts rising, ben's two falling, cyd's two rising; a mark per attempt).
TEST_F(CohortPanelPicture, WholeClassMatchesGolden) {
  ui::CohortPanel panel;
  panel.state.show_export = true;
  EXPECT_TRUE(matches_golden(picture(panel, {1280, 720}), "panel_cohort"));
}

// Station st-2 from 2026-11-03: sessions 3 and 5 (ana's single attempt is a single mark; no time to
// target for ben's failed one), the filters showing their values.
TEST_F(CohortPanelPicture, FilteredClassMatchesGolden) {
  ui::CohortPanel panel;
  panel.state.station = "st-2";
  std::snprintf(panel.state.since, sizeof panel.state.since, "2026-11-03");
  EXPECT_TRUE(matches_golden(picture(panel, {1280, 720}), "panel_cohort_filtered"));
  EXPECT_EQ(panel.view.sessions, 2u);
}

}  // namespace
}  // namespace needle::test
