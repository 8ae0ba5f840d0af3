// needle-sim run: the main job. With a display it opens the simulator window; without one
// (or with --headless) it renders the scene offscreen to a PNG. Until the haptic loop drives it,
// a scripted needle performs the thesis's insertion on the scene's first deformable tissue.
#include <chrono>
#include <cstdio>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/headless_target.hpp"
#include "engine/scripted_needle.hpp"
#include "engine/ui_pass.hpp"
#include "engine/vulkan_context.hpp"
#include "engine/window.hpp"
#include "engine/window_target.hpp"
#include "ui/status_panel.hpp"

namespace needle::cli {
namespace {

// The scripted needle's target: the first deformable tissue's bounding sphere, if any.
std::optional<engine::ScriptedSphere> script_target(const engine::GpuScene& scene) {
  const auto& assets = scene.scene().assets;
  for (size_t i = 0; i < assets.size(); ++i) {
    if (!assets[i].deformation) continue;
    const engine::Bounds& b = scene.asset_model(i).world_bounds();
    engine::ScriptedSphere sphere;
    sphere.centre = glm::dvec3(assets[i].transform() * glm::vec4((b.min + b.max) * 0.5f, 1.0f));
    sphere.radius = 0.5 * double(b.max.x - b.min.x) * double(assets[i].scale.x);
    return sphere;
  }
  return std::nullopt;
}

// The moment of the script a headless run shows: the needle pivoted in the tissue.
constexpr double kHeadlessMoment_s = 7.0;

struct RunOptions {
  std::filesystem::path scene;
  std::string out;
  Size2 size;
  long frames = 0;  // window: close after this many frames (0: when the user closes it)
  std::optional<int> msaa;
  bool hud = true;
  std::optional<std::string> screenshot;
};

int run_window(const engine::Scene& scene, const RunOptions& options) {
  engine::Window window("needle-sim", int(options.size.width), int(options.size.height));
  engine::ContextOptions context_options;
  context_options.instance_extensions = engine::Window::required_instance_extensions();
  context_options.make_surface = [&](VkInstance instance) { return window.create_surface(instance); };
  engine::VulkanContext context(context_options);
  engine::WindowTarget target(context, window);
  // On a CPU device (lavapipe) 4x MSAA costs about 5x the frame time (docs/BENCHMARKS.md):
  // unless asked, the interactive window keeps its frame rate instead; stills keep MSAA.
  const bool cpu_device = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  engine::SceneRenderer renderer(context, target,
                                 {static_cast<VkSampleCountFlagBits>(options.msaa.value_or(cpu_device ? 1 : 4))});
  engine::GpuScene gpu_scene(renderer, scene);
  const std::optional<engine::ScriptedSphere> script = script_target(gpu_scene);
  const auto start = std::chrono::steady_clock::now();
  std::optional<engine::UiPass> ui_pass;
  if (options.hud) ui_pass.emplace(context, renderer, &window);
  ui::FrameClock clock;

  long drawn = 0;
  while (!window.should_close()) {
    window.poll_events();
    bool last = options.frames > 0 && drawn + 1 == options.frames;
    std::optional<engine::NeedleLoad> needle;
    if (script) {
      needle = engine::scripted_needle(*script,
                                       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    engine::FrameParams params = gpu_scene.frame_params(needle ? &*needle : nullptr);
    float dt = clock.tick();
    if (ui_pass) {
      ui_pass->begin_frame(target.extent(), dt);
      ui::draw_status_panel({context.device_description(), options.scene.filename().string(), int(renderer.samples()),
                             clock.mean_frame_ms()});
      params.overlay = ui_pass->end_frame();
    }
    engine::RgbaImage shot;
    if (!renderer.draw(target, params, last && options.screenshot ? &shot : nullptr)) {
      window.wait_events();  // minimised or resizing: nothing to draw into
      continue;
    }
    ++drawn;
    if (last) {
      if (options.screenshot) {
        engine::write_png(*options.screenshot, shot);
        std::printf("wrote %s (%ux%u)\n", options.screenshot->c_str(), shot.width, shot.height);
      }
      window.request_close();
    }
  }
  renderer.wait_idle();
  std::printf("presented %ld frames\n", drawn);
  return 0;
}

int run_headless(const engine::Scene& scene, const RunOptions& options) {
  engine::VulkanContext context(engine::ContextOptions{});
  engine::HeadlessTarget target(context, {options.size.width, options.size.height});
  engine::SceneRenderer renderer(context, target, {static_cast<VkSampleCountFlagBits>(options.msaa.value_or(4))});
  engine::GpuScene gpu_scene(renderer, scene);
  std::optional<engine::NeedleLoad> needle;
  if (auto script = script_target(gpu_scene)) needle = engine::scripted_needle(*script, kHeadlessMoment_s);
  engine::RgbaImage image;
  renderer.draw(target, gpu_scene.frame_params(needle ? &*needle : nullptr), &image);
  engine::write_png(options.out, image);
  std::printf("wrote %s (%ux%u)\n", options.out.c_str(), image.width, image.height);
  return 0;
}

int run_run(ArgList& args) {
  RunOptions options;
  options.scene = args.value("--scene").value_or((asset_dir() / "scenes" / "penetrable_sphere.json").string());
  options.out = args.value("--out").value_or("out/run.png");
  options.size = parse_size(args.value("--size").value_or("1280x720"), "--size");
  if (auto frames = args.value("--frames")) {
    double n = parse_number(*frames, "--frames");
    if (n < 1 || n != long(n)) throw UsageError("--frames: expected a whole number ≥ 1, got '" + *frames + "'");
    options.frames = long(n);
  }
  options.screenshot = args.value("--screenshot");
  if (auto msaa = args.value("--msaa")) options.msaa = parse_msaa(*msaa, "--msaa");
  bool headless = args.flag("--headless");
  options.hud = !args.flag("--no-hud");
  args.finish();
  if (options.screenshot && options.frames == 0)
    throw UsageError("--screenshot needs --frames N (the frame to capture)");

  engine::Scene scene = engine::load_scene(options.scene);
  if (!headless && engine::Window::display_available()) return run_window(scene, options);
  if (!headless) std::printf("no display: rendering headless\n");
  return run_headless(scene, options);
}

const CommandRegistrar reg{{"run",
                            "needle-sim run [--scene FILE] [--headless] [--out FILE] [--size WxH] [--msaa N] [--frames "
                            "N] [--screenshot FILE]\n"
                            "  --scene FILE       scene to show (default: assets/scenes/penetrable_sphere.json)\n"
                            "  --headless         render offscreen even when a display is available\n"
                            "  --out FILE         headless: where to write the PNG (default out/run.png)\n"
                            "  --size WxH         window or image size (default 1280x720)\n"
                            "  --msaa N           MSAA samples (default 4; 1 in a window on a CPU device)\n"
                            "  --frames N         window: close after N frames\n"
                            "  --screenshot FILE  window: save frame N as presented (needs --frames)\n"
                            "  --no-hud           window: no status panel",
                            run_run}};

}  // namespace
}  // namespace needle::cli
