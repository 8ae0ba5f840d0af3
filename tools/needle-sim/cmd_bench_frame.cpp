// needle-sim bench frame: the trainee's whole frame as `run` draws it (app::TraineeFrame: the
// scene with its deformation pass, the status panel, the trainee panel and the guidance), driven
// by a scripted needle, in a window and offscreen, pass by pass: the CPU time to record each
// pass, the device's time for it (timestamp queries), the waits for the swapchain, and the frame
// period's median, p95 and p99.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "app/session_window.hpp"
#include "app/task_session.hpp"
#include "app/trainee_frame.hpp"
#include "app/ultrasound_window.hpp"
#include "app/window_frames.hpp"
#include "asset-gen/assets.hpp"
#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/offscreen.hpp"
#include "flag_ranges.hpp"
#include "printed_messages.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kTissuePrefix = "tissue:";

// What a row draws: a thesis task through its haptic loop with the scripted good operator, or
// the N x N sphere (with its levels of detail) under the scripted needle.
struct Content {
  std::string name;
  fs::path task;   // a task file, or
  int tissue = 0;  // the sphere's resolution
};

std::vector<Content> parse_contents(const std::string& list) {
  std::vector<Content> contents;
  for (const std::string& item : split_list(list, "--contents", kMaxListItems)) {
    if (item.rfind(kTissuePrefix, 0) == 0) {
      const long long n =
          parse_whole(item.substr(std::string(kTissuePrefix).size()), "--contents tissue:N", kDeformSpheres);
      contents.push_back({item, {}, int(n)});
      continue;
    }
    fs::path task = item.ends_with(".json") ? fs::path(item) : asset_dir() / "tasks" / (item + ".json");
    if (!fs::is_regular_file(task)) throw UsageError("--contents: no task file " + task.string());
    contents.push_back({fs::path(item).stem().string(), task, 0});
  }
  return contents;
}

std::vector<engine::Extent> parse_sizes(const std::string& list) {
  std::vector<engine::Extent> sizes;
  for (const std::string& item : split_list(list, "--sizes", kMaxListItems))
    sizes.push_back(parse_size(item, "--sizes"));
  return sizes;
}

// A variant of the frame's settings; the variants of a row take turns block by block, so a load
// that comes and goes on a shared machine weighs on all of them alike and their ratios hold.
struct Variant {
  std::string name;            // as given, "default" for the product's own settings
  std::optional<float> scale;  // scale=S: a fixed render scale
  bool cut_culling = true;     // cut_culling=off: the section's cut-away chunks drawn (to measure the culling)
  bool inside_culling = true;  // inside_culling=off: the layers held inside the skin drawn without a section
  bool specialized = true;     // specialized=off: every draw with the general mesh shader (to measure the specializing)
  std::optional<engine::WindowTarget::Presentation> presentation;  // present=...; none: the window's own
  std::optional<uint32_t> sweep_frames;  // sweep=N: the ultrasound image made over N frames; none: the window's own
  engine::Translucency translucency = engine::Translucency::Blended;  // translucency=screen_door: the dither
};

