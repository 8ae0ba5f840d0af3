// The ultrasound image's compute passes behind UltrasoundView (engine/ultrasound.hpp): each scan
// line's layer changes, reflections and runs between them (shaders/ultrasound_lines.comp), a
// deformed tissue's rest positions at nodes down the lines (ultrasound_rest.comp), each sample's
// echo from them and its scatterer (ultrasound_echoes.comp), the point spread function
// along the lines (ultrasound_axial.comp), across them with the envelope and log compression into
// an RGBA8 storage image (ultrasound_image.comp). The image is left for fragment shaders to sample
// (the UI pass draws it).
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "engine/ultrasound.hpp"
#include "engine/vulkan/gpu_buffer.hpp"
#include "engine/vulkan/gpu_image.hpp"

namespace needle::engine {

class VulkanContext;

class UltrasoundPass {
 public:
  // std::invalid_argument for more layers or primitives than the shaders take, or a size of 0.
  UltrasoundPass(const VulkanContext& context, EchoScene scene, const UltrasoundSettings& settings);
  ~UltrasoundPass();
  UltrasoundPass(const UltrasoundPass&) = delete;
  UltrasoundPass& operator=(const UltrasoundPass&) = delete;

  const VulkanContext& context() const { return context_; }
  const EchoScene& scene() const { return scene_; }
  const UltrasoundSettings& settings() const { return settings_; }

  // The recorder of one image for this probe and needle (its uniforms are filled now). With
  // `unless_shown`, once there is an image: the next slice of the sweep (settings().sweep_frames)
  // whose lines were last recorded from other uniforms, or none (an empty function) when every
  // slice's were these (the scene and settings are the pass's own, so the lines would be the same).
  std::function<void(VkCommandBuffer)> update(const UltrasoundProbe& probe, const NeedleLoad* needle,
                                              bool unless_shown = false);
  // From the next image on, every line made again when it changes; std::invalid_argument for 0.
  void set_sweep_frames(uint32_t frames);

  // The image: sampled by fragment shaders in SHADER_READ_ONLY_OPTIMAL once an image was recorded.
  VkImageView image_view() const { return image_.view(); }
  bool has_image() const { return image_layout_ == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL; }
  RgbaImage read_image() const;
  std::vector<ScanLine> read_lines() const;

  // Device time of each pass of the images recorded from now on (timestamp queries; a device
  // without them gives none), read once an image is done.
  static constexpr size_t kPasses = 5;
  static constexpr std::array<const char*, kPasses> kPassNames{"lines", "rest", "echoes", "axial", "image"};
  void set_device_timings(bool on);
  std::optional<std::array<double, kPasses>> read_pass_ms() const;

 private:
  static constexpr size_t kRing = 3;  // more than the renderer's frames in flight

  // The pipeline of pass `pass` (kPassNames) with its specialization constant (ultrasound.glsl:
  // LOADS for the line, rest and echo passes, AXIAL_RADIUS, LATERAL_RADIUS for the convolutions)
  // set to `constant`, made the first time an image needs it.
  static constexpr std::array<uint32_t, kPasses> kConstantId{0, 0, 0, 1, 2};
  VkPipeline pipeline(size_t pass, uint32_t constant);
  static constexpr size_t kRestPass = 1;  // kPassNames: dispatched only for a deformed tissue
  // Slice k of the sweep: lines [first, end).
  struct Slice {
    uint32_t first = 0, end = 0;
  };
  // settings_.sweep_frames => slices_, and made_ emptied: every slice is made again.
  void divide_lines();
  // `spacing`: the rest nodes' (echo.kernel.w), `lateral_radius` the lateral kernel's (echo.kernel.y);
  // `slice`: the sweep's slice recorded, none: all.
  void record(VkCommandBuffer cmd, const std::vector<uint8_t>& uniforms,
              const std::array<VkPipeline, kPasses>& pipelines, uint32_t spacing, uint32_t lateral_radius,
              std::optional<size_t> slice);

  const VulkanContext& context_;
  VkDevice device_;
  EchoScene scene_;
  UltrasoundSettings settings_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  std::map<std::pair<size_t, uint32_t>, VkPipeline> pipelines_;  // (pass, constant) -> pipeline
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::array<VkDescriptorSet, kRing> sets_{};
  std::array<GpuBuffer, kRing> uniforms_;
  GpuBuffer layers_;
  GpuBuffer grid_values_;                          // every grid layer's values, 16 bits each (EchoGrid)
  GpuImage echoes_, axial_, runs_, rest_offsets_;  // float images between the passes, in GENERAL layout
  bool work_images_ready_ = false;                 // once transitioned to GENERAL
  GpuBuffer lines_;                                // host-visible: read back after an image
  GpuImage image_;
  VkImageLayout image_layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
  size_t ring_ = 0;
  std::vector<Slice> slices_;                // the sweep's
  std::vector<std::vector<uint8_t>> made_;   // per slice, the uniforms its lines were last recorded with
  size_t next_slice_ = 0;                    // where the sweep goes on
  VkQueryPool timestamps_ = VK_NULL_HANDLE;  // kPasses + 1 a ring slot, while timings are on
  bool timed_ = false;
  size_t timed_slot_ = kRing;  // the slot of the last image recorded with timings
};

}  // namespace needle::engine
