// Kinematics of the Novint Falcon, a three-leg translational delta (Stamper's parallel
// manipulator). Geometry constants as published by libnifalcon
// (include/falcon/core/FalconGeometry.h, after R. E. Stamper, "A Three Degree of Freedom
// Parallel Manipulator with Only Translational Degrees of Freedom", PhD thesis, University
// of Maryland, 1997, tech. report PhD 97-4, p. 30). The leg equations below are derived here
// from that geometry, not taken from libnifalcon's code.
//
// Leg i is rotated by phi_i about z. In its frame (u, v, w) the handle centre is
//   u = a cos(t1) + L cos(t2) - c,   v = b cos(t3) - f,   w = a sin(t1) + L sin(t2),
//   L = d + e + b sin(t3),
// where t1 is the actuated hip angle, t2 and t3 the passive parallelogram angles, and the
// leg frame is p_leg = Rz(-phi_i) x - (r, s, 0).
#pragma once

#include <array>
#include <cstdint>

namespace needle::haptics::falcon {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<std::array<double, 3>, 3>;  // row-major

struct Geometry {
  double a = 0.060;     // hip to knee, m
  double b = 0.1025;    // parallelogram (shin) length, m
  double c = 0.01443;   // shin joint to handle centre, u component, m
  double d = 0.01125;   // shin to handle joint, m
  double e = 0.01125;   // knee to shin joint, m
  double f = -0.025;    // shin joint to handle centre, v component, m
  double r = 0.0400;    // base origin to leg base, u component, m
  double s = -0.02309;  // base origin to leg base, v component, m
  // Leg angles about z: 90, -30, -150 degrees, each tilted 15 degrees from the desk plane.
  std::array<double, 3> phi = {1.8325957145940461, -0.2617993877991494, -2.3561944901923448};
};

struct LegAngles {
  Vec3 hip{};   // t1, actuated (the encoders measure these)
  Vec3 knee{};  // t2
  Vec3 shin{};  // t3
};

// Closed form. False when the position is outside the reachable set (no real solution).
// Of the two elbow configurations the one with the knee outward is the Falcon's.
bool inverse_kinematics(const Geometry& g, const Vec3& position, LegAngles& out);

// d(hip angles)/d(position), analytic (implicit differentiation of the leg closure
// equation). False at a singular pose.
bool hip_jacobian(const Geometry& g, const Vec3& position, Mat3& dtheta_dx);

// Newton iteration on inverse_kinematics from `guess` (the last solution makes a good one).
// False when it does not converge to |hip error| < 1e-12 rad within 30 iterations.
bool forward_kinematics(const Geometry& g, const Vec3& hip, const Vec3& guess, Vec3& position);

// Joint torques for a handle force, tau = J^T F with J = dx/dtheta (so tau . dtheta =
// F . dx). When a torque exceeds max_torque_nm, all three are scaled by the same factor so
// the force keeps its direction. False at a singular pose (torques zero).
bool torques_for_force(const Geometry& g, const Vec3& position, const Vec3& force_n, double max_torque_nm,
                       Vec3& torque_nm);

}  // namespace needle::haptics::falcon

namespace needle::haptics::falcon {

// The drive: each hip is turned by a capstan (a cable on the motor shaft, diameter 14.25
// mm, wound on the arm's drum, diameter 110 mm); the motor's encoder wheel has 320 slots,
// read in quadrature (4 counts per slot). Encoder 0 is the hip at about 35 degrees
// (libnifalcon FalconGeometry.h and FalconKinematic.h::getTheta give the same numbers).
struct Drive {
  double shaft_diameter_m = 0.01425;
  double drum_diameter_m = 0.110;
  double counts_per_motor_turn = 320.0 * 4.0;
  double zero_angle_rad = 35.0 * 3.14159265358979323846 / 180.0;
  // Motor command per hip torque; the firmware takes the negative (libnifalcon
  // FalconKinematicStamper::getForces scales N m by -10000).
  double command_per_nm = -10000.0;
};

// Hip angle in radians for an encoder count: the arm turns by the cable length the shaft
// winds, (count / counts per turn) * pi * shaft diameter, over the drum's pi * diameter.
double encoder_to_hip_angle(const Drive& drive, int encoder_count);
// The 16-bit motor command for a hip torque, clamped to the int16 range.
int16_t torque_to_command(const Drive& drive, double torque_nm);

}  // namespace needle::haptics::falcon
