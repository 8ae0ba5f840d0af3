// Layered tissue as data: an ordered list of layers, each a shape and its mechanical
// parameters in SI units. Immutable once built; the per-tick state is TissueState
// (haptics/tissue/tissue_step.hpp). The equations are in docs/TISSUE.md.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "haptics/tissue/layer_shape.hpp"

namespace needle::haptics {

// One layer's mechanics. Every number ≥ 0; zero means "absent".
struct LayerMechanics {
  double stiffness_N_per_m = 0.0;        // k₁ of the surface before puncture, F = k₁d + k₂d²
  double stiffness2_N_per_m2 = 0.0;      // k₂ (Okamura, Simone, O'Leary, IEEE TBME 2004)
  double puncture_force_N = 0.0;         // the surface gives way when F reaches it
  double cutting_force_N = 0.0;          // at the tip while it advances into uncut tissue of this layer
  double friction_N_per_m = 0.0;         // dynamic shaft friction per metre of shaft in the layer
  double static_friction_N_per_m = 0.0;  // static (stick) limit per metre, ≥ the dynamic one
  double damping_Ns_per_m = 0.0;         // viscous, while the shaft crosses the layer
  bool rigid = false;                    // bone: never punctured, every other number zero
};

// A numeric parameter of `Set` by its key in scenario and parameter set files, with the largest
// value it may take and its unit.
template <class Set>
struct ParameterField {
  const char* key;
  double Set::*member;
  double max;
  const char* unit;
};
// The mechanical parameters, in file order. Each is in [0, max]; max is a design value about 20
// times the largest of the shipped parameter sets (assets/tissues/: the flavum's 500 N/m,
// 6e5 N/m², 5 N puncture, 1.5 N cutting, 150 and 225 N/m friction; no set gives a damping, and
// 1000 N·s/m resists a 5 mm/s insertion with 5 N, a puncture's force), beyond any tissue their
// sources measured: past it a number is a typo or an attack (1e300 N/m is not a tissue), and the
// tick's forces would overflow what the device and the solver can take (docs/TISSUE.md).
inline constexpr ParameterField<LayerMechanics> kMechanicsFields[] = {
    {"stiffness_N_per_m", &LayerMechanics::stiffness_N_per_m, 1e4, "N/m"},
    {"stiffness2_N_per_m2", &LayerMechanics::stiffness2_N_per_m2, 1.2e7, "N/m^2"},
    {"puncture_force_N", &LayerMechanics::puncture_force_N, 100.0, "N"},
    {"cutting_force_N", &LayerMechanics::cutting_force_N, 30.0, "N"},
    {"friction_N_per_m", &LayerMechanics::friction_N_per_m, 5000.0, "N/m"},
    {"static_friction_N_per_m", &LayerMechanics::static_friction_N_per_m, 5000.0, "N/m"},
    {"damping_Ns_per_m", &LayerMechanics::damping_Ns_per_m, 1000.0, "N*s/m"}};

// What is wrong with a layer's mechanics: the offending parameter's key and the reason.
struct MechanicsProblem {
  const char* key;
  std::string what;
};
std::optional<MechanicsProblem> mechanics_problem(const LayerMechanics& m);

// (mechanics) => d_p, the surface's deflection when it gives way: the root of k₁d + k₂d² = F_p
// (the tent's depth, m); 0 for a layer without a surface (entered when reached) and a rigid one.
double tent_depth_m(const LayerMechanics& m);

// What a layer is to ultrasound (the simulated image, docs/RENDERING.md "Ultrasound"); the
// physics does not use it. Absent, the image takes a generic soft tissue.
struct LayerAcoustics {
  double impedance_MRayl = 0.0;            // > 0: the interfaces' reflection
  double attenuation_dB_per_cm_MHz = 0.0;  // ≥ 0, one way
  double echogenicity = 0.0;               // mean backscatter amplitude, 0 (anechoic) to 1
  double scatterer_density = 0.0;          // share of scatterer cells that hold one, (0, 1]
};

// The largest values (design values): an impedance of 100 MRayl is past any solid (the shipped
// bone's 6.5, steel's about 46), an attenuation of 100 dB/(cm MHz) seven times the shipped
// bone's 15 (assets/tissues/bone.json cites both); echogenicity and scatterer density are fractions.
inline constexpr ParameterField<LayerAcoustics> kAcousticsFields[] = {
    {"impedance_MRayl", &LayerAcoustics::impedance_MRayl, 100.0, "MRayl"},
    {"attenuation_dB_per_cm_MHz", &LayerAcoustics::attenuation_dB_per_cm_MHz, 100.0, "dB/(cm MHz)"},
    {"echogenicity", &LayerAcoustics::echogenicity, 1.0, ""},
    {"scatterer_density", &LayerAcoustics::scatterer_density, 1.0, ""}};

// The parameter at fault and why, or nothing when every number is in its range.
std::optional<MechanicsProblem> acoustics_problem(const LayerAcoustics& a);

// What a layer does to fluid pushed into it from the needle's tip (the loss-of-resistance syringe,
// haptics/syringe/, docs/TISSUE.md "The syringe"): no flow below the opening pressure (gauge, at
// the tip), above it a hydraulic resistance to saline (air's is scaled by the viscosities, Darcy's
// law). The physics of the needle ignores it.
struct LayerInjection {
  double opening_pressure_Pa = 0.0;
  double resistance_Pa_s_per_m3 = 0.0;
};

// The largest values (design values): 1 MPa is about 7 times the shipped ligaments' 150 kPa and
// 56 N on the loss-of-resistance syringe's plunger, past any thumb; 1e15 Pa s/m^3 100 times the
// ligaments' resistance, at which a thumb's 60 kPa moves 0.06 uL/s.
inline constexpr ParameterField<LayerInjection> kInjectionFields[] = {
    {"opening_pressure_Pa", &LayerInjection::opening_pressure_Pa, 1e6, "Pa"},
    {"resistance_Pa_s_per_m3", &LayerInjection::resistance_Pa_s_per_m3, 1e15, "Pa*s/m^3"}};

// The parameter at fault and why, or nothing when every number is in [0, max].
std::optional<MechanicsProblem> injection_problem(const LayerInjection& i);

struct TissueLayer {
  std::string name;
  LayerShape shape;
  LayerMechanics mechanics;
  std::optional<LayerAcoustics> acoustics = std::nullopt;
  std::optional<LayerInjection> injection = std::nullopt;  // needed by a scenario with a syringe
};

// The tissue's grip on the shaft while it sticks (Karnopp's band) is elastic: a spring of this
// stiffness between the shaft and the tissue, which slips at the friction limits. Design values
// with their reasoning in docs/TISSUE.md.
struct StickParams {
  double stiffness_N_per_m = 5000.0;
  double band_mps = 5e-4;  // |axial speed| below this sticks
};

// A layer that cannot be part of a model: its index, the key at fault ("name", "shape" or a
// mechanics key) and why.
struct TissueLayerError : std::invalid_argument {
  TissueLayerError(int layer, std::string key, const std::string& what)
      : std::invalid_argument(what), layer(layer), key(std::move(key)) {}
  int layer;
  std::string key;
};

class TissueModel {
 public:
  static constexpr int kMaxLayers = 16;

