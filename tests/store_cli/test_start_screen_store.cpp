// The start screen's records read from the configured store (app/start_screen.hpp): a PostgreSQL
// server's sessions from every station (the schema made on a new database, as a run would), an
// SQLite file not made yet read as none (and not made), an unreachable server a clear error
// without the password.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "app/start_screen.hpp"
#include "tests/support/quick_task.hpp"
#include "tests/support/stored_sessions.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"
#include "tests/tools/cli_process.hpp"
#include "training/sessions/trainee_history.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;

training::SessionResult scored(double score, bool passed) {
  training::SessionResult r = a_result();
  r.score.total = score;
  r.score.passed = passed;
  return r;
}

TEST(StartScreenStore, ReadsEveryStationsSessionsFromTheServer) {
  const std::string uri = fresh_postgres_database("start_screen");
  EXPECT_TRUE(app::start_screen_sessions(uri).empty());  // a new database: its schema made, no sessions
  {
    training::SessionStore store(uri, training::kReadOnly);  // the schema is there now
    EXPECT_EQ(store.schema_version(), training::kSessionSchemaVersion);
  }
  training::SessionStore server(uri);
  server.finish_session(server.begin_session({"ana", "pivot_drill", "Pivot drill", "", "sim", "", "station-a", "",
                                              "2026-11-01T09:00:00Z"}),
                        scored(72, true));
  server.finish_session(server.begin_session({"ana", "pivot_drill", "Pivot drill", "", "sim", "", "station-b", "",
                                              "2026-11-02T09:00:00Z"}),
                        scored(64, false));
  server.begin_session({"ben", "pivot_drill", "Pivot drill", "", "sim", "", "station-b", "", "2026-11-03T09:00:00Z"});
  const std::vector<training::SessionInfo> sessions = app::start_screen_sessions(uri);
  ASSERT_EQ(sessions.size(), 3u);
  EXPECT_EQ(training::known_trainees(sessions), (std::vector<std::string>{"ben", "ana"}));
  // ana's record on the screen, from both stations: last 64 (not passed), best 72, 2 done.
  const std::map<std::string, training::TaskHistory> ana = training::task_history(sessions, "ana");
  ASSERT_EQ(ana.count("pivot_drill"), 1u);
  EXPECT_EQ(ana.at("pivot_drill").last.score, 64);
  EXPECT_FALSE(ana.at("pivot_drill").last.passed);
  EXPECT_EQ(ana.at("pivot_drill").best, 72);
  EXPECT_EQ(ana.at("pivot_drill").completed, 2);
}

TEST(StartScreenStore, AnSqliteFileNotMadeYetHasNoSessionsAndIsNotMade) {
  const fs::path file = test_output_dir("start_screen_store") / "not_yet.db";
  fs::remove(file);
  EXPECT_TRUE(app::start_screen_sessions(file.string()).empty());
  EXPECT_FALSE(fs::exists(file));
}

TEST(StartScreenStore, AnUnreachableServerIsAnErrorNamingItWithoutThePassword) {
  try {
    app::start_screen_sessions("postgresql://needle:hunter2@/no_such_database?host=" + postgres_dir() +
                               "&port=" + postgres_port());
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("postgresql://needle:***@/no_such_database"), std::string::npos) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
    EXPECT_EQ(message.find("hunter2"), std::string::npos) << message;
  }
}

// `needle-sim --station st-screen` with NEEDLE_DB naming the server, under Xvfb: the start screen
// reads carla's record from the server (no error printed), xdotool starts the first task (one that
// ends at once), goes Back and quits; the session is on the server, complete, from that station.
TEST(StartScreenStore, TheStartScreenRunsItsTasksAgainstNeedleDb) {
  const std::string uri = fresh_postgres_database("start_screen_run");
  {
    training::SessionStore server(uri);
    server.finish_session(server.begin_session({"carla", "quick", "Quick", "", "sim", "", "st-old", "", ""}),
                          scored(50, false));
  }
  const fs::path dir = test_output_dir("start_screen_store") / "run";
  fs::remove_all(dir);
  fs::create_directories(dir / "config/needle-sim");
  fs::create_directories(dir / "assets/tasks");
  std::ofstream(dir / "config/needle-sim/settings.json")
      << R"({"version": 1, "trainee": "carla", "device": "keyboard", "window": {"width": 640, "height": 360}})";
  write_quick_task(dir / "assets/tasks/quick.json", "quick", "Quick");
  const fs::path log = dir / "needle-sim.log", script = dir / "drive.sh";
  std::ofstream(script) << "export XDG_CONFIG_HOME=" << quoted(dir / "config")
                        << " XDG_DATA_HOME=" << quoted(dir / "data") << " NEEDLE_ASSETS=" << quoted(dir / "assets")
                        << " NEEDLE_DB='" << uri << "'\n"
                        << needle_sim_exe().string() << " --station st-screen > " << quoted(log) << " 2>&1 &\napp=$!\n"
                        << "id=$(xdotool search --sync --name '^needle-sim$' | head -1)\n"
                        << "xdotool mousemove --window \"$id\" 300 300; sleep 2; xdotool key Return\n"
                        << "n=0; until grep -q '^score ' " << quoted(log)
                        << "; do n=$((n+1)); [ $n -gt 600 ] && { kill $app; echo 'driver: the task did not end'; exit "
                           "1; }; sleep 0.1; done\n"
                        << "sleep 1; xdotool key Escape; sleep 2; xdotool key Escape\nwait $app; rc=$?; cat "
                        << quoted(log) << "; exit $rc\n";
  const ProcessResult r = run_on_virtual_display("sh " + script.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("needle-sim: "), std::string::npos) << "no store error\n" << r.output;
  training::SessionStore server(uri, training::kReadOnly);
  const std::vector<training::SessionInfo> sessions = server.sessions();  // newest first
  ASSERT_EQ(sessions.size(), 2u) << r.output;
  EXPECT_EQ(sessions[0].trainee, "carla");
  EXPECT_EQ(sessions[0].task, "quick");
  EXPECT_EQ(sessions[0].station, "st-screen");
  EXPECT_TRUE(sessions[0].complete);
  // Its score.json in the station's own folder (a server has none): XDG_DATA_HOME/needle-sim/runs/.
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(dir / "data/needle-sim/runs/quick/score.json"));
  EXPECT_TRUE(score["stored"].get<bool>());
}

}  // namespace
}  // namespace needle::test
