// The servo tick allocates nothing: the C allocator itself is interposed (glibc allows the
// executable to define malloc and friends; these forward to __libc_*), so operator new, Eigen's
// aligned_malloc and anything else that reaches the heap is counted while ticks run.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <atomic>
#include <functional>
#include <vector>

#include "haptics/sim/tick_workload.hpp"
#include "sim_fixtures.hpp"

namespace {
std::atomic<long> g_allocations{0};
std::atomic<bool> g_counting{false};
void count() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void __libc_free(void*);

void* malloc(size_t size) {
  count();
  return __libc_malloc(size);
}
void* calloc(size_t n, size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* p, size_t size) {
  count();
  return __libc_realloc(p, size);
}
void* memalign(size_t alignment, size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(size_t alignment, size_t size) { return memalign(alignment, size); }
int posix_memalign(void** out, size_t alignment, size_t size) {
  *out = memalign(alignment, size);
  return *out ? 0 : 12;  // ENOMEM
}
void free(void* p) { __libc_free(p); }
}

namespace needle::haptics {
namespace {

long allocations_during(const std::function<void()>& work) {
  g_allocations = 0;
  g_counting = true;
  work();
  g_counting = false;
  return g_allocations.load();
}

TEST(BenchTickAllocations, CounterSeesAllocations) {
  // The hook works for operator new and for Eigen's own heap storage.
  EXPECT_GE(allocations_during([] { std::vector<double> v(100); (void)v; }), 1);
  EXPECT_GE(allocations_during([] { Eigen::VectorXd v(100); (void)v; }), 1);
}

TEST(BenchTickAllocations, NonholonomicContactTickAllocatesNothing) {
  TickWorkload workload(test::scenario("nonholonomic_needle"), 8.0);
  EXPECT_EQ(allocations_during([&] {
              for (int k = 0; k < 2000; ++k) workload.tick();
            }),
            0);
  EXPECT_EQ(workload.teleoperation().world().report().mode, ContactMode::Nonholonomic);
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