  TissueModel() = default;  // no tissue
  // Throws TissueLayerError: a layer past kMaxLayers, an empty or repeated name, invalid
  // mechanics (mechanics_problem) or a shape in conflict with an earlier one (find_layer_conflict).
  // Throws std::invalid_argument on stick parameters ≤ 0.
  TissueModel(std::vector<TissueLayer> layers, StickParams stick = {});
  // The thesis's penetrable tissue (section 4.4): one layer, "tissue", every parameter zero.
  static TissueModel single_surface(const LayerShape& shape);

  bool empty() const { return layers_.empty(); }
  int layer_count() const { return int(layers_.size()); }
  const TissueLayer& layer(int i) const { return layers_[size_t(i)]; }
  std::span<const TissueLayer> layers() const { return layers_; }
  const StickParams& stick() const { return stick_; }

  // x => the last layer whose shape holds x, its surface included (layers are listed outside in, so
  // on a face two layers share it is the inner one; LayerShape::contains), −1 in none.
  int layer_at(const Eigen::Vector3d& x) const;
  // x => the tissue's signed distance: the least φ of its non-rigid layers (< 0 inside the tissue;
  // +∞ with none). For a single surface, that surface's φ.
  double distance(const Eigen::Vector3d& x) const;
  // Whether any non-rigid layer has a surface, cutting, friction or damping: whether the needle can
  // feel anything along its axis (the thesis's penetrable sphere cannot).
  bool has_axial_mechanics() const;

 private:
  std::vector<TissueLayer> layers_;
  StickParams stick_;
};

}  // namespace needle::haptics
