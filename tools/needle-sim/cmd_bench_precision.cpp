// needle-sim bench precision: work-precision table of the integrators on the needle-in-tissue
// dynamics of the virtual robot, steps 4 ms down to 62.5 µs, error against RK4 at 1/64 of the
// smallest step, constraint drift, fitted and theoretical convergence order.
#include <cstdio>

#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "haptics/model/urdf_loader.hpp"
#include "haptics/sim/work_precision.hpp"

namespace needle::cli {
namespace {

struct PrecisionFlags {
  std::optional<std::string> robot, json;
  double horizon_s = haptics::PrecisionProblem{}.horizon_s;
};

int run(const PrecisionFlags& f) {
  const std::string robot = f.robot.value_or((asset_dir() / "robots" / "virtual_needle_robot.urdf").string());
  const haptics::RobotModel model = haptics::load_robot_urdf(robot, 5);
  haptics::PrecisionProblem p;
  p.model = &model;
  p.q0 = (haptics::VecN(5) << 0.0, 1.0, -1.6, 0.0, 0.5).finished();    // scenario home pose
  p.dq0 = (haptics::VecN(5) << 0.2, -0.3, 0.4, 0.5, -0.5).finished();  // includes a lateral tip speed
  p.tau = haptics::VecN::Constant(5, 0.01);
  p.horizon_s = f.horizon_s;

  const std::vector<double> steps = {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5};
  const double reference_dt = steps.back() / 64;
  const haptics::VecN reference = haptics::reference_solution(p, reference_dt);
  BenchTable table(
      {"integrator", "dt_s", "steps", "time_per_step_us", "error", "drift_mps", "fitted_order", "theoretical_order"});
  for (haptics::Integrator integrator : {haptics::Integrator::SemiImplicitEuler, haptics::Integrator::Rk4}) {
    std::vector<haptics::PrecisionRow> rows;
    for (double dt : steps) rows.push_back(haptics::run_precision(p, integrator, dt, &reference));
    const double order = haptics::fitted_order(rows);
    for (const auto& r : rows)
      table.add_row({std::string(haptics::integrator_name(integrator)), r.dt_s, r.steps, r.time_per_step_us, r.error,
                     r.drift, order, haptics::integrator_order(integrator)});
  }
  table.emit("work-precision, virtual robot in tissue, horizon " + std::to_string(p.horizon_s) +
                 " s, reference RK4 at " + std::to_string(reference_dt * 1e6) + " us (error: |q - q_ref| in rad)",
             f.json);
  return 0;
}

// The options of bench precision, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<PrecisionFlags>();
  add_text(app, "--robot", f->robot, "FILE.urdf", "5-DOF robot (default assets/robots/virtual_needle_robot.urdf)");
  add_number(app, "--horizon", f->horizon_s, kPrecisionHorizon_s, "S",
             "simulated time per run, a multiple of every step");
  add_output_file(app, "--json", f->json, "FILE",
                  "also write the rows as JSON (integrator, dt_s, time_per_step_us, error, ...)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench precision", "work-precision table of the integrators on the needle-in-tissue dynamics", declare}};

}  // namespace
}  // namespace needle::cli
