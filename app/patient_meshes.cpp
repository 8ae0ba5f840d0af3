#include "app/patient_meshes.hpp"

#include <meshoptimizer.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "app/patient_look.hpp"

namespace needle::app {
namespace {

// Design value: a drawn layer may leave its surface-nets mesh by a quarter of its grid's spacing
// (the mesh is its region only to within the spacing times the stride already). Large smooth
// regions (the back, the sheets of fat and muscle) become a few large triangles and the bone's
// processes keep their shape; on llvmpipe the frame pays for every triangle it sets up.
constexpr double kDrawnErrorPerSpacing = 0.25;

// (triangles over `positions`, absolute error, borders locked) => meshoptimizer's simplification:
// edges collapsed while the surface moves less than `error_m` (its quadric error bound).
std::vector<uint32_t> simplified(const std::vector<uint32_t>& indices, const std::vector<Eigen::Vector3f>& positions,
                                 double error_m, bool lock_border) {
  if (indices.empty()) return {};
  const float* xyz = positions[0].data();
  const float scale = meshopt_simplifyScale(xyz, positions.size(), sizeof(Eigen::Vector3f));
  std::vector<uint32_t> out(indices.size());
  out.resize(meshopt_simplify(out.data(), indices.data(), indices.size(), xyz, positions.size(),
                              sizeof(Eigen::Vector3f), 0, float(error_m) / scale,
                              lock_border ? unsigned(meshopt_SimplifyLockBorder) : 0u, nullptr));
  return out;
}

// The triangles drawn of a layer's mesh, simplified within kDrawnErrorPerSpacing of the grid's
// spacing in parts, each part's edge locked so that the parts meet without a crack: the walls
// where the region meets the grid's box (flat, with normals of their own) apart from the tissue's
// surface, so that no large triangle spans the crease between them; the skin's surface along the
// midline (x = midline_x, model frame) kept whole.
std::vector<uint32_t> drawn_triangles(const haptics::anatomy::SurfaceMesh& mesh, const haptics::SdfGrid& grid,
                                      int stride, bool skin, double midline_x) {
  const double h = grid.spacing() * stride;
  const Eigen::Vector3d lo = grid.origin(),
                        hi = lo + grid.spacing() *
                                      Eigen::Vector3d(grid.nodes()[0] - 1, grid.nodes()[1] - 1, grid.nodes()[2] - 1);
  // Surface-nets vertices on a wall lie within a cell of the box's face.
  const auto on_wall = [&](uint32_t v) {
    const Eigen::Vector3d p = mesh.positions[v].cast<double>();
    return ((p - lo).cwiseAbs().minCoeff() < h) || ((hi - p).cwiseAbs().minCoeff() < h);
  };
  std::vector<uint32_t> whole, walls, surface;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t* tri = &mesh.indices[t];
    bool near_midline = skin, wall = true;
    for (size_t k = 0; k < 3; ++k) {
      near_midline = near_midline && std::abs(mesh.positions[tri[k]].x() - midline_x) < kSkinDetailHalfWidth_m;
      wall = wall && on_wall(tri[k]);
    }
    std::vector<uint32_t>& part = wall ? walls : near_midline ? whole : surface;
    part.insert(part.end(), tri, tri + 3);
  }
  const double error_m = kDrawnErrorPerSpacing * grid.spacing();
  for (const std::vector<uint32_t>* part : {&walls, &surface}) {
    const std::vector<uint32_t> fewer = simplified(*part, mesh.positions, error_m, true);
    whole.insert(whole.end(), fewer.begin(), fewer.end());
  }
  return whole;
}

}  // namespace

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
  primitive.indices =
      drawn_triangles(mesh, *layer.shape.grid(), look.stride, layer.name == "skin", patient.approaches[0].entry.x());
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
    // Every layer lies beneath the skin (the generator cuts each to the body under the fat), whose
    // mesh is closed: seen only through a section view.
    if (layer.name == "skin")
      asset.deformation = patient_skin_deformation();
    else
      asset.inside = "skin";
    scene.assets.push_back(std::move(asset));
  }
  return scene;
}

}  // namespace needle::app
