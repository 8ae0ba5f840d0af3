#include "training/scoring/layer_events.hpp"

#include <algorithm>
#include <cmath>

namespace needle::training {

LayerEventTracker::LayerEventTracker(const Task& task) : task_(task) {
  for (size_t i = 0; i < task.layers.size() && i < 32; ++i)
    if (task.layers[i].puncture_force_N > 0.0) membranes_ |= 1u << i;
  punctures_.reserve(kMaxPunctures);
}

const LayerEvents& LayerEventTracker::feed(const haptics::ToolSnapshot& s, const Vec3* entry) {
  const haptics::TissueSnapshot& tissue = s.tissue;
  const double t = s.time_s, dt = started_ ? t - t_prev_ : 0.0;
  const Vec3 tip = vec3(s.needle_tip_m);
  if (!started_) passed_prev_ = tissue.punctured_layers, tip_prev_ = tip;  // a session begun in tissue: no puncture yet
  events_.passed = tissue.punctured_layers & ~passed_prev_;
  events_.punctured = events_.passed & membranes_;
  events_.bone_entry = events_.redirection = false;

  // Punctures, in order of depth within one state (a pop can carry the tip through two).
  peak_force_ = std::max(peak_force_, tissue.axial_force_N);
  for (uint32_t left = events_.punctured; left != 0; left &= left - 1) {
    if (punctures_.size() < kMaxPunctures)
      punctures_.push_back({std::countr_zero(left), t, entry ? distance(tip, *entry) : 0.0, peak_force_});
  }
  if (events_.punctured) peak_force_ = 0.0;
  if (tissue.punctured_layers == 0 && tissue.surface_layer < 0) peak_force_ = 0.0;  // out, pressing nothing

  // The run after a puncture: from the pop until the tip stops moving along the needle. A pop
  // while it runs (through the dura after the flavum) is part of the same run.
  const auto a = haptics::needle_axis(s);
  const Vec3 axis{a[0], a[1], a[2]};
  if (events_.punctured && !running_) {
    running_ = true;
    run_start_ = tip_prev_;  // where the tip was when the surface gave way
    run_axis_ = axis;
    events_.run_m = 0.0;
    slow_since_s_ = -1.0;
  }
  if (running_) {
    events_.run_m = std::max(events_.run_m, dot(tip - run_start_, run_axis_));
    const double speed = dt > 0.0 ? dot(tip - tip_prev_, run_axis_) / dt : 1.0;
    if (speed >= kStopSpeed_mps)
      slow_since_s_ = -1.0;
    else if (slow_since_s_ < 0.0)
      slow_since_s_ = t;
    if (slow_since_s_ >= 0.0 && t - slow_since_s_ >= kStopHold_s) running_ = false;
  }

  // Bone: the tip meeting a rigid layer; leaving and meeting it again within kDebounce_s is the
  // penalty contact's chatter, one contact.
  const bool on_bone = tissue.bone_layer >= 0;
  if (on_bone && !on_bone_) {
    events_.bone_entry = !bone_seen_ || t - bone_left_s_ >= kDebounce_s;
    bone_seen_ = true;
  }
  if (on_bone_ && !on_bone) bone_left_s_ = t;
  on_bone_ = on_bone;

  // Redirection: back to a shallower layer than the track's deepest, then deeper again.
  const int layer = tissue.tip_layer;
  if (tissue.punctured_layers == 0) {
    deepest_ = shallowest_since_ = -1;
    withdrawn_ = false;
  } else if (layer >= 0) {
    if (layer < deepest_ && !withdrawn_) {
      withdrawn_ = true;
      shallowest_since_ = layer;
    }
    if (withdrawn_) shallowest_since_ = std::min(shallowest_since_, layer);
    if (withdrawn_ && layer > shallowest_since_) {
      events_.redirection = true;
      withdrawn_ = false;
      deepest_ = layer;
    }
    deepest_ = std::max(deepest_, layer);
  }

  started_ = true;
  t_prev_ = t;
  tip_prev_ = tip;
  passed_prev_ = tissue.punctured_layers;
  return events_;
}

}  // namespace needle::training
