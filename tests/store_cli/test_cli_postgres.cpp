// needle-sim with --db postgresql://...: a run stores its session and recording on the server, a
// report on "another machine" (the recording file gone) replays it from there, a station that
// loses the server mid-run, or has none when the run starts, keeps the session and `sync` sends it
// once, credentials never show.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"
#include "tests/tools/cli_process.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string run_arguments(const std::string& uri, const fs::path& dir, const std::string& station) {
  return "run --headless --size 320x240 --trainee ana --station " + station + " --db '" + uri + "' --local " +
         quoted(dir / "station.db") + " --out " + quoted(dir / "out");
}

// The one session DIR/station.db keeps for the server (complete, in its outbox): `sync` twice sends
// it once (then nothing), and the server holds it complete, from `station`, with the score, the
// steps and the recording byte for byte of the run's `score` (its score.json).
void expect_sent_once(const std::string& uri, const fs::path& dir, const std::string& station_name,
                      const nlohmann::json& score) {
  const std::string local = file_bytes(score["recording"].get<std::string>());
  ASSERT_GT(local.size(), 1000u);
  std::string uid;
  {
    training::SessionStore station((dir / "station.db").string(), training::kReadOnly);
    ASSERT_EQ(station.outbox().size(), 1u);
    uid = station.sessions().at(0).uid;
    EXPECT_TRUE(station.sessions().at(0).complete);
  }
  for (int pass = 0; pass < 2; ++pass) {
    const ProcessResult sync = run_needle_sim("sync --db '" + uri + "' --local " + quoted(dir / "station.db"));
    ASSERT_EQ(sync.exit_code, 0) << sync.output;
    EXPECT_NE(sync.output.find(pass == 0 ? "1 sent" : "0 sent"), std::string::npos) << sync.output;
  }
  training::SessionStore server(uri, training::kReadOnly);
  const std::vector<training::SessionInfo> sessions = server.sessions();
  ASSERT_EQ(sessions.size(), 1u) << "sent once";
  EXPECT_EQ(sessions[0].uid, uid);
  EXPECT_TRUE(sessions[0].complete);
  EXPECT_EQ(sessions[0].station, station_name);
  EXPECT_DOUBLE_EQ(sessions[0].score, score["score"].get<double>());
  EXPECT_EQ(server.load(sessions[0].id).steps.size(), score["steps"].size());
  EXPECT_EQ(server.recording(sessions[0].id), local) << "every tick arrived, none twice";
}

TEST(CliPostgres, ARunStoresItsSessionAndRecordingOnTheServerAndAReportReplaysIt) {
  const std::string uri = fresh_postgres_database("cli_run");
  const fs::path dir = test_output_dir("cli_postgres_run");
  fs::remove_all(dir);
  const ProcessResult run = run_needle_sim(run_arguments(uri, dir, "station-01"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.find("Vulkan validation"), std::string::npos) << run.output;
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(dir / "out" / "score.json"));
  EXPECT_TRUE(score["stored"].get<bool>());
  EXPECT_FALSE(score["kept_for_sync"].get<bool>());

  training::SessionStore server(uri, training::kReadOnly);
  const std::vector<training::SessionInfo> sessions = server.sessions();
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_TRUE(sessions[0].complete);
  EXPECT_EQ(sessions[0].station, "station-01");
  EXPECT_DOUBLE_EQ(sessions[0].score, score["score"].get<double>());
  // The whole recording, byte for byte, is on the server.
  const fs::path recording = score["recording"].get<std::string>();
  const std::string local = file_bytes(recording);
  ASSERT_GT(local.size(), 1000u);
  EXPECT_EQ(server.recording(sessions[0].id), local);
  // Chunked as written: many chunks, each at most a send period's worth (not the file at the end).
  training::PostgresConnection c(uri, true);
  const int64_t chunks = c.query("SELECT count(*) FROM recording_chunks", {}, "").rows[0].integer(0);
  EXPECT_GT(chunks, 10) << "the recording went up in " << chunks << " chunks";
  // On another machine: no recording file, the report replays the server's.
  fs::remove(recording);
  const ProcessResult report = run_needle_sim("report --db '" + uri + "' --session " + std::to_string(sessions[0].id) +
                                              " --out " + quoted(dir / "report"));
  ASSERT_EQ(report.exit_code, 0) << report.output;
  EXPECT_EQ(report.output.find("Vulkan validation"), std::string::npos) << report.output;
  for (const char* picture : {"plot_force.png", "plot_depth.png", "review_replay.png"})
    EXPECT_TRUE(fs::is_regular_file(dir / "report" / picture)) << picture << "\n" << report.output;
  EXPECT_EQ(report.output.find("recording not found"), std::string::npos) << report.output;
  EXPECT_FALSE(fs::exists(fs::temp_directory_path() / ("needle-sim-recording-" + sessions[0].uid + ".nrec")))
      << "the server's copy is removed once read";
}

TEST(CliPostgres, AStationThatLosesTheServerKeepsTheSessionAndSyncSendsItOnce) {
  const std::string uri = fresh_postgres_database("cli_offline");
  const fs::path dir = test_output_dir("cli_postgres_offline");
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The run in the background; the server stops as soon as the session has begun on it.
  FILE* pipe = popen((needle_sim_exe().string() + " " + run_arguments(uri, dir, "station-02") + " 2>&1").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char line[4096];
  bool stopped = false;
  while (std::fgets(line, sizeof line, pipe)) {
    output += line;
    if (!stopped && std::string(line).rfind("recording ", 0) == 0) {
      postgres_server("stop");
      stopped = true;
    }
  }
  const int status = pclose(pipe);
  postgres_server("start");
  ASSERT_TRUE(stopped) << output;
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;
  EXPECT_NE(output.find("the server could not be reached"), std::string::npos) << output;
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(dir / "out" / "score.json"));
  EXPECT_TRUE(score["kept_for_sync"].get<bool>());
  expect_sent_once(uri, dir, "station-02", score);
}

