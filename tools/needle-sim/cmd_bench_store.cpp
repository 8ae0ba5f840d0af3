// needle-sim bench store: N stations (processes) storing scripted sessions at once, recordings
// included, on one PostgreSQL server and on one SQLite file shared by the processes. One real
// session is run first (the task's good script on the simulated device, headless, no pictures);
// each station then stores it again and again as fast as the store takes it: begin, the recording
// in chunks of 50 ms of ticks (as a run sends it), finish. Rows for 1, 4 and 16 stations per
// engine: sessions per minute, p99 latency of the finishing commit, database growth per session,
// and the check that every session and every byte of every recording arrived once. Then a verify
// row per engine: `verify --all` (app/session_verify.hpp) over a store of --verify copies of the
// session, each with a recording that names it, in sessions per minute, beside the time the same
// number of replays alone take, as many at once (what verify cannot beat).
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <thread>

#include "app/recording_bytes.hpp"
#include "app/session_verify.hpp"
#include "app/task_session.hpp"
#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "io/file_write.hpp"
#include "printed_messages.hpp"
#include "sample_stats.hpp"
#include "training/sessions/postgres_connection.hpp"
#include "training/sessions/store_location.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Workload {
  training::NewSession session;  // station and uid set per copy
  training::SessionResult result;
  std::string recording;   // the bytes the run recorded
  size_t chunk_bytes = 0;  // 50 ms of ticks
};

