// A scene file (JSON): which glTF assets, in which role and where, seen from which camera
// under which lights. Format: docs/SCENE_FORMAT.md.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/tissue.hpp"

namespace needle::engine {

enum class AssetRole { Tissue, Tool, Bone, Marker };

struct SceneAsset {
  std::string name;
  std::filesystem::path gltf;  // absolute, resolved against the scene file's folder
  // A model made in memory instead of a glTF file (a generated patient's meshes, added by the app;
  // never read from a scene file).
  std::shared_ptr<const Model> model;
  AssetRole role = AssetRole::Tissue;
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
  // Tissue that deforms around the needle (GPU deformation pass); none: it stays rigid.
  std::optional<TissueParams> deformation;
  // The asset (its name) whose closed opaque surface holds this one wholly, as the skin holds a
  // generated patient's deeper layers: drawn only where it can be seen (DrawItem::inside). Set by
  // the app for models made in memory; never read from a scene file. Empty: none.
  std::string inside;
  glm::mat4 transform() const;
};

struct Camera {
  glm::vec3 position{0.0f, -1.0f, 0.3f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 0.0f, 1.0f};
  float fov_y_deg = 45.0f;
  float near_m = 0.01f;
  float far_m = 10.0f;
};

struct DirectionalLight {
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // the way the light travels, world frame
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
};

struct Lights {
  std::vector<DirectionalLight> directional;  // at most Lights::kMax
  glm::vec3 ambient{0.1f};
  static constexpr size_t kMax = 4;
};

struct Scene {
  std::vector<SceneAsset> assets;
  Camera camera;
  Lights lights;
  glm::vec3 background{0.05f, 0.06f, 0.08f};  // linear RGB
};

// Parses and validates a scene file; AssetError "FILE: /json/path: what is wrong" on any
// fault (missing file, unknown key, wrong type, missing referenced glTF).
Scene load_scene(const std::filesystem::path& file);

// A camera that frames the given bounds (used by `render --gltf`).
Camera framing_camera(const Bounds& bounds, float aspect);

// A default light rig: a key light, a fill light and ambient.
Lights default_lights();

}  // namespace needle::engine
