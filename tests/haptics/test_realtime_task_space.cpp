#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "haptics/realtime/task_space_step.hpp"
#include "test_realtime_fakes.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::haptics {
namespace {

// A handle the test puts where it wants (a position-only device, like the Falcon or the mouse).
class HeldHandle : public HapticDevice {
 public:
  HeldHandle() {
    caps_.name = "held";
    caps_.command_space = CommandSpace::kTaskForce;
    caps_.max_force_n = 100.0;
  }
  void open() override {}
  void close() noexcept override {}
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  void read(DeviceReading& out) noexcept override {
    out.sequence = ++sequence_;
    out.connected = 1;
    for (int i = 0; i < 3; ++i) out.position_m[i] = position[i];
  }
  void write(const DeviceCommand& c) noexcept override { last = c; }

  Eigen::Vector3d position = Eigen::Vector3d(0.01, 0.02, 0.1);  // anywhere: it maps onto the tool's start
  DeviceCommand last;

 private:
  DeviceCapabilities caps_;
  uint64_t sequence_ = 0;
};

struct Coupled {
  explicit Coupled(const TaskCoupling& coupling = {})
      : scenario(load_scenario(test::source_dir().string() + "/assets/scenarios/holonomic_sphere.json")),
        step(scenario, coupling),
        rig(handle, step, limits()) {
    tip_start_world = step.start_tip() + scenario.base_in_world;
    direction_start = step.start_direction();
    rig.run(0, 1, kDt);  // the first reading fixes the mapping
  }
  static SafetyLimits limits() {
    SafetyLimits l;
    l.max_force_n = 100.0;
    l.frozen_min_force_n = 1e9;  // this handle is perfectly still by construction, no hand trembles
    return l;
  }
  // Holds the handle displaced by `delta` from its start for `seconds`.
  void hold(const Eigen::Vector3d& delta, double seconds) {
    handle.position += delta;
    rig.run(1, static_cast<uint64_t>(seconds / kDt), kDt);
  }
  Eigen::Vector3d tip() const {
    const ToolSnapshot& s = rig.tick.last_sample().state;
    return {s.needle_tip_m[0], s.needle_tip_m[1], s.needle_tip_m[2]};
  }
  Eigen::Vector3d device_force() const { return {handle.last.force_n[0], handle.last.force_n[1], handle.last.force_n[2]}; }

  static constexpr double kDt = 0.001;
  Scenario scenario;
  HeldHandle handle;
  TaskSpaceStep step;
  testing::TickRig rig;
  Eigen::Vector3d tip_start_world, direction_start;
};

TEST(RealtimeTaskSpace, FreeMotionTipFollowsTheHandleAndTheForceVanishes) {
  Coupled c;
  const Eigen::Vector3d delta(-0.02, 0.01, 0.015);  // away from the sphere
  c.hold(delta, 3.0);
  const ToolSnapshot& s = c.rig.tick.last_sample().state;
  EXPECT_EQ(s.contact, ContactState::kFree);
  // Static equilibrium of a spring with gravity compensated: the tip sits on the target.
  EXPECT_LT((c.tip() - (c.tip_start_world + delta)).norm(), 1e-3);
  EXPECT_LT(c.device_force().norm(), 300.0 * 1e-3);
  const Eigen::Vector3d axis(needle_axis(s).data());
  EXPECT_GT(axis.dot(c.direction_start), std::cos(5.0 * M_PI / 180.0)) << "the needle keeps its direction";
}

TEST(RealtimeTaskSpace, PushingIntoTheRigidSphereIsFeltAlongItsNormal) {
  Coupled c;
  // Thesis sphere: centre (0.4, 0, 0) m, radius 0.1 m (world frame). Put the target 10 mm
  // inside it on the radial line through the tool's start.
  const Eigen::Vector3d centre(0.4, 0.0, 0.0);
  const double radius = 0.1, depth = 0.01;
  const Eigen::Vector3d outward = (c.tip_start_world - centre).normalized();
  const Eigen::Vector3d target = centre + (radius - depth) * outward;
  c.hold(target - c.tip_start_world, 4.0);

  const ToolSnapshot& s = c.rig.tick.last_sample().state;
  EXPECT_EQ(s.contact, ContactState::kRigidSurface);
  // At rest the coupling spring K and the penalty surface's stiffness k = alpha omega^2 (3.15)
  // are two springs in series: the tool sinks p = K d / (K + k) and the force is k p.
  const double K = TaskCoupling{}.stiffness_n_per_m, k = c.scenario.gains.gpm.stiffness();
  const double sink = K * depth / (K + k);
  EXPECT_NEAR(radius - (c.tip() - centre).norm(), sink, 0.05 * sink);
  // The handle is pushed back out along the normal at the contact.
  const Eigen::Vector3d normal = (c.tip() - centre).normalized();
  const Eigen::Vector3d f = c.device_force();
  EXPECT_GT(f.normalized().dot(normal), std::cos(5.0 * M_PI / 180.0));
  EXPECT_NEAR(f.norm(), k * sink, 0.05 * k * sink);
  EXPECT_EQ(c.rig.safety.fault(), FaultCause::kNone);
}

TEST(RealtimeTaskSpace, DeviceAxesAreTurnedIntoTheSceneAndTheForceBack) {
  TaskCoupling coupling;
  coupling.device_to_scene = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Coupled c(coupling);
  const Eigen::Vector3d centre(0.4, 0.0, 0.0);
  const Eigen::Vector3d outward = (c.tip_start_world - centre).normalized();
  const Eigen::Vector3d target = centre + (0.1 - 0.01) * outward;
  // Scene x is device -y and scene y is device x: move the handle by R^T times the scene move.
  c.hold(coupling.device_to_scene.transpose() * (target - c.tip_start_world), 4.0);
  EXPECT_EQ(c.rig.tick.last_sample().state.contact, ContactState::kRigidSurface);
  const Eigen::Vector3d normal_in_device = coupling.device_to_scene.transpose() * (c.tip() - centre).normalized();
  EXPECT_GT(c.device_force().normalized().dot(normal_in_device), std::cos(5.0 * M_PI / 180.0));
}

}  // namespace
}  // namespace needle::haptics
