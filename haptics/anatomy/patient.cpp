#include "haptics/anatomy/patient.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics::anatomy {
namespace {

using Eigen::Vector3d;
constexpr double mm = 1e-3;
constexpr int kL3L4 = 2;

// The skin's height above the deep surface at (x, y): the offset o along the surface's normal.
double skin_height(const Spine& s, double x, double y, double offset, double* slope_norm = nullptr) {
  double dzdx = 0.0, dzdy = 0.0;
  const double top = s.deep_top(x, y, &dzdx, &dzdy);
  const double norm = std::sqrt(1.0 + dzdx * dzdx + dzdy * dzdy);
  if (slope_norm) *slope_norm = norm;
  return top + offset * norm;
}

// The offset o = skin + fat over the deep surface such that the midline approach to L3–L4, from the
// skin over the spinous processes' gap to the window's centre, is `depth` long (the skin point moves
// along z with o: |E(o) − W| = depth solved for o); at least the skin and 2 mm of fat (design value).
double offset_for_depth(const Spine& s, double depth, double skin) {
  const Interspace& is = s.interspaces[kL3L4];
  double norm = 1.0;
  const double top = skin_height(s, 0.0, is.spinous_gap.y(), 0.0, &norm);
  const double dy = is.spinous_gap.y() - is.window_centre.y();
  const double dz = std::sqrt(std::max(depth * depth - dy * dy, 0.0));
  return std::max((is.window_centre.z() + dz - top) / norm, skin + 2.0 * mm);
}

}  // namespace

