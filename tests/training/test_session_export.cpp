// JSON and CSV export of a session: every metric of every step, NaN as null or an empty field.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/test_paths.hpp"
#include "training/scoring/metric_fields.hpp"
#include "training/sessions/session_export.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;

StoredSession a_session() {
  StoredSession s;
  s.info.id = 42;
  s.info.trainee = "ana";
  s.info.task = "rigid_sphere";
  s.info.device = "sim";
  s.info.complete = true;
  s.info.score = 77.25;
  s.info.passed = true;
  StepResult touch{"touch, then \"hold\"", {StepOutcome::kCompleted, 0.0, 6.5}, {}};
  touch.metrics.peak_force_N = 1.5;
  touch.metrics.withdrawals = 3;
  StepResult press{"press", {StepOutcome::kTimedOut, 6.5, 26.5}, {}};
  press.metrics.force_sd_N = 0.125;
  s.steps = {touch, press};
  s.overall = combine_metrics(s.steps);
  s.components = {{"completion", 0.5, 30.0}};
  return s;
}

// Splits one CSV line, honouring quotes.
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      out.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

size_t metric_count() {
  size_t n = 0;
  Metrics m;
  for_each_metric(m, [&](const char*, auto&) { ++n; });
  return n;
}

TEST(SessionExport, JsonHasScoreMetricsAndSteps) {
  const nlohmann::json j = session_json(a_session());
  EXPECT_EQ(j["session"]["id"], 42);
  EXPECT_EQ(j["session"]["trainee"], "ana");
  EXPECT_DOUBLE_EQ(j["score"].get<double>(), 77.25);
  EXPECT_TRUE(j["passed"].get<bool>());
  ASSERT_EQ(j["steps"].size(), 2u);
  EXPECT_EQ(j["steps"][0]["id"], "touch, then \"hold\"");
  EXPECT_EQ(j["steps"][1]["outcome"], "timed_out");
  EXPECT_DOUBLE_EQ(j["steps"][1]["start_s"].get<double>(), 6.5);
  EXPECT_DOUBLE_EQ(j["steps"][1]["metrics"]["force_sd_N"].get<double>(), 0.125);
  EXPECT_TRUE(j["steps"][0]["metrics"]["force_sd_N"].is_null());  // does not apply
  EXPECT_EQ(j["steps"][0]["metrics"]["withdrawals"], 3);
  EXPECT_EQ(j["steps"][0]["metrics"].size(), metric_count());
  EXPECT_DOUBLE_EQ(j["metrics"]["peak_force_N"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j["components"][0]["points"].get<double>(), 15.0);
}

// A session whose run ended before the task did was never scored: its export says so with null,
// not with a score of 0 that failed (the store keeps 0 and 0 for it).
TEST(SessionExport, AnIncompleteSessionHasNoScoreAndNoVerdict) {
  StoredSession s;
  s.info.id = 7;
  s.info.complete = false;
  const nlohmann::json j = session_json(s);
  EXPECT_TRUE(j["score"].is_null()) << j.dump();
  EXPECT_TRUE(j["passed"].is_null()) << j.dump();
  EXPECT_FALSE(j["session"]["complete"].get<bool>());
  s.info.complete = true;  // and a complete one with a score of 0 says 0, failed
  EXPECT_EQ(session_json(s)["score"], 0.0);
  EXPECT_EQ(session_json(s)["passed"], false);
}

TEST(SessionExport, ResultJsonCarriesWhatScoreJsonNeeds) {
  SessionResult r;
  r.steps = a_session().steps;
  r.overall = combine_metrics(r.steps);
  r.score.total = 40.0;
  r.score.reasons_failed = {"score 40 below the pass mark 70"};
  const nlohmann::json j = result_json(r);
  for (const char* key : {"score", "passed", "metrics", "steps"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_FALSE(j["passed"].get<bool>());
  EXPECT_EQ(j["reasons_failed"][0], "score 40 below the pass mark 70");
}

TEST(SessionExport, CsvHasOneRowPerMetricPerStepAndForTheSession) {
  const std::string csv = session_csv(a_session());
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "session_id,step_index,step_id,outcome,start_s,end_s,metric,value");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) rows.push_back(fields(line));
  ASSERT_EQ(rows.size(), 3 * metric_count());
  for (const auto& row : rows) ASSERT_EQ(row.size(), 8u) << row[0];
  const auto find = [&](const std::string& step, const std::string& metric) {
    for (const auto& row : rows)
      if (row[1] == step && row[6] == metric) return row;
    return std::vector<std::string>{};
  };
  const auto peak = find("0", "peak_force_N");
  ASSERT_FALSE(peak.empty());
  EXPECT_EQ(peak[2], "touch, then \"hold\"");
  EXPECT_EQ(peak[3], "completed");
  EXPECT_DOUBLE_EQ(std::stod(peak[7]), 1.5);
  EXPECT_EQ(find("0", "force_sd_N")[7], "");      // does not apply
  EXPECT_EQ(find("1", "force_sd_N")[5], "26.5");  // the step's end
  EXPECT_EQ(find("1", "force_sd_N")[7], "0.125");
  const auto session = find("-1", "duration_s");
  EXPECT_EQ(session[2], "session");
  EXPECT_EQ(session[3], "complete");
}

TEST(SessionExport, WritesBothFilesIntoTheFolder) {
  const fs::path dir = test::output_dir() / "export";
  fs::remove_all(dir);
  const fs::path json_file = export_session(a_session(), dir / "nested");
  EXPECT_EQ(json_file, dir / "nested" / "session_42.json");
  std::ifstream in(json_file);
  EXPECT_EQ(nlohmann::json::parse(in)["session"]["id"], 42);
  EXPECT_TRUE(fs::is_regular_file(dir / "nested" / "session_42.csv"));
  EXPECT_THROW(export_session(a_session(), "/proc/version/x"), std::runtime_error);
}

}  // namespace
}  // namespace needle::training
