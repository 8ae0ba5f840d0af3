// needle-sim bench render: frame time of the scene pass on this machine's Vulkan device for the
// thesis sphere at growing resolutions (the thesis stopped at 100x100, section 3.3.2).
#include <chrono>
#include <cstdio>

#include "arg_list.hpp"
#include "asset-gen/assets.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/headless_target.hpp"
#include "engine/offscreen.hpp"
#include "engine/vulkan_context.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

int run_bench_render(ArgList& args) {
  auto json = args.value("--json");
  Size2 size = parse_size(args.value("--size").value_or("1280x720"), "--size");
  std::vector<double> resolutions = parse_number_list(args.value("--spheres").value_or("100,200,400,800"), "--spheres");
  double frames = parse_number(args.value("--frames").value_or("200"), "--frames");
  std::vector<int> msaa_counts;
  for (double m : parse_number_list(args.value("--msaa").value_or("1,4"), "--msaa")) {
    msaa_counts.push_back(parse_msaa(std::to_string(int(m)), "--msaa"));
  }
  args.finish();
  if (frames < 1 || frames != double(long(frames))) throw UsageError("--frames: expected a whole number ≥ 1");
  for (double r : resolutions) {
    if (r < 3 || r > 4000 || r != double(long(r)))
      throw UsageError("--spheres: each resolution a whole number in 3..4000");
  }

  engine::VulkanContext context(engine::ContextOptions{});
  VkExtent2D extent{size.width, size.height};
  engine::HeadlessTarget target(context, extent);

  BenchTable table({"sphere", "vertices", "triangles", "width", "height", "msaa", "frames", "frame_ms_median",
                    "frame_ms_p95", "fps_median"});
  for (double r : resolutions) {
    int n = int(r);
    engine::Model model = engine::convert_gltf(asset_gen::make_sphere(n, n), "sphere_" + std::to_string(n));
    for (int msaa : msaa_counts) {
      engine::SceneRenderer renderer(context, target, {static_cast<VkSampleCountFlagBits>(msaa)});
      engine::GpuScene scene(renderer, model, engine::framing_view(model, extent));
      engine::FrameParams params = scene.frame_params();
      size_t vertices = 0, triangles = 0;
      for (const auto& p : model.primitives) {
        vertices += p.vertices.size();
        triangles += p.indices.size() / 3;
      }
      for (int warmup = 0; warmup < 5; ++warmup) renderer.draw(target, params);
      renderer.wait_idle();
      // A frame is submit to completion: the latency a trainee sees, not a pipelined throughput.
      std::vector<double> ms;
      for (long f = 0; f < long(frames); ++f) {
        auto start = std::chrono::steady_clock::now();
        renderer.draw(target, params);
        renderer.wait_idle();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      }
      double median = percentile(ms, 0.5);
      table.add_row({std::to_string(n) + "x" + std::to_string(n), vertices, triangles, extent.width, extent.height,
                     int(renderer.samples()), long(frames), median, percentile(ms, 0.95), 1000.0 / median});
    }
  }
  table.emit("bench render: scene pass on " + context.device_description(), json);
  return 0;
}

const CommandRegistrar reg{
    {"bench render",
     "needle-sim bench render [--json FILE] [--size WxH] [--spheres 100,200,400,800] [--frames N] [--msaa 1,4]\n"
     "  --json FILE     also write the rows as JSON\n"
     "  --size WxH      frame size (default 1280x720)\n"
     "  --spheres LIST  sphere resolutions p = m (default 100,200,400,800)\n"
     "  --frames N      timed frames per sphere (default 200)\n"
     "  --msaa LIST     MSAA sample counts to compare (default 1,4; capped at what the device has)",
     run_bench_render}};

}  // namespace
}  // namespace needle::cli
