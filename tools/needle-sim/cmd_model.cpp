// needle-sim model: a robot's kinematics and dynamics at one state, as JSON on stdout.
#include <cstdio>

#include "arg_list.hpp"
#include "command.hpp"
#include "haptics/model/model_report.hpp"
#include "haptics/model/urdf_loader.hpp"

namespace needle::cli {
namespace {

haptics::VecN joint_vector(const std::vector<double>& values, int dof, const std::string& flag) {
  if (static_cast<int>(values.size()) != dof)
    throw UsageError(flag + " has " + std::to_string(values.size()) + " values, the robot has " + std::to_string(dof) + " joints");
  return Eigen::Map<const Eigen::VectorXd>(values.data(), dof);
}

int run_model(ArgList& args) {
  const std::string robot = args.required("--robot");
  const std::string q_text = args.required("--q");
  const auto dq_text = args.value("--dq");
  const auto ddq_text = args.value("--ddq");
  args.finish();
  const haptics::RobotModel model = haptics::load_robot_urdf(robot);
  const int n = model.dof();
  const haptics::VecN q = joint_vector(parse_number_list(q_text, "--q"), n, "--q");
  const haptics::VecN dq = dq_text ? joint_vector(parse_number_list(*dq_text, "--dq"), n, "--dq") : haptics::VecN::Zero(n);
  const haptics::VecN ddq =
      ddq_text ? joint_vector(parse_number_list(*ddq_text, "--ddq"), n, "--ddq") : haptics::VecN::Zero(n);
  std::printf("%s\n", haptics::model_report(model, q, dq, ddq).dump(2).c_str());
  return 0;
}

const CommandRegistrar reg{{"model",
                            "needle-sim model --robot FILE.urdf --q q1,...,qn [--dq ...] [--ddq ...]\n"
                            "  --robot FILE.urdf  serial robot of revolute joints (assets/robots/)\n"
                            "  --q    joint angles in rad, URDF chain order\n"
                            "  --dq   joint velocities in rad/s (default 0)\n"
                            "  --ddq  joint accelerations in rad/s² (default 0)\n"
                            "  prints JSON: pose {p, R}, J, H, Cdq, g, gravity, tau_id (SI units, base frame)",
                            run_model}};

}  // namespace
}  // namespace needle::cli
