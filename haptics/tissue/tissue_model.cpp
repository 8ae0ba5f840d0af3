#include "haptics/tissue/tissue_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace needle::haptics {
namespace {

// "must be in [0, 10000] N/m, got 1e+300".
template <class Set>
std::string out_of_range(const ParameterField<Set>& f, double lo, double value) {
  char text[128];
  std::snprintf(text, sizeof text, "must be in [%g, %g]%s%s, got %g", lo, f.max, *f.unit ? " " : "", f.unit, value);
  return text;
}

}  // namespace

std::optional<MechanicsProblem> mechanics_problem(const LayerMechanics& m) {
  for (const auto& f : kMechanicsFields) {
    const double value = m.*f.member;
    if (!(value >= 0.0 && value <= f.max)) return MechanicsProblem{f.key, out_of_range(f, 0.0, value)};
    if (m.rigid && value != 0.0)
      return MechanicsProblem{f.key, "a rigid layer takes no other parameter (it is the GPM contact of (3.15))"};
  }
  if (m.puncture_force_N > 0.0 && m.stiffness_N_per_m == 0.0 && m.stiffness2_N_per_m2 == 0.0)
    return MechanicsProblem{
        "puncture_force_N",
        "needs stiffness_N_per_m or stiffness2_N_per_m2 > 0 (a surface without stiffness never reaches it)"};
  if (m.static_friction_N_per_m < m.friction_N_per_m)
    return MechanicsProblem{"static_friction_N_per_m",
                            "must be >= friction_N_per_m (the stick limit is at least the slip force)"};
  return std::nullopt;
}

double tent_depth_m(const LayerMechanics& m) {
  if (m.rigid || !(m.puncture_force_N > 0.0)) return 0.0;
  const double k1 = m.stiffness_N_per_m, k2 = m.stiffness2_N_per_m2, f = m.puncture_force_N;
  if (k2 == 0.0) return f / k1;
  return 2.0 * f / (k1 + std::sqrt(k1 * k1 + 4.0 * k2 * f));  // the positive root, without cancellation
}

std::optional<MechanicsProblem> acoustics_problem(const LayerAcoustics& a) {
  for (const auto& f : kAcousticsFields)
    if (!std::isfinite(a.*f.member) || a.*f.member > f.max)
      return MechanicsProblem{f.key, out_of_range(f, 0.0, a.*f.member)};
  if (!(a.impedance_MRayl > 0.0)) return MechanicsProblem{"impedance_MRayl", "must be > 0"};
  if (!(a.attenuation_dB_per_cm_MHz >= 0.0)) return MechanicsProblem{"attenuation_dB_per_cm_MHz", "must be >= 0"};
  if (!(a.echogenicity >= 0.0 && a.echogenicity <= 1.0)) return MechanicsProblem{"echogenicity", "must be in [0, 1]"};
  if (!(a.scatterer_density > 0.0 && a.scatterer_density <= 1.0))
    return MechanicsProblem{"scatterer_density", "must be in (0, 1]"};
  return std::nullopt;
}

std::optional<MechanicsProblem> injection_problem(const LayerInjection& i) {
  for (const auto& f : kInjectionFields)
    if (!(i.*f.member >= 0.0 && i.*f.member <= f.max))
      return MechanicsProblem{f.key, out_of_range(f, 0.0, i.*f.member)};
  return std::nullopt;
}

TissueModel::TissueModel(std::vector<TissueLayer> layers, StickParams stick)
    : layers_(std::move(layers)), stick_(stick) {
  if (!(stick_.stiffness_N_per_m > 0.0) || !(stick_.band_mps > 0.0))
    throw std::invalid_argument("stick stiffness and band must be > 0");
  std::vector<LayerShape> shapes;
  for (int i = 0; i < layer_count(); ++i) {
    const TissueLayer& l = layers_[size_t(i)];
    if (i == kMaxLayers) throw TissueLayerError(i, "name", "at most " + std::to_string(kMaxLayers) + " layers");
    if (l.name.empty()) throw TissueLayerError(i, "name", "a layer needs a name");
    for (int k = 0; k < i; ++k)
      if (layers_[size_t(k)].name == l.name)
        throw TissueLayerError(i, "name", "\"" + l.name + "\" names an earlier layer too");
    if (const auto p = mechanics_problem(l.mechanics)) throw TissueLayerError(i, p->key, p->what);
    if (l.acoustics)
      if (const auto p = acoustics_problem(*l.acoustics))
        throw TissueLayerError(i, std::string("ultrasound/") + p->key, p->what);
    if (l.injection && l.mechanics.rigid)
      throw TissueLayerError(i, "injection", "a rigid layer takes no injection (the tip never enters it)");
    if (l.injection)
      if (const auto p = injection_problem(*l.injection))
        throw TissueLayerError(i, std::string("injection/") + p->key, p->what);
    shapes.push_back(l.shape);
  }
  if (const auto c = find_layer_conflict(shapes))
    throw TissueLayerError(c->later, "shape",
                           std::string(layer_conflict_text(c->kind)) + " (layer " + std::to_string(c->earlier) +
                               ", \"" + layers_[size_t(c->earlier)].name + "\")");
}

TissueModel TissueModel::single_surface(const LayerShape& shape) {
  return TissueModel({TissueLayer{"tissue", shape, {}}});
}

int TissueModel::layer_at(const Eigen::Vector3d& x) const {
  for (int i = layer_count() - 1; i >= 0; --i)
    if (layers_[size_t(i)].shape.contains(x)) return i;
  return -1;
}

double TissueModel::distance(const Eigen::Vector3d& x) const {
  double phi = std::numeric_limits<double>::infinity();
  for (const TissueLayer& l : layers_)
    if (!l.mechanics.rigid) phi = std::min(phi, l.shape.phi(x));
  return phi;
}

bool TissueModel::has_axial_mechanics() const {
  for (const TissueLayer& l : layers_)
    for (const auto& f : kMechanicsFields)
      if (l.mechanics.*f.member > 0.0) return true;
  return false;
}

}  // namespace needle::haptics
