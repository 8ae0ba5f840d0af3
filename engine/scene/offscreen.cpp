#include "engine/offscreen.hpp"

#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"

namespace needle::engine {
namespace {

template <typename... SceneArgs>
RgbaImage render_once(const GpuDevice& device, Extent extent, const RendererSettings& settings,
                      SceneArgs&&... scene_args) {
  HeadlessTarget target(device, extent);
  SceneRenderer renderer(device, target, settings);
  GpuScene scene(renderer, std::forward<SceneArgs>(scene_args)...);
  RgbaImage image;
  renderer.draw(target, scene.frame_params(), &image);
  return image;
}

}  // namespace

RgbaImage render_scene_offscreen(const GpuDevice& device, const Scene& scene, Extent extent,
                                 const RendererSettings& settings) {
  return render_once(device, extent, settings, scene);
}

RgbaImage render_model_offscreen(const GpuDevice& device, const Model& model, Extent extent, const Scene& view,
                                 const RendererSettings& settings) {
  return render_once(device, extent, settings, model, view);
}

Scene framing_view(const Model& model, Extent extent) {
  Scene view;
  view.camera = framing_camera(model.world_bounds, float(extent.width) / float(extent.height));
  view.lights = default_lights();
  return view;
}

}  // namespace needle::engine
