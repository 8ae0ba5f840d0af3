// needle-sim bench deform: the GPU deformation pass on spheres from 10^4 to 10^6 vertices, time
// per frame against the same field evaluated on the CPU in one thread (double precision), with
// the vertices processed and skipped, and the largest GPU-vs-CPU position error.
#include <chrono>
#include <cstdio>

#include "asset-gen/assets.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "engine/deformation_bench.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/gpu_device.hpp"
#include "engine/scripted_needle.hpp"
#include "flag_ranges.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Frame f of the scripted experiment between the press (2 s) and the end of the second
// insertion (9.5 s): the field changes every frame, so every frame dispatches.
engine::NeedleLoad needle_at_frame(int f, int frames) {
  return engine::scripted_needle(engine::ScriptedSphere{}, 2.0 + 7.5 * double(f) / double(frames - 1));
}

struct DeformFlags {
  std::optional<std::string> json;
  std::vector<long long> spheres{100, 316, 400, 1000};
  long long frames = 60;
};

int run(const DeformFlags& f) {
  engine::GpuDevice device;
  const engine::TissueParams tissue;
  BenchTable table({"sphere", "vertices", "processed", "skipped", "gpu_ms", "gpu_ms_p95", "cpu_ms", "cpu_over_gpu",
                    "max_abs_error_m"});
  for (const long long r : f.spheres) {
    const int n = int(r);
    engine::DeformationBench bench(
        device, engine::convert_gltf(asset_gen::make_sphere(n, n), "sphere_" + std::to_string(n)), tissue);
    std::vector<double> gpu_ms, cpu_ms, processed;
    for (int frame = 0; frame < int(f.frames); ++frame) {
      bench.set_needle(needle_at_frame(frame, int(f.frames)));
      auto start = Clock::now();
      const size_t processed_now = bench.deform_on_gpu();
      gpu_ms.push_back(ms_since(start));
      processed.push_back(double(processed_now));
      start = Clock::now();
      bench.deform_on_cpu();
      cpu_ms.push_back(ms_since(start));
    }
    const double max_error = bench.max_distance_m();  // after the last frame, over every vertex
    const double gpu_median = percentile(gpu_ms, 0.5), cpu_median = percentile(cpu_ms, 0.5);
    const long vertices = long(bench.vertex_count()), processed_median = long(percentile(processed, 0.5));
    table.add_row({std::to_string(n) + "x" + std::to_string(n), vertices, processed_median, vertices - processed_median,
                   gpu_median, percentile(gpu_ms, 0.95), cpu_median, cpu_median / gpu_median, max_error});
  }
  table.emit("bench deform: deformation pass per frame on " + device.device_description() +
                 " (processed: median over frames; cpu: the same vertices, one thread, double)",
             f.json);
  return 0;
}

// The options of bench deform, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<DeformFlags>();
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  add_whole_list(app, "--spheres", f->spheres, kDeformSpheres, "LIST", "sphere resolutions p = m ((p+1)^2 vertices)");
  add_whole(app, "--frames", f->frames, kDeformFrames, "N", "frames of the scripted press-insert-pivot per sphere");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{{"bench deform", "the GPU deformation pass against the same field on the CPU", declare}};

}  // namespace
}  // namespace needle::cli