// A run that starts while the server is down (nothing answers at the URI): it runs, its session is
// kept in the station's file from the start, and sync sends it once the server is back, recording
// included, once. A server that answers but refuses (a database it lacks) is still an error at the
// start: only an unreachable server is worked around.
TEST(CliPostgres, ARunThatStartsWhileTheServerIsDownKeepsItsSessionForSync) {
  const std::string uri = fresh_postgres_database("cli_down");
  const fs::path dir = test_output_dir("cli_postgres_down");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const ProcessResult refused = run_needle_sim(run_arguments(postgres_uri("cli_no_such_database"), dir, "station-04"));
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("does not exist"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(dir / "station.db")) << "nothing kept for a server that answered";

  postgres_server("stop");
  const ProcessResult run = run_needle_sim(run_arguments(uri, dir, "station-04"));
  postgres_server("start");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("the server could not be reached when the session began"), std::string::npos) << run.output;
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(dir / "out" / "score.json"));
  EXPECT_TRUE(score["stored"].get<bool>());
  EXPECT_TRUE(score["kept_for_sync"].get<bool>());
  expect_sent_once(uri, dir, "station-04", score);
}

// The instructor's class view from the server: two stations' sessions, one trainee's learning
// curve over both, the tables and the plots.
TEST(CliPostgres, TheCohortReportReadsEveryStationsSessions) {
  const std::string uri = fresh_postgres_database("cli_cohort");
  const fs::path dir = test_output_dir("cli_postgres_cohort");
  fs::remove_all(dir);
  std::vector<nlohmann::json> scores;
  for (const char* op : {"sloppy", "good"}) {
    const fs::path run_dir = dir / op;
    const ProcessResult run =
        run_needle_sim(run_arguments(uri, run_dir, std::string("station-") + op) + " --operator " + op);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    scores.push_back(nlohmann::json::parse(std::ifstream(run_dir / "out" / "score.json")));
  }
  const ProcessResult report = run_needle_sim("report --cohort --db '" + uri + "' --out " + quoted(dir / "cohort"));
  ASSERT_EQ(report.exit_code, 0) << report.output;
  EXPECT_EQ(report.output.find("Vulkan validation"), std::string::npos) << report.output;
  const nlohmann::json cohort = nlohmann::json::parse(std::ifstream(dir / "cohort" / "cohort.json"));
  EXPECT_EQ(cohort["sessions"], 2);
  ASSERT_EQ(cohort["curves"].size(), 1u);
  const nlohmann::json& curve = cohort["curves"][0];
  EXPECT_EQ(curve["trainee"], "ana");
  ASSERT_EQ(curve["attempts"].size(), 2u);
  EXPECT_DOUBLE_EQ(curve["attempts"][0]["score"].get<double>(), scores[0]["score"].get<double>());
  EXPECT_DOUBLE_EQ(curve["attempts"][1]["score"].get<double>(), scores[1]["score"].get<double>());
  EXPECT_EQ(curve["first_pass"], scores[0]["passed"]);
  EXPECT_EQ(curve["attempts"][1]["station"], "station-good");
  for (const char* file : {"cohort_curves.csv", "cohort_failed_steps.csv", "cohort_percentiles.csv",
                           "cohort_penetrable_sphere_score.png", "cohort_penetrable_sphere_time_to_target.png"})
    EXPECT_TRUE(fs::is_regular_file(dir / "cohort" / file)) << file << "\n" << report.output;
  // A filter: one station's sessions only.
  const ProcessResult one =
      run_needle_sim("report --cohort --station station-good --db '" + uri + "' --out " + quoted(dir / "one"));
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(dir / "one" / "cohort.json"))["sessions"], 1);
  const ProcessResult bad =
      run_needle_sim("report --cohort --since yesterday --db '" + uri + "' --out " + quoted(dir / "bad"));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--since: expected a date YYYY-MM-DD, got 'yesterday'"), std::string::npos) << bad.output;
}

TEST(CliPostgres, CredentialsAreNeverPrinted) {
  const std::string secret = "s3cret-Pw";
  // The server answers (its socket and port) and refuses: a server that does not answer at all is
  // not an error for run, which keeps the session for sync (ARunThatStartsWhileTheServerIsDown...).
  const std::string uri =
      "postgresql://needle:" + secret + "@/no_such_database?host=" + postgres_dir() + "&port=" + postgres_port();
  const fs::path dir = test_output_dir("cli_postgres_secret");
  for (const std::string& command :
       {run_arguments(uri, dir, "station-03"), "report --db '" + uri + "' --session 1 --out " + quoted(dir / "r"),
        "sync --db '" + uri + "' --local " + quoted(dir / "station.db")}) {
    const ProcessResult r = run_needle_sim(command);
    EXPECT_NE(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find(secret), std::string::npos) << r.output;
  }
  // From the environment too, and in the password=... form.
  const ProcessResult env = run_command("NEEDLE_DB='postgresql:///no_such_database?host=" + postgres_dir() +
                                        "&port=" + postgres_port() + "&password=" + secret + "' " +
                                        needle_sim_exe().string() + " report --session 1 --out " + quoted(dir / "r"));
  EXPECT_EQ(env.exit_code, 1) << env.output;
  EXPECT_NE(env.output.find("password=***"), std::string::npos) << env.output;
  EXPECT_EQ(env.output.find(secret), std::string::npos) << env.output;
}

}  // namespace
}  // namespace needle::test