std::vector<Variant> parse_variants(const std::string& list) {
  std::vector<Variant> variants;
  for (size_t start = 0; start <= list.size();) {
    const size_t end = std::min(list.find(';', start), list.size());
    Variant v{list.substr(start, end - start)};
    start = end + 1;
    if (variants.size() == kMaxListItems)
      throw UsageError("--variants: expected at most " + std::to_string(kMaxListItems) + " variants");
    for (size_t k = 0; k <= v.name.size() && v.name != "default";) {
      const size_t stop = std::min(v.name.find(',', k), v.name.size());
      const std::string setting = v.name.substr(k, stop - k);
      k = stop + 1;
      const size_t eq = setting.find('=');
      const std::string key = setting.substr(0, eq), value = eq == std::string::npos ? "" : setting.substr(eq + 1);
      if (key == "scale") {
        v.scale = float(parse_number(value, "--variants scale=S", {engine::kMinRenderScale, engine::kMaxRenderScale}));
      } else if (setting == "present=fifo" || setting == "present=mailbox" || setting == "present=immediate" ||
                 setting == "present=shm") {
        using P = engine::WindowTarget::Presentation;
        v.presentation = setting == "present=mailbox"     ? P::Mailbox
                         : setting == "present=immediate" ? P::Immediate
                         : setting == "present=shm"       ? P::SharedMemory
                                                          : P::Fifo;
      } else if (key == "sweep") {
        v.sweep_frames = uint32_t(parse_whole(value, "--variants sweep=N", kSweepFrames));
      } else if (setting == "cut_culling=off") {
        v.cut_culling = false;
      } else if (setting == "inside_culling=off") {
        v.inside_culling = false;
      } else if (setting == "specialized=off") {
        v.specialized = false;
      } else if (setting == "translucency=screen_door") {
        v.translucency = engine::Translucency::ScreenDoor;
      } else {
        throw UsageError("--variants: unknown setting '" + setting +
                         "' (default, scale=S, cut_culling=off, inside_culling=off, specialized=off, "
                         "translucency=screen_door, "
                         "present=fifo|mailbox|immediate|shm, sweep=N)");
      }
    }
    variants.push_back(std::move(v));
  }
  return variants;
}

// One frame's measures, in milliseconds.
struct FrameSample {
  size_t variant = 0;
  bool timed = false;      // drawn with timestamp queries
  double period_ms = 0.0;  // from this frame's start to the next one's
  float render_scale = 1.0f;
  std::map<std::string, double> passes;
};

// The frame's parts, named as the JSON's `passes` keys.
std::map<std::string, double> pass_times(const app::ContentCost& content, const engine::FrameCost& cost) {
  std::map<std::string, double> passes{
      {"needle_cpu", content.needle_ms},
      {"frame_params_cpu", content.scene_ms},
      {"ui_build_cpu", content.ui_ms},
      {"deformation_record_cpu", cost.before_pass.record_ms},
      {"scene_record_cpu", cost.scene.record_ms},
      {"ui_record_cpu", cost.overlay.record_ms},
      {"submit_cpu", cost.submit_ms},
      {"slot_wait", cost.slot_wait_ms},
      {"acquire_wait", cost.acquire_ms},
      {"present_wait", cost.present_ms},
  };
  if (cost.before_pass.device_ms) passes["deformation_device"] = *cost.before_pass.device_ms;
  if (cost.scene.device_ms) passes["scene_device"] = *cost.scene.device_ms;
  if (cost.upscale.device_ms) passes["upscale_device"] = *cost.upscale.device_ms;
  if (cost.overlay.device_ms) passes["ui_device"] = *cost.overlay.device_ms;
  return passes;
}

struct RowOptions {
  long frames = 300;
  long warmup = 30;
  bool timestamps = true;
  long block = 8;  // frames of one variant, timed or not, in a row
  std::vector<Variant> variants;
};

