#include "engine/offscreen.hpp"

#include "engine/gpu_scene.hpp"
#include "engine/headless_target.hpp"

namespace needle::engine {
namespace {

template <typename... SceneArgs>
RgbaImage render_once(const VulkanContext& context, VkExtent2D extent, const RendererSettings& settings,
                      SceneArgs&&... scene_args) {
  HeadlessTarget target(context, extent);
  SceneRenderer renderer(context, target, settings);
  GpuScene scene(renderer, std::forward<SceneArgs>(scene_args)...);
  RgbaImage image;
  renderer.draw(target, scene.frame_params(), &image);
  return image;
}

}  // namespace

RgbaImage render_scene_offscreen(const VulkanContext& context, const Scene& scene, VkExtent2D extent,
                                 const RendererSettings& settings) {
  return render_once(context, extent, settings, scene);
}

RgbaImage render_model_offscreen(const VulkanContext& context, const Model& model, VkExtent2D extent,
                                 const Scene& view, const RendererSettings& settings) {
  return render_once(context, extent, settings, model, view);
}

Scene framing_view(const Model& model, VkExtent2D extent) {
  Scene view;
  view.camera = framing_camera(model.world_bounds, float(extent.width) / float(extent.height));
  view.lights = default_lights();
  return view;
}

}  // namespace needle::engine
