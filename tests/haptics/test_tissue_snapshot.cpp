// The layered tissue in the published ToolSnapshot: the scripted hand of
// tissue_block_layers pushed on down to the bone plate, through the sim device and the
// controller step as the loop runs them. The snapshot's layer, punctured set, dimple and bone
// contact are checked against the block's geometry (skin 68-70 mm, fat 58-68, muscle 30-58, bone
// 20-30 mm above the table, the needle vertical), not against the tissue model's own numbers.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>

#include "haptics/realtime/sim_session.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::haptics {
namespace {

struct Slab {
  double bottom_z, top_z;
};
constexpr Slab kBlock[] = {{0.068, 0.070}, {0.058, 0.068}, {0.030, 0.058}, {0.020, 0.030}};  // skin, fat, muscle, bone
constexpr int kBone = 3;
constexpr double kTrack = 2e-3;

// The shipped scenario with its hand going on to 18 mm below the bone's top, held, withdrawn (with the
// master held on the needle by the lateral spring the tip no longer runs ahead of the hand: 10 mm
// below did not reach the bone through the muscle's friction).
Scenario down_to_bone() {
  Scenario s = load_scenario(test::source_dir().string() + "/assets/scenarios/tissue_block_layers.json");
  const nlohmann::json hand = nlohmann::json::parse(R"({
    "mass_kg": 0.554, "damping_Ns_per_m": 6.45, "stiffness_N_per_m": 135.0, "grip_length_m": 0.05,
    "waypoints": [
      {"t": 0.0, "p": [0.3476, 0.024, 0.1328], "dir": [0.724, 0.479, -0.496]},
      {"t": 3.0, "p": [0.33, 0.0, 0.08], "dir": [0.0, 0.0, -1.0]},
      {"t": 5.0, "p": [0.33, 0.0, 0.07], "dir": [0.0, 0.0, -1.0]},
      {"t": 22.0, "p": [0.33, 0.0, 0.012], "dir": [0.0, 0.0, -1.0]},
      {"t": 25.0, "p": [0.33, 0.0, 0.012], "dir": [0.0, 0.0, -1.0]},
      {"t": 35.0, "p": [0.33, 0.0, 0.09], "dir": [0.0, 0.0, -1.0]}]})");
  const OperatorHand read = read_hand(hand, "test", "/hand", s.base_in_world);
  s.hand = read.impedance;
  s.trajectory = read.trajectory;
  s.duration_s = 38.0;
  return s;
}

