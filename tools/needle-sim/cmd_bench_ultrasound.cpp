// needle-sim bench ultrasound: the ultrasound image's compute passes through the layered tissue
// block and the lumbar epidural section with the needle in plane, at 256 x 512 and 512 x 1024:
// time per image (submitted and waited for) against the scan-line model's double-precision CPU
// reference over the same lines, and the largest depth difference between the two. A third scene,
// the penetrable sphere of the sphere_ultrasound task, images a tissue the needle deforms, as bench
// frame --views ultrasound draws it: the passes undo its displacement at nodes down each line and
// interpolate between them, at the spacing chosen for the deformation and, at 256 x 512, at fixed
// ones (rest_error_m, the interpolation's largest error against the exact rest positions;
// pixels_unlike_exact, the image's pixels more than a count away from the one with a node at
// every sample). A fourth, the generated BMI 22 patient's paramedian view (docs/PATIENTS.md), images
// twelve sampled distance grids.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "app/echo_scene.hpp"
#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "engine/gpu_device.hpp"
#include "flag_ranges.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The CPU time this process has used, all its threads (a CPU device's too), in milliseconds: on
// a machine shared with other work it is what the images cost, where the wall time also holds
// the waits for a core.
double process_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) { return 1e3 * double(t.tv_sec) + 1e-3 * double(t.tv_usec); };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

// A scene of the bench: the layers of a scenario (at rest) or of a task (with its scene's
// deformable tissue), a probe on its skin and a needle in the probe's plane.
struct Case {
  const char* name;
  engine::EchoScene scene;
  engine::UltrasoundProbe probe;
  engine::NeedleLoad needle;
};

engine::EchoScene scenario_layers(const char* scenario) {
  return app::echo_scene(haptics::load_scenario((asset_dir() / scenario).string()), engine::Scene{});
}

engine::NeedleLoad needle_in_plane(glm::dvec3 entry, double angle_rad, double depth_m) {
  engine::NeedleLoad n;
  n.contact = engine::NeedleContact::Inserted;
  n.axis = {std::cos(angle_rad), 0.0, -std::sin(angle_rad)};
  n.tip = entry + depth_m * n.axis;
  n.surface_point = entry;
  return n;
}

std::vector<Case> cases() {
  engine::UltrasoundProbe block;  // a 7.5 MHz linear probe on the block's skin (z = 0.07 m), 50 mm deep
  block.position = {0.33, 0.0, 0.07};
  engine::UltrasoundProbe epidural = block;  // 5 MHz, 80 mm deep, 50 mm wide: down to the vertebral body
  epidural.depth_m = 0.08;
  epidural.width_m = 0.05;
  epidural.frequency_MHz = 5.0;
  // The sphere_ultrasound task's probe and sphere, the needle 35 mm in from its entry marker at 30°
  // with the step's lateral push (0.5 N) and its entry point dragged 1 mm: three Kelvinlets (two
  // along the shaft, one at the entry) displace every sample of the image.
  const training::Task sphere_task = training::load_task(asset_dir() / "tasks/sphere_ultrasound.json");
  engine::EchoScene sphere = app::echo_scene(sphere_task);
  engine::NeedleLoad pushed = needle_in_plane({0.37, 0.0, 0.09539}, 0.5236, 0.035);
  pushed.surface_point.z -= 0.001;
  pushed.lateral_force_on_tissue_N = {0.0, 0.5, 0.0};
  const engine::UltrasoundProbe sphere_probe = app::task_probe(sphere_task, sphere).probe;
  // The BMI 22 patient's twelve layer grids seen in the paramedian sagittal oblique view 12 mm off
  // the L3-L4 entry, tilted 10° to the midline, the needle in the midline at 40 mm.
  engine::EchoScene patient = app::echo_scene(training::load_task(asset_dir() / "tasks/epidural_patient_bmi22.json"));
  const engine::UltrasoundProbe paramedian =
      app::paramedian_sagittal_oblique_probe(patient, {0.33, 0.0, 0.07}, 0.012, 10.0 * std::numbers::pi / 180.0);
  return {{"block", scenario_layers("scenarios/tissue_block_layers.json"), block,
           needle_in_plane({0.315, 0.0, 0.07}, 0.5236, 0.035)},
          {"epidural", scenario_layers("scenarios/lumbar_epidural.json"), epidural,
           needle_in_plane({0.31, 0.0, 0.07}, 0.7854, 0.06)},
          {"sphere_deformed", std::move(sphere), sphere_probe, pushed},
          {"patient_paramedian", std::move(patient), paramedian, needle_in_plane({0.33, 0.0, 0.07}, 1.5708, 0.04)}};
}

// The largest depth difference between the GPU's and the reference's interfaces and needle walls.
double max_depth_error(const std::vector<engine::ScanLine>& gpu, const std::vector<engine::ScanLine>& cpu) {
  double worst = 0.0;
  for (size_t i = 0; i < cpu.size(); ++i) {
    if (gpu[i].interfaces.size() != cpu[i].interfaces.size() ||
        std::isinf(gpu[i].needle_depth_m) != std::isinf(cpu[i].needle_depth_m))
      return std::numeric_limits<double>::infinity();  // a line that met other things
    for (size_t k = 0; k < cpu[i].interfaces.size(); ++k)
      worst = std::max(worst, std::abs(gpu[i].interfaces[k].depth_m - cpu[i].interfaces[k].depth_m));
    if (!std::isinf(cpu[i].needle_depth_m))
      worst = std::max(worst, std::abs(gpu[i].needle_depth_m - cpu[i].needle_depth_m));
  }
  return worst;
}

