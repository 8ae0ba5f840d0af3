#include "engine/ultrasound/ultrasound_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "engine/ultrasound/echo_model.hpp"
#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/ultrasound_axial_comp.h"
#include "spirv/ultrasound_echoes_comp.h"
#include "spirv/ultrasound_image_comp.h"
#include "spirv/ultrasound_lines_comp.h"
#include "spirv/ultrasound_rest_comp.h"

namespace needle::engine {
namespace {

// local_size_x of the passes: a line's walk is long and its length varies, so lines go in small
// groups (a CPU device runs a group's invocations on its SIMD lanes, a group to a thread).
constexpr std::array<uint32_t, UltrasoundPass::kPasses> kWorkgroup{8, 64, 64, 64, 64};
// The lines a work item of the per-sample passes does (ultrasound.glsl LINES_PER_ITEM): each SIMD
// group of work items a CPU device (lavapipe) starts costs about as much as a few samples' arithmetic.
constexpr uint32_t kLinesPerItem = 16;
// A sweep's slices start at multiples of this many lines, so that each starts a work group of
// every pass (vkCmdDispatchBase): the line pass's, the rest pass's and the per-sample passes'.
constexpr uint32_t kSliceLines = 64;
static_assert(kSliceLines % kWorkgroup[0] == 0 && kSliceLines % kWorkgroup[1] == 0 && kSliceLines % kLinesPerItem == 0,
              "a slice starts a work group of every pass");
constexpr size_t kMaxLoads = 8;     // ultrasound.glsl MAX_LOADS
constexpr size_t kKernelVec4s = 5;  // ultrasound.glsl KERNEL_VEC4S
constexpr size_t kMaxPrimitives = 128;
static_assert(4 * kKernelVec4s > size_t(echo::kMaxKernelRadius), "the kernel's weights fit the uniform");

// std140 mirror of ultrasound.glsl's Echo block.
struct LoadUniform {
  glm::vec4 center_epsilon;
  glm::vec4 force_support;
};
struct EchoUniforms {
  glm::vec4 origin, direction, lateral, elevation, image;
  glm::uvec4 counts, kernel;
  glm::vec4 beam, media, needle_tip, needle_axis, needle, display, material;
  glm::vec4 axial_weights[kKernelVec4s];
  glm::vec4 lateral_weights[kKernelVec4s];
  LoadUniform loads[kMaxLoads];
};
static_assert(sizeof(EchoUniforms) == 16 * (14 + 2 * kKernelVec4s) + 32 * kMaxLoads, "std140 layout of Echo");

// Mirrors of the Layers block (std140) and the Lines buffer (std430).
struct LayerGpu {
  glm::uvec4 shape;  // x first primitive, y count, z intersection, w grid + 1 (0: primitives)
  glm::vec4 material;
  glm::vec4 grid;  // x the grid's offset (m)
};
struct GridGpu {
  glm::vec4 origin_spacing;  // xyz origin, w spacing (m)
  glm::uvec4 nodes_first;    // xyz node counts, w its first value in the grid values' buffer
  glm::vec4 quantum;         // x quantum (m)
};
struct PrimitiveGpu {
  glm::vec4 a_kind;
  glm::vec4 b_radius;
};
struct LayersGpu {
  LayerGpu layers[EchoScene::kMaxLayers];
  PrimitiveGpu primitives[kMaxPrimitives];
  GridGpu grids[EchoScene::kMaxGrids];
};
struct InterfaceGpu {
  float depth;
  int32_t from_layer, to_layer;
  float pad;
};
constexpr uint32_t kMaxRuns = 32;  // ultrasound.glsl MAX_RUNS: the runs image's width
struct LineRecordGpu {
  uint32_t count, shadow_sample;
  float needle_depth, needle_weight;
  uint32_t run_count;
  float sample_spacing;
  uint32_t pad[2];
  InterfaceGpu interfaces[ScanLine::kMaxInterfaces];
};
static_assert(sizeof(LineRecordGpu) == 32 + 16 * ScanLine::kMaxInterfaces, "std430 layout of LineRecord");

enum Binding : uint32_t {
  kUniforms,
  kLayers,
  kEchoes,
  kAxial,
  kLines,
  kPicture,
  kRuns,
  kUniformsStorage,
  kRestOffsets,
  kGridValues,
  kBindings
};

VkDescriptorType descriptor_type(uint32_t binding) {
  switch (binding) {
    case kUniforms:
    case kLayers:
      return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case kLines:
    case kUniformsStorage:
    case kGridValues:
      return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    default:
      return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  }
}

// A float image the passes keep in GENERAL layout between them: four channels, or two for the
// complex echoes (half the memory the convolutions read: on lavapipe the axial pass took half the
// time, docs/BENCHMARKS.md, "Fifth round").
constexpr VkFormat kComplexFormat = VK_FORMAT_R32G32_SFLOAT;
GpuImage work_image(const VulkanContext& context, uint32_t width, uint32_t height,
                    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT) {
  return GpuImage(context, {{width, height}, format, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
}

// The device stores two-channel float images (not every Vulkan device must).
void check_device(const VulkanContext& context) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), kComplexFormat, &properties);
  if (!context.storage_image_extended_formats() ||
      !(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT))
    throw VulkanError(
        "the ultrasound image needs R32G32_SFLOAT storage images (shaderStorageImageExtendedFormats), which " +
        context.device_description() + " does not offer");
}

void check(const EchoScene& scene, const UltrasoundSettings& settings) {
  if (settings.lines == 0 || settings.samples == 0)
    throw std::invalid_argument("an ultrasound image needs lines and samples");
  if (settings.sweep_frames == 0) throw std::invalid_argument("an ultrasound sweep takes at least one frame");
  if (scene.layers.size() > EchoScene::kMaxLayers)
    throw std::invalid_argument("the ultrasound takes " + std::to_string(EchoScene::kMaxLayers) + " layers, not " +
                                std::to_string(scene.layers.size()));
  for (const EchoLayer& layer : scene.layers) {
    if (layer.grid) {
      if (!layer.primitives.empty())
        throw std::invalid_argument("layer \"" + layer.name + "\" has both a grid and primitives");
      const glm::uvec3 n = layer.grid->nodes;
      if (n.x < 2 || n.y < 2 || n.z < 2 || !layer.grid->values || layer.grid->values->size() != size_t(n.x) * n.y * n.z)
        throw std::invalid_argument("layer \"" + layer.name + "\": its grid's values are not its nodes' count");
      continue;
    }
    if (layer.primitives.empty() || layer.primitives.size() > EchoLayer::kMaxPrimitives)
      throw std::invalid_argument("layer \"" + layer.name + "\" has " + std::to_string(layer.primitives.size()) +
                                  " primitives; the ultrasound takes 1 to " +
                                  std::to_string(EchoLayer::kMaxPrimitives));
  }
}

// The scene's distinct grids, in the order their layers first use them.
std::vector<const EchoGrid*> distinct_grids(const EchoScene& scene) {
  std::vector<const EchoGrid*> grids;
  for (const EchoLayer& l : scene.layers)
    if (l.grid && std::find(grids.begin(), grids.end(), l.grid.get()) == grids.end()) grids.push_back(l.grid.get());
  if (grids.size() > EchoScene::kMaxGrids)
    throw std::invalid_argument("the ultrasound takes " + std::to_string(EchoScene::kMaxGrids) + " grids, not " +
                                std::to_string(grids.size()));
  size_t values = 0;
  for (const EchoGrid* g : grids) values += g->values->size();
  if (values > EchoScene::kMaxGridValues)
    throw std::invalid_argument("the ultrasound takes " + std::to_string(EchoScene::kMaxGridValues) +
                                " grid nodes in all, not " + std::to_string(values));
  return grids;
}

// Every grid's values one after the other (16 bits each, two to a 32-bit word), padded to a word;
// one word when there is no grid (a buffer must not be empty).
std::vector<int16_t> grid_values(const std::vector<const EchoGrid*>& grids) {
  std::vector<int16_t> all;
  for (const EchoGrid* g : grids) all.insert(all.end(), g->values->begin(), g->values->end());
  all.resize(std::max<size_t>(2, all.size() + all.size() % 2), 0);
  return all;
}

LayersGpu pack_layers(const EchoScene& scene, const std::vector<const EchoGrid*>& grids) {
  LayersGpu out{};
  uint32_t first_value = 0;
  for (size_t g = 0; g < grids.size(); ++g) {
    out.grids[g] = {glm::vec4(glm::vec3(grids[g]->origin), float(grids[g]->spacing_m)),
                    glm::uvec4(grids[g]->nodes, first_value), glm::vec4(float(grids[g]->quantum_m), 0.0f, 0.0f, 0.0f)};
    first_value += uint32_t(grids[g]->values->size());
  }
  uint32_t next = 0;
  for (size_t k = 0; k < scene.layers.size(); ++k) {
    const EchoLayer& l = scene.layers[k];
    const EchoMaterial& m = l.material;
    const uint32_t grid =
        l.grid ? uint32_t(std::find(grids.begin(), grids.end(), l.grid.get()) - grids.begin()) + 1u : 0u;
    out.layers[k] = {glm::uvec4(next, uint32_t(l.primitives.size()), l.intersection ? 1u : 0u, grid),
                     glm::vec4(float(m.impedance_MRayl), float(m.attenuation_dB_per_cm_MHz), float(m.echogenicity),
                               float(m.scatterer_density)),
                     glm::vec4(float(l.grid_offset_m), 0.0f, 0.0f, 0.0f)};
    for (const EchoPrimitive& p : l.primitives)
      out.primitives[next++] = {glm::vec4(glm::vec3(p.a), float(int(p.kind))),
                                glm::vec4(glm::vec3(p.b), float(p.radius))};
  }
  return out;
}

// Gaussian weights exp(−(kΔ)²/2σ²) for k = 0..radius, radius = ⌈3σ/Δ⌉ up to the shaders' limit.
std::vector<float> gaussian_weights(double sigma, double spacing) {
  const int radius = std::clamp(int(std::ceil(3.0 * sigma / spacing)), 0, echo::kMaxKernelRadius);
  std::vector<float> w;
  for (int k = 0; k <= radius; ++k) w.push_back(float(std::exp(-0.5 * std::pow(k * spacing / sigma, 2.0))));
  return w;
}

// Σ of the weights (or of their squares) over the kernel's whole width (both sides).
double sum(const std::vector<float>& w, int power) {
  double s = std::pow(double(w[0]), power);
  for (size_t k = 1; k < w.size(); ++k) s += 2.0 * std::pow(double(w[k]), power);
  return s;
}

void compute_barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src, VkAccessFlags dst) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = src;
  barrier.dstAccessMask = dst;
  vkCmdPipelineBarrier(cmd, src_stage, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

UltrasoundPass::UltrasoundPass(const VulkanContext& context, EchoScene scene, const UltrasoundSettings& settings)
    : context_(context), device_(context.device()), scene_(std::move(scene)), settings_(settings) {
  check(scene_, settings_);
  check_device(context_);
  std::array<VkDescriptorSetLayoutBinding, kBindings> bindings{};
  for (uint32_t b = 0; b < kBindings; ++b) {
    bindings[b] = {b, descriptor_type(b), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  }
  set_layout_ = descriptor_set_layout(device_, {bindings.begin(), bindings.end()});
  pipeline_layout_ = single_set_pipeline_layout(device_, set_layout_);

  const std::vector<const EchoGrid*> grids = distinct_grids(scene_);
  const LayersGpu packed = pack_layers(scene_, grids);
  layers_ = GpuBuffer::device_local_with_data(context_, &packed, sizeof packed, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  const std::vector<int16_t> values = grid_values(grids);
  grid_values_ = GpuBuffer::device_local_with_data(context_, values.data(), values.size() * sizeof(int16_t),
                                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  echoes_ = work_image(context_, settings_.samples, settings_.lines, kComplexFormat);
  axial_ = work_image(context_, settings_.samples, settings_.lines, kComplexFormat);
  runs_ = work_image(context_, kMaxRuns, settings_.lines);
  rest_offsets_ = work_image(context_, settings_.samples + 1, settings_.lines);  // rest_nodes() at a spacing of 1
  lines_ =
      GpuBuffer::host_visible(context_, settings_.lines * sizeof(LineRecordGpu), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  image_ =
      GpuImage(context_, {{settings_.lines, settings_.samples},
                          VK_FORMAT_R8G8B8A8_UNORM,
                          VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});

  std::array<VkDescriptorPoolSize, 3> sizes{{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2 * kRing},
                                             {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * kRing},
                                             {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 5 * kRing}}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = kRing;
  pool_info.poolSizeCount = uint32_t(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VK_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &pool_));
  for (size_t slot = 0; slot < kRing; ++slot) {
    uniforms_[slot] = GpuBuffer::host_visible(context_, sizeof(EchoUniforms),
                                              VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    VK_CHECK(vkAllocateDescriptorSets(device_, &alloc, &sets_[slot]));
    const std::array<VkDescriptorBufferInfo, kBindings> buffers{{{uniforms_[slot].handle(), 0, VK_WHOLE_SIZE},
                                                                 {layers_.handle(), 0, VK_WHOLE_SIZE},
                                                                 {},
                                                                 {},
                                                                 {lines_.handle(), 0, VK_WHOLE_SIZE},
                                                                 {},
                                                                 {},
                                                                 {uniforms_[slot].handle(), 0, VK_WHOLE_SIZE},
                                                                 {},
                                                                 {grid_values_.handle(), 0, VK_WHOLE_SIZE}}};
    std::array<VkDescriptorImageInfo, kBindings> images{};
    images[kEchoes] = {VK_NULL_HANDLE, echoes_.view(), VK_IMAGE_LAYOUT_GENERAL};
    images[kAxial] = {VK_NULL_HANDLE, axial_.view(), VK_IMAGE_LAYOUT_GENERAL};
    images[kPicture] = {VK_NULL_HANDLE, image_.view(), VK_IMAGE_LAYOUT_GENERAL};
    images[kRuns] = {VK_NULL_HANDLE, runs_.view(), VK_IMAGE_LAYOUT_GENERAL};
    images[kRestOffsets] = {VK_NULL_HANDLE, rest_offsets_.view(), VK_IMAGE_LAYOUT_GENERAL};
    std::array<VkWriteDescriptorSet, kBindings> writes{};
    for (uint32_t b = 0; b < kBindings; ++b) {
      writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      writes[b].dstSet = sets_[slot];
      writes[b].dstBinding = b;
      writes[b].descriptorCount = 1;
      writes[b].descriptorType = bindings[b].descriptorType;
      if (bindings[b].descriptorType == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)
        writes[b].pImageInfo = &images[b];
      else
        writes[b].pBufferInfo = &buffers[b];
    }
    vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);
  }
  divide_lines();
}

void UltrasoundPass::set_sweep_frames(uint32_t frames) {
  if (frames == 0) throw std::invalid_argument("an ultrasound sweep takes at least one frame");
  if (frames == settings_.sweep_frames) return;
  settings_.sweep_frames = frames;
  divide_lines();
}

void UltrasoundPass::divide_lines() {
  // Slice k: groups of kSliceLines lines [k G / n, (k + 1) G / n) of the image's G, n at most G.
  const uint32_t groups = (settings_.lines + kSliceLines - 1) / kSliceLines,
                 n = std::min(settings_.sweep_frames, groups);
  slices_.clear();
  for (uint32_t k = 0; k < n; ++k)
    slices_.push_back({std::min(settings_.lines, k * groups / n * kSliceLines),
                       std::min(settings_.lines, (k + 1) * groups / n * kSliceLines)});
  made_.assign(n, {});
  next_slice_ = 0;
}

UltrasoundPass::~UltrasoundPass() {
  vkDeviceWaitIdle(device_);
  if (timestamps_) vkDestroyQueryPool(device_, timestamps_, nullptr);
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
  for (const auto& [key, p] : pipelines_) vkDestroyPipeline(device_, p, nullptr);
  if (pipeline_layout_) vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
}

void UltrasoundPass::set_device_timings(bool on) {
  timed_ = on && context_.timestamp_period_ns() > 0.0;
  if (!timed_ || timestamps_) return;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = uint32_t(kRing * (kPasses + 1));
  VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &timestamps_));
}

std::optional<std::array<double, UltrasoundPass::kPasses>> UltrasoundPass::read_pass_ms() const {
  if (!timed_ || timed_slot_ >= kRing) return std::nullopt;
  std::array<uint64_t, kPasses + 1> ticks{};
  VK_CHECK(vkGetQueryPoolResults(device_, timestamps_, uint32_t(timed_slot_ * (kPasses + 1)), uint32_t(ticks.size()),
                                 sizeof ticks, ticks.data(), sizeof(uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  const uint32_t bits = context_.timestamp_valid_bits();
  const uint64_t mask = bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
  std::array<double, kPasses> ms{};
  for (size_t p = 0; p < kPasses; ++p)
    ms[p] = double((ticks[p + 1] - ticks[p]) & mask) * context_.timestamp_period_ns() * 1e-6;
  return ms;
}

VkPipeline UltrasoundPass::pipeline(size_t pass, uint32_t constant) {
  const auto key = std::pair{pass, constant};
  if (const auto found = pipelines_.find(key); found != pipelines_.end()) return found->second;
  static constexpr std::array<std::pair<const uint32_t*, size_t>, kPasses> kCode{
      {{ultrasound_lines_comp_spv, sizeof(ultrasound_lines_comp_spv)},
       {ultrasound_rest_comp_spv, sizeof(ultrasound_rest_comp_spv)},
       {ultrasound_echoes_comp_spv, sizeof(ultrasound_echoes_comp_spv)},
       {ultrasound_axial_comp_spv, sizeof(ultrasound_axial_comp_spv)},
       {ultrasound_image_comp_spv, sizeof(ultrasound_image_comp_spv)}}};
  const VkSpecializationMapEntry entry{kConstantId[pass], 0, sizeof constant};
  const VkSpecializationInfo info{1, &entry, sizeof constant, &constant};
  return pipelines_[key] = compute_pipeline(device_, pipeline_layout_, kCode[pass].first, kCode[pass].second, &info,
                                            VK_PIPELINE_CREATE_DISPATCH_BASE_BIT);  // a slice's lines (record)
}

std::function<void(VkCommandBuffer)> UltrasoundPass::update(const UltrasoundProbe& probe, const NeedleLoad* needle,
                                                            bool unless_shown) {
  const UltrasoundSettings& s = settings_;
  const double dz = probe.depth_m / s.samples, dx = probe.width_m / s.lines;
  const std::vector<float> axial = gaussian_weights(echo::axial_sigma_m(probe), dz);
  const std::vector<float> lateral = gaussian_weights(echo::lateral_sigma_m(probe), dx);
  const DeformationField field = echo::echo_field(scene_, needle);
  if (field.loads.size() > kMaxLoads)
    throw std::invalid_argument("the ultrasound takes " + std::to_string(kMaxLoads) + " tissue loads");

  EchoUniforms u{};
  u.origin = glm::vec4(glm::vec3(probe.position), 0.0f);
  u.direction = glm::vec4(glm::vec3(probe.direction), 0.0f);
  u.lateral = glm::vec4(glm::vec3(probe.lateral), 0.0f);
  u.elevation = glm::vec4(glm::vec3(probe.elevation()), 0.0f);
  u.image = glm::vec4(float(probe.depth_m), float(probe.width_m), float(dz), float(dx));
  u.counts = glm::uvec4(s.lines, s.samples, uint32_t(scene_.layers.size()), uint32_t(field.loads.size()));
  const uint32_t rest_spacing = echo::rest_node_spacing(field, s, dz);
  u.kernel = glm::uvec4(uint32_t(axial.size() - 1), uint32_t(lateral.size() - 1), s.speckle ? 1u : 0u, rest_spacing);
  u.beam = glm::vec4(float(echo::nepers_per_m(1.0, probe.frequency_MHz)),
                     float(echo::nepers_per_m(echo::kTimeGain_dB_per_cm_MHz, probe.frequency_MHz)),
                     float(echo::kBackscatterLevel), float(echo::kSpecularWidth_rad));
  u.media = glm::vec4(float(echo::kGelImpedance_MRayl), float(echo::kNeedleImpedance_MRayl),
                      float(echo::kReverberationRatio), float(echo::kShadowLevel));
  if (needle) {
    u.needle_tip = glm::vec4(glm::vec3(needle->tip), 1.0f);
    u.needle_axis = glm::vec4(glm::vec3(glm::normalize(needle->axis)), float(scene_.needle.length_m));
  }
  u.needle = glm::vec4(float(scene_.needle.radius_m), float(probe.slice_thickness_m / 2.3548200450309493),
                       float(echo::kReverberationEchoes), 0.0f);
  // The tissue's level after the point spread function is its backscatter whatever the sampling:
  // speckle's mean power over 1/√(Σ h²) of the 2-D kernel, a uniform level (no speckle) over 1/Σ h.
  const double normalisation =
      s.speckle ? 1.0 / std::sqrt(sum(axial, 2) * sum(lateral, 2)) : 1.0 / (sum(axial, 1) * sum(lateral, 1));
  u.display =
      glm::vec4(float(s.dynamic_range_dB), float(s.gain_dB), float(normalisation), float(echo::kScattererCell_m));
  u.material = glm::vec4(float(field.material.a()), float(field.material.b()), 0.0f, 0.0f);
  for (size_t k = 0; k < axial.size(); ++k) u.axial_weights[k / 4][int(k % 4)] = axial[k];
  for (size_t k = 0; k < lateral.size(); ++k) u.lateral_weights[k / 4][int(k % 4)] = lateral[k];
  for (size_t i = 0; i < field.loads.size(); ++i) {
    const Kelvinlet& k = field.loads[i];
    u.loads[i] = {glm::vec4(glm::vec3(k.center), float(k.epsilon)), glm::vec4(glm::vec3(k.force), float(k.support))};
  }
  auto bytes = std::make_shared<std::vector<uint8_t>>(sizeof u);
  std::memcpy(bytes->data(), &u, sizeof u);
  std::optional<size_t> slice;  // none: the whole image
  if (unless_shown && has_image()) {
    for (size_t k = 0; k < made_.size() && !slice; ++k)
      if (const size_t at = (next_slice_ + k) % made_.size(); made_[at] != *bytes) slice = at;
    if (!slice) return {};
  }
  const std::array<uint32_t, kPasses> constants{u.counts.w, u.counts.w, u.counts.w, u.kernel.x, u.kernel.y};
  std::array<VkPipeline, kPasses> pipelines{};
  for (size_t p = 0; p < kPasses; ++p) pipelines[p] = pipeline(p, constants[p]);
  if (u.counts.w == 0) pipelines[kRestPass] = VK_NULL_HANDLE;  // a tissue at rest: no nodes to make
  const uint32_t lateral_radius = u.kernel.y;
  return [this, bytes, pipelines, rest_spacing, lateral_radius, slice](VkCommandBuffer cmd) {
    record(cmd, *bytes, pipelines, rest_spacing, lateral_radius, slice);
  };
}

void UltrasoundPass::record(VkCommandBuffer cmd, const std::vector<uint8_t>& uniforms,
                            const std::array<VkPipeline, kPasses>& pipelines, uint32_t spacing, uint32_t lateral_radius,
                            std::optional<size_t> slice) {
  const size_t slot = ring_;
  ring_ = (ring_ + 1) % kRing;
  std::memcpy(uniforms_[slot].mapped(), uniforms.data(), uniforms.size());
  for (size_t k = 0; k < made_.size(); ++k)
    if (!slice || k == *slice) made_[k] = uniforms;
  if (slice) next_slice_ = (*slice + 1) % made_.size();
  const Slice made = slice ? slices_[*slice] : Slice{0, settings_.lines};
  const uint32_t first = made.first, lines = made.end - made.first, samples = settings_.samples;

  // The last image's reads (the UI's fragment shader, a read-back copy, the passes themselves)
  // come before this image's writes.
  compute_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  transition_image(
      cmd, image_.image(), image_layout_, VK_IMAGE_LAYOUT_GENERAL,
      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT);
  if (!work_images_ready_) {
    for (const GpuImage* work : {&echoes_, &axial_, &runs_, &rest_offsets_})
      transition_image(cmd, work->image(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                       VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                       VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    work_images_ready_ = true;
  }
  // The echoes cleared for the line pass to add the specular echoes to, after the last image's
  // passes read them (another slice's are in the axial image by then).
  VkMemoryBarrier before_clear{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  before_clear.srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  before_clear.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before_clear,
                       0, nullptr, 0, nullptr);
  const VkClearColorValue zero{};
  const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, echoes_.image(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &whole);
  compute_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &sets_[slot], 0, nullptr);
  // A timestamp after each pass: the barrier after each makes a CPU device (lavapipe) finish the
  // pass before it takes the next (engine/passes/scene_pass.cpp, write_timestamp).
  const uint32_t first_query = uint32_t(slot * (kPasses + 1));
  if (timed_) {
    vkCmdResetQueryPool(cmd, timestamps_, first_query, uint32_t(kPasses + 1));
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, first_query);
    timed_slot_ = slot;
  } else {
    timed_slot_ = kRing;
  }
  // The slice's lines: the line pass a work item a line; the rest pass a work item a node of a
  // line, the lines across a group; the others a work item a sample of kLinesPerItem lines. The
  // work groups (x, y) from the slice's first line's (vkCmdDispatchBase). The image pass also
  // remakes the neighbouring slices' lines within the lateral kernel's reach: their picture
  // blends this slice's lines, so after a whole sweep every line is its probe's and needle's.
  const auto groups_of = [](uint32_t n, uint32_t size) { return (n + size - 1) / size; };
  const uint32_t nodes = (samples - 1) / spacing + 2;  // ultrasound.glsl rest_nodes
  const uint32_t line_groups = groups_of(lines, kLinesPerItem), first_group = first / kLinesPerItem;
  const uint32_t reach_first = (first - std::min(first, lateral_radius)) / kLinesPerItem;
  const uint32_t reach_end = groups_of(std::min(settings_.lines, made.end + lateral_radius), kLinesPerItem);
  struct Groups {
    uint32_t base_x, base_y, x, y;
  };
  const std::array<Groups, kPasses> groups{
      {{first / kWorkgroup[0], 0, groups_of(lines, kWorkgroup[0]), 1},
       {first / kWorkgroup[1], 0, groups_of(lines, kWorkgroup[1]), nodes},
       {0, first_group, groups_of(samples, kWorkgroup[2]), line_groups},
       {0, first_group, groups_of(samples, kWorkgroup[3]), line_groups},
       {0, reach_first, groups_of(samples, kWorkgroup[4]), reach_end - reach_first}}};
  for (size_t p = 0; p < kPasses; ++p) {
    if (p > 0)
      compute_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    if (pipelines[p]) {
      const Groups& g = groups[p];
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines[p]);
      vkCmdDispatchBase(cmd, g.base_x, g.base_y, 0, g.x, g.y, 1);
    }
    if (timed_) {
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr,
                           0, nullptr, 0, nullptr);
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, first_query + uint32_t(p) + 1);
    }
  }

  // The picture goes to fragment shaders (the UI pass); the scan lines to the host.
  transition_image(cmd, image_.image(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
  VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0,
                       nullptr, 0, nullptr);
  image_layout_ = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

RgbaImage UltrasoundPass::read_image() const {
  RgbaImage out{settings_.lines, settings_.samples,
                std::vector<uint8_t>(size_t(settings_.lines) * settings_.samples * 4)};
  if (image_layout_ == VK_IMAGE_LAYOUT_UNDEFINED) return out;  // no image yet: black
  GpuBuffer host = GpuBuffer::host_visible(context_, out.pixels.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  context_.submit_and_wait([&](VkCommandBuffer cmd) {
    transition_image(cmd, image_.image(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {settings_.lines, settings_.samples, 1};
    vkCmdCopyImageToBuffer(cmd, image_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.handle(), 1, &region);
    transition_image(cmd, image_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0);
    VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0,
                         nullptr);
  });
  std::memcpy(out.pixels.data(), host.mapped(), out.pixels.size());
  return out;
}

std::vector<ScanLine> UltrasoundPass::read_lines() const {
  std::vector<LineRecordGpu> records(settings_.lines);
  std::memcpy(records.data(), lines_.mapped(), records.size() * sizeof(LineRecordGpu));
  std::vector<ScanLine> out(records.size());
  for (size_t i = 0; i < records.size(); ++i) {
    const LineRecordGpu& r = records[i];
    for (uint32_t k = 0; k < std::min<uint32_t>(r.count, ScanLine::kMaxInterfaces); ++k)
      out[i].interfaces.push_back({r.interfaces[k].depth, r.interfaces[k].from_layer, r.interfaces[k].to_layer});
    if (r.shadow_sample != ~uint32_t(0)) out[i].shadow_depth_m = (double(r.shadow_sample) + 0.5) * r.sample_spacing;
    if (r.needle_weight > 0.0f) out[i].needle_depth_m = r.needle_depth;
  }
  return out;
}

}  // namespace needle::engine
