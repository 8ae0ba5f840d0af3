// The review table's filter and sort rules, without ImGui, on four sessions written by hand.
#include <gtest/gtest.h>

#include "training/sessions/session_table.hpp"

namespace needle::training {
namespace {

SessionInfo info(int64_t id, std::string trainee, std::string task, std::string date, bool complete, double score,
                 bool passed, double duration) {
  SessionInfo s;
  s.id = id;
  s.trainee = std::move(trainee);
  s.task = std::move(task);
  s.started_at = std::move(date);
  s.device = "sim (good)";
  s.complete = complete;
  s.score = score;
  s.passed = passed;
  s.duration_s = duration;
  return s;
}

// As SessionStore::sessions() gives them: newest first.
const std::vector<SessionInfo> kSessions = {
    info(4, "ana", "penetrable_sphere", "2026-01-04T09:00:00Z", true, 91.0, true, 28.0),
    info(3, "Carla", "penetrable_sphere", "2026-01-03T09:00:00Z", false, 0.0, false, 12.0),
    info(2, "bo", "penetrable_sphere", "2026-01-01T09:00:00Z", true, 40.0, false, 50.0),
    info(1, "ana", "rigid_sphere", "2026-01-02T09:00:00Z", true, 80.0, true, 30.0),
};

std::vector<int64_t> ids(const std::string& filter, const std::vector<SessionSort>& sort) {
  std::vector<int64_t> out;
  for (size_t row : session_rows(kSessions, filter, sort)) out.push_back(kSessions[row].id);
  return out;
}

TEST(SessionTable, WithoutSortOrFilterKeepsTheStoresOrder) {
  EXPECT_EQ(ids("", {}), (std::vector<int64_t>{4, 3, 2, 1}));
  EXPECT_EQ(ids("   ", {}), (std::vector<int64_t>{4, 3, 2, 1}));
}

TEST(SessionTable, ScoreSortPutsTheIncompleteSessionLastEitherWay) {
  EXPECT_EQ(ids("", {{SessionColumn::kScore, false}}), (std::vector<int64_t>{2, 1, 4, 3}));
  EXPECT_EQ(ids("", {{SessionColumn::kScore, true}}), (std::vector<int64_t>{4, 1, 2, 3}));
}

TEST(SessionTable, SortsByEachColumn) {
  EXPECT_EQ(ids("", {{SessionColumn::kId, false}}), (std::vector<int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(ids("", {{SessionColumn::kDate, false}}), (std::vector<int64_t>{2, 1, 3, 4}));
  EXPECT_EQ(ids("", {{SessionColumn::kDuration, true}}), (std::vector<int64_t>{2, 1, 4, 3}));
  EXPECT_EQ(ids("", {{SessionColumn::kTask, true}}), (std::vector<int64_t>{1, 4, 3, 2}));  // ties: store order
  // failed < incomplete < passed; the two passed keep the store's order.
  EXPECT_EQ(ids("", {{SessionColumn::kResult, false}}), (std::vector<int64_t>{2, 3, 4, 1}));
}

TEST(SessionTable, TraineeSortIgnoresCaseAndASecondColumnBreaksTies) {
  EXPECT_EQ(ids("", {{SessionColumn::kTrainee, false}, {SessionColumn::kScore, false}}),
            (std::vector<int64_t>{1, 4, 2, 3}));  // ana 80, ana 91, bo, Carla
  EXPECT_EQ(ids("", {{SessionColumn::kTrainee, true}, {SessionColumn::kScore, true}}),
            (std::vector<int64_t>{3, 2, 4, 1}));
}

TEST(SessionTable, FilterTermsAllMatchIgnoringCaseAndMinusExcludes) {
  EXPECT_EQ(ids("penetrable", {}), (std::vector<int64_t>{4, 3, 2}));
  EXPECT_EQ(ids("penetrable -failed", {}), (std::vector<int64_t>{4, 3}));
  EXPECT_EQ(ids("ANA passed", {}), (std::vector<int64_t>{4, 1}));
  EXPECT_EQ(ids("incomplete", {}), (std::vector<int64_t>{3}));
  EXPECT_EQ(ids("2026-01-0", {{SessionColumn::kId, false}}), (std::vector<int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(ids("2026-01-02", {}), (std::vector<int64_t>{1}));
  EXPECT_EQ(ids("sim", {}).size(), 4u);  // the device
  EXPECT_TRUE(ids("nobody", {}).empty());
  EXPECT_TRUE(ids("ana -ana", {}).empty());
}

TEST(SessionTable, ResultWords) {
  EXPECT_STREQ(session_result_word(kSessions[0]), "passed");
  EXPECT_STREQ(session_result_word(kSessions[1]), "incomplete");
  EXPECT_STREQ(session_result_word(kSessions[2]), "failed");
}

}  // namespace
}  // namespace needle::training
