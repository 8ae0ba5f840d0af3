// The analytic pieces a patient's structures are built from, each a signed distance (φ < 0 inside,
// metres, exact or a lower bound of the distance outside) with the box that holds it: a box with
// rounded edges in any orientation, a capsule, and a prism of rounded-rectangle section (a
// vertebral body). Sampled onto a lattice by LatticeField.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <variant>

namespace needle::haptics::anatomy {

// Centre, orientation (columns: the box's axes in the world) and half sizes; edges rounded by
// `rounding` (≤ the smallest half size).
struct RoundedBox {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half = Eigen::Vector3d::Constant(0.001);
  double rounding = 0.0;
};

struct Capsule {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  double radius = 0.001;
};

// Along its local y axis (half length `half_y`, edges rounded by `edge`) a section in local x–z
// that is a rectangle of half sizes half_x, half_z with corners of radius `corner`.
struct RoundedPrism {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  double half_x = 0.001, half_y = 0.001, half_z = 0.001, corner = 0.0, edge = 0.0;
};

using ShapePrimitive = std::variant<RoundedBox, Capsule, RoundedPrism>;

double primitive_phi(const ShapePrimitive& p, const Eigen::Vector3d& x);
// The primitive's axis-aligned bounds: lo, hi.
void primitive_bounds(const ShapePrimitive& p, Eigen::Vector3d& lo, Eigen::Vector3d& hi);

// The rotation about the x axis by `angle` (radians): y turns towards z.
inline Eigen::Matrix3d rotation_x(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

}  // namespace needle::haptics::anatomy
