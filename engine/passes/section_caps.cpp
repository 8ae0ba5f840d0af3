#include "engine/passes/section_caps.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "engine/passes/gpu_model.hpp"
#include "engine/passes/mesh_pipelines.hpp"
#include "engine/screen_projection.hpp"
#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/mesh_frag.h"
#include "spirv/section_stencil_frag.h"

namespace needle::engine {
namespace {

// The stencil's bits: up to 8 structures each have their own before the stencil is cleared.
constexpr uint32_t kStencilBits = 8;

VkStencilOpState stencil_op(VkStencilOp pass, VkCompareOp compare) {
  return {VK_STENCIL_OP_KEEP, pass, VK_STENCIL_OP_KEEP, compare, 0, 0, 0};  // masks and reference: dynamic
}

// The pixels of `extent` where `box` (world space) can show: its corners' projections' bounding
// rectangle, the whole extent when a corner lies behind the camera.
VkRect2D screen_rect(const Bounds& box, const Camera& camera, VkExtent2D extent) {
  const glm::mat4 view_proj = view_projection(camera, {extent.width, extent.height});
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 clip =
        view_proj * glm::vec4((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                              (corner & 4) ? box.max.z : box.min.z, 1.0f);
    if (clip.w <= 0.0f) return {{0, 0}, extent};
    // The viewport flips y: NDC y up is the framebuffer's row 0 at the top.
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const glm::vec2 px((ndc.x + 1.0f) * 0.5f * float(extent.width), (1.0f - ndc.y) * 0.5f * float(extent.height));
    lo = glm::min(lo, px), hi = glm::max(hi, px);
  }
  const int32_t x0 = std::clamp(int32_t(std::floor(lo.x)) - 1, 0, int32_t(extent.width));
  const int32_t y0 = std::clamp(int32_t(std::floor(lo.y)) - 1, 0, int32_t(extent.height));
  const int32_t x1 = std::clamp(int32_t(std::ceil(hi.x)) + 1, 0, int32_t(extent.width));
  const int32_t y1 = std::clamp(int32_t(std::ceil(hi.y)) + 1, 0, int32_t(extent.height));
  return {{x0, y0}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
}

}  // namespace

std::array<MeshVertex, 6> cap_quad(const Section& section, const std::vector<Sphere>& cut) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(section.normal));
  const glm::dvec3 point = glm::dvec3(section.point);
  // An orthonormal basis of the plane, u × v = n: counter-clockwise seen from the viewer's side.
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n)), v = glm::cross(n, u);
  // Centred on the first sphere's cut; the half side reaches past every sphere's.
  const glm::dvec3 centre = cut.empty() ? point : cut.front().center - glm::dot(cut.front().center - point, n) * n;
  double half = 0.0;
  for (const Sphere& s : cut) {
    const glm::dvec3 d = s.center - centre;
    half = std::max({half, std::abs(glm::dot(d, u)) + s.radius, std::abs(glm::dot(d, v)) + s.radius});
  }
  const glm::dvec3 corners[4] = {centre - half * u - half * v, centre + half * u - half * v,
                                 centre + half * u + half * v, centre - half * u + half * v};
  std::array<MeshVertex, 6> quad;
  const int order[6] = {0, 1, 2, 0, 2, 3};
  for (size_t i = 0; i < quad.size(); ++i) {
    quad[i].position = glm::vec3(corners[order[i]]);
    quad[i].normal = glm::vec3(n);
    quad[i].uv = glm::vec2(0.5f);  // a textured surface's cut takes its texture's middle
  }
  return quad;
}

