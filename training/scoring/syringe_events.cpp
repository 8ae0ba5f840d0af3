#include "training/scoring/syringe_events.hpp"

#include <algorithm>

namespace needle::training {

SyringeEventTracker::SyringeEventTracker(const Task& task) : task_(task) {}

const SyringeEvents& SyringeEventTracker::feed(const haptics::ToolSnapshot& s) {
  SyringeEvents& e = events_;
  e.pressing = s.syringe.thumb_force_N > kPressing_N;
  e.false_loss = e.loss = e.loss_settled = false;
  const int space = task_.syringe ? task_.syringe->space : -1;
  if (detector_.add(s.time_s, s.syringe.flow_m3_per_s, s.syringe.pressure_Pa, s.syringe.layer,
                    s.syringe.thumb_force_N)) {
    if (detector_.current().layer != space) {
      e.false_loss = true;
    } else if (!found_) {
      e.loss = found_ = true;
      loss_t_ = detector_.current().t_s;
      e.pressure_before_Pa = detector_.current().pressure_before_Pa;
      tip_ = vec3(s.needle_tip_m);
      const auto axis = haptics::needle_axis(s);
      axis_ = {axis[0], axis[1], axis[2]};
      e.advance_m = 0.0;
    }
  }
  if (found_ && !settled_ && detector_.settled_now() && detector_.current().t_s == loss_t_) {
    e.loss_settled = settled_ = true;
    e.pressure_after_Pa = detector_.current().pressure_after_Pa;
  }
  if (found_) e.advance_m = std::max(e.advance_m, dot(vec3(s.needle_tip_m) - tip_, axis_));
  return e;
}

}  // namespace needle::training