// One station: `count` copies of the session, the finishing commit's latency (ms) of each written
// to `out` as doubles. Exit status 0 when every one was stored.
int station(const std::string& location, const Workload& w, const std::string& name, int count, int out) {
  try {
    training::SessionStore store(location);
    for (int k = 0; k < count; ++k) {
      training::NewSession n = w.session;
      n.station = name;
      n.uid = "";
      const int64_t id = store.begin_session(n);
      for (size_t offset = 0; offset < w.recording.size(); offset += w.chunk_bytes)
        store.append_recording(id, int64_t(offset), w.recording.substr(offset, w.chunk_bytes));
      const auto t0 = Clock::now();
      store.finish_session(id, w.result);
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
      if (write(out, &ms, sizeof ms) != sizeof ms) return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
    return 1;
  }
}

int64_t database_bytes(const std::string& location) {
  if (!training::is_postgres_uri(location)) {
    int64_t total = 0;
    for (const char* suffix : {"", "-wal"})
      if (fs::exists(location + suffix)) total += int64_t(fs::file_size(location + suffix));
    return total;
  }
  training::PostgresConnection c(location, true);
  return c.query("SELECT pg_database_size(current_database())", {}, "measuring the database").rows.at(0).integer(0);
}

struct Row {
  double sessions_per_min = 0, p99_ms = 0, bytes_per_session = 0;
  int stored = 0, lost = 0, duplicated = 0, failed_stations = 0;
};

Row measure(const std::string& location, const Workload& w, int stations, int per_station, const std::string& prefix) {
  { training::SessionStore create(location); }
  const int64_t bytes_before = database_bytes(location);
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) throw std::runtime_error("bench store: cannot make a pipe");
  std::fflush(nullptr);
  const auto t0 = Clock::now();
  std::vector<pid_t> children;
  for (int s = 0; s < stations; ++s) {
    const pid_t child = fork();
    if (child < 0) throw std::runtime_error("bench store: cannot start a station process");
    if (child == 0) {
      close(pipe_fd[0]);
      _exit(station(location, w, prefix + std::to_string(s), per_station, pipe_fd[1]));
    }
    children.push_back(child);
  }
  close(pipe_fd[1]);
  std::vector<double> latencies;
  for (double ms; read(pipe_fd[0], &ms, sizeof ms) == sizeof ms;) latencies.push_back(ms);
  close(pipe_fd[0]);
  Row row;
  for (const pid_t child : children) {
    int status = 0;
    waitpid(child, &status, 0);
    row.failed_stations += !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  // Every session whole, once: complete, its recording byte for byte, no uid twice.
  training::SessionStore check(location, training::kReadOnly);
  std::set<std::string> uids;
  for (const training::SessionInfo& info : check.sessions()) {
    if (info.station.rfind(prefix, 0) != 0) continue;
    if (!uids.insert(info.uid).second) ++row.duplicated;
    if (info.complete && check.recording(info.id) == w.recording) ++row.stored;
  }
  row.lost = stations * per_station - row.stored;
  row.sessions_per_min = double(row.stored) / seconds * 60.0;
  row.p99_ms = percentile(latencies, 0.99);
  row.bytes_per_session = row.stored ? double(database_bytes(location) - bytes_before) / row.stored : 0.0;
  return row;
}

struct VerifyRow {
  double sessions_per_min = 0, seconds = 0;
  int verified = 0, not_verified = 0;
};

// `count` copies of the session stored at `location` as station `station`, each with a recording
// naming it (on the server in chunks; beside an SQLite file in `recordings`), then verified as
// `verify --all` verifies them, `jobs` at a time.
VerifyRow measure_verify(const std::string& location, const Workload& w, const haptics::Session& recorded, int count,
                         int jobs, const std::string& station, const fs::path& recordings) {
  std::vector<int64_t> ids;
  {
    training::SessionStore store(location);
    const bool postgres = store.engine() == training::SqlEngine::kPostgres;
    for (int k = 0; k < count; ++k) {
      training::NewSession n = w.session;
      n.station = station;
      n.uid = training::new_session_uid();
      haptics::Session copy = recorded;
      copy.header.context = app::context_for_session(recorded.header.context, n.uid);
      const std::string bytes = app::encode_session(copy);
      if (!postgres) {
        n.recording_path = (recordings / (n.uid + ".nrec")).string();
        io::write_file(n.recording_path, bytes);
      }
      const int64_t id = store.begin_session(n);
      if (postgres)
        for (size_t offset = 0; offset < bytes.size(); offset += w.chunk_bytes)
          store.append_recording(id, int64_t(offset), bytes.substr(offset, w.chunk_bytes));
      store.finish_session(id, w.result);
      ids.push_back(id);
    }
  }
  const auto t0 = Clock::now();
  const std::vector<app::VerifiedSession> checked =
      app::verify_sessions(location, ids, jobs, [](const app::VerifiedSession&) {});
  VerifyRow row;
  row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  for (const app::VerifiedSession& v : checked) {
    if (v.check.outcome == training::CheckOutcome::kVerified)
      ++row.verified;
    else
      ++row.not_verified;
  }
  row.sessions_per_min = double(count) / row.seconds * 60.0;
  return row;
}

// Seconds `jobs` threads take to replay `recording` `count` times between them (app::replay_result:
// the file read and checked, the task rebuilt, every tick replayed and scored).
double bare_replays_s(const std::string& recording, int count, int jobs, const fs::path& scratch) {
  std::atomic<int> next{0};
  const auto work = [&](int thread) {
    const fs::path dir = scratch / ("replay_" + std::to_string(thread));
    fs::create_directories(dir);
    std::string task_name;
    while (next++ < count) app::replay_result(recording, dir, task_name);
  };
  const auto t0 = Clock::now();
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(work, j);
  work(0);
  for (std::thread& t : threads) t.join();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct StoreFlags {
  std::optional<std::string> db, task, json;
  long long sessions = 8, verify = 100;
};

int run(const StoreFlags& f) {
  const std::optional<std::string>& server = f.db;
  const int per_station = int(f.sessions);
  const int verify_count = int(f.verify);
  const int jobs = int(std::max(1u, std::thread::hardware_concurrency()));
  const std::string task = f.task.value_or((asset_dir() / "tasks" / "penetrable_sphere.json").string());
  if (server && !training::is_postgres_uri(*server))
    throw UsageError("--db: a postgresql:// URI, the server to measure");

  const fs::path scratch = fs::temp_directory_path() / ("needle_bench_store_" + std::to_string(::getpid()));
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  Workload w;
  {
    app::TaskSessionOptions options;
    options.task = task;
    options.trainee = "bench";
    options.station = "bench";
    options.db = scratch / "run.db";
    options.out_dir = scratch;
    app::TaskSession run(options);
    run.run_offline([](size_t) {});
    const training::SessionResult* result = run.finish();
    if (!result) throw std::runtime_error("bench store: the scripted session did not complete");
    w.result = *result;
    std::ifstream in(run.recording_path(), std::ios::binary);
    w.recording.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    w.session = {
        "bench", run.task().name, run.task().title, run.task().source, "sim", run.recording_path().string(), "", "",
        ""};
    w.chunk_bytes = std::max<size_t>(1, size_t(double(w.recording.size()) / result->overall.duration_s * 0.05));
  }
  // What verify cannot beat: the replays alone, the session's recording read from its file and
  // replayed as many times as verify replays copies, as many at once, no store.
  const haptics::Session recorded = haptics::read_session(w.session.recording_path);
  const double replays_s =
      verify_count > 0 ? bare_replays_s(w.session.recording_path, verify_count, jobs, scratch) : 0.0;

  // Store rows: "stored", "lost" as said above. Verify rows: "stations" the jobs, "stored" the
  // sessions verified, "lost" those not; "replays_s" the replays alone (bare_replays_s), "vs_replays"
  // verify's time over theirs.
  BenchTable table({"work", "engine", "stations", "sessions", "sessions_per_min", "p99_commit_ms", "bytes_per_session",
                    "recording_bytes", "stored", "lost", "duplicated", "failed_stations", "replays_s", "vs_replays"});
  for (const bool postgres : {true, false}) {
    if (postgres && !server) {
      std::printf("note: no --db postgresql://...: PostgreSQL rows skipped\n");
      continue;
    }
    for (const int stations : {1, 4, 16}) {
      const std::string prefix = "bench-" + std::to_string(::getpid()) + "-" + std::to_string(stations) + "-";
      const std::string location =
          postgres ? *server : (scratch / ("shared_" + std::to_string(stations) + ".db")).string();
      const Row r = measure(location, w, stations, per_station, prefix);
      table.add_row({"store", postgres ? "postgresql" : "sqlite", stations, stations * per_station, r.sessions_per_min,
                     r.p99_ms, r.bytes_per_session, w.recording.size(), r.stored, r.lost, r.duplicated,
                     r.failed_stations, nullptr, nullptr});
    }
    if (verify_count == 0) continue;
    const std::string location = postgres ? *server : (scratch / "verify.db").string();
    fs::create_directories(scratch / "recordings");
    const VerifyRow v = measure_verify(location, w, recorded, verify_count, jobs,
                                       "bench-" + std::to_string(::getpid()) + "-verify", scratch / "recordings");
    table.add_row({"verify", postgres ? "postgresql" : "sqlite", jobs, verify_count, v.sessions_per_min, nullptr,
                   nullptr, w.recording.size(), v.verified, v.not_verified, 0, 0, replays_s, v.seconds / replays_s});
  }
  fs::remove_all(scratch);
  table.emit("bench store: stations storing a " + std::to_string(w.result.overall.duration_s).substr(0, 4) +
                 " s scripted session (" + std::to_string(per_station) + " each, recording in 50 ms chunks) at once; " +
                 "verify --all over " + std::to_string(verify_count) + " stored copies, " + std::to_string(jobs) +
                 " at a time",
             f.json);
  return 0;
}

// The options of bench store, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<StoreFlags>();
  add_text(app, "--db", f->db, "URI",
           "the PostgreSQL server to measure (a database of its own: the bench adds sessions of\n"
           "stations named bench-*); without it only the SQLite rows");
  add_whole(app, "--sessions", f->sessions, kStoreSessions, "N", "sessions each station stores");
  add_whole(app, "--verify", f->verify, kVerifySessions, "N",
            "copies of the session stored, then verified as verify --all does (0: no verify rows)");
  add_text(app, "--task", f->task, "FILE",
           "the task whose good script makes the session (default assets/tasks/penetrable_sphere.json)");
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  app.footer(
      "rows: 1, 4 and 16 station processes on PostgreSQL, then on one SQLite file they share: sessions per\n"
      "minute, p99 of the finishing commit (ms), database growth per session, and stored/lost/duplicated\n"
      "(every session complete with every byte of its recording, no uid twice); then per engine a verify\n"
      "row: sessions verified per minute, the same replays' time alone and verify's time over theirs");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench store", "stations storing scripted sessions at once, and verify over a store, per engine", declare}};

}  // namespace
}  // namespace needle::cli
