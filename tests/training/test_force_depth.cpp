// The force–depth plot's data (training/sessions/force_depth.hpp) on hand-built states: a needle
// leaning 30 degrees from the vertical tents the skin, punctures it, crosses into the fat, is held,
// withdrawn out of the tissue and inserted again. Depths are along the needle from where it first
// met the tissue, in mm; the punctures are the session scorer's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tool_states.hpp"
#include "training/sessions/force_depth.hpp"

namespace needle::training {
namespace {
using haptics::ContactState;

Task block() {
  Task t;
  t.name = "block";
  t.layers = {{"skin", false, 1.5}, {"fat", false, 0.0}, {"bone", true, 0.0}};
  Step s;
  s.id = "in";
  s.condition.type = ConditionType::kTipInLayer;
  s.condition.layer = 1;
  s.condition.hold_s = 100.0;  // never completes: every state falls in this step
  t.steps = {s};
  return t;
}

constexpr double kPitch = std::numbers::pi / 3;  // the needle along (cos 60, 0, -sin 60): 30 degrees off the vertical
const Vec3 kAxis{std::cos(kPitch), 0.0, -std::sin(kPitch)};
const Vec3 kStart{0.01, 0.0, 0.07};

// The tip `along` metres down the needle's line from kStart, with the tissue as given.
haptics::TickSample at(double t, double along, int surface, int layer, uint32_t passed, double force) {
  const Vec3 p = kStart + along * kAxis;
  haptics::ToolSnapshot s = test::state(t, p, kPitch, layer >= 0 ? ContactState::kTissue : ContactState::kFree);
  s.tissue.surface_layer = surface;
  s.tissue.tip_layer = layer;
  s.tissue.punctured_layers = passed;
  s.tissue.axial_force_N = force;
  return test::sample(s);
}

std::vector<haptics::TickSample> two_tracks() {
  return {
      at(0.0, -0.005, -1, -1, 0, 0.0),   // free above the skin
      at(0.1, 0.000, 0, -1, 0, 0.1),     // meets the skin: the first track's origin
      at(0.2, 0.002, 0, -1, 0, 0.9),     // tenting
      at(0.3, 0.004, 0, -1, 0, 1.6),     // the peak
      at(0.4, 0.005, -1, 0, 0b1, 0.3),   // through: the tip in the skin
      at(0.5, 0.008, -1, 1, 0b11, 0.5),  // into the fat
      at(0.6, 0.008, -1, 1, 0b11, 0.5),  // held: the same point, left out of the line
      at(0.7, 0.008, -1, 1, 0b11, 0.5),
      at(0.8, 0.003, -1, 0, 0b11, -0.4),  // pulled back into the skin: friction against the motion
      at(0.9, -0.010, -1, -1, 0, 0.0),    // out: the track ends
      at(1.0, 0.001, 0, -1, 0, 0.2),      // meets the skin again: the second track's origin
      at(1.1, 0.003, 0, -1, 0, 1.4),
  };
}

TEST(ForceDepth, DepthsAlongTheNeedleFromWhereItMetTheTissueOneLinePerTrack) {
  const Task task = block();
  const ForceDepth fd = force_depth(two_tracks(), &task);
  EXPECT_TRUE(fd.plot.missing.empty());
  EXPECT_EQ(fd.plot.x_label, "depth (mm)");
  ASSERT_EQ(fd.plot.lines.size(), 2u);
  const Series& one = fd.plot.lines[0];
  // 0, 2, 4, 5, 8 mm (the two held states dropped), 3 mm on the way back.
  const std::vector<double> depths{0.0, 2.0, 4.0, 5.0, 8.0, 3.0}, forces{0.1, 0.9, 1.6, 0.3, 0.5, -0.4};
  ASSERT_EQ(one.t.size(), depths.size());
  for (size_t i = 0; i < depths.size(); ++i) {
    EXPECT_NEAR(one.t[i], depths[i], 1e-9) << i;
    EXPECT_DOUBLE_EQ(one.v[i], forces[i]) << i;
  }
  const Series& two = fd.plot.lines[1];
  ASSERT_EQ(two.t.size(), 2u);
  EXPECT_NEAR(two.t[0], 0.0, 1e-9);  // measured from its own origin, 1 mm deeper than the first's
  EXPECT_NEAR(two.t[1], 2.0, 1e-9);
}

TEST(ForceDepth, TheLayersFirstEnteredAndTheScorersPuncturesAtTheirDepth) {
  const Task task = block();
  const ForceDepth fd = force_depth(two_tracks(), &task);
  ASSERT_EQ(fd.boundaries.size(), 2u);
  EXPECT_EQ(fd.boundaries[0].label, "skin");
  EXPECT_NEAR(fd.boundaries[0].x, 5.0, 1e-9);
  EXPECT_EQ(fd.boundaries[1].label, "fat");
  EXPECT_NEAR(fd.boundaries[1].x, 8.0, 1e-9);
  // The skin's puncture (the fat has no puncture force): its peak the largest force before it.
  ASSERT_EQ(fd.puncture_list.size(), 1u);
  EXPECT_EQ(fd.puncture_list[0].layer, "skin");
  EXPECT_DOUBLE_EQ(fd.puncture_list[0].t_s, 0.4);
  EXPECT_DOUBLE_EQ(fd.puncture_list[0].peak_force_N, 1.6);
  ASSERT_EQ(fd.punctures.size(), 1u);
  EXPECT_NEAR(fd.punctures[0].x, 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(fd.punctures[0].y, 1.6);
  EXPECT_EQ(fd.punctures[0].label, "skin");
}

TEST(ForceDepth, NoPlotWithoutALayeredTissueOrSamples) {
  Task single = block();
  single.layers.resize(1);
  EXPECT_NE(force_depth(two_tracks(), &single).plot.missing.find("no layered tissue"), std::string::npos);
  EXPECT_FALSE(force_depth(two_tracks(), nullptr).plot.missing.empty());
  const Task task = block();
  EXPECT_EQ(force_depth({}, &task).plot.missing, "the recording has no samples");
  EXPECT_EQ(force_depth({at(0.0, -0.005, -1, -1, 0, 0.0)}, &task).plot.missing, "the needle never met the tissue");
}

}  // namespace
}  // namespace needle::training
