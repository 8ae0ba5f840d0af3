// needle-sim bench store: N stations (processes) storing scripted sessions at once, recordings
// included, on one PostgreSQL server and on one SQLite file shared by the processes. One real
// session is run first (the task's good script on the simulated device, headless, no pictures);
// each station then stores it again and again as fast as the store takes it: begin, the recording
// in chunks of 50 ms of ticks (as a run sends it), finish. Rows for 1, 4 and 16 stations per
// engine: sessions per minute, p99 latency of the finishing commit, database growth per session,
// and the check that every session and every byte of every recording arrived once.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>

#include "app/task_session.hpp"
#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
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

struct StoreFlags {
  std::optional<std::string> db, task, json;
  long long sessions = 8;
};

int run(const StoreFlags& f) {
  const std::optional<std::string>& server = f.db;
  const int per_station = int(f.sessions);
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
    options.messages = printed_messages("needle-sim bench store");
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

  BenchTable table({"engine", "stations", "sessions", "sessions_per_min", "p99_commit_ms", "bytes_per_session",
                    "recording_bytes", "stored", "lost", "duplicated", "failed_stations"});
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
      table.add_row({postgres ? "postgresql" : "sqlite", stations, stations * per_station, r.sessions_per_min, r.p99_ms,
                     r.bytes_per_session, w.recording.size(), r.stored, r.lost, r.duplicated, r.failed_stations});
    }
  }
  fs::remove_all(scratch);
  table.emit("bench store: stations storing a " + std::to_string(w.result.overall.duration_s).substr(0, 4) +
                 " s scripted session (" + std::to_string(per_station) + " each, recording in 50 ms chunks) at once",
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
  add_text(app, "--task", f->task, "FILE",
           "the task whose good script makes the session (default assets/tasks/penetrable_sphere.json)");
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  app.footer(
      "rows: 1, 4 and 16 station processes on PostgreSQL, then on one SQLite file they share: sessions per\n"
      "minute, p99 of the finishing commit (ms), database growth per session, and stored/lost/duplicated\n"
      "(every session complete with every byte of its recording, no uid twice)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench store", "stations storing scripted sessions at once, on PostgreSQL and on one SQLite file", declare}};

}  // namespace
}  // namespace needle::cli
