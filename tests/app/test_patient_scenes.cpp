// A generated patient drawn (app/patient_meshes.hpp): the three shipped patients' backs, and the
// midsagittal section through L3-L4 with each structure's cut in its colour, against goldens
// (tests/engine/image_compare.hpp's tolerance), under the validation layer. PatientScenes generates
// patients: SANITIZE_SKIP (tests/README.md).
#include <gtest/gtest.h>

#include <array>
#include <numbers>
#include <set>

#include "app/echo_scene.hpp"
#include "app/patient_look.hpp"
#include "app/patient_meshes.hpp"
#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/screen_projection.hpp"
#include "engine/ultrasound.hpp"
#include "haptics/anatomy/patient.hpp"
#include "tests/engine/image_compare.hpp"
#include "tests/support/closed_mesh.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/scan_lines.hpp"
#include "tests/support/test_paths.hpp"
#include "training/tasks/scripted_operator.hpp"

namespace needle::test {
namespace {

constexpr engine::Extent kSize{320, 240};

// The scenario a session of the task runs (its patient inline), loaded.
haptics::Scenario task_scenario(const std::string& task) {
  const training::Task t = training::load_task(source_dir() / "assets/tasks" / (task + ".json"));
  return training::write_scenario(training::task_scenario_json(t),
                                  process_folder(output_dir() / "patient_scenes") / (task + ".json"));
}

engine::Scene patient_scene(const haptics::Scenario& scenario) {
  return app::with_patient(engine::load_scene(source_dir() / "assets/scenes/lumbar_patient.json"), scenario);
}

engine::GpuDevice& device() {
  static engine::GpuDevice d(engine::DeviceOptions{.validation = true, .announce_device = false});
  return d;
}

TEST(PatientScenes, TheThreePatientsBacks) {
  for (const char* patient : {"bmi22", "bmi30", "bmi40"}) {
    SCOPED_TRACE(patient);
    const haptics::Scenario scenario = task_scenario(std::string("epidural_patient_") + patient);
    engine::HeadlessTarget target(device(), kSize);
    engine::SceneRenderer renderer(device(), target);
    engine::GpuScene scene(renderer, patient_scene(scenario));
    engine::RgbaImage image;
    ASSERT_TRUE(renderer.draw(target, scene.frame_params(), &image));
    EXPECT_TRUE(matches_golden(image, std::string("patient_back_") + patient));
  }
  EXPECT_TRUE(device().validation_messages().empty()) << device().validation_messages().front();
}

// Each layer as drawn (app::patient_layer_model: its surface-nets mesh simplified in parts) against
// the surface-nets mesh it comes from: watertight and wound one way (the parts meet without a crack),
// its volume within the simplification's bound (a quarter of the spacing times the surface's
// area), the skin's surface along the midline kept whole, and the whole patient in under a tenth
// of the triangles.
TEST(PatientScenes, EachLayerDrawnIsClosedAndKeepsItsVolumeInFewerTriangles) {
  const haptics::Scenario scenario = task_scenario("epidural_patient_bmi22");
  const haptics::anatomy::Patient& patient = *scenario.patient;
  size_t drawn_total = 0, nets_total = 0;
  for (size_t i = 0; i < patient.layers.size(); ++i) {
    SCOPED_TRACE(patient.layers[i].name);
    const engine::Model model = app::patient_layer_model(patient, i, Eigen::Vector3d::Zero());
    const std::vector<uint32_t>& drawn = model.primitives.at(0).indices;
    const std::vector<engine::MeshVertex>& vertices = model.primitives[0].vertices;
    const haptics::anatomy::SurfaceMesh nets =
        haptics::anatomy::layer_surface(patient, i, app::patient_layer_look(patient.layers[i].name).stride);
    ASSERT_EQ(vertices.size(), nets.positions.size());
    ASSERT_TRUE(watertight(nets.indices));
    EXPECT_TRUE(watertight(drawn));
    const auto at = [&](uint32_t v) { return Eigen::Vector3d(nets.positions[v].cast<double>()); };
    double area = 0.0;
    for (size_t t = 0; t + 2 < nets.indices.size(); t += 3)
      area +=
          0.5 *
          (at(nets.indices[t + 1]) - at(nets.indices[t])).cross(at(nets.indices[t + 2]) - at(nets.indices[t])).norm();
    const double spacing = patient.layers[i].shape.grid()->spacing();
    EXPECT_NEAR(enclosed_volume(drawn, at), enclosed_volume(nets.indices, at), 0.25 * spacing * area);
    EXPECT_LE(drawn.size(), nets.indices.size());
    drawn_total += drawn.size(), nets_total += nets.indices.size();
    if (patient.layers[i].name != "skin") continue;
    // The strip: every triangle of the surface-nets mesh within 15 mm of the midline, on the back's
    // surface (two strided cells from the grid's box and its walls), is drawn.
    const haptics::SdfGrid& grid = *patient.layers[i].shape.grid();
    const Eigen::Vector3d lo = grid.origin(),
                          hi = lo +
                               spacing * Eigen::Vector3d(grid.nodes()[0] - 1, grid.nodes()[1] - 1, grid.nodes()[2] - 1);
    const double margin = 2.0 * spacing * app::patient_layer_look("skin").stride;
    std::set<std::array<uint32_t, 3>> drawn_triangles;
    for (size_t t = 0; t + 2 < drawn.size(); t += 3) drawn_triangles.insert({drawn[t], drawn[t + 1], drawn[t + 2]});
    size_t strip = 0;
    for (size_t t = 0; t + 2 < nets.indices.size(); t += 3) {
      bool near = true;
      for (size_t k = 0; k < 3; ++k)
        near = near && std::abs(at(nets.indices[t + k]).x() - patient.approaches[0].entry.x()) < 0.015 &&
               (at(nets.indices[t + k]) - lo).minCoeff() > margin && (hi - at(nets.indices[t + k])).minCoeff() > margin;
      if (!near) continue;
      ++strip;
      EXPECT_TRUE(drawn_triangles.count({nets.indices[t], nets.indices[t + 1], nets.indices[t + 2]}));
    }
    EXPECT_GT(strip, 500u);
  }
  EXPECT_LT(10 * drawn_total, nets_total);
}

// The midsagittal plane through the L3-L4 entry, seen from the patient's right (the task's section):
// the cut shows the skin, the fat, the ligaments and the spinous processes (bone) in their colours.
TEST(PatientScenes, TheSectionThroughL3L4ShowsEachStructureInItsColour) {
  const haptics::Scenario scenario = task_scenario("epidural_patient_bmi22");
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene scene(renderer, patient_scene(scenario));
  engine::FrameParams params = scene.frame_params();
  engine::Section section;
  section.point = glm::vec3(0.33f, 0.0f, 0.07f);
  section.normal = glm::vec3(1.0f, 0.0f, 0.0f);
  params.section = section;
  engine::RgbaImage image;
  ASSERT_TRUE(renderer.draw(target, params, &image));
  EXPECT_TRUE(matches_golden(image, "patient_section_l3_l4"));
  // The L3 spinous process's tip, 5 mm into the bone: bone's ivory, not the ligaments' or the skin's.
  const Eigen::Vector3d tip =
      scenario.patient->to_model(scenario.patient->spine.spinous_tips[2]) + scenario.base_in_world;
  const std::optional<glm::vec2> at =
      engine::project_to_screen(params.camera, kSize, glm::vec3(0.33f, float(tip.y()), float(tip.z() - 0.005)));
  ASSERT_TRUE(at);
  const size_t i = (size_t(at->y) * image.width + size_t(at->x)) * 4;
  const glm::vec3 seen(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
  EXPECT_GT(seen.b, 150.0f) << "bone is pale (ivory), the muscle and fat would be red or yellow: " << seen.r << " "
                            << seen.g << " " << seen.b;
  EXPECT_TRUE(device().validation_messages().empty()) << device().validation_messages().front();
}

// The GPU's scan lines against the double-precision reference's, line by line: the same interfaces
// between the same layers, each between the same two samples, and the same shadows. The
// GPU places a crossing by one linear interpolation of φ between its two samples (exact for planes,
// tests/engine/test_ultrasound.cpp) where the reference bisects to a nanometre; a grid's trilinear
// φ curves within its 1 mm cells, and where the beam grazes a face (a lamina's edge, a disc's rim)
// that moves the crossing within its sample interval, 0.13 mm (0.85 of a sample) at the most on
// these patients.
void expect_lines_match(const engine::UltrasoundView& view, const engine::UltrasoundProbe& probe) {
  const double sample_m = probe.depth_m / view.settings().samples;
  expect_scan_lines_match(view.scan_lines(), engine::trace_scan_lines(view.scene(), probe, nullptr, view.settings()),
                          sample_m, sample_m);
}

// Each line's walk evaluates a layer only where its clearance runs out and the sample's layer
// depends on it (docs/RENDERING.md, "How the passes find the layers"): on each shipped patient, in
// the paramedian view on both sides, the midline sagittal view and a transverse view over L3-L4,
// it finds every interface the reference's sample-by-sample walk finds.
TEST(PatientScenes, EachPatientsScanLinesAreTheReferencesInFourViews) {
  for (const char* task : {"epidural_patient_bmi22", "epidural_patient_bmi30", "epidural_patient_bmi40"}) {
    SCOPED_TRACE(task);
    const engine::EchoScene echo = app::echo_scene(task_scenario(task), engine::Scene{});
    const glm::dvec3 entry{0.33, 0.0, 0.07};
    const double tilt = 10.0 * std::numbers::pi / 180.0;
    engine::UltrasoundProbe transverse = app::paramedian_sagittal_oblique_probe(echo, entry, 0.0, 0.0);
    transverse.lateral = {1.0, 0.0, 0.0};  // the array across the spine
    for (const engine::UltrasoundProbe& probe :
         {app::paramedian_sagittal_oblique_probe(echo, entry, 0.012, tilt),
          app::paramedian_sagittal_oblique_probe(echo, entry, -0.012, -tilt),
          app::paramedian_sagittal_oblique_probe(echo, entry, 0.0, 0.0), transverse}) {
      engine::UltrasoundView view(device(), echo);
      view.render(probe, nullptr);
      expect_lines_match(view, probe);
    }
  }
  EXPECT_TRUE(device().validation_messages().empty()) << device().validation_messages().front();
}

// The paramedian sagittal oblique ultrasound view over L3-L4 (5 MHz, 60 mm wide along the spine,
// 80 mm deep, 12 mm to the patient's right tilted 10° toward the midline: design values within
// the 1-2 cm and the medial tilt of the clinical view, app/echo_scene.hpp): the laminae are bright
// steps that hide what lies below them (the sawtooth), the interlaminar windows between them let the
// beam through to the flavum, the dura and the front of the canal. The GPU's lines against the
// double-precision reference, and the image against its golden.
TEST(PatientScenes, TheParamedianUltrasoundShowsTheLaminaeAndTheWindows) {
  const haptics::Scenario scenario = task_scenario("epidural_patient_bmi22");
  const engine::EchoScene echo = app::echo_scene(scenario, engine::Scene{});
  ASSERT_EQ(echo.layers.size(), 12u);
  const engine::UltrasoundProbe probe =
      app::paramedian_sagittal_oblique_probe(echo, {0.33, 0.0, 0.07}, 0.012, 10.0 * std::numbers::pi / 180.0);
  engine::UltrasoundView view(device(), echo);
  view.render(probe, nullptr);
  expect_lines_match(view, probe);
  const std::vector<engine::ScanLine> cpu = engine::trace_scan_lines(echo, probe, nullptr, view.settings());
  const int bone = 10, flavum = 5;
  // Along the array (the spine): where each line first meets bone, or none before its shadow.
  std::vector<double> bone_depth(cpu.size(), -1.0);
  bool window = false;
  for (size_t i = 0; i < cpu.size(); ++i) {
    for (size_t k = 0; k < cpu[i].interfaces.size(); ++k) {
      if (cpu[i].interfaces[k].to_layer == bone && bone_depth[i] < 0.0) bone_depth[i] = cpu[i].interfaces[k].depth_m;
      window |= cpu[i].interfaces[k].to_layer == flavum;
    }
  }
  // The sawtooth: runs of lines on bone (the laminae) alternate with runs whose bone lies deeper or
  // not at all (the windows): at least two laminae with a window between them.
  int steps = 0;
  for (size_t i = 1; i < cpu.size(); ++i)
    if (bone_depth[i - 1] > 0.0 && bone_depth[i] > 0.0 ? std::abs(bone_depth[i] - bone_depth[i - 1]) > 0.005
                                                       : (bone_depth[i - 1] > 0.0) != (bone_depth[i] > 0.0))
      ++steps;
  EXPECT_GE(steps, 3);
  EXPECT_TRUE(window) << "a window lets the beam reach the flavum";
  EXPECT_TRUE(matches_golden(engine::to_picture(view.image(), probe), "ultrasound_patient_paramedian"));
  EXPECT_TRUE(device().validation_messages().empty()) << device().validation_messages().front();
}

}  // namespace
}  // namespace needle::test
