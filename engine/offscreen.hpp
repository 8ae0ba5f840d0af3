// One frame of a scene or a model rendered offscreen and read back: `render`, `run` headless,
// golden-image tests.
#pragma once

#include "engine/extent.hpp"
#include "engine/model.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene.hpp"
#include "engine/scene_renderer.hpp"

namespace needle::engine {

class GpuDevice;

RgbaImage render_scene_offscreen(const GpuDevice& device, const Scene& scene, Extent extent,
                                 const RendererSettings& settings = {});
// The model at the origin seen with the view's camera, lights and background (its assets unused).
RgbaImage render_model_offscreen(const GpuDevice& device, const Model& model, Extent extent, const Scene& view,
                                 const RendererSettings& settings = {});
// A view that frames the model (framing_camera) under default_lights().
Scene framing_view(const Model& model, Extent extent);

}  // namespace needle::engine
