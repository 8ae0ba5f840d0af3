// The dimple of a layered tissue comes from the tissue model's own surface deflection (
// "visual agreement"): the needle tracker reads ToolSnapshot::tissue, and the deformation field it
// feeds moves the skin under the tip by the deflection that makes the force. Checked on
// constructed snapshots, then on the scripted hand of tissue_block_layers pressing the layered
// block's skin in closed loop (the sim device and the controller step as the loop runs them),
// against the block's geometry (skin top 70 mm above the table) and the skin's closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "app/needle_tracker.hpp"
#include "app/replay_cursor.hpp"
#include "engine/scene.hpp"
#include "haptics/realtime/sim_session.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

constexpr double kSkinTop_m = 0.07;

// The needle pointing straight down (+x turned onto −z: a quarter turn about y), its tip at
// `tip_z` over the block's entry; the skin met at rest there and pressed by `deflection_m`.
haptics::ToolSnapshot down(double tip_z, int surface_layer, double deflection_m, uint32_t punctured) {
  haptics::ToolSnapshot s;
  s.needle_tip_m[0] = 0.33;
  s.needle_tip_m[2] = tip_z;
  s.needle_orientation[0] = std::sqrt(0.5);
  s.needle_orientation[2] = std::sqrt(0.5);
  s.contact = punctured != 0 ? haptics::ContactState::kTissue : haptics::ContactState::kFree;
  s.tissue.surface_layer = surface_layer;
  s.tissue.deflection_m = deflection_m;
  s.tissue.punctured_layers = punctured;
  if (surface_layer >= 0) {
    s.tissue.surface_point_m[0] = 0.33;
    s.tissue.surface_point_m[2] = kSkinTop_m;
  }
  return s;
}

TEST(LayeredDimple, PressingTheSkinTouchesAtThePhysicsRestPoint) {
  app::NeedleTracker tracker(app::TissueKind::Layered);
  const engine::NeedleLoad load = tracker.update(down(kSkinTop_m - 0.004, 0, 0.004, 0));
  EXPECT_EQ(load.contact, engine::NeedleContact::Touching);
  EXPECT_EQ(load.surface_point, glm::dvec3(0.33, 0.0, kSkinTop_m));
  EXPECT_NEAR(load.tip.z, kSkinTop_m - 0.004, 1e-15);
  EXPECT_NEAR(load.surface_normal.z, 1.0, 1e-12);  // facing the needle: up
  // The thesis's tissue reads the contact state alone: the same snapshot (contact Free) is free.
  EXPECT_EQ(app::NeedleTracker().update(down(kSkinTop_m - 0.004, 0, 0.004, 0)).contact, engine::NeedleContact::Free);
}

TEST(LayeredDimple, AfterThePopTheEntryIsWhereTheSkinGaveWayNotTheTip) {
  app::NeedleTracker tracker(app::TissueKind::Layered);
  tracker.update(down(kSkinTop_m - 0.006, 0, 0.006, 0));
  // The tick the skin gives way names it; the tip then jumps 3 mm on into the fat.
  EXPECT_EQ(tracker.update(down(kSkinTop_m - 0.0061, 0, 0.0061, 1)).surface_point, glm::dvec3(0.33, 0.0, kSkinTop_m));
  const engine::NeedleLoad after = tracker.update(down(kSkinTop_m - 0.009, -1, 0.0, 3));
  EXPECT_EQ(after.contact, engine::NeedleContact::Inserted);
  EXPECT_EQ(after.surface_point, glm::dvec3(0.33, 0.0, kSkinTop_m));
  // A deeper surface pressed later does not move the entry.
  EXPECT_EQ(tracker.update(down(0.055, 2, 0.003, 3)).surface_point, glm::dvec3(0.33, 0.0, kSkinTop_m));
  // Withdrawn: free, and a new press starts over.
  EXPECT_EQ(tracker.update(down(0.08, -1, 0.0, 0)).contact, engine::NeedleContact::Free);
}

TEST(LayeredDimple, APopBetweenSnapshotsStillEntersWhereTheSkinWasPressed) {
  app::NeedleTracker tracker(app::TissueKind::Layered);
  tracker.update(down(kSkinTop_m - 0.005, 0, 0.005, 0));
  const engine::NeedleLoad after = tracker.update(down(kSkinTop_m - 0.01, -1, 0.0, 3));  // the pop tick unseen
  EXPECT_EQ(after.surface_point, glm::dvec3(0.33, 0.0, kSkinTop_m));
}

