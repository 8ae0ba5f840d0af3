// needle-sim bench precision: work-precision table of the integrators on the needle-in-tissue
// dynamics of the virtual robot, steps 4 ms down to 62.5 µs, error against RK4 at 1/64 of the
// smallest step, constraint drift, fitted and theoretical convergence order.
#include <cstdio>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "haptics/model/urdf_loader.hpp"
#include "haptics/sim/work_precision.hpp"

namespace needle::cli {
namespace {

int run_bench_precision(ArgList& args) {
  const std::string robot =
      args.value("--robot").value_or((asset_dir() / "robots" / "virtual_needle_robot.urdf").string());
  const auto horizon_text = args.value("--horizon");
  const auto json = output_file(args, "--json");
  args.finish();
  const haptics::RobotModel model = haptics::load_robot_urdf(robot, 5);
  haptics::PrecisionProblem p;
  p.model = &model;
  p.q0 = (haptics::VecN(5) << 0.0, 1.0, -1.6, 0.0, 0.5).finished();   // scenario home pose
  p.dq0 = (haptics::VecN(5) << 0.2, -0.3, 0.4, 0.5, -0.5).finished(); // includes a lateral tip speed
  p.tau = haptics::VecN::Constant(5, 0.01);
  if (horizon_text) p.horizon_s = parse_number(*horizon_text, "--horizon");
  if (!(p.horizon_s > 0.004)) throw UsageError("--horizon must exceed the largest step, 4 ms");

  const std::vector<double> steps = {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5};
  const double reference_dt = steps.back() / 64;
  const haptics::VecN reference = haptics::reference_solution(p, reference_dt);
  BenchTable table({"integrator", "dt_s", "steps", "time_per_step_us", "error", "drift_mps", "fitted_order", "theoretical_order"});
  for (haptics::Integrator integrator : {haptics::Integrator::SemiImplicitEuler, haptics::Integrator::Rk4}) {
    std::vector<haptics::PrecisionRow> rows;
    for (double dt : steps) rows.push_back(haptics::run_precision(p, integrator, dt, &reference));
    const double order = haptics::fitted_order(rows);
    for (const auto& r : rows)
      table.add_row({std::string(haptics::integrator_name(integrator)), r.dt_s, r.steps, r.time_per_step_us, r.error, r.drift,
                     order, haptics::integrator_order(integrator)});
  }
  table.emit("work-precision, virtual robot in tissue, horizon " + std::to_string(p.horizon_s) + " s, reference RK4 at " +
                 std::to_string(reference_dt * 1e6) + " us (error: |q - q_ref| in rad)",
             json);
  return 0;
}

const CommandRegistrar reg{{"bench precision",
                            "needle-sim bench precision [--robot FILE.urdf] [--horizon S] [--json FILE]\n"
                            "  --robot FILE.urdf  5-DOF robot (default assets/robots/virtual_needle_robot.urdf)\n"
                            "  --horizon S        simulated time per run (default 0.256, a multiple of every step)\n"
                            "  --json FILE        also write the rows as JSON (integrator, dt_s, time_per_step_us, error, ...)",
                            run_bench_precision}};

}  // namespace
}  // namespace needle::cli
