// needle-sim against a PostgreSQL server whose refusals must not pass for an outage: a server that
// refuses (an unknown host, a certificate that does not verify, a password refused) stops a run
// before it starts, with nothing kept; only a known host that refuses the connection or never
// answers lets a run go on without it, and says so; a server that accepts the connection and never
// speaks holds run, sync and report --cohort no longer than the connect timeout.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>

#include "rigid_run.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"
#include "tests/tools/cli_process.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

bool says(const ProcessResult& r, const std::string& text) { return r.output.find(text) != std::string::npos; }

// A TCP port on 127.0.0.1 that completes every connection (the kernel's backlog) and never sends a
// byte: a server that hangs, or something else listening where the server should be.
class SilentListener {
 public:
  SilentListener() {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in at{};
    at.sin_family = AF_INET;
    at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof at;
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&at), sizeof at) != 0 || ::listen(fd_, 64) != 0 ||
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&at), &size) != 0)
      throw std::runtime_error("cannot listen on 127.0.0.1");
    port_ = ntohs(at.sin_port);
  }
  ~SilentListener() { ::close(fd_); }
  int port() const { return port_; }

 private:
  int fd_ = -1;
  int port_ = 0;
};

// A port on 127.0.0.1 nothing listens on (bound, then closed).
int closed_port() {
  SilentListener l;
  return l.port();
}

