#include "haptics/tissue/tissue_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace needle::haptics {
namespace {

// (state) => (state: no track)
void forget_track(TissueState& st) {
  st.on_track = false;
  st.s = st.cut_s = st.surface_s = 0.0;
  st.stretch_count = 0;
  st.surface_layer = -1;
  st.grip_force_N = 0.0;  // no shaft in tissue, nothing to grip with
}

// (state, layer, s) => (state.stretches): from s on the shaft lies in layer.
void add_stretch(TissueState& st, int layer, double begin_s) {
  if (st.stretch_count == TissueState::kMaxStretches) return;  // the track keeps its last layer
  st.stretches[size_t(st.stretch_count++)] = {layer, begin_s};
}

// (state) => the layer holding the tip: the last stretch begun before it, −1 before the first.
int holding_layer(const TissueState& st) {
  int layer = -1;
  for (int k = 0; k < st.stretch_count && st.stretches[size_t(k)].begin_s < st.s; ++k)
    layer = st.stretches[size_t(k)].layer;
  return layer;
}

// (shape, x₀, x₁) => t ∈ [0, 1] where φ changes sign on x₀ + t(x₁ − x₀) (linear in φ: exact for
// planes, second order for curved surfaces); 0 when x₀ is already inside.
double crossing(const LayerShape& shape, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1) {
  const double phi0 = shape.phi(x0), phi1 = shape.phi(x1);
  return phi0 == phi1 ? 0.0 : std::clamp(phi0 / (phi0 - phi1), 0.0, 1.0);
}

// (model, state, tip, axis) => (state: track begun at the first surface the tip crossed)
void meet_tissue(const TissueModel& model, TissueState& st, const Eigen::Vector3d& tip, const Eigen::Vector3d& axis) {
  const int layer = model.layer_at(tip);
  if (layer < 0) return;
  const Eigen::Vector3d met = st.tip + crossing(model.layer(layer).shape, st.tip, tip) * (tip - st.tip);
  forget_track(st);
  st.on_track = true;
  st.s = (tip - met).dot(axis);
  st.surface_layer = layer;
  st.surface_point = met;
}

// (model, state, tip, s before the tick) => (state: the surface of the layer the tip now enters,
// or a stretch of no layer when it left the tissue). In uncut tissue only, with no surface pressed.
void meet_boundary(const TissueModel& model, TissueState& st, const Eigen::Vector3d& tip, double s_before) {
  const int entered = model.layer_at(tip);
  const int left = holding_layer(st);
  if (entered == left) return;
  const double t = crossing(model.layer(entered >= 0 ? entered : left).shape, st.tip, tip);
  // A surface carried along by the one above it while that was tented meets the tip where the
  // pop left it, not behind it: the channel is cut up to cut_s.
  const double met_s = std::max(s_before + t * (st.s - s_before), st.cut_s);
  if (entered < 0) {
    add_stretch(st, -1, met_s);
    return;
  }
  st.surface_layer = entered;
  st.surface_s = met_s;
  st.surface_point = st.tip + t * (tip - st.tip);
}

// (model, state, tip) => (F_s, out.surface fields, out.punctured_*; state: the layer entered
// when its surface gives way). F_s = k₁d + k₂d², d = s − s_met (Okamura et al. 2004).
double press_surface(const TissueModel& model, TissueState& st, const Eigen::Vector3d& tip) {
  TissueOutput& out = st.out;
  out.surface_layer = st.surface_layer;
  out.rigid_contact = false;
  out.deflection_m = 0.0;
  if (st.surface_layer < 0) return 0.0;
  const LayerMechanics& m = model.layer(st.surface_layer).mechanics;
  const double d = st.s - st.surface_s;
  out.deflection_m = d;
  out.contact_point = st.surface_point;
  if (m.rigid) {  // no puncture: the rigid layer is a holonomic contact for the virtual robot
    out.rigid_contact = true;
    out.rigid_surface = model.layer(st.surface_layer).shape.evaluate(tip);
    return 0.0;
  }
  const double force = d * (m.stiffness_N_per_m + m.stiffness2_N_per_m2 * d);
  if (force >= m.puncture_force_N) {  // gives way: this tick renders the peak, the next its release
    if (m.puncture_force_N > 0.0) {
      out.punctured_layer = st.surface_layer;
      out.puncture_force_N = force;
    }
    add_stretch(st, st.surface_layer, st.surface_s);
    st.cut_s = std::max(st.cut_s, st.s);
    st.surface_layer = -1;
  }
  return force;
}

}  // namespace

