// The servo tick allocates nothing: every call into the C allocator is counted while ticks run
// (haptics/sim/allocation_counter.hpp), so operator new and Eigen's heap storage are both seen.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "haptics/sim/allocation_counter.hpp"
#include "haptics/sim/tick_workload.hpp"
#include "sim_fixtures.hpp"

namespace needle::haptics {
namespace {

long allocations_during(const std::function<void()>& work) {
  allocation_counter::start();
  work();
  return allocation_counter::stop();
}

TEST(BenchTickAllocations, CounterSeesAllocations) {
  // The hook works for operator new and for Eigen's own heap storage.
  EXPECT_GE(allocations_during([] { std::vector<double> v(100); (void)v; }), 1);
  EXPECT_GE(allocations_during([] { Eigen::VectorXd v(100); (void)v; }), 1);
}

// (scenario played settle_s seconds) => allocations over its next 2000 ticks; the needle still in tissue.
long allocations_in_tissue(const char* scenario, double settle_s) {
  TickWorkload workload(test::scenario(scenario), settle_s);
  const long count = allocations_during([&] {
    for (int k = 0; k < 2000; ++k) workload.tick();
  });
  EXPECT_EQ(workload.teleoperation().world().report().mode, ContactMode::Nonholonomic) << scenario;
  return count;
}

TEST(BenchTickAllocations, NonholonomicContactTickAllocatesNothing) {
  EXPECT_EQ(allocations_in_tissue("nonholonomic_needle", 8.0), 0);
}

TEST(BenchTickAllocations, LayeredTissueTickAllocatesNothing) {
  // lumbar_epidural at 22 s: the tip in the interspinous ligament, the shaft through skin, fat and the
  // supraspinous ligament (friction on three layers, the track's events).
  EXPECT_EQ(allocations_in_tissue("lumbar_epidural", 22.0), 0);
}

TEST(BenchTickAllocations, RigidContactAndFreeMotionTicksAllocateNothing) {
  const Scenario& sc = test::scenario("holonomic_sphere");
  Teleoperation tele(sc.master, sc.virt, sc.scene, sc.gains, sc.period_s, sc.virtual_substeps);
  tele.reset(sc.q0, VecN::Zero(5));
  // Drive the master straight into the sphere and out again through its own tracking.
  TickInput in{sc.q0, VecN::Zero(5), Wrench::Zero()};
  in.wrench_h[0] = 1.0;
  bool touched = false;
  const long count = allocations_during([&] {
    for (int k = 0; k < 3000; ++k) {
      in.q_m[1] -= 0.0004;  // shoulder down: the tip sweeps through the sphere
      touched |= tele.step(in).mode == ContactMode::Holonomic;
    }
  });
  EXPECT_TRUE(touched);
  EXPECT_EQ(count, 0);
}

}  // namespace
}  // namespace needle::haptics
