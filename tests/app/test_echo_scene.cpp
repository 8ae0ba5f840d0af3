// What the ultrasound images of a scenario (app/echo_scene.hpp): the haptic tissue model's layers
// moved back to the world frame with their tissue files' acoustics, and a probe set on the skin.
#include <gtest/gtest.h>

#include "app/echo_scene.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

engine::EchoScene block() {
  return app::echo_scene(haptics::load_scenario((source_dir() / "assets/scenarios/tissue_block_layers.json").string()),
                         engine::Scene{});
}

TEST(EchoScene, TheLayeredBlocksLayersAreWhereItsScenarioPutsThemWithTheirAcoustics) {
  const engine::EchoScene scene = block();
  ASSERT_EQ(scene.layers.size(), 4u);
  EXPECT_EQ(scene.layers[0].name, "skin");
  EXPECT_DOUBLE_EQ(scene.layers[0].material.impedance_MRayl, 1.99);  // assets/tissues/skin.json
  EXPECT_DOUBLE_EQ(scene.layers[3].material.impedance_MRayl, 6.50);  // bone.json
  EXPECT_FALSE(scene.deformation.has_value());                        // no deformable tissue in an empty scene
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

}  // namespace
}  // namespace needle::test
