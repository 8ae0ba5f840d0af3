#include "haptics/control/passivity_control.hpp"

#include <algorithm>

namespace needle::haptics {

void observe_passivity(const VecN& q_m, double stored_J, PassivityObserver& obs) {
  if (!obs.started) {
    obs.started = true;
    obs.q_prev = q_m;
    obs.tau_prev.setZero(q_m.size());
    obs.absorbed_J = 0.0;
    obs.stored0_J = stored_J;
  }
  obs.absorbed_J -= obs.tau_prev.dot(q_m - obs.q_prev);
  obs.q_prev = q_m;
  obs.stored_J = stored_J;
  obs.dissipated_J = obs.absorbed_J - (stored_J - obs.stored0_J);
}

double predicted_dissipation(const VecN& tau_m, const VecN& dq_m, double T, double stored_next_J,
                             const PassivityObserver& obs) {
  return obs.dissipated_J - T * tau_m.dot(dq_m) - (stored_next_J - obs.stored_J);
}

void passivity_control(const PassivityGains& gains, const DeviceLimit& limit, const MatN& H_m, const VecN& dq_m,
                       const VecN& tau_conservative, double T, PassivityObserver& obs, VecN& tau_m) {
  const double predicted_J = obs.predicted_J;
  obs.damping_per_s = 0.0;
  obs.share_withheld = 0.0;
  if (!passivity_owed(gains, predicted_J)) return;
  // The active part withheld in proportion to the deficit; what it would have done over the tick, undone.
  const double active_work = T * (tau_m - tau_conservative).dot(dq_m);
  obs.share_withheld = std::min(1.0, -predicted_J / gains.full_at_J);
  tau_m = tau_conservative + (1.0 - obs.share_withheld) * (tau_m - tau_conservative);
  const double left = predicted_J + obs.share_withheld * active_work;
  if (!(left < 0.0)) return;
  // The damper on the actuated joints, H_aa q̇_a, for what is left, within the device's limit.
  const int m = limit.actuated_joints;
  VecN h = VecN::Zero(dq_m.size());
  h.head(m).noalias() = H_m.topLeftCorner(m, m) * dq_m.head(m);
  const double twice_kinetic = dq_m.head(m).dot(h.head(m));  // q̇_aᵀH_aa q̇_a
  if (!(twice_kinetic > 0.0)) return;                        // at rest: nothing to damp
  const double beta =
      std::min({gains.max_damping_per_tick / T, -left / (T * twice_kinetic), room_within_limit(limit, tau_m, h)});
  obs.damping_per_s = beta;
  tau_m.noalias() -= beta * h;
}

void passivity_virtual_damping(const PassivityGains& gains, const MatN& H_v, const VecN& dq_v, double T,
                               PassivityObserver& obs, VecN& B_v) {
  obs.virtual_damping_per_s = 0.0;
  if (!passivity_owed(gains, obs.dissipated_J)) return;
  const double twice_kinetic = dq_v.dot(H_v.diagonal().cwiseProduct(dq_v));
  if (!(twice_kinetic > 0.0)) return;
  obs.virtual_damping_per_s = std::min(gains.max_damping_per_tick / T, -obs.dissipated_J / (T * twice_kinetic));
  B_v += obs.virtual_damping_per_s * H_v.diagonal();
}

}  // namespace needle::haptics
