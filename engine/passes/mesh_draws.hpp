// The draws of a frame's meshes: each primitive instance of FrameParams' items as the index
// ranges left by chunk culling, at the level of detail its size calls for (docs/RENDERING.md,
// "What a draw leaves out"), opaque and masked ones apart from blended ones (sorted back to
// front); then recorded with the mesh pipeline each needs.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "engine/passes/triangle_chunks.hpp"
#include "engine/scene_renderer.hpp"

namespace needle::engine {

class GpuModel;
class MeshPipelines;

// The section's plane as (n, d), n unit: the cut discards where n · p + d > 0.
glm::vec4 section_plane(const Section& section);

struct MeshDraw {
  const GpuModel* model = nullptr;
  uint32_t primitive = 0;
  glm::mat4 transform{1.0f};
  float depth = 0.0f;              // distance from the camera, for back-to-front blending
  std::vector<IndexRange> ranges;  // of the primitive's indices
  bool sectioned = false;          // cut or made see-through by the frame's section
  // Sectioned: where its vertices may lie, world space: its rest box and the spheres where a
  // deformation may have moved them (DrawItem::moved).
  Bounds reach;
};

struct MeshDraws {
  std::vector<MeshDraw> opaque;       // opaque and masked, in the items' order
  std::vector<MeshDraw> blended;      // back to front
  std::vector<MeshDraw> translucent;  // sectioned, in a Translucent section drawn blended (translucent_pass.hpp)
};

// What RendererSettings (and the bench's variants) switch on and off.
struct DrawOptions {
  bool level_of_detail = true;
  bool cull_chunks = true;
  bool cull_cut_away = true;
  bool cull_inside = true;
  bool specialized = true;  // each draw's pipeline specialized to what it needs
  Translucency translucency = Translucency::Blended;
};

// (frame, the size of the pixels drawn, options) => its draws.
MeshDraws collect_draws(const FrameParams& params, VkExtent2D extent, const DrawOptions& options);

// (a bounding sphere in model space, the model's transform) => one holding it in world space.
Sphere world_sphere(const Sphere& model_space, const glm::mat4& model_to_world);
// (a box in model space, the model's transform) => the axis-aligned box holding it in world space.
Bounds world_box(const Bounds& model_space, const glm::mat4& model_to_world);

// Binds `draw`'s material set and pushes its transform for a pipeline of `layout` (MeshPipelines').
void bind_material_and_transform(VkCommandBuffer cmd, const MeshDraw& draw, VkPipelineLayout layout);
// That, then its vertex and index buffers, and draws its ranges; returns the triangles drawn.
size_t bind_and_draw(VkCommandBuffer cmd, const MeshDraw& draw, VkPipelineLayout layout);

// Records `draws` (with blending when `blended`) in a render pass whose frame set is bound;
// returns the triangles sent to the device.
size_t record_draws(VkCommandBuffer cmd, const std::vector<MeshDraw>& draws, bool blended,
                    const MeshPipelines& pipelines, const DrawOptions& options);

}  // namespace needle::engine
