// needle-sim bench loop: timing of the haptic loop thread against a bare clock_nanosleep
// loop at the same rates, alone and (with a renderer hook) under rendering load.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "arg_list.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "haptics/devices/mouse_device.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "haptics/realtime/periodic_timer.hpp"
#include "haptics/recording/session_recorder.hpp"
#include "render_load_hook.hpp"

namespace needle::cli {

namespace {
RenderLoad& render_load_slot() {
  static RenderLoad load;
  return load;
}
}  // namespace

void set_render_load(RenderLoad load) { render_load_slot() = std::move(load); }
const RenderLoad* render_load() { return render_load_slot() ? &render_load_slot() : nullptr; }

namespace {

using haptics::LoopStatsSummary;

void sleep_seconds(double seconds) { std::this_thread::sleep_for(std::chrono::duration<double>(seconds)); }

// The haptic loop as the app runs it: a device without I/O of its own (mouse), the safety
// monitor, snapshot and sample ring, and the recorder thread writing the session.
LoopStatsSummary time_haptic_loop(double rate_hz, double seconds, std::string& realtime_line) {
  haptics::MouseDevice device;
  haptics::SafetyLimits limits;
  haptics::LoopConfig config;
  config.rate_hz = rate_hz;
  haptics::HapticLoop loop(device, limits, config);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("needle_bench_loop_" + std::to_string(::getpid()) + ".nsrec")).string();
  haptics::SessionRecorder recorder(path, {haptics::kSessionFormatVersion, rate_hz, 0, "mouse"}, loop.samples());
  realtime_line = loop.launch();
  recorder.start();
  loop.apply({haptics::LoopCommandType::kStart});
  sleep_seconds(0.2);  // settle: the first periods include thread start-up
  loop.apply({haptics::LoopCommandType::kResetStats});
  sleep_seconds(seconds);
  const LoopStatsSummary stats = loop.stats();
  loop.shutdown();
  recorder.stop();
  std::filesystem::remove(path);
  return stats;
}

// The baseline this machine allows: the same timer and statistics, no work at all.
LoopStatsSummary time_bare_loop(double rate_hz, double seconds, const haptics::RealtimeRequest& request) {
  haptics::LoopStats stats;
  std::atomic<bool> stop{false};
  std::atomic<bool> measuring{false};
  std::thread thread([&] {
    haptics::request_realtime(request);
    haptics::PeriodicTimer timer(static_cast<int64_t>(1e9 / rate_hz + 0.5));
    timer.start();
    int64_t last = 0;
    while (!stop.load(std::memory_order_relaxed)) {
      const int64_t wake = timer.wait();
      const int64_t end = haptics::monotonic_ns();
      const bool overran = timer.advance(end);
      if (last != 0 && measuring.load(std::memory_order_relaxed))
        stats.record(static_cast<uint64_t>(wake - last), static_cast<uint64_t>(timer.period_ns()),
                     static_cast<uint64_t>(end - wake), overran);
      last = wake;
    }
  });
  sleep_seconds(0.2);
  measuring = true;
  sleep_seconds(seconds);
  stop = true;
  thread.join();
  return stats.summary();
}

double us(double ns) { return ns / 1000.0; }

int run_bench_loop(ArgList& args) {
  const auto json = args.value("--json");
  const std::vector<double> rates = parse_number_list(args.value("--rates").value_or("1000,2000,4000"), "--rates");
  const double seconds = parse_number(args.value("--seconds").value_or("30"), "--seconds");
  const bool with_load = args.flag("--render-load");
  args.finish();
  if (!(seconds > 0.0 && seconds <= 3600.0)) throw UsageError("--seconds: expected a duration in (0, 3600]");
  for (double r : rates) {
    try {
      haptics::check_loop_rate(r);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--rates: ") + e.what());
    }
  }
  if (with_load && render_load() == nullptr)
    throw UsageError("--render-load: this build registers no renderer load (see render_load_hook.hpp)");

  BenchTable table({"loop", "rate_hz", "render_load", "seconds", "ticks", "period_err_p50_us", "period_err_p99_us",
                    "period_err_p999_us", "period_err_max_us", "overruns", "compute_p50_us", "compute_p99_us",
                    "rate_measured_hz"});
  std::string realtime_line;
  auto add = [&](const char* loop, double rate, bool load, const LoopStatsSummary& s) {
    table.add_row({loop, rate, load, seconds, s.period_error.count, us(s.period_error.p50_ns), us(s.period_error.p99_ns),
                   us(s.period_error.p999_ns), us(s.period_error.max_ns), s.overruns, us(s.compute.p50_ns),
                   us(s.compute.p99_ns), s.rate_hz});
  };
  auto run_all = [&](bool load) {
    for (double rate : rates) {
      add("haptic", rate, load, time_haptic_loop(rate, seconds, realtime_line));
      add("bare", rate, load, time_bare_loop(rate, seconds, haptics::LoopConfig{}.realtime));
    }
  };
  run_all(false);
  if (with_load) {
    std::atomic<bool> stop{false};
    std::thread renderer([&stop] { (*render_load())(stop); });
    run_all(true);
    stop = true;
    renderer.join();
  }
  std::printf("%s\n", realtime_line.c_str());
  table.emit("haptic loop vs bare clock_nanosleep loop (period error = |period - nominal|)", json);
  return 0;
}

const CommandRegistrar reg{
    {"bench loop",
     "needle-sim bench loop [--rates 1000,2000,4000] [--seconds 30] [--render-load] [--json FILE]\n"
     "  --rates        loop rates in Hz, each 250..10000\n"
     "  --seconds      measuring time per row (after 0.2 s of settling)\n"
     "  --render-load  repeat every row while the renderer draws as fast as it can\n"
     "  --json FILE    also write the rows as JSON",
     run_bench_loop}};

}  // namespace
}  // namespace needle::cli
