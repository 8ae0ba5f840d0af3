// Position tracking terms of the teleoperation controller (thesis (3.6)-(3.12)) for robot i
// following robot j: Δq = q_i − q_j (3.8), s = q̇_i − q̇_j + Λ Δq (3.9), σ̇ = K_β s + sign(s)
// (3.10), q̇_r = q̇_j − Λ Δq − K_γ σ (3.11), s_a = q̇_i − q̇_r = s + K_γ σ (3.12).
// The printed (3.11) has q̇_r on both sides and a + on ΛΔq; this is Arteaga's form, which (3.12)
// needs to vanish on the sliding surface. The printed (3.7) reads q̇_di = q̇_i; it must be q̇_j.
#pragma once

#include "haptics/control/gains.hpp"

namespace needle::haptics {

struct TrackingTerms {
  VecN s, s_a;
};

class TrackingState {
 public:
  void reset(int n) { sigma_.setZero(n); }
  const VecN& sigma() const { return sigma_; }

  // (Λ, K_β, K_γ, q_i, q̇_i, q_j, q̇_j, T; σ) => (s, s_a; σ)   (3.6)-(3.12): s and s_a at this tick
  // (with σ before the update), then σ += T (K_β s + sign s).
  void update(const RobotGains& g, const VecN& q_i, const VecN& dq_i, const VecN& q_j, const VecN& dq_j, double T,
              TrackingTerms& out);

 private:
  VecN sigma_;
};

}  // namespace needle::haptics
