// A tissue mesh deformed frame after frame by the GPU pass outside any scene, and the same work
// done on the CPU (one thread, double precision) on the vertices the pass visits: what
// `needle-sim bench deform` times, side by side, and compares.
#pragma once

#include <cstddef>
#include <memory>

#include "engine/model.hpp"
#include "engine/tissue.hpp"

namespace needle::engine {

class GpuDevice;

class DeformationBench {
 public:
  // The model's first primitive placed by its first instance, sorted into the pass's grid and
  // uploaded.
  DeformationBench(const GpuDevice& device, const Model& model, const TissueParams& tissue);
  ~DeformationBench();
  DeformationBench(const DeformationBench&) = delete;
  DeformationBench& operator=(const DeformationBench&) = delete;

  size_t vertex_count() const;
  // The needle of the next frame. Its field and the vertices it reaches are found here, so that
  // the two calls below do only their own side's work.
  void set_needle(const NeedleLoad& needle);
  // The GPU pass for the field, submitted and waited for; returns the vertices it processed.
  size_t deform_on_gpu();
  // The CPU's own deformed mesh through the same field: the vertices of the grid cells this
  // frame's and the last frame's loads reach, as the pass visits them.
  void deform_on_cpu();
  // The largest distance between a vertex on the GPU and the same one on the CPU, over every
  // vertex, in metres (world frame).
  double max_distance_m() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace needle::engine
