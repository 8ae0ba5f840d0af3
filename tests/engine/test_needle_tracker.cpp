// Snapshots of the haptic loop become needle loads: the pose from tip and quaternion, the entry
// point remembered from the first snapshot in tissue until the needle leaves it, and the tissue
// pushed opposite to the lateral constraint force.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/needle_tracker.hpp"

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
  engine::NeedleTracker tracker;
  engine::NeedleLoad load = tracker.update(snapshot(haptics::ContactState::kFree, {0.1, 0.2, 0.3}, M_PI / 2));
  EXPECT_EQ(load.contact, engine::NeedleContact::Free);
  EXPECT_EQ(load.tip, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_NEAR(load.axis.x, 0.0, 1e-12);  // +x turned a quarter about z is +y
  EXPECT_NEAR(load.axis.y, 1.0, 1e-12);
}

TEST(NeedleTracker, EntryIsWhereTheNeedleFirstWasInTissueUntilItLeaves) {
  engine::NeedleTracker tracker;
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
  engine::NeedleTracker tracker;
  // Needle along +x; the constraint pushes it along -y (and a little along its axis).
  engine::NeedleLoad load = tracker.update(snapshot(haptics::ContactState::kTissue, {0.33, 0, 0}, 0, {0.2, -0.7, 0}));
  EXPECT_NEAR(load.lateral_force_on_tissue_N.x, 0.0, 1e-12);
  EXPECT_NEAR(load.lateral_force_on_tissue_N.y, 0.7, 1e-12);
}

TEST(NeedleTracker, LateralMultipliersActAlongTheNeedleFramesYAndZ) {
  engine::NeedleTracker tracker;
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
  engine::NeedleTracker tracker;
  engine::NeedleLoad load = tracker.update(snapshot(haptics::ContactState::kRigidSurface, {0.3, 0, 0}, 0, {-2.0, 0, 0}));
  EXPECT_EQ(load.contact, engine::NeedleContact::Touching);
  EXPECT_EQ(load.surface_normal, glm::dvec3(-1, 0, 0));
  EXPECT_DOUBLE_EQ(load.normal_force_N, 2.0);
}

}  // namespace
}  // namespace needle::test
