#include "haptics/syringe/syringe_insertion.hpp"

#include <algorithm>
#include <stdexcept>

#include "haptics/syringe/loss_of_resistance.hpp"
#include "haptics/syringe/syringe_step.hpp"

namespace needle::haptics {

SyringeInsertionRun run_syringe_insertion(const TissueModel& model, const InsertionPlan& plan,
                                          const SyringeDrive& drive) {
  for (const TissueLayer& layer : model.layers())
    if (!layer.mechanics.rigid && !layer.injection)
      throw std::invalid_argument("layer \"" + layer.name + "\" has no injection parameters, which the syringe needs");
  const SyringeParams& p = drive.params;
  SyringeInsertionRun run;
  SyringeState state = syringe_at_rest(p);
  LossDetector losses;
  bool pressing = false;
  double deepest = -1.0;
  run.insertion = run_kinematic_insertion(model, plan, [&](long tick, double depth, const TissueOutput& out) {
    const LayerInjection* tip = out.opening_layer >= 0 ? &*model.layer(out.opening_layer).injection : nullptr;
    const bool advancing = depth > deepest;  // the thumb presses while the needle goes in, not while held or withdrawn
    deepest = std::max(deepest, depth);
    pressing =
        advancing && (pressing || (tip && tip->opening_pressure_Pa * p.plunger_area_m2 >= drive.plunger_force_N));
    step_syringe(p, state, pressing ? drive.plunger_force_N : 0.0, flow_path(p, tip), plan.period_s);
    run.samples.push_back({state.pressure_Pa, state.travel_m});
    if (losses.add(double(tick) * plan.period_s, state.flow_m3_per_s, state.pressure_Pa, out.opening_layer,
                   state.thumb_force_N))
      run.losses.push_back(
          {depth, out.opening_layer, losses.current().pressure_before_Pa, losses.current().pressure_after_Pa});
    if (losses.settled_now()) {
      run.losses.back().pressure_after_Pa = losses.current().pressure_after_Pa;
      pressing = false;  // the loss felt: the thumb lets go until the plunger is held again
    }
  });
  run.work_J = state.work_J;
  return run;
}

}  // namespace needle::haptics
