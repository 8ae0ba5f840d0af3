// `needle-sim report` and `needle-sim review` as an instructor runs them, on a database holding
// recorded closed-loop sessions: the report's files (metrics JSON and CSV, plots and panels as
// PNG) and each of its clear errors; the review window under Xvfb (its Class tab's export too), and
// its message without a display.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "engine/rgba_image.hpp"
#include "tests/app/recorded_session.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

const char* const kPlots[] = {"plot_force.png", "plot_lateral_load.png", "plot_depth.png", "plot_tracking_error.png"};

class CliReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = process_folder(test_output_dir("cli_report"));
    fs::create_directories(dir_ / "db");
    db_ = dir_ / "db" / "sessions.db";
    good_ = record_session(db_, {"penetrable_sphere", "good", "ana", true});
    died_ = record_session(db_, {"rigid_sphere", "good", "bo", false});
    lost_ = record_session(db_, {"rigid_sphere", "sloppy", "cy", true});
    fs::remove(lost_.recording);
  }
  static ProcessResult report(int64_t id, const fs::path& out) {
    fs::remove_all(out);
    return run_needle_sim("report --session " + std::to_string(id) + " --db " + quoted(db_) + " --out " + quoted(out));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static inline fs::path dir_, db_;
  static inline RecordedSession good_, died_, lost_;
};

TEST_F(CliReport, WritesMetricsPlotsAndPanels) {
  const fs::path out = dir_ / "good";
  const ProcessResult r = report(good_.id, out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  // An offline run ticks unpaced at the scenario's 2 ms: its loop reads as on time.
  EXPECT_NE(r.output.find("haptic loop 500.0 Hz (nominal 500), period p99 2.00 ms, worst 2.00 ms, 0 late ticks"),
            std::string::npos)
      << r.output;
  const std::string stem = "session_" + std::to_string(good_.id);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out / (stem + ".json")));
  EXPECT_DOUBLE_EQ(j["score"].get<double>(), good_.result.score.total);
  EXPECT_EQ(j["steps"].size(), good_.result.steps.size());
  EXPECT_EQ(j["session"]["recording_path"], good_.recording.string());
  std::ifstream csv(out / (stem + ".csv"));
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "session_id,step_index,step_id,outcome,start_s,end_s,metric,value");
  for (const char* plot : kPlots) {
    const engine::RgbaImage image = engine::read_png(out / plot);
    EXPECT_EQ(image.width, 900u) << plot;
    EXPECT_EQ(image.height, 320u) << plot;
  }
  for (const char* panel : {"review_table.png", "review_detail.png", "review_replay.png"}) {
    EXPECT_TRUE(fs::is_regular_file(out / panel)) << panel;
  }
  EXPECT_EQ(engine::read_png(out / "review_replay.png").width, 1280u);
}

// --from/--to: the plots of a time range; a range reaching past the recording is cut to it and
// said; one outside it is an error before anything is written.
TEST_F(CliReport, PlotsOfATimeRange) {
  const fs::path out = dir_ / "zoomed";
  fs::remove_all(out);
  const std::string base = "report --session " + std::to_string(good_.id) + " --db " + quoted(db_) + " --out ";
  const ProcessResult r = run_needle_sim(base + quoted(out) + " --from 10 --to 12");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("plots from 10.000 to 12.000 s"), std::string::npos) << r.output;
  for (const char* plot : kPlots) EXPECT_TRUE(fs::is_regular_file(out / plot)) << plot;
  const ProcessResult tail = run_needle_sim(base + quoted(dir_ / "tail") + " --from 12");
  ASSERT_EQ(tail.exit_code, 0) << tail.output;
  EXPECT_NE(tail.output.find("plots from 12.000 to "), std::string::npos) << tail.output;

  const fs::path never = dir_ / "never";
  fs::remove_all(never);
  const ProcessResult outside = run_needle_sim(base + quoted(never) + " --from 1000 --to 1500");
  EXPECT_EQ(outside.exit_code, 1) << outside.output;
  EXPECT_NE(outside.output.find("the plots' range 1000 to 1500 s lies outside the recording"), std::string::npos)
      << outside.output;
  EXPECT_FALSE(fs::exists(never));
  const ProcessResult backwards = run_needle_sim(base + quoted(never) + " --from 12 --to 10");
  EXPECT_EQ(backwards.exit_code, 2) << backwards.output;
  EXPECT_NE(backwards.output.find("--to must be later than --from"), std::string::npos) << backwards.output;
}

