#include "haptics/model/urdf_loader.hpp"

#include <Eigen/Eigenvalues>
#include <fstream>
#include <sstream>
#include <urdf_parser/urdf_parser.h>

namespace needle::haptics {
namespace {

Eigen::Isometry3d to_isometry(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized().toRotationMatrix();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  return t;
}

[[noreturn]] void fail(const std::string& source, const std::string& what) { throw UrdfError(source + ": " + what); }

// A link's own mass properties expressed in `frame_of_link` (the frame the link's origin is at).
BodyInertia link_inertia(const urdf::Link& link, const Eigen::Isometry3d& frame_of_link, const std::string& source) {
  BodyInertia b;
  if (!link.inertial) return b;
  const urdf::Inertial& in = *link.inertial;
  const std::string where = "link '" + link.name + "' <inertial>: ";
  if (!(in.mass > 0.0)) fail(source, where + "mass must be positive, got " + std::to_string(in.mass));
  Eigen::Matrix3d i;
  i << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(i);
  const Eigen::Vector3d e = eig.eigenvalues();
  if (!(e.minCoeff() > 0.0)) fail(source, where + "inertia tensor must be positive definite (smallest eigenvalue " + std::to_string(e.minCoeff()) + ")");
  // A rigid body's principal moments obey the triangle inequality (each ≤ sum of the other two).
  const double slack = 1e-12 * e.maxCoeff();
  if (e[0] + e[1] < e[2] - slack) fail(source, where + "principal moments violate the triangle inequality (no rigid body has them)");
  const Eigen::Isometry3d t = frame_of_link * to_isometry(in.origin);
  b.mass = in.mass;
  b.com = t.translation();
  b.inertia_com = t.linear() * i * t.linear().transpose();
  return b;
}

// Two bodies rigidly joined, both expressed in the same frame (parallel-axis theorem).
BodyInertia combine(const BodyInertia& a, const BodyInertia& b) {
  if (b.mass == 0.0) return a;
  if (a.mass == 0.0) return b;
  BodyInertia c;
  c.mass = a.mass + b.mass;
  c.com = (a.mass * a.com + b.mass * b.com) / c.mass;
  auto shift = [&](const BodyInertia& x) {
    const Eigen::Vector3d d = x.com - c.com;
    return Eigen::Matrix3d(x.inertia_com + x.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
  };
  c.inertia_com = shift(a) + shift(b);
  return c;
}

}  // namespace

RobotModel parse_robot_urdf(const std::string& xml, const std::string& source, std::optional<int> expected_dof) {
  urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(xml);
  if (!urdf) fail(source, "not a valid URDF document (urdfdom rejected it)");
  urdf::LinkConstSharedPtr link = urdf->getRoot();
  if (!link) fail(source, "no root link");

  RobotModel model;
  model.name = urdf->getName();
  model.base_link = link->name;
  Eigen::Isometry3d pending = Eigen::Isometry3d::Identity();  // current joint frame (or base) to `link`
  while (!link->child_joints.empty()) {
    if (link->child_joints.size() > 1) fail(source, "link '" + link->name + "' has " + std::to_string(link->child_joints.size()) + " child joints; only a serial chain is supported");
    const urdf::Joint& joint = *link->child_joints.front();
    link = urdf->getLink(joint.child_link_name);
    const Eigen::Isometry3d to_joint = pending * to_isometry(joint.parent_to_joint_origin_transform);
    switch (joint.type) {
      case urdf::Joint::FIXED:
        pending = to_joint;
        if (!model.joints.empty()) model.joints.back().body = combine(model.joints.back().body, link_inertia(*link, pending, source));
        break;
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS: {
        JointModel j;
        j.name = joint.name;
        j.origin = to_joint;
        const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
        if (!(axis.norm() > 1e-9)) fail(source, "joint '" + joint.name + "': <axis> must be a nonzero vector");
        j.axis = axis.normalized();
        if (joint.dynamics) {
          if (joint.dynamics->damping < 0.0) fail(source, "joint '" + joint.name + "' <dynamics>: damping must be non-negative");
          j.damping = joint.dynamics->damping;
        }
        j.body = link_inertia(*link, Eigen::Isometry3d::Identity(), source);
        model.joints.push_back(j);
        pending = Eigen::Isometry3d::Identity();
        break;
      }
      default:
        fail(source, "joint '" + joint.name + "': unsupported type (only revolute, continuous and fixed)");
    }
  }
  model.tip_link = link->name;
  model.tool = pending;

  if (model.joints.empty()) fail(source, "no revolute or continuous joint");
  if (model.dof() > kMaxDof) fail(source, std::to_string(model.dof()) + " movable joints, at most " + std::to_string(kMaxDof) + " supported");
  if (expected_dof && model.dof() != *expected_dof)
    fail(source, std::to_string(model.dof()) + " movable joints, expected " + std::to_string(*expected_dof));
  for (const JointModel& j : model.joints)
    if (!(j.body.mass > 0.0)) fail(source, "joint '" + j.name + "' moves no mass (its child link needs an <inertial>)");
  return model;
}

RobotModel load_robot_urdf(const std::string& path, std::optional<int> expected_dof) {
  std::ifstream in(path);
  if (!in) throw UrdfError(path + ": cannot open");
  std::stringstream text;
  text << in.rdbuf();
  return parse_robot_urdf(text.str(), path, expected_dof);
}

}  // namespace needle::haptics
