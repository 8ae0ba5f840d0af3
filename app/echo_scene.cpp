#include "app/echo_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace needle::app {
namespace {

glm::dvec3 world(const Eigen::Vector3d& base, const Eigen::Vector3d& base_in_world) {
  const Eigen::Vector3d w = base + base_in_world;
  return {w.x(), w.y(), w.z()};
}

engine::EchoPrimitive echo_primitive(const haptics::SurfacePrimitive& p, const Eigen::Vector3d& base_in_world) {
  using Kind = haptics::SurfacePrimitive::Kind;
  switch (p.kind) {
    case Kind::Sphere:
      return {engine::EchoPrimitive::Kind::Sphere, world(p.a, base_in_world), {}, p.radius};
    case Kind::Plane:
      return {engine::EchoPrimitive::Kind::Plane, world(p.a, base_in_world), {p.b.x(), p.b.y(), p.b.z()}, 0.0};
    case Kind::Capsule:
      return {engine::EchoPrimitive::Kind::Capsule, world(p.a, base_in_world), world(p.b, base_in_world), p.radius};
  }
  return {};
}

glm::dvec3 glm_of(const training::Vec3& v) { return {v[0], v[1], v[2]}; }

// A grid layer's grid in the world frame (values shared, not copied, between the layers of one grid).
std::shared_ptr<const engine::EchoGrid> echo_grid(const std::shared_ptr<const haptics::SdfGrid>& shared_grid,
                                                  const Eigen::Vector3d& base_in_world) {
  const haptics::SdfGrid& grid = *shared_grid;
  auto out = std::make_shared<engine::EchoGrid>();
  out->origin = world(grid.origin(), base_in_world);
  out->spacing_m = grid.spacing();
  out->quantum_m = grid.quantum();
  out->nodes = glm::uvec3(grid.nodes()[0], grid.nodes()[1], grid.nodes()[2]);
  out->values = std::shared_ptr<const std::vector<int16_t>>(shared_grid, &grid.values());  // kept alive by the grid
  return out;
}

}  // namespace

engine::EchoScene echo_scene(const haptics::Scenario& scenario, const engine::Scene& scene) {
  engine::EchoScene out;
  std::map<const haptics::SdfGrid*, std::shared_ptr<const engine::EchoGrid>> grids;
  for (const haptics::TissueLayer& layer : scenario.scene.tissue.layers()) {
    engine::EchoLayer echo;
    echo.name = layer.name;
    if (const auto& grid = layer.shape.grid()) {
      auto& shared = grids[grid.get()];
      if (!shared) shared = echo_grid(grid, scenario.base_in_world);
      echo.grid = shared;
      echo.grid_offset_m = layer.shape.grid_offset();
    }
    const haptics::ImplicitSurface& surface = layer.shape.surface();
    echo.intersection = surface.combine() == haptics::ImplicitSurface::Combine::Intersection;
    for (const haptics::SurfacePrimitive& p : surface.primitives())
      echo.primitives.push_back(echo_primitive(p, scenario.base_in_world));
    if (layer.acoustics) {
      const haptics::LayerAcoustics& a = *layer.acoustics;
      echo.material = {a.impedance_MRayl, a.attenuation_dB_per_cm_MHz, a.echogenicity, a.scatterer_density};
    }
    out.layers.push_back(std::move(echo));
  }
  const auto deformable = std::find_if(scene.assets.begin(), scene.assets.end(), [](const engine::SceneAsset& a) {
    return a.role == engine::AssetRole::Tissue && a.deformation;
  });
  if (deformable != scene.assets.end()) out.deformation = deformable->deformation;
  return out;
}

engine::EchoScene echo_scene(const training::Task& task) {
  const engine::Scene scene = engine::load_scene(task.scene);
  if (task.scenario.empty()) return echo_scene(haptics::Scenario{}, scene);
  return echo_scene(haptics::load_scenario(task.scenario.string()), scene);
}

bool layers_have_acoustics(const training::Task& task) {
  if (task.scenario.empty()) return false;
  const haptics::Scenario scenario = haptics::load_scenario(task.scenario.string());
  const auto& layers = scenario.scene.tissue.layers();
  return std::any_of(layers.begin(), layers.end(),
                     [](const haptics::TissueLayer& l) { return l.acoustics.has_value(); });
}

engine::UltrasoundProbe to_engine(const training::UltrasoundProbeSpec& p) {
  engine::UltrasoundProbe out;
  out.position = glm_of(p.position);
  out.direction = glm_of(p.direction);
  out.lateral = glm_of(p.lateral);
  out.depth_m = p.depth_m;
  out.width_m = p.width_m;
  out.frequency_MHz = p.frequency_MHz;
  out.slice_thickness_m = p.slice_thickness_m;
  return out;
}

engine::UltrasoundProbe paramedian_sagittal_oblique_probe(const engine::EchoScene& scene, const glm::dvec3& over,
                                                          double offset_m, double medial_tilt_rad) {
  engine::UltrasoundProbe probe;
  probe.direction = {-std::sin(medial_tilt_rad), 0.0, -std::cos(medial_tilt_rad)};
  probe.lateral = {0.0, 1.0, 0.0};
  probe.depth_m = 0.08;
  probe.width_m = 0.06;
  probe.frequency_MHz = 5.0;
  const glm::dvec3 beside = over + glm::dvec3(offset_m, 0.0, 0.0);
  probe.position = beside;
  return engine::probe_on_skin(scene, probe, beside - 0.1 * probe.direction);
}

ProbePlan task_probe(const training::Task& task, const engine::EchoScene& echo) {
  if (task.ultrasound_probe) return {to_engine(*task.ultrasound_probe), false};
  engine::UltrasoundProbe probe;
  probe.depth_m = 0.06;
  const auto point = std::find_if(task.markers.begin(), task.markers.end(),
                                  [](const training::Marker& m) { return m.kind == training::MarkerKind::kPoint; });
  const glm::dvec3 over = point != task.markers.end() ? glm_of(point->position) : glm::dvec3(0.0);
  probe.position = over;
  return {engine::probe_on_skin(echo, probe, over - 0.5 * probe.direction), true};
}

}  // namespace needle::app
