#include "haptics/control/tracking.hpp"

namespace needle::haptics {

void TrackingState::update(const RobotGains& g, const VecN& q_i, const VecN& dq_i, const VecN& q_j, const VecN& dq_j,
                           double T, TrackingTerms& out) {
  out.s = dq_i - dq_j + g.Lambda.cwiseProduct(q_i - q_j);
  out.s_a = out.s + g.Kgamma.cwiseProduct(sigma_);
  sigma_ += T * (g.Kbeta.cwiseProduct(out.s) + out.s.unaryExpr([](double v) { return double((v > 0) - (v < 0)); }));
}

}  // namespace needle::haptics
