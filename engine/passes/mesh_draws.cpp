#include "engine/passes/mesh_draws.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/passes/frame_uniforms.hpp"
#include "engine/passes/gpu_model.hpp"
#include "engine/passes/level_of_detail.hpp"
#include "engine/passes/mesh_pipelines.hpp"
#include "engine/screen_projection.hpp"

namespace needle::engine {
namespace {

size_t level_to_draw(const GpuPrimitive& p, const glm::mat4& model_to_world, const Camera& camera, VkExtent2D extent) {
  if (p.levels.size() < 2) return 0;
  std::vector<uint32_t> triangles;
  for (const GpuLevel& level : p.levels) triangles.push_back(level.index_count / 3);
  return choose_level(
      triangles, projected_radius_px(world_sphere(p.bounds, model_to_world), camera, {extent.width, extent.height}));
}

// Where a mesh's vertices may lie, world space: its rest box placed by `transform` and the spheres
// where a deformation may have moved them (DrawItem::moved).
Bounds reach_of(const Bounds& rest_box, const glm::mat4& transform, const std::vector<Sphere>& moved) {
  Bounds reach = world_box(rest_box, transform);
  for (const Sphere& s : moved) {
    reach.min = glm::min(reach.min, glm::vec3(s.center - s.radius));
    reach.max = glm::max(reach.max, glm::vec3(s.center + s.radius));
  }
  return reach;
}

// An item inside another's closed opaque surface cannot be seen without a section view while the
// whole near plane is outside that surface: the eye outside its reach by more than the distance
// from the eye to the near plane's corners.
bool hidden_inside(const FrameParams& params, const DrawItem& item, VkExtent2D extent) {
  if (!item.inside || params.section) return false;
  const DrawItem& outer = params.items.at(*item.inside);
  const Bounds reach = reach_of(outer.model->world_bounds(), outer.transform, outer.moved);
  const Camera& c = params.camera;
  const double up = std::tan(0.5 * glm::radians(double(c.fov_y_deg))),
               across = up * double(extent.width) / std::max(1.0, double(extent.height));
  const float corner = float(c.near_m * std::sqrt(1.0 + up * up + across * across));
  return glm::any(glm::lessThan(c.position, reach.min - corner)) ||
         glm::any(glm::greaterThan(c.position, reach.max + corner));
}

}  // namespace

Sphere world_sphere(const Sphere& model_space, const glm::mat4& model_to_world) {
  const glm::mat3 linear(model_to_world);
  const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  return {glm::dvec3(model_to_world * glm::vec4(glm::vec3(model_space.center), 1.0f)), model_space.radius * scale};
}

Bounds world_box(const Bounds& b, const glm::mat4& model_to_world) {
  Bounds out{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                      (corner & 4) ? b.max.z : b.min.z);
    const glm::vec3 w(model_to_world * glm::vec4(p, 1.0f));
    out.min = glm::min(out.min, w), out.max = glm::max(out.max, w);
  }
  return out;
}

glm::vec4 section_plane(const Section& section) {
  const glm::vec3 n = glm::normalize(section.normal);
  return glm::vec4(n, -glm::dot(n, section.point));
}

