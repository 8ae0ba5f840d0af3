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

// The layered tissue at the needle, as the last sub-step of the tick left it: what the
// task layer needs to say "the tip is in layer L", "layer L was punctured", "bone was touched",
// and what the renderer needs for the dimple. Layers are the scenario tissue's indices (outside
// in); recorded from payload version 2 on (haptics/recording/session_format.hpp).
struct TissueSnapshot {
  int32_t tip_layer = -1;  // the layer holding the tip, -1 outside the tissue (or still tenting the first surface)
  uint32_t punctured_layers = 0;  // bit i: the current track has passed into layer i (its surface punctured, or
                                  // entered where it has none); a full withdrawal clears it
  int32_t surface_layer = -1;     // the layer whose surface the tip presses (tents), -1 when none
  int32_t bone_layer = -1;        // the rigid layer (bone) holding the tip against its surface, -1 when none
  double axial_force_N = 0.0;     // needle on tissue along the needle axis, > 0 while it resists the advance
  double bone_force_n[3] = {0.0, 0.0, 0.0};  // tool on bone (F_v of thesis eq. 3.16) while bone_layer >= 0
  double deflection_m = 0.0;                 // the pressed surface's deflection along the needle (the dimple's depth)
  double surface_point_m[3] = {0.0, 0.0, 0.0};  // where the tip met that surface, at rest, world frame
};

// The loss-of-resistance syringe on the needle's hub (haptics/syringe/), in a session that has one:
// the thumb, the plunger and the barrel as the tick left them. Recorded from payload version 3 on.
struct SyringeSnapshot {
  uint32_t fluid = 0;          // 0: no syringe; 1 saline, 2 air (haptics::SyringeFluid)
  int32_t layer = -1;          // the tissue layer the needle's opening is in at the end of the tick (the one
                               // holding the tip, or whose surface gave way in the tick): where fluid goes;
                               // −1 in none. Set with or without a syringe.
  double thumb_force_N = 0.0;  // the thumb's force on the plunger
  double pressure_Pa = 0.0;    // in the barrel, gauge
  double travel_m = 0.0;       // the plunger from full
  double flow_m3_per_s = 0.0;  // out of the barrel through the needle into the tissue
  double injected_m3 = 0.0;    // fluid gone into the tissue since the start (air at the atmosphere's pressure)
  double work_J = 0.0;         // the thumb's work on the plunger since the start
};

// ToolSnapshot::limits: what held the tick's force back, one bit each.
inline constexpr uint32_t kLimitForce = 1u;  // the safety monitor saturated the command at the device's limit
inline constexpr uint32_t kLimitRate = 2u;   // ... or limited its rate of change
inline constexpr uint32_t kLimitPassivityDamper =
    4u;  // the passivity controller withheld or damped (the world owed energy)

struct ToolSnapshot {
  uint64_t tick = 0;
  double time_s = 0.0;
  double needle_tip_m[3] = {0.0, 0.0, 0.0};             // world frame
  double needle_orientation[4] = {1.0, 0.0, 0.0, 0.0};  // unit quaternion w, x, y, z
  double virtual_q[kMaxSnapshotJoints] = {};            // virtual robot joints
  double virtual_dq[kMaxSnapshotJoints] = {};
  uint32_t joint_count = 0;
  ContactState contact = ContactState::kFree;
  int32_t active_constraint = -1;  // index in the scene, -1 when free
  uint32_t multiplier_count = 0;
  double multipliers[kMaxMultipliers] = {};         // Lagrange multipliers lambda
  double operator_force_n[3] = {0.0, 0.0, 0.0};     // sensed or estimated F_h
  double environment_force_n[3] = {0.0, 0.0, 0.0};  // F_v = J_phi^T lambda
  double device_force_n[3] = {0.0, 0.0, 0.0};       // what the device was commanded
  uint32_t fault = 0;                               // haptics::FaultCause, 0 when none
  uint32_t limits = 0;                              // kLimit* bits; recordings made before they existed hold 0 here

  TissueSnapshot tissue;
  SyringeSnapshot syringe;
};

// Whether `layer` (a tissue layer's index) is in the snapshot's punctured set.
inline bool punctured(const TissueSnapshot& t, int layer) {
  return layer >= 0 && layer < 32 && (t.punctured_layers >> layer & 1u) != 0;
}

// The needle axis x5 in the world: the unit quaternion (w, x, y, z) applied to the body x axis
// (the needle has its tip at the origin, pointing along +x).
inline std::array<double, 3> needle_axis(const ToolSnapshot& s) {
  const double w = s.needle_orientation[0], x = s.needle_orientation[1], y = s.needle_orientation[2],
               z = s.needle_orientation[3];
  return {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)};
}

}  // namespace needle::haptics
