// The ultrasound probe a task places on the skin (docs/TASKS.md, "Ultrasound"): what the image of
// the task shows, and what the needle's visibility is measured against. The imaged region is a
// slice: the image's rectangle (across the array's width, from the face to the imaging depth)
// thickened by the elevation beam's width.
#pragma once

#include "training/tasks/vec3.hpp"

namespace needle::training {

struct UltrasoundProbeSpec {
  Vec3 position{};                 // centre of the transducer face, world (m)
  Vec3 direction{0.0, 0.0, -1.0};  // the beams', unit
  Vec3 lateral{1.0, 0.0, 0.0};     // along the array, unit, perpendicular to direction
  double depth_m = 0.05;
  double width_m = 0.04;
  double frequency_MHz = 7.5;
  double slice_thickness_m = 0.0015;  // elevation beam width

  Vec3 elevation() const;  // direction × lateral
};

// p lies in the imaged slice: within half the slice thickness of the image plane, within half the
// width of the array's centre line, between the face and the imaging depth.
bool in_image_slice(const UltrasoundProbeSpec& probe, const Vec3& p);

// The share of the segment from `entry` to `tip` inside the imaged slice, in [0, 1] (exact: each
// bound is a plane); a needle just in (no length yet) counts whole when its tip is in the slice.
double share_in_image_slice(const UltrasoundProbeSpec& probe, const Vec3& entry, const Vec3& tip);

}  // namespace needle::training
