// needle-sim bench deform: the GPU deformation pass on spheres from 10^4 to 10^6 vertices, time
// per frame against the same field evaluated on the CPU in one thread (double precision), with
// the vertices processed and skipped, and the largest GPU-vs-CPU position error.
#include <chrono>
#include <cstdio>

#include "arg_list.hpp"
#include "asset-gen/assets.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "engine/deformation_pass.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/scripted_needle.hpp"
#include "engine/vulkan_context.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

// Frame f of the scripted experiment between the press (2 s) and the end of the second
// insertion (9.5 s): the field changes every frame, so every frame dispatches.
engine::NeedleLoad needle_at_frame(int f, int frames) {
  return engine::scripted_needle(engine::ScriptedSphere{}, 2.0 + 7.5 * double(f) / double(frames - 1));
}

int run_bench_deform(ArgList& args) {
  auto json = args.value("--json");
  std::vector<double> resolutions = parse_number_list(args.value("--spheres").value_or("100,316,400,1000"), "--spheres");
  double frames = parse_number(args.value("--frames").value_or("60"), "--frames");
  args.finish();
  if (frames < 2 || frames != double(long(frames))) throw UsageError("--frames: expected a whole number ≥ 2");
  for (double r : resolutions) {
    if (r < 3 || r > 2000 || r != double(long(r))) throw UsageError("--spheres: each resolution a whole number in 3..2000");
  }

  engine::VulkanContext context(engine::ContextOptions{});
  const engine::TissueParams tissue;
  BenchTable table({"sphere", "vertices", "processed", "skipped", "gpu_ms", "gpu_ms_p95", "cpu_ms", "cpu_over_gpu",
                    "max_abs_error_m"});
  for (double r : resolutions) {
    const int n = int(r);
    engine::Model model = engine::convert_gltf(asset_gen::make_sphere(n, n), "sphere_" + std::to_string(n));
    engine::Primitive rest = model.primitives.at(0);
    const glm::dmat4 model_to_world(model.instances.at(0).world);
    engine::VertexGrid grid = engine::VertexGrid::sort_vertices(rest, 0.5 * tissue.falloff * tissue.radius_m);
    engine::GpuPrimitive gpu = engine::upload_primitive(context, rest);
    engine::DeformationPass pass(context);
    pass.add_target(gpu, rest, grid, model_to_world);

    // The CPU keeps its own deformed mesh (world positions) through the same frames.
    std::vector<glm::dvec3> cpu_state(rest.vertices.size());
    for (size_t v = 0; v < cpu_state.size(); ++v) {
      cpu_state[v] = glm::dvec3(model_to_world * glm::dvec4(glm::dvec3(rest.vertices[v].position), 1.0));
    }
    std::vector<engine::Sphere> previous_reach;
    std::vector<double> gpu_ms, cpu_ms, processed;
    for (int f = 0; f < int(frames); ++f) {
      engine::DeformationField field = engine::build_field(needle_at_frame(f, int(frames)), tissue);
      auto start = Clock::now();
      auto record = pass.update(field);
      if (record) context.submit_and_wait(record);
      gpu_ms.push_back(ms_since(start));
      processed.push_back(double(pass.last_frame().processed));

      // The same work on the CPU: the vertices of the grid cells this frame's and the last
      // frame's loads reach, as the pass visits them.
      std::vector<engine::Sphere> reach;
      for (const engine::Kelvinlet& k : field.loads) {
        reach.push_back({glm::dvec3(glm::inverse(model_to_world) * glm::dvec4(k.center, 1.0)), k.support});
      }
      std::vector<engine::Sphere> visit = reach;
      visit.insert(visit.end(), previous_reach.begin(), previous_reach.end());
      previous_reach = reach;
      start = Clock::now();
      for (const engine::VertexRange& range : grid.ranges_near(visit)) {
        for (uint32_t v = range.first; v < range.first + range.count; ++v) {
          glm::dvec3 p = glm::dvec3(model_to_world * glm::dvec4(glm::dvec3(rest.vertices[v].position), 1.0));
          cpu_state[v] = engine::deform(field, p, glm::dvec3(rest.vertices[v].normal)).position;
        }
      }
      cpu_ms.push_back(ms_since(start));
    }
    double max_error = 0.0;  // after the last frame, over every vertex
    std::vector<engine::MeshVertex> out = engine::read_back_vertices(context, gpu);
    for (size_t v = 0; v < out.size(); ++v) {
      glm::dvec3 got = glm::dvec3(model_to_world * glm::dvec4(glm::dvec3(out[v].position), 1.0));
      max_error = std::max(max_error, glm::length(got - cpu_state[v]));
    }
    const double gpu_median = percentile(gpu_ms, 0.5), cpu_median = percentile(cpu_ms, 0.5);
    const long vertices = long(rest.vertices.size()), processed_median = long(percentile(processed, 0.5));
    table.add_row({std::to_string(n) + "x" + std::to_string(n), vertices, processed_median, vertices - processed_median,
                   gpu_median, percentile(gpu_ms, 0.95), cpu_median, cpu_median / gpu_median, max_error});
  }
  table.emit("bench deform: deformation pass per frame on " + context.device_description() +
                 " (processed: median over frames; cpu: the same vertices, one thread, double)",
             json);
  return 0;
}

const CommandRegistrar reg{{"bench deform",
                            "needle-sim bench deform [--json FILE] [--spheres 100,316,400,1000] [--frames N]\n"
                            "  --json FILE     also write the rows as JSON\n"
                            "  --spheres LIST  sphere resolutions p = m ((p+1)^2 vertices; default 100,316,400,1000)\n"
                            "  --frames N      frames of the scripted press-insert-pivot per sphere (default 60)",
                            run_bench_deform}};

}  // namespace
}  // namespace needle::cli
