#include "haptics/syringe/loss_of_resistance.hpp"

#include <algorithm>

namespace needle::haptics {

bool LossDetector::add(double t_s, double flow_m3_per_s, double pressure_Pa, int layer, double thumb_force_N) {
  settled_now_ = false;
  if (any_ && !current_.settled && t_s >= current_.t_s + kLossSettle_s - 1e-9) {
    current_.pressure_after_Pa = pressure_Pa;
    current_.settled = settled_now_ = true;
  }
  const bool flowing = flow_m3_per_s > kLossFlow_m3_per_s && thumb_force_N > 0.0;
  const bool begins = flowing && !flowing_;
  if (begins) {
    current_ = {t_s, layer, held_peak_Pa_, pressure_Pa, false};
    any_ = true;
    held_peak_Pa_ = 0.0;
  }
  if (!flowing) held_peak_Pa_ = std::max(held_peak_Pa_, pressure_Pa);
  flowing_ = flowing;
  return begins;
}

}  // namespace needle::haptics