TEST(TissueSnapshot, TheScriptedHandThroughTheLayeredBlockDownToBone) {
  SimSession sim(down_to_bone(), 500.0);
  sim.device().open();
  const double dt = sim.scenario().period_s;
  DeviceReading reading;
  DeviceCommand command;
  ToolSnapshot s;
  int deepest = -1, bone_ticks = 0;
  double bone_push = 0.0, worst_above = 0.0, z_before = 0.0;
  double advance_force = 0.0, withdraw_force = 0.0;
  int advance_ticks = 0, withdraw_ticks = 0;
  for (int k = 0; k * dt < sim.scenario().duration_s; ++k) {
    sim.device().read(reading);
    sim.step().step(reading, dt, command, s);
    sim.device().write(command);
    const TissueSnapshot& t = s.tissue;
    const double z = s.needle_tip_m[2];
    const auto at = [&] { return "t = " + std::to_string(s.time_s) + " s, tip z = " + std::to_string(z); };
    ASSERT_GE(t.tip_layer, -1);
    ASSERT_LT(t.tip_layer, kBone) << at();  // bone holds no tip: it is never entered
    if (t.tip_layer >= 0) {
      const Slab& layer = kBlock[t.tip_layer];
      // It passed the layer's top surface (the track measures along the needle, which leans a
      // little: within kTrack of the geometry) and is at most a dimple beyond the bottom of the
      // deepest layer passed (the tip's, or the next one's in the tick a pop carries it there).
      EXPECT_LE(z, layer.top_z + kTrack) << at();
      const double tent = t.surface_layer >= 0 ? t.deflection_m : 0.0;
      EXPECT_GE(z, kBlock[std::bit_width(t.punctured_layers) - 1].bottom_z - tent - kTrack) << at();
      worst_above = std::max(worst_above, z - layer.top_z);
      deepest = std::max(deepest, t.tip_layer);
    } else {
      EXPECT_LE(t.surface_layer, 0) << at();  // outside, or still tenting the skin
      EXPECT_GE(z, kBlock[0].top_z - (t.surface_layer == 0 ? t.deflection_m : 0.0) - 2e-4) << at();
    }
    // Straight down through a stack: on the way in the punctured set is every layer down to the
    // tip's, or to the next one in the tick a pop carries the tip onto it.
    if (s.time_s < 22.0 && t.tip_layer >= 0)
      EXPECT_TRUE(t.punctured_layers == (2u << t.tip_layer) - 1u || t.punctured_layers == (4u << t.tip_layer) - 1u)
          << at() << ", punctured " << t.punctured_layers << ", layer " << t.tip_layer;
    if (z > kBlock[0].top_z + 2e-3) EXPECT_EQ(t.punctured_layers, 0u) << at();  // out: the track is cleared
    if (t.surface_layer >= 0) {
      // The dimple: how far the tip went past where it met the surface, along the needle.
      const auto axis = needle_axis(s);
      double along = 0.0;
      for (int i = 0; i < 3; ++i) along += (s.needle_tip_m[i] - t.surface_point_m[i]) * axis[i];
      EXPECT_NEAR(t.deflection_m, along, 5e-4) << at();
      // The skin is met at rest; a deeper surface where the tented one above carried it to.
      EXPECT_LE(t.surface_point_m[2], kBlock[t.surface_layer].top_z + 5e-4) << at();
      if (t.surface_layer == 0) EXPECT_NEAR(t.surface_point_m[2], kBlock[0].top_z, 5e-4) << at();
    }
    if (t.bone_layer >= 0) {
      ++bone_ticks;
      EXPECT_EQ(t.bone_layer, kBone) << at();
      EXPECT_NEAR(z, kBlock[kBone].top_z, 3e-3) << at();  // the penalty (3.15) is 800 N/m: 2.4 N presses 3 mm
      EXPECT_LE(t.bone_force_n[2], 0.0) << at();          // the tool presses the bone down (or, touching, not yet)
      bone_push = std::min(bone_push, t.bone_force_n[2]);
      for (int i = 0; i < 3; ++i) EXPECT_EQ(t.bone_force_n[i], s.environment_force_n[i]) << at();
    } else {
      for (int i = 0; i < 3; ++i) EXPECT_EQ(t.bone_force_n[i], 0.0) << at();
    }
    // In the muscle, clear of the bone, moving faster than the stick band: friction opposes the motion.
    const double rising = (z - z_before) / dt;
    const bool in_muscle = t.tip_layer == 2 && z > kBlock[kBone].top_z + 1e-3;
    if (in_muscle && rising < -2e-3) advance_force += t.axial_force_N, ++advance_ticks;
    if (in_muscle && rising > 2e-3) withdraw_force += t.axial_force_N, ++withdraw_ticks;
    z_before = z;
  }
  std::printf("tip above its layer's top by at most %.2f mm\n", 1e3 * worst_above);
  EXPECT_EQ(deepest, 2);       // the muscle, then the bone's surface
  EXPECT_GT(bone_ticks, 500);  // pressed on it for more than a second
  EXPECT_LT(bone_push, -0.5);  // the hand's spring, 18 mm below the bone's top, less the muscle's friction
  ASSERT_GT(advance_ticks, 0);
  ASSERT_GT(withdraw_ticks, 0);
  EXPECT_GT(advance_force / advance_ticks, 0.1);     // the muscle resists the advance
  EXPECT_LT(withdraw_force / withdraw_ticks, -0.1);  // and holds the shaft on the way out
  EXPECT_EQ(s.tissue.tip_layer, -1);                 // withdrawn at the end
  EXPECT_EQ(s.tissue.punctured_layers, 0u);
}

}  // namespace
}  // namespace needle::haptics
