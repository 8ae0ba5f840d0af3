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
  obs.dissipated_J = obs.absorbed_J - (stored_J - obs.stored0_J);
}

void passivity_control(const PassivityGains& gains, const MatN& H_m, const VecN& dq_m, const VecN& tau_conservative,
                       double T, PassivityObserver& obs, VecN& tau_m) {
  obs.damping_per_s = 0.0;
  obs.share_withheld = 0.0;
  if (!gains.enabled() || obs.dissipated_J >= 0.0) return;
  obs.share_withheld = std::min(1.0, -obs.dissipated_J / gains.full_at_J);
  tau_m = tau_conservative + (1.0 - obs.share_withheld) * (tau_m - tau_conservative);
  const VecN h_dq = H_m * dq_m;
  const double twice_kinetic = dq_m.dot(h_dq);  // q̇ᵀH q̇
  if (!(twice_kinetic > 0.0)) return;            // at rest: nothing to damp
  obs.damping_per_s = std::min(gains.max_damping_per_tick / T, -obs.dissipated_J / (T * twice_kinetic));
  tau_m.noalias() -= obs.damping_per_s * h_dq;
}

void passivity_virtual_damping(const PassivityGains& gains, const MatN& H_v, const VecN& dq_v, double T,
                               PassivityObserver& obs, VecN& B_v) {
  obs.virtual_damping_per_s = 0.0;
  if (!gains.enabled() || obs.dissipated_J >= 0.0) return;
  const double twice_kinetic = dq_v.dot(H_v.diagonal().cwiseProduct(dq_v));
  if (!(twice_kinetic > 0.0)) return;
  obs.virtual_damping_per_s = std::min(gains.max_damping_per_tick / T, -obs.dissipated_J / (T * twice_kinetic));
  B_v += obs.virtual_damping_per_s * H_v.diagonal();
}

}  // namespace needle::haptics
