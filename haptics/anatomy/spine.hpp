// Where the patient's lumbar spine is and what it is made of: the vertebrae stacked on their discs
// with the lordosis the discs' wedges give, less the posture's flexion, and each structure as
// analytic primitives (shape_primitives.hpp), before they are sampled and cut from each other
// (patient.cpp). Patient frame: x to the patient's right, y cranial, z posterior (out of the back),
// metres; the body of L3 upright with its centre at the origin.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "haptics/anatomy/morphometry.hpp"
#include "haptics/anatomy/shape_primitives.hpp"

namespace needle::haptics::anatomy {

// A vertebra's frame: the centre of its body and its tilt about x (its axis y turned towards z,
// radians).
struct VertebraFrame {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double tilt = 0.0;
  Eigen::Matrix3d axes() const { return rotation_x(tilt); }
  Eigen::Vector3d point(const Eigen::Vector3d& local) const { return centre + axes() * local; }
};

// An interspace's landmarks on the midline.
struct Interspace {
  Eigen::Vector3d window_centre;    // the middle of the interlaminar window on the canal's roof (the flavum's front)
  Eigen::Vector3d upper_edge;       // the upper lamina's lower edge there
  Eigen::Vector3d lower_edge;       // the lower lamina's upper edge there
  Eigen::Vector3d spinous_gap;      // between the spinous processes' tips
  double tilt = 0.0;                // the mean of the two vertebrae's
  double interlaminar_gap_m = 0.0;  // |upper_edge − lower_edge|
};

struct Spine {
  PatientDimensions dims;
  std::array<VertebraFrame, 6> frames;  // L1..L5, S1
  std::array<Interspace, 5> interspaces;
  std::array<Eigen::Vector3d, 7> spinous_tips;  // L1..L5, then the sacrum's median crest at S1 and S3
  std::array<double, 6> lamina_bottom_y{};      // each lamina's lower edge in its vertebra's frame (L1..L5, S1's plate)
  double crest_top_y = 0.0;                     // the iliac crests' highest point (Tuffier's line), patient frame
  double lateral_extent_m = 0.0;                // |x| of the farthest structure (the crests), patient frame
  Eigen::Vector3d lo, hi;                       // the structures' bounds, patient frame

  // The top of the deep tissue, where the subcutaneous fat ends: z of the erector spinae's and
  // the supraspinous ligament's posterior surface at (x, y), and its slopes ∂z/∂x, ∂z/∂y. On the
  // midline a smooth curve (Catmull–Rom) through the supraspinous cord's top over each tip, less
  // 1 mm (so the cord reaches it and is cut by it); beside it the erector spinae rise by
  // kMuscleRise_m·(1 − exp(−x²/2w²)), w = 22 mm, and the back falls away as x²/2R, R = 0.2 m
  // (design values: the midline furrow between the muscles, the back's transverse curve).
  double deep_top(double x, double y, double* dzdx = nullptr, double* dzdy = nullptr) const;

  // The primitives of each structure, before the cuts.
  std::vector<ShapePrimitive> bone, iliac_crest, flavum, canal, sac, interspinous, disc;
  std::vector<Capsule> supraspinous;  // the cord over the spinous processes' tips
};

// (dimensions) => the spine in the patient frame.
Spine build_spine(const PatientDimensions& dims);

}  // namespace needle::haptics::anatomy
