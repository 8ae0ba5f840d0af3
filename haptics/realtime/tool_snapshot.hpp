// The newest state of the simulated tool, published by the haptic loop for the renderer
// and the UI. Plain arrays only (no Eigen): training and the panels read it without the
// physics (docs/ARCHITECTURE.md).
#pragma once

#include <array>
#include <cstdint>

namespace needle::haptics {

enum class ContactState : uint32_t {
  kFree = 0,          // no constraint active
  kRigidSurface = 1,  // holonomic contact (thesis eq. 2.25-2.28)
  kTissue = 2,        // nonholonomic insertion (thesis eq. 2.29-2.33)
};

inline constexpr int kMaxSnapshotJoints = 8;
inline constexpr int kMaxMultipliers = 4;

struct ToolSnapshot {
  uint64_t tick = 0;
  double time_s = 0.0;
  double needle_tip_m[3] = {0.0, 0.0, 0.0};                   // world frame
  double needle_orientation[4] = {1.0, 0.0, 0.0, 0.0};        // unit quaternion w, x, y, z
  double virtual_q[kMaxSnapshotJoints] = {};                  // virtual robot joints
  double virtual_dq[kMaxSnapshotJoints] = {};
  uint32_t joint_count = 0;
  ContactState contact = ContactState::kFree;
  int32_t active_constraint = -1;  // index in the scene, -1 when free
  uint32_t multiplier_count = 0;
  double multipliers[kMaxMultipliers] = {};  // Lagrange multipliers lambda
  double operator_force_n[3] = {0.0, 0.0, 0.0};     // sensed or estimated F_h
  double environment_force_n[3] = {0.0, 0.0, 0.0};  // F_v = J_phi^T lambda
  double device_force_n[3] = {0.0, 0.0, 0.0};       // what the device was commanded
  uint32_t fault = 0;  // haptics::FaultCause, 0 when none
  uint32_t reserved = 0;
};

// The needle axis x5 in the world: the unit quaternion (w, x, y, z) applied to the body x axis
// (the needle has its tip at the origin, pointing along +x).
inline std::array<double, 3> needle_axis(const ToolSnapshot& s) {
  const double w = s.needle_orientation[0], x = s.needle_orientation[1], y = s.needle_orientation[2],
               z = s.needle_orientation[3];
  return {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)};
}

}  // namespace needle::haptics
