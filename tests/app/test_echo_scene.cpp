// What the ultrasound images of a scenario (app/echo_scene.hpp): the haptic tissue model's layers
// moved back to the world frame with their tissue files' acoustics, and a probe set on the skin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "app/echo_scene.hpp"
#include "engine/gpu_device.hpp"
#include "tests/engine/image_compare.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

engine::EchoScene scenario_echo(const char* name) {
  return app::echo_scene(haptics::load_scenario((source_dir() / "assets/scenarios" / name).string()), engine::Scene{});
}
engine::EchoScene block() { return scenario_echo("tissue_block_layers.json"); }

TEST(EchoScene, TheLayeredBlocksLayersAreWhereItsScenarioPutsThemWithTheirAcoustics) {
  const engine::EchoScene scene = block();
  ASSERT_EQ(scene.layers.size(), 4u);
  EXPECT_EQ(scene.layers[0].name, "skin");
  EXPECT_DOUBLE_EQ(scene.layers[0].material.impedance_MRayl, 1.99);  // assets/tissues/skin.json
  EXPECT_DOUBLE_EQ(scene.layers[3].material.impedance_MRayl, 6.50);  // bone.json
  EXPECT_FALSE(scene.deformation.has_value());                       // no deformable tissue in an empty scene
  // A beam straight down the block's centre meets skin at z = 0.07 m (the file's world frame,
  // though the tissue model holds it in the robots' base frame), fat 2 mm down, muscle 12, bone 40.
  engine::UltrasoundProbe probe;
  probe.position = {0.33, 0.0, 0.075};
  probe.depth_m = 0.06;
  const engine::ScanLine line = engine::trace_scan_lines(scene, probe, nullptr, {1, 6000})[0];
  ASSERT_EQ(line.interfaces.size(), 5u);
  const double expected[] = {0.005, 0.007, 0.017, 0.045, 0.055};
  for (size_t k = 0; k < 5; ++k) EXPECT_NEAR(line.interfaces[k].depth_m, expected[k], 1e-6) << "interface " << k;
  EXPECT_EQ(line.interfaces[4].to_layer, -1);  // out of the bone's bottom into gel
}

TEST(EchoScene, AProbeLowersOntoTheSkin) {
  const engine::EchoScene scene = block();
  engine::UltrasoundProbe probe;
  const engine::UltrasoundProbe on = engine::probe_on_skin(scene, probe, {0.31, 0.01, 0.2});
  EXPECT_NEAR(on.position.z, 0.07, 1e-6);
  EXPECT_DOUBLE_EQ(on.position.x, 0.31);
  EXPECT_DOUBLE_EQ(on.position.y, 0.01);
  // Beside the block the beam meets nothing: the probe stays where it was.
  EXPECT_EQ(engine::probe_on_skin(scene, probe, {0.5, 0.0, 0.2}).position, probe.position);
}

// A needle entering the skin (z = 0.07 m) at `entry`, `angle_deg` below the horizontal, turned
// `yaw_deg` about the vertical from +x (the probes' array), its tip `depth_m` along it.
engine::NeedleLoad needle(glm::dvec3 entry, double angle_deg, double yaw_deg, double depth_m) {
  const double a = angle_deg * M_PI / 180.0, y = yaw_deg * M_PI / 180.0;
  engine::NeedleLoad n;
  n.contact = engine::NeedleContact::Inserted;
  n.axis = {std::cos(a) * std::cos(y), std::cos(a) * std::sin(y), -std::sin(a)};
  n.tip = entry + depth_m * n.axis;
  n.surface_point = entry;
  return n;
}

// The images of the layered block and the epidural section with the needle in the image plane
// (a bright line with its reverberation tail) and across it (a bright dot), against goldens
// (tests/engine/image_compare.hpp's tolerance: 0.2 % of pixels may differ by more than 8 counts),
// under the validation layer.
TEST(EchoScene, GoldenImagesOfTheBlockAndTheEpiduralNeedleInAndOutOfPlane) {
  engine::GpuDevice device(engine::DeviceOptions{.validation = true, .announce_device = false});
  engine::UltrasoundProbe block_probe;  // 7.5 MHz, 50 mm deep, 40 mm wide, on the block's skin
  block_probe.position = {0.33, 0.0, 0.07};
  engine::UltrasoundProbe epidural_probe = block_probe;  // 5 MHz, 80 mm deep, 50 mm wide
  epidural_probe.depth_m = 0.08;
  epidural_probe.width_m = 0.05;
  epidural_probe.frequency_MHz = 5.0;
  struct Case {
    const char* golden;
    const char* scenario;
    engine::UltrasoundProbe probe;
    engine::NeedleLoad needle;
  };
  const Case cases[] = {
      {"ultrasound_block_in_plane", "tissue_block_layers.json", block_probe,
       needle({0.305, 0.0, 0.07}, 30.0, 0.0, 0.04)},
      {"ultrasound_block_out_of_plane", "tissue_block_layers.json", block_probe,
       needle({0.335, -0.02, 0.07}, 45.0, 90.0, 0.032)},
      {"ultrasound_epidural_in_plane", "lumbar_epidural.json", epidural_probe,
       needle({0.30, 0.0, 0.07}, 40.0, 0.0, 0.06)},
      {"ultrasound_epidural_out_of_plane", "lumbar_epidural.json", epidural_probe,
       needle({0.335, -0.03, 0.07}, 45.0, 90.0, 0.05)},
  };
  for (const Case& c : cases) {
    engine::UltrasoundView view(device, scenario_echo(c.scenario));
    view.render(c.probe, &c.needle);
    EXPECT_TRUE(matches_golden(view.image(), c.golden));
    // The needle is in the image where the reference puts it: at its wall's depth each line it
    // crosses is brighter than 95 % of that line's samples (speckle, interfaces and all).
    const std::vector<engine::ScanLine> lines =
        engine::trace_scan_lines(view.scene(), c.probe, &c.needle, view.settings());
    const engine::RgbaImage image = view.image();
    size_t hit = 0, bright = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
      if (std::isinf(lines[i].needle_depth_m)) continue;
      ++hit;
      std::vector<int> column;
      for (size_t j = 0; j < image.height; ++j) column.push_back(image.pixels[(j * image.width + i) * 4]);
      const long row = std::lround(lines[i].needle_depth_m / c.probe.depth_m * image.height - 0.5);
      int wall = 0;
      for (long j = std::max(0L, row - 1); j <= std::min(long(image.height) - 1, row + 1); ++j)
        wall = std::max(wall, column[size_t(j)]);
      std::nth_element(column.begin(), column.begin() + long(0.95 * column.size()), column.end());
      if (wall > column[size_t(0.95 * column.size())]) ++bright;
    }
    EXPECT_GT(hit, 0u) << c.golden;
    EXPECT_GE(double(bright), 0.8 * double(hit)) << c.golden;
  }
  for (const std::string& m : device.validation_messages()) ADD_FAILURE() << "Vulkan validation " << m;
}

}  // namespace
}  // namespace needle::test
