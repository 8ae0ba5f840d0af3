// The instructor's class view against a hand-counted cohort: learning curves in time order,
// first-pass success, time to target, the most failed steps, percentiles by the R-7 rule, filters.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tests/support/stored_sessions.hpp"
#include "tests/support/test_paths.hpp"
#include "training/sessions/cohort_export.hpp"
#include "training/sessions/cohort_view.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;

// `score` and `passed`; with `reached`, the pivot step completes (its tip error applies): the
// target is reached at its end, 9 s.
SessionResult scored(double score, bool passed, bool reached) {
  SessionResult r = test::a_result();
  r.score.total = score;
  r.score.passed = passed;
  if (reached) r.steps[1].record.outcome = StepOutcome::kCompleted;
  return r;
}

class CohortViewTest : public testing::Test {
 protected:
  void SetUp() override {
    const fs::path dir = test::output_dir() / "cohort";
    fs::create_directories(dir);
    file_ = (dir / (std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + ".db")).string();
    for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(file_ + suffix);
    store_ = std::make_unique<SessionStore>(file_);
    // Written out of time order: the curves follow started_at, not the ids.
    add("ana", "pivot_drill", "st-1", "2026-11-02T09:00:00Z", scored(80, true, true));
    add("ana", "pivot_drill", "st-1", "2026-11-01T09:00:00Z", scored(40, false, false));
    add("ben", "pivot_drill", "st-2", "2026-11-03T09:00:00Z", scored(90, true, true));
    add("ben", "rigid_sphere", "st-2", "2026-11-04T09:00:00Z", scored(70, true, false));
    store_->begin_session(
        {"cyd", "pivot_drill", "Pivot drill", "", "sim", "", "st-1", "", "2026-11-05T09:00:00Z"});  // incomplete
  }
  void add(const std::string& trainee, const std::string& task, const std::string& station, const std::string& at,
           const SessionResult& result) {
    const int64_t id = store_->begin_session({trainee, task, task, "", "sim", "", station, "", at});
    store_->finish_session(id, result);
  }
  std::string file_;
  std::unique_ptr<SessionStore> store_;
};

TEST_F(CohortViewTest, CurvesFirstPassTimeToTargetFailedStepsAndPercentiles) {
  const CohortView v = cohort_view(*store_, {});
  EXPECT_EQ(v.sessions, 4u);  // the incomplete one is not counted
  ASSERT_EQ(v.curves.size(), 3u);
  const LearningCurve& ana = v.curves[0];
  EXPECT_EQ(ana.trainee, "ana");
  EXPECT_EQ(ana.task, "pivot_drill");
  ASSERT_EQ(ana.attempts.size(), 2u);
  EXPECT_EQ(ana.attempts[0].score, 40);  // the older first
  EXPECT_EQ(ana.attempts[1].score, 80);
  EXPECT_FALSE(ana.first_pass);
  EXPECT_EQ(ana.attempts_to_pass, 2);
  EXPECT_TRUE(std::isnan(ana.attempts[0].time_to_target_s));
  EXPECT_EQ(ana.attempts[1].time_to_target_s, 9.0);
  EXPECT_TRUE(v.curves[1].first_pass);  // ben, pivot_drill
  EXPECT_EQ(v.curves[1].attempts_to_pass, 1);
  EXPECT_EQ(v.curves[2].task, "rigid_sphere");

  // The pivot step failed in the two sessions that did not reach the target, once in each task;
  // equal counts rank by share: 1 of 1 (rigid_sphere) before 1 of 3 (pivot_drill).
  ASSERT_EQ(v.most_failed.size(), 2u);
  EXPECT_EQ(v.most_failed[0].task, "rigid_sphere");
  EXPECT_EQ(v.most_failed[0].failed, 1);
  EXPECT_EQ(v.most_failed[0].attempts, 1);
  EXPECT_EQ(v.most_failed[1].task, "pivot_drill");
  EXPECT_EQ(v.most_failed[1].step, "pivot");
  EXPECT_EQ(v.most_failed[1].failed, 1);
  EXPECT_EQ(v.most_failed[1].attempts, 3);

  // Scores of pivot_drill: 40, 80, 90. R-7: rank p/100 * (n - 1), linear between neighbours.
  const Percentiles* score = nullptr;
  for (const Percentiles& p : v.percentiles)
    if (p.task == "pivot_drill" && p.metric == "score") score = &p;
  ASSERT_NE(score, nullptr);
  EXPECT_EQ(score->n, 3u);
  EXPECT_DOUBLE_EQ(score->p10, 48.0);
  EXPECT_DOUBLE_EQ(score->p25, 60.0);
  EXPECT_DOUBLE_EQ(score->p50, 80.0);
  EXPECT_DOUBLE_EQ(score->p75, 85.0);
  EXPECT_DOUBLE_EQ(score->p90, 88.0);
  EXPECT_DOUBLE_EQ(percentile({5.0}, 90), 5.0);
  EXPECT_TRUE(std::isnan(percentile({}, 50)));
}