TEST(LayeredDimple, TheReplayMapsTheSameWayAtTheScrubbedTime) {
  std::vector<haptics::ToolSnapshot> states = {down(0.075, -1, 0.0, 0), down(kSkinTop_m - 0.003, 0, 0.003, 0),
                                               down(kSkinTop_m - 0.006, 0, 0.006, 1),
                                               down(kSkinTop_m - 0.009, -1, 0.0, 3)};
  for (size_t k = 0; k < states.size(); ++k) states[k].time_s = 0.1 * double(k);
  app::ReplayCursor cursor(app::TissueKind::Layered);
  EXPECT_EQ(cursor.at(states, 0.35).surface_point, glm::dvec3(0.33, 0.0, kSkinTop_m));
  const engine::NeedleLoad pressed = cursor.at(states, 0.15);  // backwards: fed again from the start
  EXPECT_EQ(pressed.contact, engine::NeedleContact::Touching);
  EXPECT_NEAR(pressed.tip.z, kSkinTop_m - 0.003, 1e-15);
}

// The shipped layered scenario's hand (5 to 20 s: from the skin down 35 mm), until 1 s after the
// skin's pop. Every tick the tip tents the skin, the skin's rest point under the tip, moved by the
// deformation field of the scene the layered target renders, lies on the tip, displaced along
// the needle by the model's deflection; at the pop the entry is that rest point.
TEST(LayeredDimple, TheScriptedHandsDimpleIsThePhysicsDeflection) {
  const engine::Scene scene = engine::load_scene(test::source_dir() / "assets/scenes/tissue_block_task.json");
  ASSERT_TRUE(scene.assets.at(0).deformation.has_value());
  const engine::TissueParams tissue = *scene.assets[0].deformation;
  haptics::SimSession sim(test::source_dir().string() + "/assets/scenarios/tissue_block_layers.json", 500.0);
  sim.device().open();
  const double dt = sim.scenario().period_s;
  haptics::DeviceReading reading;
  haptics::DeviceCommand command;
  haptics::ToolSnapshot s;
  app::NeedleTracker tracker(app::TissueKind::Layered);
  int pressed_ticks = 0;
  double deepest = 0.0, worst_along = 0.0, worst_onto_tip = 0.0;
  glm::dvec3 last_pressed(0.0);
  std::optional<double> popped_at;
  for (int k = 0; k * dt < 20.0 && !(popped_at && s.time_s > *popped_at + 1.0); ++k) {
    sim.device().read(reading);
    sim.step().step(reading, dt, command, s);
    sim.device().write(command);
    const engine::NeedleLoad load = tracker.update(s);
    const haptics::TissueSnapshot& t = s.tissue;
    const auto at = [&] { return "t = " + std::to_string(s.time_s) + " s"; };
    if (t.punctured_layers == 0 && t.surface_layer == 0) {
      ++pressed_ticks;
      ASSERT_EQ(load.contact, engine::NeedleContact::Touching) << at();
      last_pressed = glm::dvec3(t.surface_point_m[0], t.surface_point_m[1], t.surface_point_m[2]);
      EXPECT_EQ(load.surface_point, last_pressed) << at();
      EXPECT_NEAR(last_pressed.z, kSkinTop_m, 5e-4) << at();  // met at rest on the skin
      const glm::dvec3 moved = engine::deformed_point(load, tissue, last_pressed);
      const double along = glm::dot(moved - last_pressed, load.axis);
      EXPECT_NEAR(along, t.deflection_m, 1e-5) << at();
      worst_along = std::max(worst_along, std::abs(along - t.deflection_m));
      worst_onto_tip = std::max(worst_onto_tip, glm::length(moved - load.tip));
      deepest = std::max(deepest, t.deflection_m);
    } else if ((t.punctured_layers & 1u) != 0) {
      ASSERT_EQ(load.contact, engine::NeedleContact::Inserted) << at();
      ASSERT_GT(pressed_ticks, 0) << at();
      EXPECT_EQ(load.surface_point, last_pressed) << at();  // the physics' surface point at the puncture
      if (!popped_at) popped_at = s.time_s;
    }
  }
  ASSERT_TRUE(popped_at.has_value());
  std::printf(
      "skin pressed for %d ticks, deepest dimple %.3f mm, popped at %.3f s; |along - deflection| <= %.2e m, "
      "|moved - tip| <= %.2e m\n",
      pressed_ticks, 1e3 * deepest, *popped_at, worst_along, worst_onto_tip);
  // The skin gives way at k1 d + k2 d^2 = F_p (assets/tissues/skin.json: 100 N/m, 475000 N/m², 1.22 N):
  // d = 1.50 mm.
  const double closed_form = (-100.0 + std::sqrt(100.0 * 100.0 + 4.0 * 475000.0 * 1.22)) / (2.0 * 475000.0);
  EXPECT_NEAR(deepest, closed_form, 1e-4);
  EXPECT_LT(worst_onto_tip, 1e-9);  // the dimple's floor is the tip
}

}  // namespace
}  // namespace needle::test
