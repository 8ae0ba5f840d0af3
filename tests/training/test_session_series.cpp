// The review's plot series from recorded samples written by hand, against values worked out by
// hand; the min/max decimation and the axis ticks the plots draw.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tests/support/test_paths.hpp"
#include "tool_states.hpp"
#include "training/sessions/session_series.hpp"

namespace needle::training {
namespace {

const std::filesystem::path kTasks = needle::test::source_dir() / "assets/tasks";

// Joint-space samples: free, then in tissue 20 mm down the penetrable task's insertion axis
// (origin (0.32929, 0, 0.07071), direction (1, 0, -1)/sqrt 2) and 10 mm off it sideways, then
// on a rigid surface.
std::vector<haptics::TickSample> joint_samples() {
  const double r = 1.0 / std::sqrt(2.0);
  const Vec3 origin{0.32929, 0.0, 0.07071};
  std::vector<haptics::TickSample> out(3);
  out[0].state = test::state(0.0, origin);
  out[0].state.environment_force_n[0] = 3.0;
  out[0].state.environment_force_n[1] = 4.0;  // |F_v| = 5
  out[0].state.operator_force_n[2] = 2.0;     // |F_h| = 2
  out[1].state =
      test::state(0.001, origin + 0.02 * Vec3{r, 0.0, -r} + Vec3{0.0, 0.01, 0.0}, 0.0, haptics::ContactState::kTissue);
  out[1].state.multiplier_count = 2;
  out[1].state.multipliers[0] = 3.0;
  out[1].state.multipliers[1] = -4.0;  // |lambda| = 5
  out[2].state = test::state(0.002, origin - 0.005 * Vec3{r, 0.0, -r}, 0.0, haptics::ContactState::kRigidSurface);
  out[2].state.multiplier_count = 1;
  out[2].state.multipliers[0] = 7.0;  // a rigid contact's lambda is not lateral load
  const double master[3][2] = {{0.1, 0.2}, {0.103, 0.204}, {0.1, 0.2}};
  const double virt[3][2] = {{0.1, 0.2}, {0.1, 0.2}, {0.1, 0.212}};
  for (size_t k = 0; k < 3; ++k) {
    out[k].command.space = haptics::CommandSpace::kJointTorque;
    out[k].reading.joint_count = out[k].state.joint_count = 2;
    for (int j = 0; j < 2; ++j) {
      out[k].reading.joint_rad[j] = master[k][j];
      out[k].state.virtual_q[j] = virt[k][j];
    }
  }
  return out;
}

void expect_values(const Series& s, const std::vector<double>& v, double tolerance = 1e-9) {
  ASSERT_EQ(s.v.size(), v.size()) << s.name;
  for (size_t i = 0; i < v.size(); ++i) EXPECT_NEAR(s.v[i], v[i], tolerance) << s.name << " [" << i << "]";
}

TEST(SessionSeries, JointDeviceSessionOnThePenetrableTask) {
  const Task task = load_task(kTasks / "penetrable_sphere.json");
  const SessionPlots p = session_plots(joint_samples(), &task);
  ASSERT_EQ(p.force.lines.size(), 4u);
  EXPECT_EQ(p.force.lines[0].t, (std::vector<double>{0.0, 0.001, 0.002}));
  // At the hand (the task's force scale is 1): the rigid contact's 5 N, then the tissue's sideways 5 N.
  expect_values(p.force.lines[0], {5.0, 5.0, 0.0});
  expect_values(p.force.lines[1], {0.0, 0.0, 0.0});  // no axial tissue force
  expect_values(p.force.lines[2], {5.0, 0.0, 0.0});  // the rigid contact
  expect_values(p.force.lines[3], {2.0, 0.0, 0.0});  // the hand's sensed push
  ASSERT_EQ(p.force.guides.size(), 1u);
  EXPECT_DOUBLE_EQ(p.force.guides[0].value, 3.0);  // the task's safe_force_N

  ASSERT_EQ(p.lateral.lines.size(), 1u);
  expect_values(p.lateral.lines[0], {0.0, 5.0, 0.0});

  EXPECT_EQ(p.depth.unit, "mm");
  EXPECT_EQ(p.depth.title, "Depth along the insertion axis");  // the marker's name in words
  ASSERT_EQ(p.depth.lines.size(), 1u);
  expect_values(p.depth.lines[0], {0.0, 20.0, -5.0}, 1e-6);  // the sideways 10 mm does not count
  ASSERT_EQ(p.depth.guides.size(), 2u);                      // the insert step's band, 2.5 to 3.5 cm
  EXPECT_NEAR(p.depth.guides[0].value, 25.0, 1e-9);
  EXPECT_NEAR(p.depth.guides[1].value, 35.0, 1e-9);

  EXPECT_EQ(p.tracking.unit, "mrad");
  ASSERT_EQ(p.tracking.lines.size(), 1u);
  expect_values(p.tracking.lines[0], {0.0, 5.0, 12.0}, 1e-9);  // hypot(3, 4) and 12 mrad
}

TEST(SessionSeries, PositionDeviceTrackingIsTheCouplingForce) {
  std::vector<haptics::TickSample> samples = joint_samples();
  for (haptics::TickSample& s : samples) s.command.space = haptics::CommandSpace::kTaskForce;
  const SessionPlots p = session_plots(samples, nullptr);
  EXPECT_EQ(p.tracking.unit, "N");
  ASSERT_EQ(p.tracking.lines.size(), 1u);
  expect_values(p.tracking.lines[0], {2.0, 0.0, 0.0});
  EXPECT_TRUE(p.force.guides.empty());  // no task, no safe limit
  EXPECT_TRUE(p.depth.lines.empty());
  EXPECT_FALSE(p.depth.missing.empty());
}

TEST(SessionSeries, TaskWithoutInsertionAxisHasNoDepthPlotAndSaysWhy) {
  const Task task = load_task(kTasks / "rigid_sphere.json");
  EXPECT_EQ(insertion_axis_marker(task), -1);
  const SessionPlots p = session_plots(joint_samples(), &task);
  EXPECT_TRUE(p.depth.lines.empty());
  EXPECT_NE(p.depth.missing.find("rigid_sphere"), std::string::npos) << p.depth.missing;
  EXPECT_EQ(p.lateral.lines.size(), 1u);
}

TEST(SessionSeries, NoSamplesNoLines) {
  const SessionPlots p = session_plots({}, nullptr);
  for (const Plot* plot : p.all()) {
    EXPECT_TRUE(plot->lines.empty());
    EXPECT_FALSE(plot->missing.empty());
  }
}

TEST(SessionSeries, DecimationKeepsEachBinsMinimumAndMaximumInTimeOrder) {
  const Series s{"s", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, {0, 5, 1, 2, -3, 4, 4, 0, 9, 1}};
  // Bins [0, 4.5] and (4.5, 9]: max 5 at t 1, min -3 at t 4; min 0 at t 7, max 9 at t 8.
  const Series d = decimate(s, 2);
  EXPECT_EQ(d.t, (std::vector<double>{1, 4, 7, 8}));
  EXPECT_EQ(d.v, (std::vector<double>{5, -3, 0, 9}));
  EXPECT_EQ(decimate(s, 5).t, s.t);  // 2 points a bin already
  // An empty middle bin adds nothing; a bin of one sample adds it once.
  const Series gap{"g", {0, 0.1, 0.2, 0.3, 0.4, 0.5, 10}, {1, 2, 0, 3, 4, -1, 4}};
  const Series g = decimate(gap, 3);
  EXPECT_EQ(g.t, (std::vector<double>{0.4, 0.5, 10}));
  EXPECT_EQ(g.v, (std::vector<double>{4, -1, 4}));
}

TEST(SessionSeries, AxisTicksAreRoundNumbersInsideTheRange) {
  EXPECT_EQ(axis_ticks(0, 10, 6), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(axis_ticks(0, 10, 5), (std::vector<double>{0, 5, 10}));
  EXPECT_EQ(axis_ticks(-35, 46, 4), (std::vector<double>{-20, 0, 20, 40}));
  EXPECT_EQ(axis_ticks(0, 1234, 4), (std::vector<double>{0, 500, 1000}));
  const std::vector<double> small = axis_ticks(-0.3, 0.72, 4);  // step 0.5
  ASSERT_EQ(small.size(), 2u);
  EXPECT_DOUBLE_EQ(small[0], 0.0);
  EXPECT_DOUBLE_EQ(small[1], 0.5);
  EXPECT_TRUE(axis_ticks(3.7, 3.7, 4).empty());
}

}  // namespace
}  // namespace needle::training
