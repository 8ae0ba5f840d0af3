#include "haptics/model/kinematics.hpp"

#include <cmath>

namespace needle::haptics {

[[gnu::flatten]] void point_jacobian(const RobotData& data, int body, const Eigen::Vector3d& p,
                                     const Eigen::Vector3d& p_velocity, Mat6N& J, Mat6N& Jdot) {
  J.setZero(6, data.n);
  Jdot.setZero(6, data.n);
  for (int j = 0; j <= body; ++j) {
    const Eigen::Vector3d& z = data.axis[j];
    const Eigen::Vector3d r = p - data.origin[j];
    // The axis is fixed in body j, so it turns with that body's angular velocity.
    const Eigen::Vector3d z_dot = data.omega[j].cross(z);
    J.col(j).head<3>() = z.cross(r);
    J.col(j).tail<3>() = z;
    Jdot.col(j).head<3>() = z_dot.cross(r) + z.cross(p_velocity - data.origin_velocity[j]);
    Jdot.col(j).tail<3>() = z_dot;
  }
}

namespace {

// Rotation by `angle` about the unit `axis` (Rodrigues): c I + s [a]× + (1 − c) a aᵀ.
Eigen::Matrix3d axis_rotation(const Eigen::Vector3d& a, double angle) {
  const double s = std::sin(angle), c = std::cos(angle), v = 1.0 - c;
  Eigen::Matrix3d r;
  r << c + v * a.x() * a.x(), v * a.x() * a.y() - s * a.z(), v * a.x() * a.z() + s * a.y(),
      v * a.y() * a.x() + s * a.z(), c + v * a.y() * a.y(), v * a.y() * a.z() - s * a.x(),
      v * a.z() * a.x() - s * a.y(), v * a.z() * a.y() + s * a.x(), c + v * a.z() * a.z();
  return r;
}

// [[gnu::flatten]] here and on the other per-tick functions: GCC at -O2 leaves Eigen's fixed-size
// 3×3 products as out-of-line calls, a third of the tick before; inlined, they unroll.
template <bool with_com_jacobians>
[[gnu::flatten]] void kinematics(const RobotModel& model, RobotData& data, const VecN& q, const VecN& dq) {
  data.q = q;
  data.dq = dq;
  // Rotation and translation kept apart (not as Isometry3d products): the same arithmetic, in
  // fixed-size operations the compiler unrolls.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_prev = Eigen::Vector3d::Zero();
  for (int i = 0; i < data.n; ++i) {
    const JointModel& joint = model.joints[static_cast<size_t>(i)];
    position.noalias() += rotation * joint.origin.translation();
    if (joint.origin.linear() != Eigen::Matrix3d::Identity()) rotation = (rotation * joint.origin.linear()).eval();
    data.origin[i] = position;
    data.axis[i].noalias() = rotation * joint.axis;
    // p_i is fixed in body i-1 (it lies on the axis of joint i).
    data.origin_velocity[i] =
        i == 0 ? Eigen::Vector3d::Zero().eval()
               : (data.origin_velocity[i - 1] + omega_prev.cross(data.origin[i] - data.origin[i - 1])).eval();
    rotation = (rotation * axis_rotation(joint.axis, q[i])).eval();
    data.frame[i].linear() = rotation;
    data.frame[i].translation() = position;
    data.omega[i] = omega_prev + data.axis[i] * dq[i];
    omega_prev = data.omega[i];
    data.com[i] = position + rotation * joint.body.com;
    if constexpr (with_com_jacobians) {
      const Eigen::Vector3d com_velocity = data.origin_velocity[i] + data.omega[i].cross(data.com[i] - data.origin[i]);
      point_jacobian(data, i, data.com[i], com_velocity, data.J_com[i], data.Jdot_com[i]);
    }
  }
  const int last = data.n - 1;
  data.tip = data.frame[last] * model.tool;
  const Eigen::Vector3d p = data.tip.translation();
  const Eigen::Vector3d v = data.origin_velocity[last] + data.omega[last].cross(p - data.origin[last]);
  point_jacobian(data, last, p, v, data.J, data.Jdot);
  data.tip_twist << v, data.omega[last];
}

}  // namespace

void update_kinematics(const RobotModel& model, RobotData& data, const VecN& q, const VecN& dq) {
  kinematics<true>(model, data, q, dq);
}

void update_frames(const RobotModel& model, RobotData& data, const VecN& q, const VecN& dq) {
  kinematics<false>(model, data, q, dq);
}

Eigen::Isometry3d tip_pose(const RobotModel& model, const VecN& q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int i = 0; i < model.dof(); ++i) {
    const JointModel& joint = model.joints[static_cast<size_t>(i)];
    t = t * joint.origin;
    t.rotate(Eigen::AngleAxisd(q[i], joint.axis));
  }
  return t * model.tool;
}

}  // namespace needle::haptics
