// needle-sim bench loop: timing of the haptic loop thread against a bare clock_nanosleep
// loop at the same rates, alone and (with a renderer hook) under rendering load.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>

#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "haptics/devices/desk_device.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "haptics/realtime/periodic_timer.hpp"
#include "haptics/realtime/sim_session.hpp"
#include "haptics/recording/session_recorder.hpp"
#include "haptics/safety/fault_cause.hpp"
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

struct HapticRun {
  LoopStatsSummary stats;
  std::string realtime_line;
};

// The haptic loop as the app runs it: the device (mouse, no step; or sim:SCENARIO, the simulated
// master with the controller), the safety monitor at the device's limits, snapshot and sample
// ring, and the recorder thread writing the session to a temporary file.
HapticRun time_haptic_loop(const haptics::DeviceSpec& device_spec, double rate_hz, double seconds) {
  std::unique_ptr<haptics::SimSession> sim;
  haptics::DeskDevice mouse(haptics::DeviceSpec{haptics::DeviceSpec::Kind::kMouse});
  haptics::HapticDevice* device = &mouse;
  haptics::ServoStep* step = nullptr;
  if (device_spec.kind == haptics::DeviceSpec::Kind::kSim) {
    sim = std::make_unique<haptics::SimSession>(device_spec.file, rate_hz);
    device = &sim->device();
    step = &sim->step();
  }
  device->open();
  haptics::LoopConfig config;
  config.rate_hz = rate_hz;
  haptics::HapticLoop loop(*device, haptics::safety_limits_for(device->capabilities()), config);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("needle_bench_loop_" + std::to_string(::getpid()) + ".nsrec"))
          .string();
  haptics::SessionRecorder recorder(path, {haptics::kSessionFormatVersion, rate_hz, 0, device_spec.text()},
                                    loop.samples());
  HapticRun run;
  run.realtime_line = loop.launch();
  recorder.start();
  loop.apply(haptics::LoopCommand::set_step(step));
  loop.apply(haptics::LoopCommand::start());
  sleep_seconds(0.2);  // settle: the first periods include thread start-up
  loop.apply(haptics::LoopCommand::reset_stats());
  sleep_seconds(seconds);
  run.stats = loop.stats();
  loop.shutdown();
  recorder.stop();
  std::filesystem::remove(path);
  return run;
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

struct LoopFlags {
  std::optional<std::string> json, device;
  std::vector<double> rates{1000, 2000, 4000};
  double seconds = 30.0;
  bool render_load = false;
};

int run(const LoopFlags& f) {
  const std::vector<double>& rates = f.rates;
  const double seconds = f.seconds;
  const bool with_load = f.render_load;
  const std::string device_text =
      f.device.value_or("sim:" + (asset_dir() / "scenarios" / "nonholonomic_needle.json").string());
  haptics::DeviceSpec device_spec;
  try {
    device_spec = haptics::DeviceSpec::parse(device_text);
  } catch (const haptics::DeviceSpecError& e) {
    throw UsageError(std::string("--device: ") + e.what());
  }
  const bool sim_scenario = device_spec.kind == haptics::DeviceSpec::Kind::kSim && !device_spec.file.empty();
  if (device_spec.kind != haptics::DeviceSpec::Kind::kMouse && !sim_scenario)
    throw UsageError("--device: expected mouse or sim:SCENARIO.json, got " + device_text);
  if (with_load && render_load() == nullptr)
    throw UsageError("--render-load: this build registers no renderer load (see render_load_hook.hpp)");

  BenchTable table({"loop", "device", "rate_hz", "render_load", "seconds", "ticks", "period_err_p50_us",
                    "period_err_p99_us", "period_err_p999_us", "period_err_max_us", "overruns", "compute_p50_us",
                    "compute_p99_us", "rate_measured_hz", "fault"});
  std::string realtime_line;
  auto add = [&](const char* loop, const std::string& device, double rate, bool load, const LoopStatsSummary& s) {
    table.add_row({loop, device, rate, load, seconds, s.period_error.count, us(s.period_error.p50_ns),
                   us(s.period_error.p99_ns), us(s.period_error.p999_ns), us(s.period_error.max_ns), s.overruns,
                   us(s.compute.p50_ns), us(s.compute.p99_ns), s.rate_hz,
                   haptics::fault_cause_name(static_cast<haptics::FaultCause>(s.fault))});
  };
  auto run_all = [&](bool load) {
    for (double rate : rates) {
      const HapticRun run = time_haptic_loop(device_spec, rate, seconds);
      realtime_line = run.realtime_line;
      add("haptic", device_spec.kind == haptics::DeviceSpec::Kind::kSim ? "sim" : "mouse", rate, load, run.stats);
      add("bare", "-", rate, load, time_bare_loop(rate, seconds, haptics::LoopConfig{}.realtime));
    }
  };
  run_all(false);
  if (with_load) {
    std::atomic<bool> stop{false};
    long frames = 0;
    const auto start = std::chrono::steady_clock::now();
    std::thread renderer([&stop, &frames] { frames = (*render_load())(stop); });
    run_all(true);
    stop = true;
    renderer.join();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("render load: %ld trainee frames in %.1f s (%.1f per second)\n", frames, s, double(frames) / s);
  }
  std::printf("%s\n", realtime_line.c_str());
  table.emit("haptic loop vs bare clock_nanosleep loop (period error = |period - nominal|)", f.json);
  return 0;
}

// The options of bench loop, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<LoopFlags>();
  add_number_list(app, "--rates", f->rates, kLoopRates_hz, "LIST", "loop rates in Hz");
  add_number(app, "--seconds", f->seconds, kLoopSeconds, "S", "measuring time per row (after 0.2 s of settling)");
  add_text(app, "--device", f->device, "sim:FILE|mouse",
           "sim:SCENARIO.json (default: the nonholonomic scenario, master simulated, controller\n"
           "stepping) or mouse (no step: the loop's own machinery only)");
  add_flag(app, "--render-load", f->render_load,
           "repeat every row while the trainee's frame (the penetrable task's scene, panels and\n"
           "guidance, 1280x720 offscreen) is drawn as fast as it can");
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{{"bench loop",
                            "the haptic loop's timing against a bare clock_nanosleep loop, with and without rendering",
                            declare}};

}  // namespace
}  // namespace needle::cli
