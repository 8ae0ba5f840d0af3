// needle-sim bench render: frame time of the scene pass on this machine's Vulkan device for the
// thesis sphere at growing resolutions (the thesis stopped at 100x100, section 3.3.2), with its
// levels of detail, drawn by renderer variants (every triangle, culled, level of detail) in turn.
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "asset-gen/assets.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/offscreen.hpp"
#include "engine/render_target.hpp"
#include "flag_ranges.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

std::vector<std::string> parse_draw_modes(const std::string& list) {
  const std::vector<std::string> modes = split_list(list, "--draws", kMaxListItems);
  for (const std::string& mode : modes)
    if (mode != "whole" && mode != "culled" && mode != "lod" && mode != "lod+culled")
      throw UsageError("--draws: expected a list of whole, culled, lod, lod+culled; got '" + mode + "'");
  return modes;
}

struct RenderBenchFlags {
  std::optional<std::string> json;
  engine::Extent size{1280, 720};
  std::vector<long long> spheres{100, 200, 400, 800};
  long long frames = 200;
  std::vector<int> msaa{1, 4};
  std::string draws = "whole,culled,lod,lod+culled";
};

int run(const RenderBenchFlags& f) {
  const std::vector<std::string> draw_modes = parse_draw_modes(f.draws);
  const engine::Extent size = f.size;
  const long long frames = f.frames;
  engine::GpuDevice device;
  engine::HeadlessTarget target(device, size);

  BenchTable table({"sphere", "vertices", "triangles", "width", "height", "msaa", "draws", "frames", "frame_ms_median",
                    "frame_ms_p95", "fps_median", "triangles_drawn"});
  for (const long long r : f.spheres) {
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
    for (int msaa : f.msaa) {
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
  table.emit("bench render: scene pass on " + device.device_description(), f.json);
  return 0;
}

// The options of bench render, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<RenderBenchFlags>();
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  add_size(app, "--size", f->size, "frame size");
  add_whole_list(app, "--spheres", f->spheres, kRenderSpheres, "LIST", "sphere resolutions p = m");
  add_whole(app, "--frames", f->frames, kBenchFrames, "N", "timed frames per sphere");
  add_msaa_list(app, "--msaa", f->msaa, "MSAA sample counts to compare, capped at what the device has");
  add_text(app, "--draws", f->draws, "LIST",
           "renderer variants to compare, frame by frame in turn: whole (every triangle),\n"
           "culled (chunks facing away left out), lod (the level of detail for the size),\n"
           "lod+culled (both: the renderer's default)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench render", "frame time of the scene pass for the thesis sphere at growing resolutions", declare}};

}  // namespace
}  // namespace needle::cli
