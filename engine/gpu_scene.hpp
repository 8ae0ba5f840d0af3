// A Scene with every glTF asset loaded and uploaded once, ready to draw. Asset transforms
// can change per frame (the needle follows the haptic state).
#pragma once

#include <memory>
#include <vector>

#include "engine/gpu_model.hpp"
#include "engine/scene.hpp"
#include "engine/scene_renderer.hpp"

namespace needle::engine {

class GpuScene {
 public:
  // Loads each distinct glTF file once (AssetError on any fault) and uploads it.
  GpuScene(const SceneRenderer& renderer, Scene scene);
  // One model at the origin, seen with the view's camera, lights and background.
  GpuScene(const SceneRenderer& renderer, const Model& model, const Scene& view);

  const Scene& scene() const { return scene_; }
  // The asset with this name; std::out_of_range naming it when there is none.
  size_t asset_index(const std::string& name) const;
  void set_asset_transform(size_t asset, const glm::mat4& transform);
  const GpuModel& asset_model(size_t asset) const { return *models_[model_of_asset_[asset]]; }

  FrameParams frame_params() const;

 private:
  Scene scene_;
  std::vector<std::unique_ptr<GpuModel>> models_;
  std::vector<size_t> model_of_asset_;
  std::vector<glm::mat4> transforms_;
};

}  // namespace needle::engine
