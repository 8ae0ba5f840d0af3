#include "training/tasks/ultrasound_probe.hpp"

#include <algorithm>

namespace needle::training {
namespace {

// The imaged slice as three slabs: |offset·axis − centre| ≤ half.
struct Slab {
  Vec3 axis;
  double centre, half;
};

std::array<Slab, 3> slabs(const UltrasoundProbeSpec& p) {
  return {Slab{p.elevation(), 0.0, 0.5 * p.slice_thickness_m}, Slab{p.lateral, 0.0, 0.5 * p.width_m},
          Slab{p.direction, 0.5 * p.depth_m, 0.5 * p.depth_m}};
}

}  // namespace

Vec3 UltrasoundProbeSpec::elevation() const {
  const Vec3& d = direction;
  const Vec3& l = lateral;
  return {d[1] * l[2] - d[2] * l[1], d[2] * l[0] - d[0] * l[2], d[0] * l[1] - d[1] * l[0]};
}

bool in_image_slice(const UltrasoundProbeSpec& probe, const Vec3& p) {
  const Vec3 offset = p - probe.position;
  const std::array<Slab, 3> all = slabs(probe);
  return std::all_of(all.begin(), all.end(),
                     [&](const Slab& s) { return std::abs(dot(offset, s.axis) - s.centre) <= s.half; });
}

double share_in_image_slice(const UltrasoundProbeSpec& probe, const Vec3& entry, const Vec3& tip) {
  const Vec3 along = tip - entry, start = entry - probe.position;
  if (norm(along) == 0.0) return in_image_slice(probe, tip) ? 1.0 : 0.0;
  double lo = 0.0, hi = 1.0;  // of the segment entry + s (tip − entry)
  for (const Slab& slab : slabs(probe)) {
    const double a = dot(start, slab.axis) - slab.centre, b = dot(along, slab.axis);  // a + s b
    if (b == 0.0) {
      if (std::abs(a) > slab.half) return 0.0;
      continue;
    }
    const double s0 = (-slab.half - a) / b, s1 = (slab.half - a) / b;
    lo = std::max(lo, std::min(s0, s1));
    hi = std::min(hi, std::max(s0, s1));
  }
  return std::max(0.0, hi - lo);
}

}  // namespace needle::training
