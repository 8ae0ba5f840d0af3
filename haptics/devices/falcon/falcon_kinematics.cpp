#include "haptics/devices/falcon/falcon_kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics::falcon {
namespace {

struct LegFrame {
  double u, v, w;
  double cos_phi, sin_phi;
};

LegFrame leg_frame(const Geometry& g, int leg, const Vec3& x) {
  const double cp = std::cos(g.phi[leg]), sp = std::sin(g.phi[leg]);
  return {cp * x[0] + sp * x[1] - g.r, -sp * x[0] + cp * x[1] - g.s, x[2], cp, sp};
}

bool solve_leg(const Geometry& g, const LegFrame& p, double& hip, double& knee, double& shin) {
  const double cos_shin = (p.v + g.f) / g.b;
  if (!(std::abs(cos_shin) <= 1.0)) return false;
  shin = std::acos(cos_shin);
  const double length = g.d + g.e + g.b * std::sin(shin);
  // Two-link planar problem in (u + c, w): hip link a, then the link of length L.
  const double uc = p.u + g.c;
  const double rho = std::hypot(uc, p.w);
  const double cos_alpha = (rho * rho + g.a * g.a - length * length) / (2.0 * g.a * rho);
  if (!(std::abs(cos_alpha) <= 1.0)) return false;
  hip = std::atan2(p.w, uc) - std::acos(cos_alpha);  // knee outward
  knee = std::atan2(p.w - g.a * std::sin(hip), uc - g.a * std::cos(hip));
  return true;
}

double det3(const Mat3& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Solves m y = rhs by Cramer's rule.
bool solve3(const Mat3& m, const Vec3& rhs, Vec3& y) {
  const double det = det3(m);
  if (!(std::abs(det) > 1e-12)) return false;
  for (int col = 0; col < 3; ++col) {
    Mat3 replaced = m;
    for (int row = 0; row < 3; ++row) replaced[row][col] = rhs[row];
    y[col] = det3(replaced) / det;
  }
  return true;
}

Mat3 transpose(const Mat3& m) {
  Mat3 t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = m[j][i];
  return t;
}

}  // namespace

bool inverse_kinematics(const Geometry& g, const Vec3& position, LegAngles& out) {
  for (int leg = 0; leg < 3; ++leg)
    if (!solve_leg(g, leg_frame(g, leg, position), out.hip[leg], out.knee[leg], out.shin[leg])) return false;
  return true;
}

bool hip_jacobian(const Geometry& g, const Vec3& position, Mat3& dtheta_dx) {
  for (int leg = 0; leg < 3; ++leg) {
    const LegFrame p = leg_frame(g, leg, position);
    double hip = 0, knee = 0, shin = 0;
    if (!solve_leg(g, p, hip, knee, shin)) return false;
    // Leg closure h = (u + c - a cos t1)^2 + (w - a sin t1)^2 - L(v)^2 = 0, so
    // dt1/dp = -(dh/dp) / (dh/dt1), with dL/dv = -cot(t3).
    const double sin_shin = std::sin(shin);
    if (!(sin_shin > 1e-9)) return false;
    const double length = g.d + g.e + g.b * sin_shin;
    const double uc = p.u + g.c, c1 = std::cos(hip), s1 = std::sin(hip);
    const double dh_dt1 = 2.0 * g.a * (uc * s1 - p.w * c1);
    if (!(std::abs(dh_dt1) > 1e-12)) return false;
    const double dh_du = 2.0 * (uc - g.a * c1);
    const double dh_dv = 2.0 * length * std::cos(shin) / sin_shin;
    const double dh_dw = 2.0 * (p.w - g.a * s1);
    const double dt_du = -dh_du / dh_dt1, dt_dv = -dh_dv / dh_dt1, dt_dw = -dh_dw / dh_dt1;
    // du/dx = (cos phi, sin phi, 0), dv/dx = (-sin phi, cos phi, 0), dw/dx = (0, 0, 1).
    dtheta_dx[leg] = {dt_du * p.cos_phi - dt_dv * p.sin_phi, dt_du * p.sin_phi + dt_dv * p.cos_phi, dt_dw};
  }
  return true;
}

bool forward_kinematics(const Geometry& g, const Vec3& hip, const Vec3& guess, Vec3& position) {
  Vec3 x = guess;
  LegAngles angles;
  if (!inverse_kinematics(g, x, angles)) return false;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Vec3 error = {angles.hip[0] - hip[0], angles.hip[1] - hip[1], angles.hip[2] - hip[2]};
    if (std::max({std::abs(error[0]), std::abs(error[1]), std::abs(error[2])}) < 1e-12) {
      position = x;
      return true;
    }
    Mat3 jac;
    Vec3 step;
    if (!hip_jacobian(g, x, jac) || !solve3(jac, error, step)) return false;
    // Newton step, halved while it leaves the reachable set.
    double scale = 1.0;
    Vec3 next;
    for (int halving = 0;; ++halving) {
      next = {x[0] - scale * step[0], x[1] - scale * step[1], x[2] - scale * step[2]};
      if (inverse_kinematics(g, next, angles)) break;
      if (halving == 20) return false;
      scale *= 0.5;
    }
    x = next;
  }
  return false;
}

bool torques_for_force(const Geometry& g, const Vec3& position, const Vec3& force_n, double max_torque_nm,
                       Vec3& torque_nm) {
  torque_nm = {0.0, 0.0, 0.0};
  Mat3 dtheta_dx;
  // J = dx/dtheta = (dtheta/dx)^-1, so tau = J^T F solves (dtheta/dx)^T tau = F.
  if (!hip_jacobian(g, position, dtheta_dx) || !solve3(transpose(dtheta_dx), force_n, torque_nm)) {
    torque_nm = {0.0, 0.0, 0.0};
    return false;
  }
  const double largest = std::max({std::abs(torque_nm[0]), std::abs(torque_nm[1]), std::abs(torque_nm[2])});
  if (largest > max_torque_nm) {
    const double scale = max_torque_nm / largest;
    for (double& t : torque_nm) t *= scale;
  }
  return true;
}

double encoder_to_hip_angle(const Drive& drive, int encoder_count) {
  const double motor_turns = encoder_count / drive.counts_per_motor_turn;
  const double arm_turns = motor_turns * drive.shaft_diameter_m / drive.drum_diameter_m;
  return drive.zero_angle_rad + arm_turns * 2.0 * 3.14159265358979323846;
}

int16_t torque_to_command(const Drive& drive, double torque_nm) {
  const double counts = std::round(torque_nm * drive.command_per_nm);
  return static_cast<int16_t>(std::clamp(counts, -32767.0, 32767.0));
}

}  // namespace needle::haptics::falcon