// The layered tissue's metrics are listed for a task whose sessions punctured something (a layered
// task: 2 and 4 punctures, one bone contact between them) and not for the others (pivot_drill,
// rigid_sphere: zeros, no rows).
TEST_F(CohortViewTest, LayeredMetricsOnlyForTasksThatPunctured) {
  for (const uint32_t punctures : {2u, 4u}) {
    SessionResult r = scored(60, false, true);
    r.overall.punctures = punctures;
    r.overall.bone_contacts = punctures == 4u ? 1u : 0u;
    add("dan", "layered_target", "st-1", punctures == 2u ? "2026-11-06T09:00:00Z" : "2026-11-07T09:00:00Z", r);
  }
  const CohortView v = cohort_view(*store_, {});
  const auto n_of = [&](const std::string& task, const std::string& metric) {
    for (const Percentiles& p : v.percentiles)
      if (p.task == task && p.metric == metric) return p.n;
    return size_t(99);
  };
  for (const char* metric :
       {"punctures", "overshoot_m", "bone_contacts", "bone_peak_force_N", "redirections", "forbidden_punctures"}) {
    EXPECT_EQ(n_of("pivot_drill", metric), 0u) << metric;
    EXPECT_EQ(n_of("rigid_sphere", metric), 0u) << metric;
  }
  EXPECT_EQ(n_of("layered_target", "punctures"), 2u);
  EXPECT_EQ(n_of("layered_target", "bone_contacts"), 2u);
  EXPECT_EQ(n_of("pivot_drill", "withdrawals"), 3u);  // the other metrics stay
  for (const Percentiles& p : v.percentiles)
    if (p.task == "layered_target" && p.metric == "punctures") {
      EXPECT_DOUBLE_EQ(p.p10, 2.2);  // R-7 on {2, 4}
      EXPECT_DOUBLE_EQ(p.p90, 3.8);
    }
}

TEST_F(CohortViewTest, FiltersByTaskTraineeStationAndDates) {
  EXPECT_EQ(cohort_view(*store_, {"rigid_sphere", "", "", "", ""}).sessions, 1u);
  EXPECT_EQ(cohort_view(*store_, {"", "ana", "", "", ""}).sessions, 2u);
  EXPECT_EQ(cohort_view(*store_, {"", "", "st-2", "", ""}).sessions, 2u);
  EXPECT_EQ(cohort_view(*store_, {"", "", "", "2026-11-02", "2026-11-03"}).sessions, 2u);  // inclusive
  EXPECT_EQ(cohort_view(*store_, {"", "", "", "2026-11-04", ""}).sessions, 1u);
  EXPECT_EQ(cohort_view(*store_, {"", "nobody", "", "", ""}).curves.size(), 0u);
  EXPECT_THROW(cohort_view(*store_, {"", "", "", "1 Nov", ""}), std::invalid_argument);
}

// A date is a day of the calendar, not any digits in its shape.
TEST(CohortFilter, DatesAreDaysOfTheCalendar) {
  for (const char* day : {"2026-01-31", "2024-02-29", "2000-02-29", "2026-12-31"})
    EXPECT_NO_THROW(check_cohort_filter({"", "", "", day, ""})) << day;
  for (const char* day :
       {"2026-13-45", "2026-02-30", "2026-02-29", "1900-02-29", "2026-04-31", "2026-00-10", "2026-01-00"})
    EXPECT_THROW(check_cohort_filter({"", "", "", "", day}), std::invalid_argument) << day;
}

TEST_F(CohortViewTest, ExportsOneRowPerValue) {
  const CohortView v = cohort_view(*store_, {});
  const std::string curves = learning_curves_csv(v);
  EXPECT_EQ(std::count(curves.begin(), curves.end(), '\n'), 1 + 4);  // the header, an attempt a row
  EXPECT_NE(curves.find("ana,pivot_drill,1,"), std::string::npos);
  EXPECT_NE(failed_steps_csv(v).find("pivot_drill,pivot,1,3\n"), std::string::npos);
  const nlohmann::json j = cohort_json(v);
  EXPECT_EQ(j["sessions"], 4);
  EXPECT_EQ(j["curves"][0]["attempts"][0]["time_to_target_s"], nullptr);
  EXPECT_EQ(j["curves"][0]["attempts"][1]["time_to_target_s"], 9.0);
}

}  // namespace
}  // namespace needle::training
