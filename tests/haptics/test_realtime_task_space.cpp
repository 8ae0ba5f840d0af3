#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "haptics/realtime/task_space_step.hpp"
#include "test_realtime_fakes.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::haptics {
namespace {

// A handle the test puts where it wants (a position-only device: the Falcon, or without actuators
// the mouse).
class HeldHandle : public HapticDevice {
 public:
  explicit HeldHandle(bool exerts_force = true) {
    caps_.name = "held";
    caps_.command_space = exerts_force ? CommandSpace::kTaskForce : CommandSpace::kNone;
    caps_.max_force_n = exerts_force ? 100.0 : 0.0;
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
  explicit Coupled(const TaskCoupling& coupling = {}, bool exerts_force = true)
      : scenario(load_scenario(test::source_dir().string() + "/assets/scenarios/holonomic_sphere.json")),
        handle(exerts_force),
        step(scenario, coupling),
        rig(handle, step, limits(exerts_force)) {
    tip_start_world = step.start_tip() + scenario.base_in_world;
    direction_start = step.start_direction();
    rig.run(0, 1, kDt);  // the first reading fixes the mapping
  }
  static SafetyLimits limits(bool exerts_force) {
    SafetyLimits l;
    l.max_force_n = exerts_force ? 100.0 : 0.0;
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
  Eigen::Vector3d device_force() const {
    return {handle.last.force_n[0], handle.last.force_n[1], handle.last.force_n[2]};
  }

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

// A handle without actuators (a desk device) pressed into the sphere: the contact force is the same
// as the actuated handle's and is reported for the screen, but the device is sent no force and no
// tick says it was held back at a limit (it has none).
TEST(RealtimeTaskSpace, AHandleWithoutActuatorsIsSentNothingAndNeverHeldAtALimit) {
  Coupled felt, shown({}, false);
  const Eigen::Vector3d centre(0.4, 0.0, 0.0);
  const Eigen::Vector3d outward = (felt.tip_start_world - centre).normalized();
  const Eigen::Vector3d push = centre + 0.09 * outward - felt.tip_start_world;  // 10 mm into the sphere
  felt.hold(push, 2.0);
  shown.hold(push, 2.0);
  const ToolSnapshot &a = felt.rig.tick.last_sample().state, &b = shown.rig.tick.last_sample().state;
  ASSERT_EQ(b.contact, ContactState::kRigidSurface);
  const Eigen::Vector3d fa(a.operator_force_n), fb(b.operator_force_n);
  EXPECT_GT(fb.norm(), 1.0);
  EXPECT_LT((fa - fb).norm(), 1e-9 + 1e-6 * fa.norm());
  EXPECT_EQ(shown.handle.last.space, CommandSpace::kNone);
  EXPECT_EQ(Eigen::Vector3d(shown.handle.last.force_n).norm(), 0.0);
  EXPECT_EQ(b.limits & kLimitForce, 0u);
  EXPECT_EQ(shown.rig.safety.fault(), FaultCause::kNone);
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

namespace needle::haptics {
namespace {

// The view of assets/scenes/penetrable_sphere.json, squared up: right along x, up along z,
// looking along +y.
Eigen::Matrix3d side_view() {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, 0, 1, 0, 1, 0;
  return m;
}

TEST(RealtimeTaskSpace, AWristSwingsTheDirectionClockwiseAsSeenAndTiltsItTowardsTheViewer) {
  const Eigen::Vector3d down_right(std::sqrt(0.5), 0.0, -std::sqrt(0.5));
  EXPECT_LT((wrist_direction(side_view(), down_right, M_PI / 4, 0.0) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  EXPECT_LT((wrist_direction(side_view(), down_right, -M_PI / 4, 0.0) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  const Eigen::Vector3d down(0, 0, -1);
  EXPECT_LT((wrist_direction(side_view(), down, 0.0, M_PI / 6) - Eigen::Vector3d(0, -0.5, -std::sqrt(0.75))).norm(),
            1e-12)
      << "a positive tilt brings the tip towards the viewer (-y)";
  // Along the view there is no plane to tilt in: it tilts about the view's right axis.
  EXPECT_LT((wrist_direction(side_view(), Eigen::Vector3d::UnitY(), 0.0, M_PI / 2) - Eigen::Vector3d::UnitZ()).norm(),
            1e-12);
}

// A handle with a virtual wrist (as a desk device has) put where the test wants.
class WristHandle : public HeldHandle {
 public:
  WristHandle() { position = Eigen::Vector3d::Zero(); }
  void read(DeviceReading& out) noexcept override {
    HeldHandle::read(out);
    out.joint_count = 2;
    out.joint_rad[0] = swing;
    out.joint_rad[1] = tilt;
  }

  double swing = 0.0, tilt = 0.0;
};

// The thesis's penetrable sphere (section 4.4) with a wrist: aligned with the insertion axis in
// free space, inserted 3 cm along it, then swung 45° to vertical: the needle pivots about its
// tip, in the tissue throughout.
struct WristRig {
  explicit WristRig(bool wrist)
      : scenario(load_scenario(test::source_dir().string() + "/assets/scenarios/nonholonomic_needle.json")),
        coupling(make_coupling(wrist)),
        step(scenario, coupling),
        rig(handle, step, limits()) {
    rig.run(tick++, 1, kDt);  // the first reading fixes the mapping
    tip_start_world = step.start_tip() + scenario.base_in_world;
  }
  static TaskCoupling make_coupling(bool wrist) {
    TaskCoupling c;
    c.device_to_scene = side_view();
    c.orientation_stiffness_nm_per_rad = 5.0;  // as the app couples the desk devices
    c.wrist = wrist;
    return c;
  }
  static SafetyLimits limits() {
    SafetyLimits l;
    l.frozen_min_force_n = 1e9;  // a perfectly still handle, by construction
    return l;
  }
  // Moves the handle in a straight line to put the tip target at `tip` (world) and the wrist at
  // (swing, tilt), over `seconds`; `each` sees every tick's state.
  template <typename Each>
  void go(const Eigen::Vector3d& tip, double swing, double tilt, double seconds, Each each) {
    const Eigen::Vector3d from = handle.position, to = coupling.device_to_scene.transpose() * (tip - tip_start_world);
    const double swing0 = handle.swing, tilt0 = handle.tilt;
    const int n = static_cast<int>(seconds / kDt);
    for (int i = 1; i <= n; ++i) {
      const double u = double(i) / n;
      handle.position = from + u * (to - from);
      handle.swing = swing0 + u * (swing - swing0);
      handle.tilt = tilt0 + u * (tilt - tilt0);
      rig.run(tick++, 1, kDt);
      each(rig.tick.last_sample().state);
    }
  }
  void go(const Eigen::Vector3d& tip, double swing, double tilt, double seconds) {
    go(tip, swing, tilt, seconds, [](const ToolSnapshot&) {});
  }
  const ToolSnapshot& state() const { return rig.tick.last_sample().state; }

  static constexpr double kDt = 0.001;
  Scenario scenario;
  TaskCoupling coupling;
  WristHandle handle;
  TaskSpaceStep step;
  testing::TickRig rig;
  uint64_t tick = 0;
  Eigen::Vector3d tip_start_world;
};

Eigen::Vector3d tip_of(const ToolSnapshot& s) { return {s.needle_tip_m[0], s.needle_tip_m[1], s.needle_tip_m[2]}; }
Eigen::Vector3d axis_of(const ToolSnapshot& s) { return Eigen::Vector3d(needle_axis(s).data()); }

TEST(RealtimeTaskSpace, AWristPivotsTheNeedleAboutItsTipInTissue) {
  WristRig w(true);
  const Eigen::Vector3d axis(std::sqrt(0.5), 0.0, -std::sqrt(0.5)), entry(0.32929, 0.0, 0.07071);
  // The wrist angles that turn the start direction onto the insertion axis (a coarse search).
  double swing = 0.0, tilt = 0.0, best = 1e9;
  for (double s = -M_PI; s < M_PI; s += 0.002)
    for (double t = -1.3; t < 1.3; t += 0.002) {
      const double e = (wrist_direction(w.coupling.device_to_scene, w.step.start_direction(), s, t) - axis).norm();
      if (e < best) best = e, swing = s, tilt = t;
    }
  ASSERT_LT(best, 0.003);
  w.go(entry - 0.02 * axis, swing, tilt, 3.0);
  w.go(entry - 0.02 * axis, swing, tilt, 2.0);
  EXPECT_EQ(w.state().contact, ContactState::kFree);
  EXPECT_GT(axis_of(w.state()).dot(axis), std::cos(1.0 * M_PI / 180)) << "aligned in free space";
  w.go(entry + 0.03 * axis, swing, tilt, 4.0);
  w.go(entry + 0.03 * axis, swing, tilt, 1.0);
  ASSERT_EQ(w.state().contact, ContactState::kTissue);
  const Eigen::Vector3d pivot = tip_of(w.state());
  EXPECT_LT((pivot - (entry + 0.03 * axis)).norm(), 0.002);

  double drift = 0.0;
  bool left_tissue = false;
  auto watch = [&](const ToolSnapshot& s) {
    drift = std::max(drift, (tip_of(s) - pivot).norm());
    left_tissue |= s.contact != ContactState::kTissue;
  };
  w.go(entry + 0.03 * axis, swing + M_PI / 4, tilt, 3.0, watch);  // a 45° swing, clockwise as seen
  w.go(entry + 0.03 * axis, swing + M_PI / 4, tilt, 1.0, watch);
  EXPECT_GT(axis_of(w.state()).dot(Eigen::Vector3d(0, 0, -1)), std::cos(1.0 * M_PI / 180)) << "vertical";
  EXPECT_LT(drift, 0.002) << "the tip stays where it pivots (the task allows 5 mm)";
  EXPECT_FALSE(left_tissue);
  EXPECT_EQ(w.rig.safety.fault(), FaultCause::kNone);
}

TEST(RealtimeTaskSpace, WithoutAWristTheNeedleKeepsItsStartDirection) {
  WristRig w(false);
  w.go(w.tip_start_world + Eigen::Vector3d(-0.01, 0.0, 0.01), 0.8, 0.4, 2.0);
  EXPECT_GT(axis_of(w.state()).dot(w.step.start_direction()), std::cos(1.0 * M_PI / 180));
  EXPECT_EQ(w.step.target_direction(), w.step.start_direction());
}

}  // namespace
}  // namespace needle::haptics
