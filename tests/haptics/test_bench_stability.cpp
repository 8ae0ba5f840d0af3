// Stress cases end bounded or in a latched fault that names its cause, never silently.
#include <gtest/gtest.h>

#include "haptics/sim/stress_cases.hpp"
#include "sim_fixtures.hpp"

namespace needle::haptics {
namespace {

TEST(BenchStability, PrintedVirtualLawEndsInANamedFaultInClosedLoop) {
  Scenario s = test::scenario("holonomic_sphere");
  s.gains.virtual_feedback = VirtualFeedback::AsPrinted;
  const SimResult r = run_closed_loop(s, false);
  ASSERT_EQ(r.summary.faults.size(), 1u);
  EXPECT_LT(r.simulated_s, 2.0);  // caught at once, not after a long silent drift
  const std::string& f = r.summary.faults.front();
  EXPECT_TRUE(f.rfind("non_finite_state", 0) == 0 || f.rfind("energy_bound_exceeded", 0) == 0 || f.rfind("tracking_diverged", 0) == 0) << f;
}

TEST(BenchStability, PushAtTwiceTheForceLimitStaysBoundedAndSaturates) {
  const Scenario& h = test::scenario("holonomic_sphere");
  const Scenario s = pressing(h, 2 * h.device.force_limit_N, 10.0);
  double deepest = 0;
  const SimResult r = run_closed_loop(s, false, [&](const TickRecord& t) { deepest = std::max(deepest, -t.lambda_v[0]); });
  EXPECT_TRUE(r.summary.faults.empty());
  // The device cannot resist more than its limit, so the hand pushes the tool harder than that.
  EXPECT_GT(deepest, h.device.force_limit_N);
  EXPECT_LT(r.summary.max_penetration_m, 0.02);
}

TEST(BenchStability, CasesCoverTheIssueSweeps) {
  const auto cases = stress_cases(test::scenario("holonomic_sphere"), test::scenario("nonholonomic_needle"), 3600.0);
  int gains = 0, periods = 0, singular = 0, push = 0, sustained = 0, stiffness = 0;
  for (const StressCase& c : cases) {
    gains += c.name.rfind("gains", 0) == 0;
    periods += c.name.rfind("period", 0) == 0;
    singular += c.name == "singular pose";
    push += c.name == "operator push";
    sustained += c.name == "sustained contact" && c.scenario.duration_s >= 3600.0;
    stiffness += c.name.rfind("penalty stiffness", 0) == 0;
  }
  EXPECT_EQ(gains, 14);
  EXPECT_EQ(periods, 8);
  EXPECT_EQ(singular, 2);
  EXPECT_EQ(push, 1);
  EXPECT_EQ(sustained, 1);
  EXPECT_EQ(stiffness, 5);
  EXPECT_DOUBLE_EQ(passivity_stiffness_bound(test::scenario("holonomic_sphere")), 2 * 6.45 / 0.002);
}

}  // namespace
}  // namespace needle::haptics
