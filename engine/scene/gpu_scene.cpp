#include "engine/gpu_scene.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "engine/deformation/deformation_pass.hpp"
#include "engine/deformation/needle_pose.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/passes/gpu_model.hpp"
#include "engine/passes/scene_pass.hpp"

namespace needle::engine {

GpuScene::GpuScene(const SceneRenderer& renderer, Scene scene) : scene_(std::move(scene)) {
  std::map<std::filesystem::path, size_t> shared;  // rigid assets share one upload per file
  for (size_t a = 0; a < scene_.assets.size(); ++a) {
    const SceneAsset& asset = scene_.assets[a];
    transforms_.push_back(asset.transform());
    if (!asset.deformation && asset.model) {
      model_of_asset_.push_back(models_.size());
      models_.push_back(renderer.pass().upload(*asset.model));
      continue;
    }
    if (!asset.deformation) {
      auto [it, fresh] = shared.try_emplace(asset.gltf, models_.size());
      if (fresh) models_.push_back(renderer.pass().upload(load_gltf(asset.gltf)));
      model_of_asset_.push_back(it->second);
      continue;
    }
    add_deformable(renderer, asset.model ? *asset.model : load_gltf(asset.gltf), a);
  }
  for (const SceneAsset& asset : scene_.assets) {
    inside_.emplace_back();
    if (asset.inside.empty()) continue;
    const size_t outer = asset_index(asset.inside);
    if (outer == inside_.size() - 1) throw AssetError(asset.name + ": an asset cannot lie inside itself");
    const GpuModel& hull = *models_[model_of_asset_[outer]];
    for (const MeshInstance& instance : hull.instances())
      if (hull.material_of(instance.primitive).alpha_mode != AlphaMode::Opaque)
        throw AssetError(asset.name + ": inside '" + asset.inside + "', which is not opaque (it would show it)");
    inside_.back() = outer;
  }
}

// A deformable tissue gets its own vertex buffers, sorted so the pass visits only the vertices
// near the needle.
void GpuScene::add_deformable(const SceneRenderer& renderer, Model model, size_t asset) {
  const TissueParams& tissue = *scene_.assets[asset].deformation;
  std::vector<VertexGrid> grids;
  for (uint32_t p = 0; p < model.primitives.size(); ++p) {
    size_t uses = std::count_if(model.instances.begin(), model.instances.end(),
                                [&](const MeshInstance& i) { return i.primitive == p; });
    if (uses > 1) {
      throw AssetError(scene_.assets[asset].name + ": a deformable tissue cannot reuse a mesh in " +
                       std::to_string(uses) + " nodes");
    }
    grids.push_back(VertexGrid::sort_vertices(model.primitives[p], 0.5 * tissue.falloff * tissue.radius_m));
  }
  model_of_asset_.push_back(models_.size());
  models_.push_back(renderer.pass().upload(model));
  DeformableTissue deformable{asset, std::make_unique<DeformationPass>(renderer.pass().context())};
  for (const MeshInstance& instance : model.instances) {
    deformable.pass->add_target(models_.back()->primitives()[instance.primitive], model.primitives[instance.primitive],
                                std::move(grids[instance.primitive]),
                                glm::dmat4(transforms_[asset]) * glm::dmat4(instance.world));
  }
  tissues_.push_back(std::move(deformable));
}

GpuScene::GpuScene(const SceneRenderer& renderer, const Model& model, const Scene& view,
                   const std::optional<TissueParams>& deformation) {
  scene_.assets.push_back(SceneAsset{"model", {}, nullptr, AssetRole::Tissue});
  scene_.assets[0].deformation = deformation;
  scene_.camera = view.camera;
  scene_.lights = view.lights;
  scene_.background = view.background;
  transforms_.push_back(glm::mat4(1.0f));
  inside_.emplace_back();
  if (deformation) {
    add_deformable(renderer, model, 0);
  } else {
    models_.push_back(renderer.pass().upload(model));
    model_of_asset_.push_back(0);
  }
}

GpuScene::~GpuScene() = default;
GpuScene::GpuScene(GpuScene&&) noexcept = default;
GpuScene& GpuScene::operator=(GpuScene&&) noexcept = default;

size_t GpuScene::asset_index(const std::string& name) const {
  for (size_t i = 0; i < scene_.assets.size(); ++i) {
    if (scene_.assets[i].name == name) return i;
  }
  throw std::out_of_range("the scene has no asset named '" + name + "'");
}

void GpuScene::set_asset_transform(size_t asset, const glm::mat4& transform) { transforms_.at(asset) = transform; }

const Bounds& GpuScene::model_bounds(size_t asset) const { return models_[model_of_asset_[asset]]->world_bounds(); }

FrameParams GpuScene::frame_params(const NeedleLoad* needle) {
  FrameParams params{scene_.camera, scene_.lights, scene_.background, {}, {}, {}, {}};
  for (size_t i = 0; i < scene_.assets.size(); ++i) {
    bool posed = needle && scene_.assets[i].role == AssetRole::Tool;
    params.items.push_back({models_[model_of_asset_[i]].get(),
                            posed ? needle_pose(needle->tip, needle->axis) : transforms_[i],
                            {},
                            scene_.assets[i].role == AssetRole::Tissue,
                            inside_[i]});
  }
  const NeedleLoad free_needle;
  std::vector<std::function<void(VkCommandBuffer)>> passes;
  for (DeformableTissue& t : tissues_) {
    auto field = build_field(needle ? *needle : free_needle, *scene_.assets[t.asset].deformation);
    if (auto record = t.pass->update(field)) passes.push_back(record);
    // Where this frame's vertex buffers differ from the rest mesh: the field's windows.
    for (const Kelvinlet& k : field.loads) params.items[t.asset].moved.push_back({k.center, k.support});
  }
  if (!passes.empty()) {
    params.before_pass = [passes = std::move(passes)](const CommandBuffer& cmd) {
      for (const auto& record : passes) record(cmd.handle);
    };
  }
  return params;
}

}  // namespace needle::engine