SectionCaps::SectionCaps(const VulkanContext& context, const MeshPipelines& pipelines, VkRenderPass render_pass,
                         VkSampleCountFlagBits samples, uint32_t slots)
    : device_(context.device()), layout_(pipelines.layout()) {
  const std::vector<VkDynamicState> stencil_state{
      VK_DYNAMIC_STATE_STENCIL_COMPARE_MASK, VK_DYNAMIC_STATE_STENCIL_WRITE_MASK, VK_DYNAMIC_STATE_STENCIL_REFERENCE};
  MeshPipelineSpec stencil{section_stencil_frag_spv, sizeof(section_stencil_frag_spv)};
  stencil.variant = {true, false, true, false};  // every face
  stencil.depth.stencilTestEnable = VK_TRUE;
  stencil.depth.front = stencil.depth.back = stencil_op(VK_STENCIL_OP_INVERT, VK_COMPARE_OP_ALWAYS);
  VkPipelineColorBlendAttachmentState no_color{};
  stencil.blends = {no_color};
  stencil.dynamic_states = stencil_state;
  stencil.render_pass = render_pass;
  stencil.samples = samples;
  stencil_ = pipelines.make(stencil);

  for (bool textured : {false, true}) {
    MeshPipelineSpec cap{mesh_frag_spv, sizeof(mesh_frag_spv)};
    cap.variant = {true, false, false, textured};
    cap.depth.depthTestEnable = VK_TRUE;
    cap.depth.depthWriteEnable = VK_TRUE;
    cap.depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;  // the later structure's cap over an earlier one's
    cap.depth.stencilTestEnable = VK_TRUE;
    cap.depth.front = cap.depth.back = stencil_op(VK_STENCIL_OP_KEEP, VK_COMPARE_OP_EQUAL);
    cap.blends = {color_writes(false)};
    cap.dynamic_states = stencil_state;
    cap.render_pass = render_pass;
    cap.samples = samples;
    caps_[textured ? 1 : 0] = pipelines.make(cap);
  }
  for (uint32_t i = 0; i < slots; ++i)
    quads_.push_back(
        GpuBuffer::host_visible(context, sizeof(std::array<MeshVertex, 6>), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT));
}

SectionCaps::~SectionCaps() {
  vkDestroyPipeline(device_, stencil_, nullptr);
  for (VkPipeline p : caps_) vkDestroyPipeline(device_, p, nullptr);
}

size_t SectionCaps::record(VkCommandBuffer cmd, uint32_t slot, const std::vector<MeshDraw>& draws,
                           const Section& section, const Camera& camera, VkExtent2D extent) {
  std::vector<const MeshDraw*> cut;
  std::vector<Sphere> bounds;
  for (const MeshDraw& d : draws) {
    if (!d.sectioned || d.ranges.empty()) continue;
    cut.push_back(&d);
    bounds.push_back(world_sphere(d.model->primitives()[d.primitive].bounds, d.transform));
  }
  if (cut.empty()) return 0;
  const std::array<MeshVertex, 6> quad = cap_quad(section, bounds);
  std::memcpy(quads_[slot].mapped(), quad.data(), sizeof quad);

  size_t triangles = 0;
  for (size_t k = 0; k < cut.size(); ++k) {
    const MeshDraw& d = *cut[k];
    const uint32_t bit = 1u << (k % kStencilBits);
    if (k > 0 && k % kStencilBits == 0) {
      const VkClearAttachment clear{VK_IMAGE_ASPECT_STENCIL_BIT, 0, {.depthStencil = {1.0f, 0}}};
      const VkClearRect rect{{{0, 0}, extent}, 0, 1};
      vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
    }
    const VkRect2D scissor = screen_rect(d.reach, camera, extent);
    if (scissor.extent.width == 0 || scissor.extent.height == 0) continue;
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, stencil_);
    vkCmdSetStencilWriteMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, bit);
    vkCmdSetStencilCompareMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, bit);
    vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, bit);
    triangles += bind_and_draw(cmd, d, layout_);

    const Material& m = d.model->material_of(d.primitive);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, caps_[m.base_color_texture >= 0 ? 1 : 0]);
    vkCmdSetStencilWriteMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, 0);
    vkCmdSetStencilCompareMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, bit);
    vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, bit);
    const MeshDraw plane{d.model, d.primitive, glm::mat4(1.0f), 0.0f, {}, false};
    bind_material_and_transform(cmd, plane, layout_);
    const VkBuffer vertices = quads_[slot].handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
    vkCmdDraw(cmd, uint32_t(quad.size()), 1, 0, 0);
    triangles += 2;
  }
  const VkRect2D whole{{0, 0}, extent};
  vkCmdSetScissor(cmd, 0, 1, &whole);
  return triangles;
}

}  // namespace needle::engine
