// Snapshots of the haptic loop become needle loads: the pose from tip and quaternion, the entry
// point remembered from the first snapshot in tissue until the needle leaves it, and the tissue
// pushed opposite to the lateral constraint force.
#include <gtest/gtest.h>

#include <cmath>

#include "app/needle_tracker.hpp"
#include "app/replay_cursor.hpp"

namespace needle::test {
namespace {

haptics::ToolSnapshot snapshot(haptics::ContactState contact, glm::dvec3 tip, double yaw_rad, glm::dvec3 force = {}) {
  haptics::ToolSnapshot s;
  s.contact = contact;
  for (int i = 0; i < 3; ++i) {
    s.needle_tip_m[i] = tip[i];
    s.environment_force_n[i] = force[i];
  }
  // A rotation about z by yaw: quaternion (cos(yaw/2), 0, 0, sin(yaw/2)).
  s.needle_orientation[0] = std::cos(yaw_rad / 2);
  s.needle_orientation[3] = std::sin(yaw_rad / 2);
  return s;
}

TEST(NeedleTracker, PoseComesFromTipAndQuaternion) {
  app::NeedleTracker tracker;
  engine::NeedleLoad load = tracker.update(snapshot(haptics::ContactState::kFree, {0.1, 0.2, 0.3}, M_PI / 2));
  EXPECT_EQ(load.contact, engine::NeedleContact::Free);
  EXPECT_EQ(load.tip, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_NEAR(load.axis.x, 0.0, 1e-12);  // +x turned a quarter about z is +y
  EXPECT_NEAR(load.axis.y, 1.0, 1e-12);
}

TEST(NeedleTracker, EntryIsWhereTheNeedleFirstWasInTissueUntilItLeaves) {
  app::NeedleTracker tracker;
  tracker.update(snapshot(haptics::ContactState::kFree, {0.29, 0, 0}, 0));
  engine::NeedleLoad first = tracker.update(snapshot(haptics::ContactState::kTissue, {0.301, 0, 0}, 0));
  engine::NeedleLoad deeper = tracker.update(snapshot(haptics::ContactState::kTissue, {0.33, 0, 0}, 0.3));
  EXPECT_EQ(first.surface_point, glm::dvec3(0.301, 0, 0));
  EXPECT_EQ(deeper.surface_point, glm::dvec3(0.301, 0, 0));
  EXPECT_EQ(deeper.contact, engine::NeedleContact::Inserted);
  tracker.update(snapshot(haptics::ContactState::kFree, {0.2, 0, 0}, 0));
  engine::NeedleLoad again = tracker.update(snapshot(haptics::ContactState::kTissue, {0.305, 0.01, 0}, 0));
  EXPECT_EQ(again.surface_point, glm::dvec3(0.305, 0.01, 0));
}

TEST(NeedleTracker, TissueTakesTheOppositeOfTheLateralConstraintForce) {
  app::NeedleTracker tracker;
  // Needle along +x; the constraint pushes it along -y (and a little along its axis).
  engine::NeedleLoad load = tracker.update(snapshot(haptics::ContactState::kTissue, {0.33, 0, 0}, 0, {0.2, -0.7, 0}));
  EXPECT_NEAR(load.lateral_force_on_tissue_N.x, 0.0, 1e-12);
  EXPECT_NEAR(load.lateral_force_on_tissue_N.y, 0.7, 1e-12);
}

TEST(NeedleTracker, LateralMultipliersActAlongTheNeedleFramesYAndZ) {
  app::NeedleTracker tracker;
  // Needle turned a quarter about z: x5 = +y, y5 = -x, z5 = +z.
  haptics::ToolSnapshot s = snapshot(haptics::ContactState::kTissue, {0.33, 0, 0}, M_PI / 2);
  s.multiplier_count = 2;
  s.multipliers[0] = 0.5;   // along y5
  s.multipliers[1] = -0.2;  // along z5
  engine::NeedleLoad load = tracker.update(s);
  EXPECT_NEAR(load.lateral_force_on_tissue_N.x, 0.5, 1e-12);  // −(0.5 · (−x))
  EXPECT_NEAR(load.lateral_force_on_tissue_N.y, 0.0, 1e-12);
  EXPECT_NEAR(load.lateral_force_on_tissue_N.z, 0.2, 1e-12);
}

TEST(NeedleTracker, RigidContactTouchesAlongTheSurfaceReaction) {
  app::NeedleTracker tracker;
  engine::NeedleLoad load =
      tracker.update(snapshot(haptics::ContactState::kRigidSurface, {0.3, 0, 0}, 0, {-2.0, 0, 0}));
  EXPECT_EQ(load.contact, engine::NeedleContact::Touching);
  EXPECT_EQ(load.surface_normal, glm::dvec3(-1, 0, 0));
  EXPECT_DOUBLE_EQ(load.normal_force_N, 2.0);
}

TEST(ReplayCursor, ScrubbingBackFeedsTheTrackerFromTheStart) {
  // In tissue from 0.1 s at two different entry points, out in between: the entry the needle
  // load shows at 0.35 s is the second one, whether reached forwards or after going further.
  auto at = [](double t, double x, haptics::ContactState c) {
    haptics::ToolSnapshot s;
    s.time_s = t;
    s.needle_tip_m[0] = x;
    s.contact = c;
    return s;
  };
  using haptics::ContactState;
  const std::vector<haptics::ToolSnapshot> states = {
      at(0.0, 0.0, ContactState::kFree), at(0.1, 0.01, ContactState::kTissue), at(0.2, 0.02, ContactState::kFree),
      at(0.3, 0.03, ContactState::kTissue), at(0.4, 0.04, ContactState::kTissue)};
  app::ReplayCursor cursor;
  EXPECT_DOUBLE_EQ(cursor.at(states, 0.15).surface_point.x, 0.01);
  EXPECT_DOUBLE_EQ(cursor.at(states, 0.45).surface_point.x, 0.03);
  EXPECT_DOUBLE_EQ(cursor.at(states, 0.45).tip.x, 0.04);
  const engine::NeedleLoad back = cursor.at(states, 0.15);  // backwards: fed again from the start
  EXPECT_DOUBLE_EQ(back.surface_point.x, 0.01);
  EXPECT_DOUBLE_EQ(back.tip.x, 0.01);
  EXPECT_EQ(cursor.at(states, -1.0).contact, engine::NeedleContact::Free);  // before the first: the first
}

}  // namespace
}  // namespace needle::test