// A layered task's session (the epidural's good run): the report adds the force–depth
// plot and the punctures, made again from the recording, equal to those the run scored live, and
// the syringe's plunger pressure against depth.
TEST(CliReportLayered, TheForceDepthPlotAndThePuncturesTheRunScored) {
  const fs::path dir = process_folder(test_output_dir("cli_report") / "layered");
  const fs::path db = dir / "sessions.db";
  const RecordedSession run = record_session(db, {"epidural", "good", "ana", true});
  ASSERT_FALSE(run.result.punctures.empty());
  const fs::path out = dir / "out";
  const ProcessResult r =
      run_needle_sim("report --session " + std::to_string(run.id) + " --db " + quoted(db) + " --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  const engine::RgbaImage plot = engine::read_png(out / "plot_force_depth.png");
  EXPECT_EQ(plot.width, 900u);
  EXPECT_EQ(plot.height, 320u);
  const std::string stem = "session_" + std::to_string(run.id);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out / (stem + ".json")));
  ASSERT_EQ(j["punctures"].size(), run.result.punctures.size()) << j["punctures"].dump();
  std::ifstream csv(out / (stem + "_punctures.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "session_id,index,layer,t_s,depth_m,peak_force_N");
  for (size_t k = 0; k < run.result.punctures.size(); ++k) {
    const training::PunctureResult& p = run.result.punctures[k];
    EXPECT_EQ(j["punctures"][k]["layer"], p.layer) << k;
    EXPECT_DOUBLE_EQ(j["punctures"][k]["t_s"].get<double>(), p.t_s) << k;
    EXPECT_DOUBLE_EQ(j["punctures"][k]["depth_m"].get<double>(), p.depth_m) << k;
    EXPECT_DOUBLE_EQ(j["punctures"][k]["peak_force_N"].get<double>(), p.peak_force_N) << k;
    ASSERT_TRUE(std::getline(csv, line)) << k;
    EXPECT_EQ(line.rfind(std::to_string(run.id) + "," + std::to_string(k) + "," + p.layer + ",", 0), 0u) << line;
  }
  EXPECT_FALSE(std::getline(csv, line)) << "one row a puncture: " << line;
  EXPECT_NE(r.output.find(std::to_string(run.result.punctures.size()) + " puncture(s)"), std::string::npos) << r.output;
  // With its syringe: the plunger's pressure against depth beside it, its one loss of resistance.
  const engine::RgbaImage pressure = engine::read_png(out / "plot_plunger_pressure.png");
  EXPECT_EQ(pressure.width, 900u);
  EXPECT_EQ(pressure.height, 320u);
  EXPECT_NE(r.output.find("1 loss(es) of resistance"), std::string::npos) << r.output;
}

TEST_F(CliReport, IncompleteSessionExportsWhatIsStoredAndSaysSo) {
  const fs::path out = dir_ / "died";
  const ProcessResult r = report(died_.id, out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("session " + std::to_string(died_.id) + " is incomplete"), std::string::npos) << r.output;
  const nlohmann::json j =
      nlohmann::json::parse(std::ifstream(out / ("session_" + std::to_string(died_.id) + ".json")));
  EXPECT_FALSE(j["session"]["complete"].get<bool>());
  EXPECT_TRUE(j["steps"].empty());
  // Its recording holds the samples up to the end: the plots are made from it.
  EXPECT_TRUE(fs::is_regular_file(out / "plot_force.png"));
  // The rigid task has no insertion axis: no depth plot, and the report says why.
  EXPECT_FALSE(fs::exists(out / "plot_depth.png"));
  EXPECT_NE(r.output.find("no plot_depth.png: task rigid_sphere has no insertion axis"), std::string::npos) << r.output;
}

TEST_F(CliReport, MissingRecordingStillExportsTheMetricsAndNamesTheFile) {
  const fs::path out = dir_ / "lost";
  const ProcessResult r = report(lost_.id, out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(lost_.recording.string() + ": recording not found"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no plots and no replay picture"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_regular_file(out / ("session_" + std::to_string(lost_.id) + ".json")));
  EXPECT_TRUE(fs::is_regular_file(out / ("session_" + std::to_string(lost_.id) + ".csv")));
  EXPECT_TRUE(fs::is_regular_file(out / "review_detail.png"));
  for (const char* plot : kPlots) EXPECT_FALSE(fs::exists(out / plot)) << plot;
}

TEST_F(CliReport, ClearErrors) {
  const ProcessResult none = report(999, dir_ / "none");
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_NE(none.output.find("reading session 999: no such session"), std::string::npos) << none.output;
  const ProcessResult no_db =
      run_needle_sim("report --session 1 --db " + quoted(dir_ / "nowhere.db") + " --out " + quoted(dir_ / "x"));
  EXPECT_EQ(no_db.exit_code, 1) << no_db.output;
  EXPECT_NE(no_db.output.find("nowhere.db: no session database"), std::string::npos) << no_db.output;
  EXPECT_FALSE(fs::exists(dir_ / "nowhere.db"));  // never created by a reader
  EXPECT_EQ(run_needle_sim("report --db " + quoted(db_) + " --out " + quoted(dir_ / "x")).exit_code, 2);
  EXPECT_EQ(run_needle_sim("report --session 1 --db " + quoted(db_)).exit_code, 2);
  EXPECT_EQ(run_needle_sim("report --session first --db " + quoted(db_) + " --out x").exit_code, 2);
  EXPECT_EQ(run_needle_sim("report --session 1.5 --db " + quoted(db_) + " --out x").exit_code, 2);
}

TEST_F(CliReport, ReviewWithoutADisplayPointsToReport) {
  const ProcessResult r = run_command("env -u DISPLAY -u WAYLAND_DISPLAY NEEDLE_VALIDATION=1 " +
                                      test::needle_sim_exe().string() + " review --db " + quoted(db_));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("needle-sim report --session ID --out DIR"), std::string::npos) << r.output;
}

TEST_F(CliReport, ReviewWindowShowsTheSessionAndItsReplay) {
  const fs::path shot = dir_ / "review_window.png";
  fs::remove(shot);
  const ProcessResult r =
      run_command("NEEDLE_VALIDATION=1 xvfb-run -a -s '-screen 0 1280x800x24' " + test::needle_sim_exe().string() +
                  " review --size 1200x700 --frames 4 --screenshot " + quoted(shot) + " --session " +
                  std::to_string(good_.id) + " --db " + quoted(db_));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("presented 4 frames"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  EXPECT_EQ(engine::read_png(shot).width, 1200u);
}

// The Class tab (review --class) under Xvfb: xdotool clicks its export button (where it stands in
// a 1200x700 window, 13 px text); the window writes the cohort's JSON, identical to what
// `report --cohort` writes (one computation), the CSV tables, and the tab as it was drawn.
TEST_F(CliReport, ReviewClassTabExportsWhatReportCohortWrites) {
  const fs::path exports = dir_ / "db" / "exports" / "cohort";
  fs::remove_all(exports);
  const fs::path script = dir_ / "class_tab.sh";
  std::ofstream(script) << "NEEDLE_VALIDATION=1 " << test::needle_sim_exe().string()
                        << " review --class --size 1200x700 --frames 400 --db " << quoted(db_)
                        << " &\napp=$!\nid=$(xdotool search --sync --name '^needle-sim review$' | head -1)\n"
                        << "sleep 3; xdotool mousemove --window \"$id\" 1030 76; sleep 0.5; xdotool click 1\n"
                        << "wait $app\n";
  const ProcessResult r = run_command("xvfb-run -a -s '-screen 0 1280x800x24' sh " + quoted(script));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  for (const char* file : {"cohort.json", "cohort_curves.csv", "cohort_failed_steps.csv", "cohort_percentiles.csv"})
    EXPECT_TRUE(fs::is_regular_file(exports / file)) << file << "\n" << r.output;
  const ProcessResult cohort =
      run_needle_sim("report --cohort --db " + quoted(db_) + " --out " + quoted(dir_ / "cohort"));
  ASSERT_EQ(cohort.exit_code, 0) << cohort.output;
  const nlohmann::json from_window = nlohmann::json::parse(std::ifstream(exports / "cohort.json"));
  EXPECT_EQ(from_window, nlohmann::json::parse(std::ifstream(dir_ / "cohort" / "cohort.json")));
  EXPECT_EQ(from_window["sessions"], 2) << "ana's and cy's complete sessions; bo's died";
  const engine::RgbaImage tab = engine::read_png(exports / "cohort_view.png");
  EXPECT_EQ(tab.width, 1200u);
  EXPECT_GT(tab.height, 600u);  // the window less the tabs above it
  EXPECT_LT(tab.height, 700u);
}

}  // namespace
}  // namespace needle::test