// Draws the content's frames into the target and measures them: blocks of frames take turns
// through the variants, untimed and (with timestamps) timed. The first frame of each block
// carries the switch from the block before and is left out. A variant without a fixed scale
// leaves the frame's own (automatic or fixed) render scale to it.
std::vector<FrameSample> measure(app::TraineeFrame& frame, engine::RenderTarget& target,
                                 engine::WindowTarget* window_target, engine::GpuScene& scene,
                                 const app::FrameContent& content, engine::Window* window,
                                 app::UltrasoundWindow* ultrasound, const RowOptions& options) {
  const std::optional<float> product_scale = frame.fixed_render_scale();
  const std::optional<engine::WindowTarget::Presentation> product_presentation =
      window_target ? std::optional(window_target->presentation()) : std::nullopt;
  const size_t kinds = options.variants.size() * (options.timestamps ? 2 : 1);
  std::vector<FrameSample> samples;
  const Clock::time_point start = Clock::now();
  Clock::time_point previous;
  bool counting = false;
  const long total = options.warmup + options.frames * long(kinds);
  for (long i = 0; i < total; ++i) {
    const long measured = i - options.warmup;
    const size_t block = measured < 0 ? 0 : size_t(measured / options.block) % kinds;
    const size_t variant = block % options.variants.size();
    const bool timed = block >= options.variants.size();
    frame.renderer().set_device_timings(timed);
    frame.set_fixed_render_scale(options.variants[variant].scale ? options.variants[variant].scale : product_scale);
    frame.renderer().set_cull_cut_away(options.variants[variant].cut_culling);
    frame.renderer().set_cull_inside(options.variants[variant].inside_culling);
    frame.renderer().set_specialized_pipelines(options.variants[variant].specialized);
    frame.renderer().set_translucency(options.variants[variant].translucency);
    const std::optional<engine::WindowTarget::Presentation> presentation =
        options.variants[variant].presentation ? options.variants[variant].presentation : product_presentation;
    if (ultrasound)
      ultrasound->set_sweep_frames(
          options.variants[variant].sweep_frames.value_or(app::UltrasoundWindow::kSweepFrames));
    if (window_target && presentation && !window_target->set_presentation(*presentation))
      throw std::runtime_error("--variants " + options.variants[variant].name +
                               ": the window's surface does not offer it");
    const Clock::time_point now = Clock::now();
    if (counting) samples.back().period_ms = std::chrono::duration<double, std::milli>(now - previous).count();
    previous = now;
    if (window) {
      window->poll_events();
      if (content.input) content.input(*window);
    }
    const double t = std::chrono::duration<double>(now - start).count();
    if (!frame.draw(target, scene, content, t)) throw std::runtime_error("the window took no frame (minimised?)");
    counting = measured >= 0 && measured % options.block != 0;
    if (counting)
      samples.push_back({variant, timed, 0.0, frame.renderer().render_scale(),
                         pass_times(frame.content_cost(), frame.renderer().frame_cost())});
  }
  if (counting) samples.pop_back();  // no next frame to end its period
  frame.renderer().wait_idle();
  return samples;
}

struct FrameFlags {
  std::optional<std::string> json;
  std::string contents = "penetrable_sphere,rigid_sphere,tissue:400", sizes = "1280x720,1920x1080";
  std::string targets = "window,offscreen", variants = "default", views = "none";
  long long frames = 300, warmup = 30;
  std::optional<int> msaa;
  bool no_timestamps = false;
  std::optional<float> render_scale;
};

