// needle-sim model: a robot's kinematics and dynamics at one state, as JSON on stdout.
#include <cstdio>
#include <limits>

#include "command.hpp"
#include "haptics/model/model_report.hpp"
#include "haptics/model/urdf_loader.hpp"

namespace needle::cli {
namespace {

struct ModelFlags {
  std::optional<std::string> robot;
  std::vector<double> q, dq, ddq;
};

haptics::VecN joint_vector(const std::vector<double>& values, int dof, const std::string& flag) {
  if (values.empty()) return haptics::VecN::Zero(dof);
  if (static_cast<int>(values.size()) != dof)
    throw UsageError(flag + " has " + std::to_string(values.size()) + " values, the robot has " + std::to_string(dof) +
                     " joints");
  return Eigen::Map<const Eigen::VectorXd>(values.data(), dof);
}

int run(const ModelFlags& f) {
  const haptics::RobotModel model = haptics::load_robot_urdf(*f.robot);
  const int n = model.dof();
  if (f.q.empty()) throw UsageError("--q is required");
  const haptics::VecN q = joint_vector(f.q, n, "--q");
  std::printf(
      "%s\n",
      haptics::model_report(model, q, joint_vector(f.dq, n, "--dq"), joint_vector(f.ddq, n, "--ddq")).dump(2).c_str());
  return 0;
}

// The options of model, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<ModelFlags>();
  // A joint's angle, speed or acceleration: any finite number (the model says when a state is not finite).
  const NumberRange joint{-std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  const size_t joints = haptics::kMaxDof;
  add_text(app, "--robot", f->robot, "FILE.urdf", "serial robot of revolute joints (assets/robots/)")->required();
  add_number_list(app, "--q", f->q, joint, "q1,...,qn", "joint angles in rad, URDF chain order", joints)->required();
  add_number_list(app, "--dq", f->dq, joint, "LIST", "joint velocities in rad/s (default 0)", joints);
  add_number_list(app, "--ddq", f->ddq, joint, "LIST", "joint accelerations in rad/s² (default 0)", joints);
  app.footer("prints JSON: pose {p, R}, J, H, Cdq, g, gravity, tau_id (SI units, base frame)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{{"model", "a robot model's pose, Jacobian and dynamics at one state, as JSON", declare}};

}  // namespace
}  // namespace needle::cli