uint32_t passed_layers(const TissueState& st) {
  static_assert(TissueModel::kMaxLayers <= 32, "one bit per layer");
  uint32_t mask = 0;
  if (!st.on_track) return mask;
  for (int k = 0; k < st.stretch_count; ++k)
    if (st.stretches[size_t(k)].layer >= 0) mask |= 1u << st.stretches[size_t(k)].layer;
  return mask;
}

const TissueOutput& step_tissue(const TissueModel& model, TissueState& st, const Eigen::Vector3d& tip,
                                const Eigen::Vector3d& axis, double dt) {
  TissueOutput& out = st.out;
  const double force_before = out.axial_force_N;
  out.punctured_layer = -1;
  out.puncture_force_N = 0.0;
  if (!st.has_pose || model.empty()) {
    st.has_pose = true;
    st.tip = tip;
    return out;
  }
  const double ds = (tip - st.tip).dot(axis);
  const double speed = ds / dt;

  // Track events: withdrawal first, then the surfaces met in intact tissue.
  const double s_before = st.s;
  if (st.on_track)
    st.s += ds;
  else
    meet_tissue(model, st, tip, axis);
  if (st.on_track && st.s < 0.0) forget_track(st);                          // withdrawn out of the first surface
  if (st.surface_layer >= 0 && st.s < st.surface_s) st.surface_layer = -1;  // pulled back off it
  const double cut_before = st.cut_s;
  if (st.on_track && st.surface_layer < 0 && st.s > st.cut_s) meet_boundary(model, st, tip, s_before);
  // Shaft behind the tip, per stretch: friction limits and damping of the layers it crosses. While
  // a surface is tented the shaft up to the tip is in the layer above (its tissue goes down with
  // the tent), also in the tick the surface gives way: the new layer holds from the next tick.
  double dynamic = 0.0, stick = 0.0, damping = 0.0;
  int holding = -1;
  for (int k = 0; k < st.stretch_count; ++k) {
    const TrackStretch& stretch = st.stretches[size_t(k)];
    if (stretch.begin_s >= st.s) break;
    holding = stretch.layer;
    if (holding < 0) continue;
    const double end =
        k + 1 < st.stretch_count ? st.stretches[size_t(k + 1)].begin_s : std::numeric_limits<double>::infinity();
    const double length = std::min(st.s, end) - stretch.begin_s;
    const LayerMechanics& m = model.layer(holding).mechanics;
    dynamic += m.friction_N_per_m * length;
    stick += m.static_friction_N_per_m * length;
    damping += m.damping_Ns_per_m;
  }

  const double surface = press_surface(model, st, tip);
  const bool tearing = out.punctured_layer >= 0 || st.surface_layer >= 0;  // the tip is at a surface, not cutting
  if (st.surface_layer < 0) st.cut_s = std::max(st.cut_s, st.s);

  // Grip: an elastic stick that slips at the friction limit (Karnopp's band decides which limit);
  // advancing into uncut tissue adds the cutting force to the forward limit.
  const bool sticking = std::abs(speed) < model.stick().band_mps;
  const bool cutting = ds > 0.0 && !tearing && holding >= 0 && st.s > cut_before;
  const double friction = sticking ? stick : dynamic;
  const double upper = friction + (cutting ? model.layer(holding).mechanics.cutting_force_N : 0.0), lower = -friction;
  st.grip_force_N = std::clamp(st.grip_force_N + model.stick().stiffness_N_per_m * ds, lower, upper);

  out.holding_layer = holding;
  out.opening_layer = st.on_track ? holding_layer(st) : -1;
  out.surface_force_N = surface;
  out.grip_force_N = st.grip_force_N;
  out.damping_force_N = damping * speed;
  out.axial_force_N = surface + st.grip_force_N + out.damping_force_N;
  st.tissue_work_J += 0.5 * (force_before + out.axial_force_N) * ds;
  st.tip = tip;
  return out;
}

double tissue_stored_energy(const TissueModel& model, const TissueState& st) {
  const double grip = st.grip_force_N * st.grip_force_N / (2.0 * model.stick().stiffness_N_per_m);
  if (!st.on_track || st.surface_layer < 0) return grip;
  const LayerMechanics& m = model.layer(st.surface_layer).mechanics;
  const double d = std::max(0.0, st.s - st.surface_s);
  return grip + d * d * (m.stiffness_N_per_m / 2.0 + m.stiffness2_N_per_m2 * d / 3.0);
}

}  // namespace needle::haptics
