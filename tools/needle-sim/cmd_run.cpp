// needle-sim run: the main job. With a display it opens the simulator window; without one
// (or with --headless) it renders the scene offscreen to a PNG.
#include <cstdio>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/offscreen.hpp"
#include "engine/ui_pass.hpp"
#include "engine/vulkan_context.hpp"
#include "engine/window.hpp"
#include "engine/window_target.hpp"
#include "ui/status_panel.hpp"

namespace needle::cli {
namespace {

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
  std::optional<engine::UiPass> ui_pass;
  if (options.hud) ui_pass.emplace(context, renderer, &window);
  ui::FrameClock clock;

  long drawn = 0;
  while (!window.should_close()) {
    window.poll_events();
    bool last = options.frames > 0 && drawn + 1 == options.frames;
    engine::FrameParams params = gpu_scene.frame_params();
    float dt = clock.tick();
    if (ui_pass) {
      ui_pass->begin_frame(target.extent(), dt);
      ui::draw_status_panel({context.device_description(), options.scene.filename().string(),
                             int(renderer.samples()), clock.mean_frame_ms()});
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
  engine::RgbaImage image =
      engine::render_scene_offscreen(context, scene, {options.size.width, options.size.height},
                                     {static_cast<VkSampleCountFlagBits>(options.msaa.value_or(4))});
  engine::write_png(options.out, image);
  std::printf("wrote %s (%ux%u)\n", options.out.c_str(), image.width, image.height);
  return 0;
}

int run_run(ArgList& args) {
  RunOptions options;
  options.scene = args.value("--scene").value_or((asset_dir() / "scenes" / "thesis_sphere.json").string());
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
                            "  --scene FILE       scene to show (default: assets/scenes/thesis_sphere.json)\n"
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
