// The step's cues (training/tasks/step_cue.hpp): distances and directions in the view's axes, the
// turn and tilt onto the planned axis, the depth against the band, and the words, against values
// worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "tests/support/test_paths.hpp"
#include "tool_states.hpp"
#include "training/tasks/step_cue.hpp"

namespace needle::training {
namespace {
using test::state;

// The view of the shipped scenes, square to the world: right +x, up +z, into the screen +y.
const ViewAxes kView{{1, 0, 0}, {0, 0, 1}, {0, 1, 0}};

Task point_and_axis(ConditionType type) {
  Task t;
  t.markers = {{"entry", MarkerKind::kPoint, {0, 0, 0}, {}, 0}, {"down", MarkerKind::kAxis, {0, 0, 0}, {0, 0, -1}, 0}};
  Step s;
  s.id = "only";
  s.condition.type = type;
  s.condition.marker = type == ConditionType::kAxisAligned || type == ConditionType::kDepthInBand ? 1 : 0;
  s.condition.within_m = 0.004;
  s.condition.within_rad = 5.0 * std::numbers::pi / 180.0;
  s.condition.min = 0.025, s.condition.max = 0.035;
  s.condition.hold_s = 0.5;
  s.guidance.entry = 0;
  s.guidance.axis = 1;
  t.steps = {s};
  return t;
}

TEST(StepCue, TheDistanceAndItsDirectionsAreInTheViewsAxes) {
  const Task t = point_and_axis(ConditionType::kTipNear);
  // The tip 10 mm right, 20 mm into the screen and 5 mm below the entry: the entry is left, up, towards you.
  const haptics::ToolSnapshot s = state(0.0, {0.01, 0.02, -0.005}, std::numbers::pi / 2);
  const StepCue cue = step_cue(t, 0, s, kView);
  EXPECT_EQ(cue.point, 0);
  EXPECT_NEAR(cue.distance_m, std::sqrt(0.01 * 0.01 + 0.02 * 0.02 + 0.005 * 0.005), 1e-12);
  EXPECT_NEAR(cue.to_point_view[0], -0.01, 1e-12);
  EXPECT_NEAR(cue.to_point_view[1], 0.005, 1e-12);
  EXPECT_NEAR(cue.to_point_view[2], -0.02, 1e-12);
  const std::vector<std::string> lines = cue_lines(t, 0, s, cue);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "entry 22.9 mm away: 10 mm left, 5 mm up, 20 mm towards you");
}

// The needle along +x (pitch 0) and the plan straight down: in the screen's plane, right to down is a
// quarter turn clockwise as seen, no tilt. Pointing into the screen instead, the hub must come
// towards the viewer by 90 degrees.
TEST(StepCue, TheTurnAndTiltOntoThePlannedAxisAreTheWristsTwoAngles) {
  const Task t = point_and_axis(ConditionType::kAxisAligned);
  const haptics::ToolSnapshot flat = state(0.0, {0, 0, 0}, 0.0);
  StepCue cue = step_cue(t, 0, flat, kView);
  EXPECT_NEAR(cue.off_axis_deg, 90.0, 1e-9);
  EXPECT_NEAR(cue.turn_deg, 90.0, 1e-9);
  EXPECT_NEAR(cue.tilt_deg, 0.0, 1e-9);
  EXPECT_NEAR(cue.within_deg, 5.0, 1e-9);
  EXPECT_EQ(cue_lines(t, 0, flat, cue).back(), "off the axis 90 deg: turn clockwise 90 deg");

  Task away = t;
  away.markers[1].direction = {0, 1, 0};
  cue = step_cue(away, 0, flat, kView);
  EXPECT_NEAR(cue.tilt_deg, -90.0, 1e-9);
  EXPECT_EQ(cue_lines(away, 0, flat, cue).back(), "off the axis 90 deg: tilt the hub towards you 90 deg");

  const haptics::ToolSnapshot aligned = state(0.0, {0, 0, 0}, std::numbers::pi / 2 - 0.03);  // 1.7 deg off
  cue = step_cue(t, 0, aligned, kView);
  EXPECT_EQ(cue_lines(t, 0, aligned, cue).back(), "off the axis 2 deg: on it (within 5 deg)");
}

TEST(StepCue, TheDepthAgainstTheBandSaysHowMuchFurtherOrBack) {
  const Task t = point_and_axis(ConditionType::kDepthInBand);
  const auto line = [&](double depth) {
    const haptics::ToolSnapshot s = state(0.0, {0, 0, -depth}, std::numbers::pi / 2);
    const StepCue cue = step_cue(t, 0, s, kView);
    EXPECT_NEAR(cue.depth_m, depth, 1e-12);
    EXPECT_EQ(cue.gauge, 1);
    return cue_lines(t, 0, s, cue).back();
  };
  EXPECT_EQ(line(0.012), "depth 12 mm: 13 mm deeper to the band (25-35 mm)");
  EXPECT_EQ(line(0.030), "depth 30 mm: in the band (25-35 mm)");
  EXPECT_EQ(line(0.041), "depth 41 mm: 6 mm back to the band (25-35 mm)");
}

TEST(StepCue, TheConditionInWords) {
  EXPECT_EQ(condition_words(point_and_axis(ConditionType::kTipNear), point_and_axis(ConditionType::kTipNear).steps[0]),
            "the tip within 4 mm of the entry, held 0.5 s");
  const Task depth = point_and_axis(ConditionType::kDepthInBand);
  EXPECT_EQ(condition_words(depth, depth.steps[0]), "the tip 25-35 mm deep along the planned axis, held 0.5 s");
  const Task axis = point_and_axis(ConditionType::kAxisAligned);
  EXPECT_EQ(condition_words(axis, axis.steps[0]), "the needle within 5 deg of the planned axis, held 0.5 s");
  const Task penetrable = load_task(needle::test::source_dir() / "assets/tasks/penetrable_sphere.json");
  EXPECT_EQ(condition_words(penetrable, penetrable.steps[4]), "the needle out, over 70 mm from the target");
  const Task patient = load_task(needle::test::source_dir() / "assets/tasks/epidural_patient_bmi22.json");
  EXPECT_EQ(condition_words(patient, patient.steps[1]),
            "the needle in through the skin over the L3-L4 interspace, near the midline, held 0.5 s");
}

// Every step of every shipped task says its condition in words (a type without words would leave
// the trainee's panel blank).
TEST(StepCue, EveryShippedStepHasItsConditionInWords) {
  for (const auto& file : std::filesystem::directory_iterator(needle::test::source_dir() / "assets/tasks")) {
    if (file.path().stem().string().ends_with("_good") || file.path().stem().string().ends_with("_sloppy")) continue;
    const Task t = load_task(file.path());
    for (const Step& s : t.steps) {
      const std::string words = condition_words(t, s);
      EXPECT_FALSE(words.empty() || words.starts_with(",")) << file.path() << " step " << s.id << ": '" << words << "'";
    }
  }
}

// Every shipped task has a depth gauge in every step: the step's own axis, else the one before it.
TEST(StepCue, EveryShippedTaskHasADepthGaugeInEveryStep) {
  for (const char* name : {"rigid_sphere", "penetrable_sphere", "sphere_ultrasound", "layered_target", "epidural"}) {
    const Task t = load_task(needle::test::source_dir() / "assets/tasks" / (std::string(name) + ".json"));
    for (size_t k = 0; k < t.steps.size(); ++k) EXPECT_GE(gauge_marker(t, k), 0) << name << " step " << k;
  }
}

}  // namespace
}  // namespace needle::training
