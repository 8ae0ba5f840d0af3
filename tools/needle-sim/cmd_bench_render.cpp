// needle-sim bench render: frame time of the scene pass on this machine's Vulkan device for the
// thesis sphere at growing resolutions (the thesis stopped at 100x100, section 3.3.2), with its
// levels of detail, drawn by renderer variants (every triangle, culled, level of detail) in turn.
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "arg_list.hpp"
#include "asset-gen/assets.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/offscreen.hpp"
#include "engine/render_target.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

std::vector<std::string> parse_draw_modes(const std::string& list) {
  std::vector<std::string> modes;
  for (size_t start = 0; start <= list.size();) {
    size_t end = std::min(list.find(',', start), list.size());
    modes.push_back(list.substr(start, end - start));
    if (modes.back() != "whole" && modes.back() != "culled" && modes.back() != "lod" && modes.back() != "lod+culled")
      throw UsageError("--draws: expected a list of whole, culled, lod, lod+culled; got '" + modes.back() + "'");
    start = end + 1;
  }
  return modes;
}

int run_bench_render(ArgList& args) {
  auto json = output_file(args, "--json");
  engine::Extent size = parse_size(args.value("--size").value_or("1280x720"), "--size");
  std::vector<double> resolutions = parse_number_list(args.value("--spheres").value_or("100,200,400,800"), "--spheres");
  const long frames = static_cast<long>(parse_whole(args.value("--frames").value_or("200"), "--frames", 1, 100000));
  std::vector<int> msaa_counts;
  for (double m : parse_number_list(args.value("--msaa").value_or("1,4"), "--msaa")) {
    msaa_counts.push_back(parse_msaa(std::to_string(int(m)), "--msaa"));
  }
  std::vector<std::string> draw_modes = parse_draw_modes(args.value("--draws").value_or("whole,culled,lod,lod+culled"));
  args.finish();
  for (double r : resolutions) {
    if (r < 3 || r > 4000 || r != double(long(r)))
      throw UsageError("--spheres: each resolution a whole number in 3..4000");
  }

  engine::GpuDevice device;
  engine::HeadlessTarget target(device, size);

  BenchTable table({"sphere", "vertices", "triangles", "width", "height", "msaa", "draws", "frames", "frame_ms_median",
                    "frame_ms_p95", "fps_median", "triangles_drawn"});
  for (double r : resolutions) {
    int n = int(r);
    // The tissue with its levels of detail: every 2nd and every 4th parallel and meridian.
    std::vector<int> lod_steps;
    for (int step : {2, 4})
      if (n % step == 0 && n / step >= 3) lod_steps.push_back(step);
    engine::Model model = engine::convert_gltf(asset_gen::make_sphere(n, n, lod_steps), "sphere_" + std::to_string(n));
    size_t vertices = 0, triangles = 0;
    for (const auto& p : model.primitives) {
      vertices += p.vertices.size();
      triangles += p.indices.size() / 3;
    }
    for (int msaa : msaa_counts) {
      // The draw modes take turns frame by frame, so a load that comes and goes on a shared
      // machine weighs on all of them alike and their ratios hold.
      struct Variant {
        std::string draws;
        std::unique_ptr<engine::SceneRenderer> renderer;
        std::unique_ptr<engine::GpuScene> scene;
        engine::FrameParams params;
        std::vector<double> ms;
      };
      std::vector<Variant> variants;
      for (const std::string& draws : draw_modes) {
        Variant v{draws};
        v.renderer = std::make_unique<engine::SceneRenderer>(
            device, target, engine::RendererSettings{msaa, draws.starts_with("lod"), draws.ends_with("culled")});
        v.scene = std::make_unique<engine::GpuScene>(*v.renderer, model, engine::framing_view(model, size));
        v.params = v.scene->frame_params();
        for (int warmup = 0; warmup < 5; ++warmup) v.renderer->draw(target, v.params);
        v.renderer->wait_idle();
        variants.push_back(std::move(v));
      }
      // A frame is submit to completion: the latency a trainee sees, not a pipelined throughput.
      for (long f = 0; f < long(frames); ++f) {
        for (Variant& v : variants) {
          auto start = std::chrono::steady_clock::now();
          v.renderer->draw(target, v.params);
          v.renderer->wait_idle();
          v.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
      }
      for (const Variant& v : variants) {
        double median = percentile(v.ms, 0.5);
        table.add_row({std::to_string(n) + "x" + std::to_string(n), vertices, triangles, size.width, size.height,
                       v.renderer->msaa_samples(), v.draws, long(frames), median, percentile(v.ms, 0.95),
                       1000.0 / median, v.renderer->triangles_drawn()});
      }
    }
  }
  table.emit("bench render: scene pass on " + device.device_description(), json);
  return 0;
}

const CommandRegistrar reg{
    {"bench render",
     "needle-sim bench render [--json FILE] [--size WxH] [--spheres 100,200,400,800] [--frames N] [--msaa 1,4]\n"
     "                        [--draws whole,culled,lod,lod+culled]\n"
     "  --json FILE     also write the rows as JSON\n"
     "  --size WxH      frame size (default 1280x720)\n"
     "  --spheres LIST  sphere resolutions p = m (default 100,200,400,800)\n"
     "  --frames N      timed frames per sphere (default 200)\n"
     "  --msaa LIST     MSAA sample counts to compare (default 1,4; capped at what the device has)\n"
     "  --draws LIST    renderer variants to compare, frame by frame in turn: whole (every triangle),\n"
     "                  culled (chunks facing away left out), lod (the level of detail for the size),\n"
     "                  lod+culled (both: the renderer's default)",
     run_bench_render}};

}  // namespace
}  // namespace needle::cli
