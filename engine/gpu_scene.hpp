// A Scene with every glTF asset loaded and uploaded once, ready to draw. Asset transforms
// can change per frame (the needle follows the haptic state), and tissue assets that declare a
// deformation get a GPU deformation pass driven by the needle's load; the others get none.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/scene.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/tissue.hpp"

namespace needle::engine {

class DeformationPass;

class GpuScene {
 public:
  // Loads each distinct glTF file once (AssetError on any fault) and uploads it.
  GpuScene(const SceneRenderer& renderer, Scene scene);
  // One model at the origin, seen with the view's camera, lights and background; deformable
  // tissue when given its parameters.
  GpuScene(const SceneRenderer& renderer, const Model& model, const Scene& view,
           const std::optional<TissueParams>& deformation = std::nullopt);
  ~GpuScene();
  GpuScene(GpuScene&&) noexcept;
  GpuScene& operator=(GpuScene&&) noexcept;

  const Scene& scene() const { return scene_; }
  // The asset with this name; std::out_of_range naming it when there is none.
  size_t asset_index(const std::string& name) const;
  void set_asset_transform(size_t asset, const glm::mat4& transform);
  // The bounds of the asset's model with its nodes placed, before the asset's own transform.
  const Bounds& model_bounds(size_t asset) const;

  // This frame's parameters. With the needle's state, tool assets are posed at it and the
  // deformation passes' work for it comes along; without, tools keep their scene transform and
  // the tissue relaxes to rest.
  FrameParams frame_params(const NeedleLoad* needle = nullptr);

 private:
  struct DeformableTissue {
    size_t asset;
    std::unique_ptr<DeformationPass> pass;
  };
  void add_deformable(const SceneRenderer& renderer, Model model, size_t asset);

  Scene scene_;
  std::vector<std::unique_ptr<GpuModel>> models_;
  std::vector<size_t> model_of_asset_;
  std::vector<glm::mat4> transforms_;
  std::vector<std::optional<size_t>> inside_;  // SceneAsset::inside as an asset's index
  std::vector<DeformableTissue> tissues_;
};

}  // namespace needle::engine