int run(const FrameFlags& f) {
  const std::vector<Content> contents = parse_contents(f.contents);
  const std::vector<engine::Extent> sizes = parse_sizes(f.sizes);
  const std::string& targets_arg = f.targets;
  RowOptions options;
  options.frames = long(f.frames);
  options.warmup = long(f.warmup);
  const std::optional<int> msaa = f.msaa;
  options.timestamps = !f.no_timestamps;
  options.variants = parse_variants(f.variants);
  const std::optional<float> render_scale = f.render_scale;
  const std::string& views = f.views;
  const std::optional<std::string>& json = f.json;
  const bool section_view = views.find("section") != std::string::npos;
  const bool translucent_view = views.find("translucent") != std::string::npos;
  const bool ultrasound_view = views.find("ultrasound") != std::string::npos;
  if (ultrasound_view)
    for (const Content& c : contents)
      if (c.task.empty())
        throw UsageError("--views ultrasound: " + c.name + " is no task (the ultrasound images a task's layers)");
  std::vector<std::string> targets;
  for (const char* t : {"window", "offscreen"})
    if (targets_arg.find(t) != std::string::npos) targets.push_back(t);
  if (targets.empty()) throw UsageError("--targets: expected window, offscreen or both, got '" + targets_arg + "'");
  const bool windows = targets.front() == "window";
  if (windows && !engine::Window::display_available()) {
    throw std::runtime_error(
        "no display: the window rows need one. Run under a virtual display (xvfb-run -a -s '-screen 0 1920x1080x24' "
        "needle-sim bench frame ...) or give --targets offscreen");
  }

  const fs::path scratch = fs::temp_directory_path() / ("needle_bench_frame_" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  BenchTable table({"content", "target", "size", "variant", "msaa", "render_scale", "frames", "frame_ms_median",
                    "frame_ms_p95", "frame_ms_p99", "fps_median", "fps_p95", "frame_ms_median_timed", "passes",
                    "views"});
  BenchTable pass_table({"content", "target", "size", "variant", "pass", "ms_median", "ms_p95"});
  std::string device_line;
  double timestamp_period_ns = 0.0;

  for (const Content& content : contents) {
    const engine::Model tissue =
        content.tissue
            ? engine::convert_gltf(asset_gen::make_sphere(content.tissue, content.tissue, {2, 4}), content.name)
            : engine::Model{};
    for (const std::string& target_name : targets) {
      for (const engine::Extent& size : sizes) {
        // A task runs its session in real time, as `run` does, into a scratch database.
        std::unique_ptr<app::TaskSession> session;
        if (!content.task.empty()) {
          app::TaskSessionOptions task;
          task.task = content.task;
          task.trainee = "bench";
          task.db = scratch / "sessions.db";
          task.out_dir = scratch;
          task.messages = printed_messages("needle-sim bench frame");
          session = std::make_unique<app::TaskSession>(task);
        }
        auto make_scene = [&](const engine::SceneRenderer& renderer) {
          return session
                     ? engine::GpuScene(renderer, session->scene())
                     : engine::GpuScene(renderer, tissue, engine::framing_view(tissue, size), engine::TissueParams{});
        };
        auto run_row = [&](const engine::GpuDevice& device, engine::RenderTarget& target, engine::Window* window,
                           engine::WindowTarget* window_target) {
          // With the status panel, as the frames in docs/BENCHMARKS.md were measured (run shows it with --debug).
          app::TraineeFrame frame(device, target,
                                  {msaa.value_or(device.is_cpu_device() ? 1 : 4), true, render_scale, true}, window);
          engine::GpuScene scene = make_scene(frame.renderer());
          // The views as the window shows them (app::with_views): the section cut, the ultrasound window open.
          app::Show show{session ? app::task_content(*session) : app::scripted_content(scene)};
          if (ultrasound_view) show.ultrasound = std::make_shared<app::UltrasoundWindow>(device, session->task());
          if (session) show.fixed_section = app::task_section(session->task(), engine::Section::Mode::Cut);
          ui::ViewState view;
          if (section_view) view.section = engine::Section::Mode::Cut;
          if (translucent_view) view.section = engine::Section::Mode::Translucent;
          view.ultrasound = view.has_ultrasound = ultrasound_view;
          const app::FrameContent shown = app::with_views(show, view, frame.renderer(), target);
          const std::vector<FrameSample> samples =
              measure(frame, target, window_target, scene, shown, window, show.ultrasound.get(), options);
          const std::string size_text =
              std::to_string(target.extent().width) + "x" + std::to_string(target.extent().height);
          for (size_t v = 0; v < options.variants.size(); ++v) {
            std::vector<double> untimed, timed, scales;
            std::map<std::string, std::vector<double>> parts;
            for (const FrameSample& s : samples) {
              if (s.variant != v) continue;
              (s.timed ? timed : untimed).push_back(s.period_ms);
              if (!s.timed) scales.push_back(s.render_scale);
              for (const auto& [name, ms] : s.passes) {
                if (s.timed == name.ends_with("_device")) parts[name].push_back(ms);
              }
            }
            const std::string& variant = options.variants[v].name;
            nlohmann::json passes = nlohmann::json::object();
            for (const auto& [name, ms] : parts) {
              passes[name] = percentile(ms, 0.5);
              pass_table.add_row(
                  {content.name, target_name, size_text, variant, name, percentile(ms, 0.5), percentile(ms, 0.95)});
            }
            const double median = percentile(untimed, 0.5), p95 = percentile(untimed, 0.95);
            table.add_row({content.name, target_name, size_text, variant, frame.renderer().msaa_samples(),
                           percentile(scales, 0.5), long(untimed.size()), median, p95, percentile(untimed, 0.99),
                           1000.0 / median, 1000.0 / p95,
                           timed.empty() ? nlohmann::json(nullptr) : nlohmann::json(percentile(timed, 0.5)), passes,
                           views});
          }
          device_line = device.device_description();
          timestamp_period_ns = device.timestamp_period_ns();
        };
        if (target_name == "window") {
          app::GpuWindow vw("needle-sim bench frame", size, printed_messages("needle-sim bench frame"));
          run_row(vw.device, vw.target, &vw.window, &vw.target);
        } else {
          engine::DeviceOptions quiet;
          quiet.announce_device = false;
          engine::GpuDevice device(quiet);
          engine::HeadlessTarget target(device, size);
          run_row(device, target, nullptr, nullptr);
        }
      }
    }
  }
  fs::remove_all(scratch);
  pass_table.print(
      "bench frame: the frame's parts (ms; *_cpu: recording on the CPU, *_device: timestamps, *_wait: "
      "waiting), medians and p95 over the frames");
  table.emit("bench frame: the trainee's frame on " + device_line + " (timestamp period " +
                 (timestamp_period_ns > 0.0 ? std::to_string(timestamp_period_ns) + " ns" : std::string("none")) + ")",
             json);
  return 0;
}

// The options of bench frame, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<FrameFlags>();
  add_output_file(app, "--json", f->json, "FILE",
                  "also write the rows as JSON (keys: content, target, size, frame_ms_median, frame_ms_p95,\n"
                  "passes: name -> median ms, ...)");
  add_text(app, "--contents", f->contents, "LIST",
           "what the frame shows: a task (a name in assets/tasks or a file) run in real time by its\n"
           "scripted good operator on the simulated device, as `run` shows it; tissue:N (N from 3 to 2000),\n"
           "the N x N sphere with its levels of detail under the scripted needle, as `run --scene` shows it");
  add_text(app, "--sizes", f->sizes, "LIST", "frame sizes, each WxH");
  add_text(app, "--targets", f->targets, "LIST", "window (needs a display: xvfb-run), offscreen, or both");
  add_whole(app, "--frames", f->frames, kFrameBenchFrames, "N", "measured frames of each kind per row");
  add_whole(app, "--warmup", f->warmup, kFrameBenchWarmup, "N", "frames drawn before the measured ones");
  add_msaa(app, "--msaa", f->msaa, "MSAA samples, by default as the window has them: 1 on a CPU device, else 4");
  add_flag(app, "--no-timestamps", f->no_timestamps,
           "no device timings; otherwise frames with and without timestamps alternate in blocks\n"
           "of 8, the frame times are those without, the device times those with");
  add_choice(app, "--views", f->views, {"none", "section", "ultrasound", "section,ultrasound", "ultrasound,section"},
             "the views open as in the window: the section view cut through the needle\n"
             "(or the task's plane), the ultrasound window with its 256 x 512 image swept over two\n"
             "frames, half its lines a frame, as the window does (its passes are in deformation_*, the\n"
             "work recorded before the scene's pass); key views");
  add_render_scale(app, "--render-scale", f->render_scale,
                   "the frame's render scale, as run's (auto: lowered on a CPU device while the\n"
                   "frame misses 60 fps); key render_scale (the median of the frames'), upscale_device");
  add_text(app, "--variants", f->variants, "LIST",
           "settings compared within each row, block by block in turn, ';' between variants and\n"
           "',' between the settings of one: default (the frame's own), scale=S (a fixed render scale),\n"
           "cut_culling=off (the section's cut-away chunks drawn, as before they were culled),\n"
           "inside_culling=off (a patient's layers inside its skin drawn without a section view),\n"
           "specialized=off (every draw with the general mesh shader, its discards and texture\n"
           "fetch run masked, as before),\n"
           "present=fifo|mailbox|immediate (the window's swapchain and its present mode) or\n"
           "present=shm (a CPU device's frames through X11 shared memory); default: the window's own\n"
           "(shm where it is offered, else fifo; the window's line says which),\n"
           "sweep=N (the ultrasound image made over N frames, N from 1 to 16, 1: whole every frame; default 2)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench frame", "the trainee's whole frame as run draws it, pass by pass, in a window and offscreen", declare}};

}  // namespace
}  // namespace needle::cli
