// The servo tick allocates nothing: every call into the C allocator is counted while ticks run
// (tests/support/allocation_counter.hpp), so operator new and Eigen's heap storage are both seen.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "haptics/sim/tick_workload.hpp"
#include "sim_fixtures.hpp"
#include "tests/support/allocation_counter.hpp"

namespace needle::haptics {
namespace {

long allocations_during(const std::function<void()>& work) {
  needle::test::allocation_counter::start();
  work();
  return needle::test::allocation_counter::stop();
}

// Keeps the compiler from proving `p` unused and removing its allocation (clang removes a malloc
// whose memory nothing reads).
void keep(const void* p) { asm volatile("" : : "g"(p) : "memory"); }

TEST(BenchTickAllocations, CounterSeesAllocations) {
  // The hook works for operator new and for Eigen's own heap storage.
  EXPECT_GE(allocations_during([] {
              std::vector<double> v(100);
              keep(v.data());
            }),
            1);
  EXPECT_GE(allocations_during([] {
              Eigen::VectorXd v(100);
              keep(v.data());
            }),
            1);
}

// (scenario with its virtual sub-steps, played settle_s seconds) => allocations over its next 2000
// ticks; the needle still in tissue.
long allocations_in_tissue(const char* name, double settle_s, int substeps) {
  Scenario scenario = test::scenario(name);
  scenario.virtual_substeps = substeps;
  TickWorkload workload(scenario, settle_s);
  const long count = allocations_during([&] {
    for (int k = 0; k < 2000; ++k) workload.tick();
  });
  EXPECT_EQ(workload.teleoperation().world().report().mode, ContactMode::Nonholonomic) << name;
  return count;
}

// The ticks `needle-sim bench tick` times, in each of its rows (1, 2 and 4 virtual sub-steps).
TEST(BenchTickAllocations, NonholonomicContactTickAllocatesNothing) {
  for (int substeps : {1, 2, 4})
    EXPECT_EQ(allocations_in_tissue("nonholonomic_needle", 8.0, substeps), 0) << substeps << " sub-steps";
}

TEST(BenchTickAllocations, LayeredTissueTickAllocatesNothing) {
  // lumbar_epidural at 22 s: the tip in the interspinous ligament, the shaft through skin, fat and the
  // supraspinous ligament (friction on three layers, the track's events).
  EXPECT_EQ(allocations_in_tissue("lumbar_epidural", 22.0, 1), 0);
}

TEST(BenchTickAllocations, PatientTissueTickAllocatesNothing) {
  // The generated patient at 24 s (bench tick's patient row): the tip in the interspinous ligament,
  // the shaft through skin, fat and the supraspinous ligament, every layer a grid.
  EXPECT_EQ(allocations_in_tissue("epidural_patient", 24.0, 1), 0);
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
