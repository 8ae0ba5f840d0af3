#include "app/patient_meshes.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "app/patient_look.hpp"

namespace needle::app {

engine::TissueParams patient_skin_deformation() {
  engine::TissueParams p;
  p.material.shear_modulus_Pa = 6000.0;
  p.material.poisson_ratio = 0.45;
  p.radius_m = 0.006;
  p.falloff = 4.0;
  return p;
}

engine::Model patient_layer_model(const haptics::anatomy::Patient& patient, size_t layer_index,
                                  const Eigen::Vector3d& base_in_world) {
  const haptics::anatomy::PatientLayer& layer = patient.layers.at(layer_index);
  const LayerLook look = patient_layer_look(layer.name);
  const haptics::anatomy::SurfaceMesh mesh = haptics::anatomy::layer_surface(patient, layer_index, look.stride);
  engine::Model model;
  engine::Primitive primitive;
  primitive.vertices.reserve(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    engine::MeshVertex v;
    const Eigen::Vector3f p = mesh.positions[i] + base_in_world.cast<float>();
    v.position = {p.x(), p.y(), p.z()};
    v.normal = {mesh.normals[i].x(), mesh.normals[i].y(), mesh.normals[i].z()};
    primitive.vertices.push_back(v);
  }
  primitive.indices = mesh.indices;
  primitive.material = 0;
  engine::Material material;
  material.base_color_factor = look.color;
  material.metallic_factor = 0.0f;
  material.roughness_factor = look.roughness;
  model.materials.push_back(material);
  model.primitives.push_back(std::move(primitive));
  model.instances.push_back({0, glm::mat4(1.0f), layer.name});
  engine::Bounds& b = model.world_bounds;
  b.min = glm::vec3(1e30f);
  b.max = glm::vec3(-1e30f);
  for (const engine::MeshVertex& v : model.primitives[0].vertices) {
    b.min = glm::min(b.min, v.position);
    b.max = glm::max(b.max, v.position);
  }
  return model;
}

engine::Scene with_patient(engine::Scene scene, const haptics::Scenario& scenario) {
  if (!scenario.patient) return scene;
  for (size_t i = 0; i < scenario.patient->layers.size(); ++i) {
    const haptics::anatomy::PatientLayer& layer = scenario.patient->layers[i];
    engine::SceneAsset asset;
    asset.name = layer.name;
    asset.role = layer.rigid ? engine::AssetRole::Bone : engine::AssetRole::Tissue;
    asset.model =
        std::make_shared<const engine::Model>(patient_layer_model(*scenario.patient, i, scenario.base_in_world));
    if (layer.name == "skin") asset.deformation = patient_skin_deformation();
    scene.assets.push_back(std::move(asset));
  }
  return scene;
}

}  // namespace needle::app
