// What the trainee did with the loss-of-resistance syringe (docs/SCORING.md, "Syringe"): the losses
// of resistance (the plunger giving way as the fluid starts to flow, haptics/syringe/
// loss_of_resistance.hpp), the one in the task's syringe space and the false ones elsewhere (fat),
// the pressure before and after it, how far the tip went on along the needle after it, and whether
// the thumb is pressing. Fed one ToolSnapshot at a time on the consumer side of the sample ring;
// fixed-size state.
#pragma once

#include "haptics/realtime/tool_snapshot.hpp"
#include "haptics/syringe/loss_of_resistance.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

// Design value: the thumb presses the plunger when it pushes with more than 0.5 N (a twentieth of
// the 11 N a loss-of-resistance syringe is pressed with; a thumb resting on it presses less).
inline constexpr double kPressing_N = 0.5;

// What happened on one state.
struct SyringeEvents {
  bool pressing = false;                                     // the thumb presses the plunger
  bool false_loss = false;                                   // a loss of resistance began outside the syringe's space
  bool loss = false;                                         // the loss of resistance in the space began (the first)
  bool loss_settled = false;                                 // its pressure after was read
  double pressure_before_Pa = 0.0, pressure_after_Pa = 0.0;  // of the loss in the space, once known
  double advance_m = -1.0;  // since that loss: the tip's furthest advance along the needle (−1 before it)
};

class SyringeEventTracker {
 public:
  explicit SyringeEventTracker(const Task& task);  // keeps a reference
  const SyringeEvents& feed(const haptics::ToolSnapshot& state);

 private:
  const Task& task_;
  haptics::LossDetector detector_;
  SyringeEvents events_;
  bool found_ = false;    // the loss in the space happened
  bool settled_ = false;  // and its pressure after was read
  double loss_t_ = 0.0;   // when it began
  Vec3 tip_{}, axis_{};   // where the tip was then and along which axis
};

}  // namespace needle::training
