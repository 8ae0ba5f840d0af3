#include "haptics/realtime/virtual_state.hpp"

#include <Eigen/Geometry>
#include <algorithm>

namespace needle::haptics {
namespace {

ContactState contact_of(ContactMode mode) {
  switch (mode) {
    case ContactMode::Holonomic:
      return ContactState::kRigidSurface;
    case ContactMode::Nonholonomic:
      return ContactState::kTissue;
    case ContactMode::Free:
      break;
  }
  return ContactState::kFree;
}

}  // namespace

void publish_virtual_state(const VirtualWorld& world, const Eigen::Vector3d& base_in_world, double dt_s,
                           ToolSnapshot& state) noexcept {
  const ContactReport& c = world.report();
  const Eigen::Vector3d tip = world.data().tip.translation() + base_in_world;
  const Eigen::Quaterniond orientation(world.data().tip.linear());
  state.time_s += dt_s;
  state.joint_count = static_cast<uint32_t>(std::min(world.q().size(), Eigen::Index{kMaxSnapshotJoints}));
  for (uint32_t j = 0; j < state.joint_count; ++j) {
    state.virtual_q[j] = world.q()[j];
    state.virtual_dq[j] = world.dq()[j];
  }
  for (int i = 0; i < 3; ++i) {
    state.needle_tip_m[i] = tip[i];
    state.environment_force_n[i] = c.force_rigid[i];
  }
  state.needle_orientation[0] = orientation.w();
  state.needle_orientation[1] = orientation.x();
  state.needle_orientation[2] = orientation.y();
  state.needle_orientation[3] = orientation.z();
  state.contact = contact_of(c.mode);
  // The scene holds one rigid surface (constraint 0) and one tissue (constraint 1).
  const bool rigid = c.mode == ContactMode::Holonomic, tissue = c.mode == ContactMode::Nonholonomic;
  state.active_constraint = rigid ? 0 : tissue ? 1 : -1;
  state.multiplier_count = rigid ? 1 : tissue ? 2 : 0;
  state.multipliers[0] = rigid ? c.lambda_rigid : tissue ? c.lambda_tissue[0] : 0.0;
  state.multipliers[1] = tissue ? c.lambda_tissue[1] : 0.0;

  const TissueState& track = world.tissue();
  TissueSnapshot& t = state.tissue;
  t.tip_layer = track.on_track ? track.out.holding_layer : -1;
  state.syringe.layer = track.on_track ? track.out.opening_layer : -1;
  t.punctured_layers = passed_layers(track);
  t.surface_layer = track.on_track ? track.out.surface_layer : -1;
  t.bone_layer = c.bone_layer;
  t.axial_force_N = c.axial_force_N;
  t.deflection_m = t.surface_layer >= 0 ? track.out.deflection_m : 0.0;
  const Eigen::Vector3d met = track.out.contact_point + base_in_world;
  for (int i = 0; i < 3; ++i) {
    t.bone_force_n[i] = c.bone_layer >= 0 ? c.force_rigid[i] : 0.0;
    t.surface_point_m[i] = t.surface_layer >= 0 ? met[i] : 0.0;
  }
}

}  // namespace needle::haptics
