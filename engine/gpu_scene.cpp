#include "engine/gpu_scene.hpp"

#include <map>
#include <stdexcept>

#include "engine/gltf_loader.hpp"

namespace needle::engine {

GpuScene::GpuScene(const SceneRenderer& renderer, Scene scene) : scene_(std::move(scene)) {
  std::map<std::filesystem::path, size_t> loaded;
  for (const SceneAsset& asset : scene_.assets) {
    auto [it, fresh] = loaded.try_emplace(asset.gltf, models_.size());
    if (fresh) models_.push_back(renderer.upload(load_gltf(asset.gltf)));
    model_of_asset_.push_back(it->second);
    transforms_.push_back(asset.transform());
  }
}

GpuScene::GpuScene(const SceneRenderer& renderer, const Model& model, const Scene& view) {
  scene_.assets.push_back(SceneAsset{"model", {}, AssetRole::Tissue});
  scene_.camera = view.camera;
  scene_.lights = view.lights;
  scene_.background = view.background;
  models_.push_back(renderer.upload(model));
  model_of_asset_.push_back(0);
  transforms_.push_back(glm::mat4(1.0f));
}

size_t GpuScene::asset_index(const std::string& name) const {
  for (size_t i = 0; i < scene_.assets.size(); ++i) {
    if (scene_.assets[i].name == name) return i;
  }
  throw std::out_of_range("the scene has no asset named '" + name + "'");
}

void GpuScene::set_asset_transform(size_t asset, const glm::mat4& transform) { transforms_.at(asset) = transform; }

FrameParams GpuScene::frame_params() const {
  FrameParams params{scene_.camera, scene_.lights, scene_.background, {}};
  for (size_t i = 0; i < scene_.assets.size(); ++i) params.items.push_back({models_[model_of_asset_[i]].get(), transforms_[i]});
  return params;
}

}  // namespace needle::engine