// Pixels whose grey differs by more than one count.
long pixels_unlike(const engine::RgbaImage& a, const engine::RgbaImage& b) {
  long n = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) n += std::abs(int(a.pixels[i]) - int(b.pixels[i])) > 1 ? 1 : 0;
  return n;
}

struct UltrasoundFlags {
  std::optional<std::string> json;
  long long frames = 60;
};

int run(const UltrasoundFlags& f) {
  const double frames = double(f.frames);

  engine::GpuDevice device;
  BenchTable table({"scene", "lines", "samples", "rest_nodes", "rest_node_spacing", "gpu_ms", "gpu_ms_p95",
                    "gpu_cpu_time_ms", "cpu_ms", "max_depth_error_m", "rest_error_m", "pixels_unlike_exact", "lines_ms",
                    "rest_ms", "echoes_ms", "axial_ms", "image_ms"});
  for (const Case& c : cases()) {
    const engine::EchoScene& scene = c.scene;
    for (const auto& [lines, samples] : {std::pair{256u, 512u}, std::pair{512u, 1024u}}) {
      // A deformed tissue's rest nodes: the product's automatic spacing, then fixed ones from a
      // node at every sample (the exact rest positions, the image compared against) up.
      const engine::UltrasoundSettings product{lines, samples};
      std::vector<uint32_t> spacings{product.rest_node_spacing};
      if (scene.deformation && lines == 256u) spacings = {product.rest_node_spacing, 1u, 4u, 16u};
      engine::UltrasoundSettings exact_settings = product;
      exact_settings.rest_node_spacing = 1;
      engine::UltrasoundView exact(device, scene, exact_settings);
      exact.render(c.probe, &c.needle);
      const engine::RgbaImage exact_image = exact.image();
      for (const uint32_t spacing : spacings) {
        engine::UltrasoundSettings settings = product;
        settings.rest_node_spacing = spacing;
        const uint32_t used = engine::rest_node_spacing(scene, c.probe, c.needle, settings);
        engine::UltrasoundView view(device, scene, settings);
        view.render(c.probe, &c.needle);  // pipelines warmed, memory touched
        std::vector<double> gpu_ms;
        const double cpu_time_before = process_cpu_ms();
        for (int frame = 0; frame < int(frames); ++frame) {
          const auto start = Clock::now();
          view.render(c.probe, &c.needle);
          gpu_ms.push_back(ms_since(start));
        }
        const double gpu_cpu_time_ms = (process_cpu_ms() - cpu_time_before) / frames;
        // Each pass's device time, from images timed apart (the timestamps add a barrier a pass).
        view.set_device_timings(true);
        std::vector<std::vector<double>> pass_ms(5);
        for (int frame = 0; frame < std::max(10, int(frames) / 4); ++frame) {
          view.render(c.probe, &c.needle);
          const auto passes = view.pass_ms();
          for (size_t p = 0; p < std::min(passes.size(), pass_ms.size()); ++p) pass_ms[p].push_back(passes[p].second);
        }
        view.set_device_timings(false);
        const auto pass_median = [&](size_t p) -> nlohmann::json {
          return pass_ms[p].empty() ? nlohmann::json(nullptr) : nlohmann::json(percentile(pass_ms[p], 0.5));
        };
        std::vector<double> cpu_ms;
        std::vector<engine::ScanLine> reference;
        for (int r = 0; r < 3; ++r) {
          const auto start = Clock::now();
          reference = engine::trace_scan_lines(scene, c.probe, &c.needle, view.settings());
          cpu_ms.push_back(ms_since(start));
        }
        table.add_row({c.name, lines, samples, spacing ? "fixed" : "auto", used, percentile(gpu_ms, 0.5),
                       percentile(gpu_ms, 0.95), gpu_cpu_time_ms, percentile(cpu_ms, 0.5),
                       max_depth_error(view.scan_lines(), reference),
                       engine::rest_interpolation_error(scene, c.probe, c.needle, settings),
                       pixels_unlike(view.image(), exact_image), pass_median(0), pass_median(1), pass_median(2),
                       pass_median(3), pass_median(4)});
      }
    }
  }
  table.emit(
      "bench ultrasound: one image on " + device.device_description() +
          " (gpu: submitted and waited for, median and 95th percentile; cpu: the scan-line reference, one thread, "
          "double; gpu_cpu_time_ms: the process's CPU time per image, all threads; *_ms: each pass's device time, "
          "median)",
      f.json);
  return 0;
}

// The options of bench ultrasound, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<UltrasoundFlags>();
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  add_whole(app, "--frames", f->frames, kUltrasoundFrames, "N", "images timed per scene and size");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench ultrasound", "the ultrasound image's compute passes against the scan-line CPU reference", declare}};

}  // namespace
}  // namespace needle::cli
