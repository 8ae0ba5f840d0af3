// The needle in layered tissue, one servo tick at a time: the state is the needle's track (where
// it met and punctured each layer's surface, how deep the channel is cut) and the tissue's grip
// on the shaft; step_tissue turns the tip's new pose into the axial force. Allocation-free, no
// locks, no I/O: it runs in the servo tick. Equations and events: docs/TISSUE.md.
//
// Sign convention: axial_force_N is the force the needle exerts on the tissue along the needle
// axis, > 0 while it resists the advance; the tissue pushes the needle with −axial_force_N·axis.
#pragma once

#include <array>

#include "haptics/tissue/tissue_model.hpp"

namespace needle::haptics {

// From track coordinate `begin_s` on (until the next stretch) the shaft lies in `layer`;
// −1 is no layer (the tip came out of the tissue's far side).
struct TrackStretch {
  int layer = -1;
  double begin_s = 0.0;
};

// What the tissue did in the last tick.
struct TissueOutput {
  double axial_force_N = 0.0;    // surface + grip + damping
  double surface_force_N = 0.0;  // k₁d + k₂d² of the surface being pressed, until it gives way
  double grip_force_N = 0.0;     // the stick/slip element: shaft friction and cutting at the tip
  double damping_force_N = 0.0;
  int holding_layer = -1;     // the layer holding the tip, −1 when it is in none
  int opening_layer = -1;     // the layer the tip is in at the end of the tick (a surface that gave way in it
                              // included): where fluid pushed through the needle goes, −1 in none
  int surface_layer = -1;     // the layer whose surface the tip presses, −1 when none
  double deflection_m = 0.0;  // that surface's deflection d along the needle (the dimple's depth)
  Eigen::Vector3d contact_point = Eigen::Vector3d::Zero();  // where the tip met it, at rest (while surface_layer ≥ 0)
  bool rigid_contact = false;                               // that surface is a rigid layer's: the GPM contact (3.15)
  SurfaceSample rigid_surface;    // its φ, normal and Hessian at the tip, while rigid_contact
  int punctured_layer = -1;       // the surface that gave way in this tick
  double puncture_force_N = 0.0;  // its surface force when it gave way (k₁d + k₂d² ≥ F_p)
};

struct TissueState {
  static constexpr int kMaxStretches = 32;  // boundaries one track remembers; later ones are not met

  bool has_pose = false;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();  // at the last tick
  bool on_track = false;                          // the tip has met the tissue; the fields below describe the track
  double s = 0.0;                                 // tip's track coordinate: axial travel since it met the first surface
  double cut_s = 0.0;                             // the channel is cut up to here; beyond it the tissue is intact
  int stretch_count = 0;
  std::array<TrackStretch, kMaxStretches> stretches{};
  int surface_layer = -1;  // the surface the tip presses (tents), −1 when none
  double surface_s = 0.0;  // track coordinate where the tip met it
  Eigen::Vector3d surface_point = Eigen::Vector3d::Zero();
  double grip_force_N = 0.0;   // the stick element's spring force
  double tissue_work_J = 0.0;  // work of the needle on the tissue since the state was made (≥ 0)
  TissueOutput out;
};

// (state) => bit i set for every layer i the current track has passed into (its surface punctured,
// or entered where it has none); 0 off the track. Rigid layers are never passed into.
uint32_t passed_layers(const TissueState& state);

// (model, state, tip, unit axis, dt > 0) => (state.track, state.grip_force_N, state.tissue_work_J, state.out)
//   ds = (x − x_prev)·u, ṡ = ds/dt; the track coordinate s += ds.
//   Surface pressed:  F_s = k₁d + k₂d², d = s − s_met; gives way (pops) once F_s ≥ F_p.
//   Grip (Karnopp): |ṡ| < band sticks with limit F_st = Σ f_st,i Lᵢ, else slips at
//   F_dyn = Σ fᵢ Lᵢ; F_g ← clamp(F_g + k_stick ds, −limit, limit + F_cut), F_cut the holding
//   layer's cutting force while the tip advances into uncut tissue, else 0.  Damping F_b = Σ bᵢ ṡ over the layers the
//   shaft crosses.  F = F_s + F_g + F_b;  W += ½(F_prev + F) ds.
const TissueOutput& step_tissue(const TissueModel& model, TissueState& state, const Eigen::Vector3d& tip,
                                const Eigen::Vector3d& axis, double dt);

// (model, state) => the energy the tissue holds and can give back: the tented surface's
// k₁d²/2 + k₂d³/3 and the stick element's F_g²/2k_g. tissue_work_J minus this is what it has
// dissipated (≥ 0: docs/TISSUE.md, Passivity).
double tissue_stored_energy(const TissueModel& model, const TissueState& state);

}  // namespace needle::haptics
