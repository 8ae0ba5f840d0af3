// A stored session against its replay (training/sessions/session_check.hpp): every stored number
// compared bit for bit (NaN, a metric that does not apply, equal to NaN), the digest of what was
// checked, and what the review shows of the latest check.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/support/stored_sessions.hpp"
#include "training/sessions/session_check.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::training {
namespace {

// The session a_result() stores, as load() returns it.
StoredSession stored_of(const SessionResult& r) {
  StoredSession s;
  s.info.id = 3;
  s.info.complete = true;
  s.info.score = r.score.total;
  s.info.passed = r.score.passed;
  s.info.duration_s = r.overall.duration_s;
  s.steps = r.steps;
  s.overall = r.overall;
  s.components = r.score.components;
  return s;
}

TEST(SessionCheck, TheReplayOfWhatWasStoredHasNoDifference) {
  const SessionResult r = test::a_result();
  ASSERT_TRUE(std::isnan(r.steps[1].metrics.force_sd_N)) << "a metric that does not apply: NaN on both sides";
  EXPECT_TRUE(result_differences(stored_of(r), r).empty());
}

TEST(SessionCheck, EachStoredNumberThatDiffersIsNamedWithBothValues) {
  const SessionResult replay = test::a_result();
  StoredSession s = stored_of(replay);
  s.info.score = 100.0;
  s.info.passed = true;
  s.steps[0].record.end_s = std::nextafter(s.steps[0].record.end_s, 1e9);  // one ulp
  s.steps[1].record.outcome = StepOutcome::kCompleted;
  s.steps[1].metrics.force_sd_N = 0.0;  // NaN replayed
  s.overall.withdrawals = 0;
  s.components[1].value = 1.0;
  const std::vector<std::string> d = result_differences(s, replay);
  const std::vector<std::string> want = {
      "score: stored 100, replay 61.5",
      "passed: stored yes, replay no",
      "step 1 (insert) end_s: stored 7.2500000000000009, replay 7.25",
      "step 2 (pivot) outcome: stored completed, replay tip_moved",
      "metric force_sd_N of step 2 (pivot): stored 0, replay nan",
      "metric withdrawals of the session: stored 0, replay 2",
      "score component tip_error value: stored 1, replay 0.69999999999999996",
  };
  EXPECT_EQ(d, want);
}

TEST(SessionCheck, StepsAndComponentsThatDoNotLineUpAreCounted) {
  const SessionResult replay = test::a_result();
  StoredSession s = stored_of(replay);
  s.steps.pop_back();
  s.components.clear();
  const std::vector<std::string> d = result_differences(s, replay);
  ASSERT_GE(d.size(), 2u);
  EXPECT_NE(std::find(d.begin(), d.end(), "steps: stored 1, replay 2"), d.end());
  EXPECT_NE(std::find(d.begin(), d.end(), "score components: stored 0, replay 2"), d.end());
}

TEST(SessionCheck, TheDigestChangesWithAnyStoredResult) {
  const StoredSession s = stored_of(test::a_result());
  const std::string digest = result_digest(s);
  EXPECT_EQ(digest.size(), 8u);
  EXPECT_EQ(result_digest(s), digest) << "the same results, the same digest";
  std::vector<StoredSession> changed(5, s);
  changed[0].info.score += 0.5;
  changed[1].steps[0].metrics.path_length_m = 0.0;
  changed[2].overall.peak_force_N = std::nextafter(changed[2].overall.peak_force_N, 1e9);
  changed[3].components[0].weight = 31.0;
  changed[4].steps[1].id = "pivoted";
  for (size_t k = 0; k < changed.size(); ++k) EXPECT_NE(result_digest(changed[k]), digest) << k;
}

TEST(SessionCheck, TheReviewShowsTheLatestCheckAgainstWhatIsStoredNow) {
  StoredSession s = stored_of(test::a_result());
  EXPECT_EQ(verification(s.info), Verification::kUnverified);
  EXPECT_EQ(verification_status(s).verdict, Verification::kUnverified);
  EXPECT_NE(verification_status(s).line.find("never checked"), std::string::npos);

  s.check =
      SessionCheck{3, CheckOutcome::kVerified, s.info.score, result_digest(s), "", "2026-11-23T10:00:00Z", "dr-lee"};
  s.info.check = CheckOutcome::kVerified;
  s.info.checked_score = s.info.score;
  EXPECT_EQ(verification(s.info), Verification::kVerified);
  EXPECT_EQ(verification_status(s).line, "verified against its recording (checked 2026-11-23T10:00:00Z by dr-lee)");
  // The score raised after the check: both the listing and the detail say mismatch.
  s.info.score = 100.0;
  EXPECT_EQ(verification(s.info), Verification::kMismatch);
  EXPECT_EQ(verification_status(s).verdict, Verification::kMismatch);
  // A check that found a difference, or could not replay.
  s = stored_of(test::a_result());
  s.info.check = CheckOutcome::kMismatch;
  s.info.checked_score = s.info.score;
  EXPECT_EQ(verification(s.info), Verification::kMismatch);
  s.info.check = CheckOutcome::kUnverifiable;
  EXPECT_EQ(verification(s.info), Verification::kUnverified);
  s.check = SessionCheck{3,
                         CheckOutcome::kUnverifiable,
                         s.info.score,
                         result_digest(s),
                         "x.nrec: block at byte 9: damaged\nmore",
                         "2026-11-23T10:00:00Z",
                         ""};
  EXPECT_EQ(verification_status(s).line,
            "unverified: its recording could not be replayed (checked 2026-11-23T10:00:00Z): x.nrec: block at byte 9: "
            "damaged");
  EXPECT_STREQ(verification_word(Verification::kMismatch), "mismatch");
}

TEST(SessionCheck, OutcomeNamesReadBack) {
  for (const CheckOutcome o : {CheckOutcome::kVerified, CheckOutcome::kMismatch, CheckOutcome::kUnverifiable}) {
    CheckOutcome back = CheckOutcome::kVerified;
    ASSERT_TRUE(check_outcome_from_name(check_outcome_name(o), back));
    EXPECT_EQ(back, o);
  }
  CheckOutcome unused;
  EXPECT_FALSE(check_outcome_from_name("trusted", unused));
}

}  // namespace
}  // namespace needle::training