double seconds_of(const std::function<void()>& f) {
  const Clock::time_point t0 = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A server that refuses is an error before the run, nothing kept for sync: an unknown host, a
// certificate that does not verify (the TLS cluster's, checked against another CA), a password
// refused. A known host where nothing listens is an outage: the run goes on and says so.
TEST(CliStoreRefusals, ARefusalStopsTheRunAndOnlyAnOutageRunsOffline) {
  const fs::path other_ca = fresh_store_dir("other_ca") / "ca.crt";
  ASSERT_EQ(run_command(
                "openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 1 -subj /CN=127.0.0.1 "
                "-addext subjectAltName=IP:127.0.0.1 -keyout " +
                quoted(other_ca.parent_path() / "ca.key") + " -out " + quoted(other_ca))
                .exit_code,
            0);
  const std::string tcp = "postgresql://needle@127.0.0.1:" + postgres_port() + "/postgres?sslmode=";
  const struct {
    std::string name, uri, reason;
  } refusals[] = {
      {"unknown_host", "postgresql://needle@nohost.invalid/needle", "unknown host \"nohost.invalid\""},
      {"certificate", tcp + "verify-full&sslrootcert=" + other_ca.string(), "certificate verify failed"},
      {"password", "postgresql://needle_password:wrong@127.0.0.1:" + postgres_port() + "/postgres?sslmode=require",
       "password authentication failed"},
  };
  test::postgres_admin(
      "DO $$ BEGIN CREATE ROLE needle_password LOGIN PASSWORD 'right'; "
      "EXCEPTION WHEN duplicate_object THEN NULL; END $$");
  for (const auto& refusal : refusals) {
    const fs::path dir = fresh_store_dir(refusal.name);
    const ProcessResult r = run_needle_sim(rigid_run_arguments(refusal.uri, dir));
    EXPECT_EQ(r.exit_code, 1) << refusal.name << "\n" << r.output;
    EXPECT_TRUE(says(r, refusal.reason)) << refusal.name << "\n" << r.output;
    // One line says it: the line that has the reason is the error.
    const size_t at = r.output.find(refusal.reason);
    const size_t start = r.output.rfind('\n', at) == std::string::npos ? 0 : r.output.rfind('\n', at) + 1;
    EXPECT_EQ(r.output.compare(start, 23, "needle-sim run: error: "), 0) << refusal.name << "\n" << r.output;
    EXPECT_EQ(r.output.find('\n', at), r.output.size() - 1) << "nothing after that line\n" << r.output;
    EXPECT_FALSE(says(r, "could not be reached")) << refusal.name << "\n" << r.output;
    EXPECT_FALSE(says(r, "simulated")) << "stopped before the run\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "station.db")) << refusal.name << ": nothing kept for a server that refused";
  }
  const fs::path dir = fresh_store_dir("refused_connection");
  const ProcessResult r =
      run_needle_sim(rigid_run_arguments("postgresql://needle@127.0.0.1:" + std::to_string(closed_port()) + "/x", dir));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(says(r, "note: the server could not be reached")) << r.output;
  EXPECT_TRUE(says(r, "Connection refused")) << r.output;
  EXPECT_EQ(training::SessionStore((dir / "station.db").string(), training::kReadOnly).outbox().size(), 1u);
}

// A listener that never speaks: run goes offline after the connect timeout (kConnectSeconds) and
// finishes as fast as a run offline from the start does, plus that wait; sync and report --cohort
// stop with an error. Each waits less than 10 s: its time less the same command's against a closed
// port (which fails at once), so a loaded machine's start-up is not counted as waiting.
TEST(CliStoreRefusals, AServerThatNeverAnswersHoldsNothingPastTheConnectTimeout) {
  const SilentListener silent;
  const std::string uri = "postgresql://needle@127.0.0.1:" + std::to_string(silent.port()) + "/needle";
  const fs::path refused_dir = fresh_store_dir("silent_baseline"), dir = fresh_store_dir("silent");
  ProcessResult baseline, run, sync, cohort;
  const double baseline_s = seconds_of([&] {
    baseline = run_needle_sim(
        rigid_run_arguments("postgresql://needle@127.0.0.1:" + std::to_string(closed_port()) + "/x", refused_dir));
  });
  const double run_s = seconds_of([&] { run = run_needle_sim(rigid_run_arguments(uri, dir)); });
  ASSERT_EQ(baseline.exit_code, 0) << baseline.output;
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(says(run, "note: the server could not be reached")) << run.output;
  EXPECT_TRUE(says(run, "no answer within 5 s (connect_timeout)")) << run.output;
  EXPECT_LT(run_s - baseline_s, 10.0) << "the run waited " << run_s - baseline_s << " s for the server";
  const std::string closed = "postgresql://needle@127.0.0.1:" + std::to_string(closed_port()) + "/needle";
  // Seconds a command waited on the silent listener: its time less the same command's on a closed port.
  const auto waited_s = [&](const std::function<std::string(const std::string&)>& command,
                            ProcessResult& silent_result) {
    const double refused_s = seconds_of([&] { run_needle_sim(command(closed)); });
    return seconds_of([&] { silent_result = run_needle_sim(command(uri)); }) - refused_s;
  };
  const double sync_s = waited_s(
      [&](const std::string& db) { return "sync --db '" + db + "' --local " + quoted(dir / "station.db"); }, sync);
  EXPECT_EQ(sync.exit_code, 1) << sync.output;
  EXPECT_TRUE(says(sync, "no answer within 5 s")) << sync.output;
  EXPECT_LT(sync_s, 10.0);
  const double cohort_s = waited_s(
      [&](const std::string& db) { return "report --cohort --db '" + db + "' --out " + quoted(dir / "c"); }, cohort);
  EXPECT_EQ(cohort.exit_code, 1) << cohort.output;
  EXPECT_TRUE(says(cohort, "no answer within 5 s")) << cohort.output;
  EXPECT_LT(cohort_s, 10.0);
  // A URI's own connect_timeout is kept.
  ProcessResult short_timeout;
  const double short_s = waited_s(
      [&](const std::string& db) {
        return "report --cohort --db '" + db + "?connect_timeout=2' --out " + quoted(dir / "c");
      },
      short_timeout);
  EXPECT_TRUE(says(short_timeout, "no answer within 2 s")) << short_timeout.output;
  EXPECT_LT(short_s, 4.5);
}

}  // namespace
}  // namespace needle::test