Patient generate_patient(const PatientParams& params, const Eigen::Vector3d& l3_l4_entry, const Lattice& base_lattice) {
  Patient p;
  p.params = params;
  p.spine = build_spine(patient_dimensions(params));
  const Spine& s = p.spine;
  const PatientDimensions& d = s.dims;
  Lattice lattice = base_lattice;
  const int skin_q = int(std::lround(d.skin_thickness_m / lattice.quantum_m));
  const int deep_q =
      int(std::lround(offset_for_depth(s, d.skin_to_epidural_l3_l4_m, d.skin_thickness_m) / lattice.quantum_m));
  const double offset = deep_q * lattice.quantum_m;
  p.fat_thickness_m = offset - skin_q * lattice.quantum_m;
  for (int k = 0; k < 5; ++k) {
    const Interspace& is = s.interspaces[size_t(k)];
    p.approaches[size_t(k)].entry = Vector3d(0.0, is.spinous_gap.y(), skin_height(s, 0.0, is.spinous_gap.y(), offset));
    p.approaches[size_t(k)].window = is.window_centre;
  }
  p.origin = l3_l4_entry - p.approaches[kL3L4].entry;
  lattice.origin = p.origin;
  for (Approach& a : p.approaches) a = {p.to_model(a.entry), p.to_model(a.window)};
  for (size_t side = 0; side < 2; ++side) {
    const double x = side == 0 ? -0.07 : 0.07;  // the crests' tops (spine.cpp)
    p.crest_tops[side] = p.to_model(Vector3d(x, s.crest_top_y, s.deep_top(x, s.crest_top_y)));
  }

  // The body beneath the skin, to 8 mm beyond the structures on every side and 10 mm in front of
  // them, up to the skin's highest point.
  const double half_x = s.lateral_extent_m + 8.0 * mm;
  double top = -1e9;
  for (double x = -half_x; x <= half_x; x += 5.0 * mm)
    for (double y = s.lo.y() - 8.0 * mm; y <= s.hi.y() + 8.0 * mm; y += 5.0 * mm)
      top = std::max(top, skin_height(s, x, y, offset));
  LatticeField body(lattice, Vector3d(-half_x, s.lo.y() - 8.0 * mm, s.lo.z() - 10.0 * mm),
                    Vector3d(half_x, s.hi.y() + 8.0 * mm, top + 3.0 * mm), 0, 0.0);
  body.assign_beneath([&](double x, double y, double& dzdx, double& dzdy) { return s.deep_top(x, y, &dzdx, &dzdy); },
                      offset);

  // Each structure: its primitives, 3 nodes of margin, a lower bound of the distance (the fill) of
  // 8 mm for bone (a tracer's steps) and 4 mm for the rest; then the cuts, in order of precedence.
  const auto field = [&](const auto& primitives, double fill) {
    Vector3d lo = Vector3d::Constant(1e9), hi = Vector3d::Constant(-1e9);
    for (const auto& prim : primitives) {
      Vector3d a, b;
      primitive_bounds(ShapePrimitive(prim), a, b);
      lo = lo.cwiseMin(a);
      hi = hi.cwiseMax(b);
    }
    LatticeField f(lattice, lo, hi, 3, fill);
    for (const auto& prim : primitives) f.add(ShapePrimitive(prim), fill);
    f.intersect(body, deep_q);  // within the deep tissue, beneath the fat
    return f;
  };
  LatticeField bone = field(s.bone, 8.0 * mm);
  LatticeField crest = field(s.iliac_crest, 8.0 * mm);
  crest.subtract(bone);  // the crests stand where they are in every adult; a tall one's sacrum reaches them
  LatticeField flavum = field(s.flavum, 4.0 * mm);
  flavum.subtract(bone);
  LatticeField epidural = field(s.canal, 4.0 * mm);
  epidural.subtract(bone);
  epidural.subtract(flavum);
  LatticeField dura = field(s.sac, 4.0 * mm);
  dura.intersect(epidural, 0);
  LatticeField supraspinous = field(s.supraspinous, 4.0 * mm);
  supraspinous.subtract(bone);
  LatticeField interspinous = field(s.interspinous, 4.0 * mm);
  for (const LatticeField* cut : {&bone, &flavum, &supraspinous, &epidural}) interspinous.subtract(*cut);
  LatticeField disc = field(s.disc, 4.0 * mm);
  disc.subtract(bone);
  disc.subtract(epidural);

  const auto body_grid = body.grid();
  const auto dura_grid = dura.grid();
  const double dura_offset = std::lround(d.dura_thickness_m / lattice.quantum_m) * lattice.quantum_m;
  const std::array<LayerShape, kPatientLayers.size()> shapes{LayerShape::grid(body_grid, 0.0),
                                                             LayerShape::grid(body_grid, skin_q * lattice.quantum_m),
                                                             LayerShape::grid(body_grid, offset),
                                                             LayerShape::grid(supraspinous.grid()),
                                                             LayerShape::grid(interspinous.grid()),
                                                             LayerShape::grid(flavum.grid()),
                                                             LayerShape::grid(epidural.grid()),
                                                             LayerShape::grid(dura_grid),
                                                             LayerShape::grid(dura_grid, dura_offset),
                                                             LayerShape::grid(disc.grid()),
                                                             LayerShape::grid(bone.grid()),
                                                             LayerShape::grid(crest.grid())};
  for (size_t i = 0; i < shapes.size(); ++i)
    p.layers.push_back({kPatientLayers[i].name, shapes[i], kPatientLayers[i].parameters, kPatientLayers[i].rigid});
  std::vector<const SdfGrid*> counted;
  for (const PatientLayer& l : p.layers)
    if (std::find(counted.begin(), counted.end(), l.shape.grid().get()) == counted.end()) {
      counted.push_back(l.shape.grid().get());
      p.field_bytes += l.shape.grid()->bytes();
    }
  return p;
}

SurfaceMesh layer_surface(const Patient& patient, size_t layer, int stride) {
  const LayerShape& shape = patient.layers.at(layer).shape;
  int rank = 0;
  for (size_t i = 0; i < layer; ++i) rank += patient.layers[i].shape.grid() == shape.grid();
  return extract_surface(*shape.grid(), shape.grid_offset(), stride, 0.5e-3 * rank);
}

TissueModel geometry_model(const Patient& patient) {
  std::vector<TissueLayer> layers;
  for (const PatientLayer& l : patient.layers) {
    LayerMechanics m;
    m.rigid = l.rigid;
    layers.push_back({l.name, l.shape, m});
  }
  return TissueModel(std::move(layers));
}

}  // namespace needle::haptics::anatomy