MeshDraws collect_draws(const FrameParams& params, VkExtent2D extent, const DrawOptions& options) {
  // A cut's caps are found from every face of what it cuts (section_caps.hpp), so none are
  // culled for their facing; those wholly on the cut-away side are.
  const bool cut = params.section && params.section->mode == Section::Mode::Cut;
  const bool translucent = params.section && params.section->mode == Section::Mode::Translucent &&
                           options.translucency == Translucency::Blended;
  const glm::vec4 cut_plane = cut ? section_plane(*params.section) : glm::vec4(0.0f);
  const ViewVolume view = view_volume(view_projection(params.camera, {extent.width, extent.height}));
  MeshDraws draws;
  for (const DrawItem& item : params.items) {
    if (options.cull_inside && hidden_inside(params, item, extent)) continue;
    for (const MeshInstance& instance : item.model->instances()) {
      glm::mat4 transform = item.transform * instance.world;
      const GpuPrimitive& p = item.model->primitives()[instance.primitive];
      if (p.index_count == 0) continue;
      const Material& m = item.model->material_of(instance.primitive);
      float depth = glm::length(glm::vec3(transform[3]) - params.camera.position);
      const GpuLevel& level =
          p.levels[options.level_of_detail ? level_to_draw(p, transform, params.camera, extent) : 0];
      if (level.index_count == 0) continue;
      const bool sectioned = params.section && item.sectioned;
      const std::vector<IndexRange> all{{level.first_index, level.index_count}};
      const std::vector<TriangleChunk> chunks =
          options.cull_chunks ? chunks_in_view(level.chunks, transform, view, item.moved) : level.chunks;
      std::vector<IndexRange> ranges =
          !options.cull_chunks ? all
          : cut && sectioned   ? (options.cull_cut_away ? ranges_kept_by_cut(chunks, transform, cut_plane, item.moved)
                                                        : index_ranges(chunks))
          : !m.double_sided    ? visible_ranges(chunks, transform, params.camera.position, item.moved)
                               : index_ranges(chunks);
      const Bounds reach = sectioned ? reach_of(p.box, transform, item.moved) : Bounds{};
      (translucent && sectioned           ? draws.translucent
       : m.alpha_mode == AlphaMode::Blend ? draws.blended
                                          : draws.opaque)
          .push_back({item.model, instance.primitive, transform, depth, std::move(ranges), sectioned, reach});
    }
  }
  std::sort(draws.blended.begin(), draws.blended.end(),
            [](const MeshDraw& a, const MeshDraw& b) { return a.depth > b.depth; });
  return draws;
}

void bind_material_and_transform(VkCommandBuffer cmd, const MeshDraw& d, VkPipelineLayout layout) {
  VkDescriptorSet set = d.model->descriptor_set_of(d.primitive);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &set, 0, nullptr);
  DrawPushConstants push{};
  push.model = d.transform;
  // Inverse-transpose keeps normals perpendicular under non-uniform scale.
  glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(d.transform)));
  for (int c = 0; c < 3; ++c) push.normal_matrix[c] = glm::vec4(normal_matrix[c], 0.0f);
  push.normal_matrix[0].w = d.sectioned ? 1.0f : 0.0f;
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
}

size_t bind_and_draw(VkCommandBuffer cmd, const MeshDraw& d, VkPipelineLayout layout) {
  bind_material_and_transform(cmd, d, layout);
  const GpuPrimitive& p = d.model->primitives()[d.primitive];
  VkDeviceSize offset = 0;
  VkBuffer vb = p.vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd, p.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  size_t triangles = 0;
  for (const IndexRange& r : d.ranges) {
    vkCmdDrawIndexed(cmd, r.count, 1, r.first, 0, 0);
    triangles += r.count / 3;
  }
  return triangles;
}

size_t record_draws(VkCommandBuffer cmd, const std::vector<MeshDraw>& draws, bool blended,
                    const MeshPipelines& pipelines, const DrawOptions& options) {
  VkPipeline bound = VK_NULL_HANDLE;
  size_t triangles = 0;
  for (const MeshDraw& d : draws) {
    const Material& m = d.model->material_of(d.primitive);
    // Only masked materials and sectioned items discard fragments (mesh.frag).
    const MeshVariant variant{m.double_sided, blended,
                              !options.specialized || m.alpha_mode == AlphaMode::Mask || d.sectioned,
                              !options.specialized || m.base_color_texture >= 0};
    VkPipeline pipeline = pipelines.pipeline(variant);
    if (pipeline != bound) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      bound = pipeline;
    }
    triangles += bind_and_draw(cmd, d, pipelines.layout());
  }
  return triangles;
}

}  // namespace needle::engine
