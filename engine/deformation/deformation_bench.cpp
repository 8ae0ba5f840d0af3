#include "engine/deformation_bench.hpp"

#include <algorithm>

#include "engine/deformation/deformation_field.hpp"
#include "engine/deformation/deformation_pass.hpp"
#include "engine/deformation/vertex_grid.hpp"
#include "engine/gpu_device.hpp"
#include "engine/passes/gpu_model.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

struct DeformationBench::State {
  State(const VulkanContext& context, const Model& model, const TissueParams& tissue)
      : context(context),
        tissue(tissue),
        rest(model.primitives.at(0)),
        model_to_world(model.instances.at(0).world),
        grid(VertexGrid::sort_vertices(rest, 0.5 * tissue.falloff * tissue.radius_m)),
        gpu(upload_primitive(context, rest)),
        pass(context) {
    pass.add_target(gpu, rest, grid, model_to_world);
    cpu_state.resize(rest.vertices.size());
    for (size_t v = 0; v < cpu_state.size(); ++v) cpu_state[v] = world_position(rest.vertices[v]);
  }

  glm::dvec3 world_position(const MeshVertex& vertex) const {
    return glm::dvec3(model_to_world * glm::dvec4(glm::dvec3(vertex.position), 1.0));
  }

  const VulkanContext& context;
  const TissueParams tissue;
  Primitive rest;  // in the grid's order, model space
  const glm::dmat4 model_to_world;
  VertexGrid grid;
  GpuPrimitive gpu;
  DeformationPass pass;
  std::vector<glm::dvec3> cpu_state;  // world positions
  DeformationField field;
  std::vector<Sphere> visit, previous_reach;  // model space
};

DeformationBench::DeformationBench(const GpuDevice& device, const Model& model, const TissueParams& tissue)
    : state_(std::make_unique<State>(device.context(), model, tissue)) {}

DeformationBench::~DeformationBench() = default;

size_t DeformationBench::vertex_count() const { return state_->rest.vertices.size(); }

void DeformationBench::set_needle(const NeedleLoad& needle) {
  State& s = *state_;
  s.field = build_field(needle, s.tissue);
  std::vector<Sphere> reach;
  for (const Kelvinlet& k : s.field.loads) {
    reach.push_back({glm::dvec3(glm::inverse(s.model_to_world) * glm::dvec4(k.center, 1.0)), k.support});
  }
  s.visit = reach;
  s.visit.insert(s.visit.end(), s.previous_reach.begin(), s.previous_reach.end());
  s.previous_reach = reach;
}

size_t DeformationBench::deform_on_gpu() {
  State& s = *state_;
  auto record = s.pass.update(s.field);
  if (record) s.context.submit_and_wait(record);
  return s.pass.last_frame().processed;
}

void DeformationBench::deform_on_cpu() {
  State& s = *state_;
  for (const VertexRange& range : s.grid.ranges_near(s.visit)) {
    for (uint32_t v = range.first; v < range.first + range.count; ++v) {
      s.cpu_state[v] =
          deform(s.field, s.world_position(s.rest.vertices[v]), glm::dvec3(s.rest.vertices[v].normal)).position;
    }
  }
}

double DeformationBench::max_distance_m() const {
  const State& s = *state_;
  double max_distance = 0.0;
  const std::vector<MeshVertex> out = read_back_vertices(s.context, s.gpu);
  for (size_t v = 0; v < out.size(); ++v) {
    max_distance = std::max(max_distance, glm::length(s.world_position(out[v]) - s.cpu_state[v]));
  }
  return max_distance;
}

}  // namespace needle::engine
