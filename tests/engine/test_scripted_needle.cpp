// The scripted stand-in follows the thesis's nonholonomic experiment: the tip never jumps
// (over the whole period, across the wrap), it stays put while the needle pivots, and the
// contact goes free -> touching -> inserted -> free in that order.
#include <gtest/gtest.h>

#include "engine/scripted_needle.hpp"

namespace needle::test {
namespace {

using engine::NeedleContact;

TEST(ScriptedNeedle, TipMovesContinuouslyAcrossThePeriod) {
  engine::ScriptedSphere sphere;
  const double dt = 0.001;
  glm::dvec3 previous = engine::scripted_needle(sphere, -dt).tip;
  double fastest = 0.0;
  for (double t = 0.0; t <= engine::kScriptPeriod_s + dt; t += dt) {
    glm::dvec3 tip = engine::scripted_needle(sphere, t).tip;
    fastest = std::max(fastest, glm::length(tip - previous) / dt);
    previous = tip;
  }
  EXPECT_LT(fastest, 0.2) << "m/s: a hand-held needle, not a jump";
}

TEST(ScriptedNeedle, TipStaysPutWhileThePivotTurnsTheAxis) {
  engine::ScriptedSphere sphere;
  engine::NeedleLoad start = engine::scripted_needle(sphere, 5.0), end = engine::scripted_needle(sphere, 8.0);
  EXPECT_LT(glm::length(end.tip - start.tip), 1e-12);
  EXPECT_NEAR(glm::degrees(std::acos(glm::dot(start.axis, end.axis))), 45.0, 1e-9);
}

TEST(ScriptedNeedle, ContactPhasesComeInOrder) {
  engine::ScriptedSphere sphere;
  std::vector<NeedleContact> phases;
  for (double t = 0.0; t < engine::kScriptPeriod_s; t += 0.01) {
    NeedleContact c = engine::scripted_needle(sphere, t).contact;
    if (phases.empty() || phases.back() != c) phases.push_back(c);
  }
  EXPECT_EQ(phases, (std::vector<NeedleContact>{NeedleContact::Free, NeedleContact::Touching, NeedleContact::Inserted,
                                                NeedleContact::Free}));
}

}  // namespace
}  // namespace needle::test
