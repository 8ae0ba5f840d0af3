#include "haptics/anatomy/spine.hpp"

#include <algorithm>
#include <cmath>

// The shapes below are a simplified vertebra built from the dimensions of morphometry.hpp; where a
// number places a part (a fraction of the canal's depth, a radius), it is a design value chosen for
// the part's place in a textbook lumbar vertebra, and the docs (docs/PATIENTS.md) show the result.

namespace needle::haptics::anatomy {
namespace {

using Eigen::Vector3d;
constexpr double mm = 1e-3;
constexpr double kDeg = M_PI / 180.0;
constexpr double kMuscleRise_m = 0.012, kMuscleWidth_m = 0.022, kBackRadius_m = 0.2;  // design values (deep_top)
constexpr double kSpinousDroop = 10.0 * kDeg;  // design value: the spinous processes point slightly caudally

// The L1..L5 dimensions and the sacrum's first segment, taken as L5's (design value).
const VertebraDimensions& dims_of(const PatientDimensions& d, int level) {
  return d.vertebrae[size_t(std::min(level, kLumbarLevels - 1))];
}

double half_height(const VertebraDimensions& v) { return 0.25 * (v.body_height_m + v.body_anterior_height_m); }
double disc_mid(const VertebraDimensions& v) { return 0.5 * (v.disc_posterior_height_m + v.disc_anterior_height_m); }
double roof_z(const VertebraDimensions& v) { return 0.5 * v.body_depth_m + v.canal_depth_m; }
double lamina_top_y(const VertebraDimensions& v) { return half_height(v) - 0.2 * v.pedicle_height_m; }

// The segment's lordosis from its disc's wedge, less the posture's flexion (radians).
double segment_angle(const VertebraDimensions& upper, double flexion_deg) {
  return std::atan2(upper.disc_anterior_height_m - upper.disc_posterior_height_m, upper.body_depth_m) -
         flexion_deg * kDeg;
}

// Frames stacked from L3 (upright, at the origin) up and down through the discs.
std::array<VertebraFrame, 6> stack(const PatientDimensions& d, double flexion_deg) {
  std::array<VertebraFrame, 6> f;
  const auto y_of = [](double tilt) { return Vector3d(0.0, std::cos(tilt), std::sin(tilt)); };
  for (int l = 2; l >= 1; --l) {  // L2, L1 from the one below
    const VertebraDimensions& up = dims_of(d, l - 1);
    const VertebraDimensions& lo = dims_of(d, l);
    VertebraFrame& u = f[size_t(l - 1)];
    const VertebraFrame& b = f[size_t(l)];
    u.tilt = b.tilt + segment_angle(up, flexion_deg);
    const Vector3d mid = y_of(0.5 * (u.tilt + b.tilt));
    u.centre = b.centre + half_height(lo) * y_of(b.tilt) + disc_mid(up) * mid + half_height(up) * y_of(u.tilt);
  }
  for (int l = 3; l <= 5; ++l) {  // L4, L5, S1 from the one above
    const VertebraDimensions& up = dims_of(d, l - 1);
    const VertebraDimensions& lo = dims_of(d, l);
    const VertebraFrame& u = f[size_t(l - 1)];
    VertebraFrame& b = f[size_t(l)];
    b.tilt = u.tilt - segment_angle(up, flexion_deg);
    const Vector3d mid = y_of(0.5 * (u.tilt + b.tilt));
    b.centre = u.centre - half_height(up) * y_of(u.tilt) - disc_mid(up) * mid - half_height(lo) * y_of(b.tilt);
  }
  return f;
}

// Each lamina's lower edge, in its own frame, such that upright (no flexion) the midline window to
// the lamina below is the dimensions' neutral interlaminar gap, measured along the vertebra's axis.
std::array<double, 6> lamina_bottoms(const PatientDimensions& d) {
  const std::array<VertebraFrame, 6> upright = stack(d, 0.0);
  std::array<double, 6> bottom{};
  for (int l = 0; l < 5; ++l) {
    const VertebraDimensions& below = dims_of(d, l + 1);
    const Vector3d next_top = upright[size_t(l + 1)].point(Vector3d(0.0, lamina_top_y(below), roof_z(below)));
    const Vector3d local = upright[size_t(l)].axes().transpose() * (next_top - upright[size_t(l)].centre);
    bottom[size_t(l)] = local.y() + dims_of(d, l).interlaminar_gap_neutral_m;
  }
  bottom[5] = -half_height(dims_of(d, 5)) - 0.07;  // the sacrum's dorsal plate runs 70 mm below S1 (design value)
  return bottom;
}

// A box between two points (its long axis), `across` thick in x, `depth` thick in the y–z plane
// perpendicular to the axis.
RoundedBox bar(const Vector3d& a, const Vector3d& b, double half_x, double half_depth, double rounding) {
  RoundedBox box;
  box.centre = 0.5 * (a + b);
  const Vector3d u = (b - a).normalized();
  const Vector3d n = Vector3d::UnitX().cross(u).normalized();
  box.axes.col(0) = Vector3d::UnitX();
  box.axes.col(1) = u;
  box.axes.col(2) = n;
  box.half = Vector3d(half_x, 0.5 * (b - a).norm(), half_depth);
  box.rounding = rounding;
  return box;
}

// A vertebral body: a rounded prism about the frame's centre, `width_share` of the dimensions' body
// width wide (design values: corners rounded by 30 % of the depth up to 1 cm, edges by 1.5 mm).
RoundedPrism vertebral_body(const VertebraFrame& f, const VertebraDimensions& v, double width_share) {
  RoundedPrism body;
  body.centre = f.centre;
  body.axes = f.axes();
  body.half_x = width_share * v.body_width_m;
  body.half_y = half_height(v);
  body.half_z = 0.5 * v.body_depth_m;
  body.corner = std::min(0.3 * v.body_depth_m, 0.01);
  body.edge = 1.5 * mm;
  return body;
}

void add_vertebra(Spine& s, int level, double lamina_bottom) {
  const VertebraDimensions& v = dims_of(s.dims, level);
  const VertebraFrame& f = s.frames[size_t(level)];
  const Eigen::Matrix3d axes = f.axes();
  const double hh = half_height(v), half_depth = 0.5 * v.body_depth_m, half_canal = 0.5 * v.canal_width_m;
  const double top = lamina_top_y(v), lamina_mid = 0.5 * (top + lamina_bottom), roof = roof_z(v);
  const double t = v.lamina_thickness_m, ph = v.pedicle_height_m, pw = v.pedicle_width_m, vcl = v.canal_depth_m;
  const auto at = [&](double x, double y, double z) { return f.point(Vector3d(x, y, z)); };

  s.bone.push_back(vertebral_body(f, v, 0.5));

  const double pedicle_y = hh - 0.6 * ph;
  for (const double side : {-1.0, 1.0}) {
    RoundedBox pedicle;
    pedicle.centre = at(side * (half_canal + 0.5 * pw), pedicle_y, half_depth + 0.25 * vcl);
    pedicle.axes = axes;
    pedicle.half = Vector3d(0.5 * pw, 0.5 * ph, 0.25 * vcl + 2.0 * mm);
    pedicle.rounding = 0.25 * std::min(pw, ph);
    s.bone.push_back(pedicle);
    // Lamina: a plate from the pedicle's back to the midline, its front the canal's roof there.
    const Vector3d lateral = at(side * (half_canal + 0.25 * pw), lamina_mid, half_depth + 0.45 * vcl + 0.5 * t);
    const Vector3d medial = at(-side * 1.0 * mm, lamina_mid, roof + 0.5 * t);
    RoundedBox lamina;
    lamina.centre = 0.5 * (lateral + medial);
    const Vector3d u = (medial - lateral).normalized();
    lamina.axes.col(0) = u;
    lamina.axes.col(1) = axes.col(1);
    lamina.axes.col(2) = u.cross(axes.col(1)).normalized();
    lamina.half = Vector3d(0.5 * (medial - lateral).norm(), 0.5 * (top - lamina_bottom), 0.5 * t);
    lamina.rounding = 1.0 * mm;
    s.bone.push_back(lamina);
    s.bone.push_back(
        Capsule{at(side * (half_canal + 0.8 * pw), pedicle_y, half_depth + 0.35 * vcl),
                at(side * 0.5 * v.transverse_process_span_m, pedicle_y - 3.0 * mm, half_depth + 0.45 * vcl),
                0.3 * ph});  // transverse process
    // The articular pillars: the superior process rising beside the canal's roof into the window above,
    // the inferior one hanging from the lamina almost to the lamina below, medial to the superior
    // process of the vertebra below; together they close the interlaminar window at its sides.
    s.bone.push_back(Capsule{at(side * (half_canal + 0.2 * pw), hh - ph, roof - 0.35 * vcl),
                             at(side * (half_canal + 0.25 * pw), hh + 0.5 * ph, roof - 0.15 * vcl), 0.45 * ph});
    s.bone.push_back(
        Capsule{at(side * (half_canal - 0.05 * pw), lamina_mid, roof + 0.2 * t),
                at(side * half_canal, lamina_bottom - 0.8 * v.interlaminar_gap_neutral_m, roof - 0.1 * vcl), 0.4 * ph});
  }
  // Spinous process: from the laminae's junction backwards, drooping slightly.
  const Eigen::Matrix3d droop = axes * rotation_x(kSpinousDroop);
  const Vector3d base = at(0.0, lamina_mid - 0.15 * (top - lamina_bottom), roof);
  RoundedBox spinous;
  spinous.axes = droop;
  spinous.centre = base + droop * Vector3d(0.0, 0.0, 0.5 * v.spinous_process_length_m);
  spinous.half =
      Vector3d(0.5 * v.spinous_process_thickness_m, 0.5 * v.spinous_process_height_m, 0.5 * v.spinous_process_length_m);
  spinous.rounding = 2.5 * mm;
  s.bone.push_back(spinous);
  s.spinous_tips[size_t(level)] = base + droop * Vector3d(0.0, 0.0, v.spinous_process_length_m - 2.5 * mm);
}

// S1 with the sacrum beneath it (design values: a body like L5's, the bodies of S2 and S3 below it,
// the alae beside it and the dorsal plate behind, whose median crest carries the supraspinous cord).
void add_sacrum(Spine& s, double plate_bottom) {
  const VertebraDimensions& v = dims_of(s.dims, 5);
  const VertebraFrame& f = s.frames[5];
  const Eigen::Matrix3d axes = f.axes();
  const double hh = half_height(v), half_depth = 0.5 * v.body_depth_m, half_canal = 0.5 * v.canal_width_m;
  const double top = lamina_top_y(v), roof = roof_z(v), t = 1.5 * v.lamina_thickness_m;
  const auto at = [&](double x, double y, double z) { return f.point(Vector3d(x, y, z)); };
  s.bone.push_back(vertebral_body(f, v, 0.55));
  RoundedBox lower;  // S2, S3
  lower.centre = at(0.0, -hh - 0.03, -0.1 * half_depth);
  lower.axes = axes;
  lower.half = Vector3d(0.35 * v.body_width_m, 0.03, 0.8 * half_depth);
  lower.rounding = 4.0 * mm;
  s.bone.push_back(lower);
  for (const double side : {-1.0, 1.0}) {
    RoundedBox ala;
    ala.centre = at(side * (0.55 * v.body_width_m + 0.015), -0.2 * hh, 0.0);
    ala.axes = axes;
    ala.half = Vector3d(0.02, 0.8 * hh, 0.7 * half_depth);
    ala.rounding = 4.0 * mm;
    s.bone.push_back(ala);
    RoundedBox pedicle;  // the side walls of the sacral canal, joining the plate to the body
    pedicle.centre = at(side * (half_canal + 0.5 * v.pedicle_width_m), 0.5 * (top + plate_bottom),
                        half_depth + 0.5 * v.canal_depth_m);
    pedicle.axes = axes;
    pedicle.half = Vector3d(0.5 * v.pedicle_width_m, 0.5 * (top - plate_bottom), 0.5 * v.canal_depth_m + 2.0 * mm);
    pedicle.rounding = 2.0 * mm;
    s.bone.push_back(pedicle);
  }
  RoundedBox plate;  // the fused laminae
  plate.centre = at(0.0, 0.5 * (top + plate_bottom), roof + 0.5 * t);
  plate.axes = axes;
  plate.half = Vector3d(half_canal + v.pedicle_width_m, 0.5 * (top - plate_bottom), 0.5 * t);
  plate.rounding = 2.0 * mm;
  s.bone.push_back(plate);
  const Vector3d crest_top = at(0.0, top - 0.012, roof + t + 4.0 * mm),
                 crest_bottom = at(0.0, plate_bottom + 0.01, roof + t + 2.0 * mm);
  s.bone.push_back(Capsule{crest_top, crest_bottom, 4.0 * mm});  // median sacral crest
  s.spinous_tips[5] = crest_top + f.axes() * Vector3d(0.0, 0.0, 2.0 * mm);
  s.spinous_tips[6] = crest_bottom + f.axes() * Vector3d(0.0, 0.0, 2.0 * mm);
}

// The canal, the dural sac and the disc over one vertebra's height or one interspace: prisms in
// `frame` about `centre`, `half_y` long each way.
void add_canal_piece(Spine& s, const VertebraDimensions& v, const Vector3d& centre, const Eigen::Matrix3d& axes,
                     double half_y) {
  const double half_depth = 0.5 * v.body_depth_m;
  RoundedBox canal;  // from 1 mm inside the body's back to 2 mm into the roof: the cuts make its walls
  canal.centre = centre + axes * Vector3d(0.0, 0.0, half_depth + 0.5 * v.canal_depth_m + 0.5 * mm);
  canal.axes = axes;
  canal.half = Vector3d(0.5 * v.canal_width_m, half_y, 0.5 * v.canal_depth_m + 1.5 * mm);
  s.canal.push_back(canal);
  RoundedPrism sac;  // from 0.5 mm behind the body to the posterior epidural space's depth in front of the roof
  const double sac_half_z = 0.5 * (v.canal_depth_m - s.dims.posterior_epidural_depth_m - 0.5 * mm);
  sac.centre = centre + axes * Vector3d(0.0, 0.0, half_depth + 0.5 * mm + sac_half_z);
  sac.axes = axes;
  sac.half_x = 0.5 * v.canal_width_m - 4.0 * mm;
  sac.half_y = half_y;
  sac.half_z = sac_half_z;
  sac.corner = std::min(sac.half_x, sac.half_z) - 1e-5;
  s.sac.push_back(sac);
}

}  // namespace

double Spine::deep_top(double x, double y, double* dzdx, double* dzdy) const {
  // The cord's top over each tip, cranial first.
  std::array<Eigen::Vector2d, 7> p;
  for (size_t i = 0; i < 7; ++i)
    p[i] = Eigen::Vector2d(spinous_tips[i].y(), spinous_tips[i].z() + dims.supraspinous_radius_m - 1.0 * mm);
  double z = p[0].y(), slope = 0.0;
  if (y >= p[0].x()) {
    z = p[0].y();
  } else if (y <= p[6].x()) {
    z = p[6].y();
  } else {
    size_t k = 0;
    while (!(y <= p[k].x() && y >= p[k + 1].x())) ++k;
    // Catmull–Rom on the segment p[k] → p[k+1] (descending y), tangents from the neighbours.
    const auto tangent = [&](size_t i) {
      const size_t a = i == 0 ? 0 : i - 1, b = std::min<size_t>(i + 1, 6);
      return (p[b].y() - p[a].y()) / (p[b].x() - p[a].x());
    };
    const double y0 = p[k].x(), y1 = p[k + 1].x(), h = y1 - y0, u = (y - y0) / h;
    const double m0 = tangent(k) * h, m1 = tangent(k + 1) * h;
    const double u2 = u * u, u3 = u2 * u;
    z = (2 * u3 - 3 * u2 + 1) * p[k].y() + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p[k + 1].y() + (u3 - u2) * m1;
    slope = ((6 * u2 - 6 * u) * p[k].y() + (3 * u2 - 4 * u + 1) * m0 + (-6 * u2 + 6 * u) * p[k + 1].y() +
             (3 * u2 - 2 * u) * m1) /
            h;
  }
  const double w2 = 2.0 * kMuscleWidth_m * kMuscleWidth_m, rise = std::exp(-x * x / w2);
  z += kMuscleRise_m * (1.0 - rise) - x * x / (2.0 * kBackRadius_m);
  if (dzdx) *dzdx = kMuscleRise_m * rise * 2.0 * x / w2 - x / kBackRadius_m;
  if (dzdy) *dzdy = slope;
  return z;
}

Spine build_spine(const PatientDimensions& dims) {
  Spine s;
  s.dims = dims;
  s.frames = stack(dims, dims.segment_flexion_deg);
  s.lamina_bottom_y = lamina_bottoms(dims);
  for (int level = 0; level < kLumbarLevels; ++level) add_vertebra(s, level, s.lamina_bottom_y[size_t(level)]);
  add_sacrum(s, s.lamina_bottom_y[5]);

  for (int level = 0; level < 6; ++level) {
    const VertebraDimensions& v = dims_of(dims, level);
    add_canal_piece(s, v, s.frames[size_t(level)].centre, s.frames[size_t(level)].axes(), half_height(v) + 2.0 * mm);
  }
  for (int k = 0; k < 5; ++k) {
    const VertebraDimensions& up = dims_of(dims, k);
    const VertebraDimensions& lo = dims_of(dims, k + 1);
    const VertebraFrame& fu = s.frames[size_t(k)];
    const VertebraFrame& fl = s.frames[size_t(k + 1)];
    const double tilt = 0.5 * (fu.tilt + fl.tilt);
    const Eigen::Matrix3d axes = rotation_x(tilt);
    const Vector3d disc_centre =
        0.5 * (fu.point(Vector3d(0, -half_height(up), 0)) + fl.point(Vector3d(0, half_height(lo), 0)));
    add_canal_piece(s, up, disc_centre, axes, 0.5 * disc_mid(up) + 3.0 * mm);
    RoundedPrism disc;
    disc.centre = disc_centre;
    disc.axes = axes;
    disc.half_x = 0.25 * (up.body_width_m + lo.body_width_m);
    disc.half_y = 0.5 * disc_mid(up) + 3.0 * mm;
    disc.half_z = 0.25 * (up.body_depth_m + lo.body_depth_m);
    disc.corner = std::min(0.3 * up.body_depth_m, 0.01);
    disc.edge = 1.0 * mm;
    s.disc.push_back(disc);

    Interspace& is = s.interspaces[size_t(k)];
    is.upper_edge = fu.point(Vector3d(0.0, s.lamina_bottom_y[size_t(k)], roof_z(up)));
    is.lower_edge = fl.point(Vector3d(0.0, lamina_top_y(lo), roof_z(lo)));
    is.window_centre = 0.5 * (is.upper_edge + is.lower_edge);
    is.interlaminar_gap_m = (is.upper_edge - is.lower_edge).norm();
    is.spinous_gap = 0.5 * (s.spinous_tips[size_t(k)] + s.spinous_tips[size_t(k + 1)]);
    is.tilt = tilt;
    // The flavum spans the window from edge to edge, its front on the roof, 5 mm into each lamina
    // (the cut by the bone leaves the window's part), out to the facet joints.
    const Vector3d along = (is.upper_edge - is.lower_edge).normalized();
    const Vector3d back = Vector3d::UnitX().cross(along).normalized();  // towards z: posterior
    RoundedBox flavum = bar(is.lower_edge - 5.0 * mm * along, is.upper_edge + 5.0 * mm * along,
                            0.5 * up.canal_width_m + 1.0 * mm, 0.5 * dims.flavum_thickness_m, 0.0);
    flavum.centre += back * 0.5 * dims.flavum_thickness_m;
    s.flavum.push_back(flavum);
    // The interspinous ligament from just inside the flavum back to the line of the tips, between
    // the spinous processes (6 mm into each: the cut by the bone leaves the gap).
    const Vector3d front = is.window_centre + back * 0.75 * dims.flavum_thickness_m;
    const double reach = 0.5 * (s.spinous_tips[size_t(k)] - s.spinous_tips[size_t(k + 1)]).norm() + 6.0 * mm;
    s.interspinous.push_back(bar(front, is.spinous_gap, 0.5 * up.spinous_process_thickness_m, reach, 0.0));
  }
  for (size_t i = 0; i + 1 < s.spinous_tips.size(); ++i)
    s.supraspinous.push_back(Capsule{s.spinous_tips[i], s.spinous_tips[i + 1], dims.supraspinous_radius_m});

  // The bounds of the bone so far: the crests are placed against the back's deep surface.
  Vector3d lo = Vector3d::Constant(1e9), hi = Vector3d::Constant(-1e9);
  for (const ShapePrimitive& p : s.bone) {
    Vector3d a, b;
    primitive_bounds(p, a, b);
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  // Iliac crests (design values): from the posterior superior iliac spine, 40 mm beside the
  // midline at S2, up and out to the crest's top 70 mm beside it level with the middle of L4's body
  // (Tuffier's line crosses L4 or the L4–L5 interspace in most adults), 10 mm under the deep
  // surface; an 8 mm bar of bone.
  s.crest_top_y = s.frames[3].centre.y();
  const double crest_r = 8.0 * mm;
  for (const double side : {-1.0, 1.0}) {
    const double psis_y = s.frames[5].centre.y() - 0.03, top_x = side * 0.07, psis_x = side * 0.04;
    const Vector3d psis(psis_x, psis_y, s.deep_top(psis_x, psis_y) - crest_r - 0.010);
    const Vector3d top(top_x, s.crest_top_y, s.deep_top(top_x, s.crest_top_y) - crest_r - 0.010);
    s.iliac_crest.push_back(Capsule{psis, top, crest_r});
    s.iliac_crest.push_back(Capsule{top, top + Vector3d(side * 0.005, -0.03, -0.03), crest_r});
  }
  for (const ShapePrimitive& p : s.iliac_crest) {
    Vector3d a, b;
    primitive_bounds(p, a, b);
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  s.lo = lo;
  s.hi = hi;
  s.lateral_extent_m = std::max(std::abs(lo.x()), std::abs(hi.x()));
  return s;
}

}  // namespace needle::haptics::anatomy
