// Scene files (docs/SCENE_FORMAT.md): strict JSON reading with JSON-pointer error messages,
// and the automatic camera and lights used when a file does not give them.
#include "engine/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "engine/gltf/gltf_errors.hpp"
#include "io/strict_json.hpp"

namespace needle::engine {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Reads one scene file; every error names the file and the JSON pointer of the culprit.
class SceneReader : io::StrictJsonReader<AssetError> {
 public:
  SceneReader(std::string file, fs::path folder) : StrictJsonReader(std::move(file)), folder_(std::move(folder)) {}

  Scene scene(const json& root) {
    object(root, "", {"assets", "camera", "lights", "background"});
    Scene scene;
    const json& assets = member(root, "", "assets");
    if (!assets.is_array() || assets.empty() || assets.size() > kMaxAssets)
      fail("/assets", "expected a non-empty array of at most " + std::to_string(kMaxAssets) + " assets");
    std::set<std::string> names;
    for (size_t i = 0; i < assets.size(); ++i) {
      scene.assets.push_back(asset(assets[i], "/assets/" + std::to_string(i)));
      if (!names.insert(scene.assets.back().name).second)
        fail("/assets/" + std::to_string(i) + "/name", "\"" + scene.assets.back().name + "\" is used twice");
    }
    if (root.contains("camera")) scene.camera = camera(root["camera"], "/camera");
    scene.lights = root.contains("lights") ? lights(root["lights"], "/lights") : default_lights();
    if (root.contains("background")) scene.background = color(root["background"], "/background");
    return scene;
  }

 private:
  // What a scene's numbers may be (docs/SCENE_FORMAT.md, "Ranges"): the renderer works in floats,
  // and a number past these gives a blank or broken picture, not an error, unless refused here.
  static constexpr double kMaxLength_m = 1e4;   // positions, translations, near, far
  static constexpr double kMaxComponent = 1e6;  // rotation and direction components, scale factors
  static constexpr double kMinScale = 1e-6;
  static constexpr double kMaxDepthRatio = 1e7;  // far / near: beyond it the depth buffer resolves nothing
  static constexpr double kMaxLight = 1e3;       // colour components, intensities
  // Each asset is a glTF read, uploaded and drawn every frame; the shipped scenes have at most 6,
  // 256 leaves room for a patient's every structure; a scene of 50,000 needles (7 MB) had drawn no
  // frame after a minute.
  static constexpr size_t kMaxAssets = 256;

  static std::string shown(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
  }

  // A number within [-limit, limit] (a float holds it).
  float bounded(const json& value, const std::string& at, double limit) const {
    const double x = number(value, at);
    if (!(std::abs(x) <= limit)) fail(at, "must be within ±" + shown(limit) + ", got " + shown(x));
    return static_cast<float>(x);
  }

  template <int N>
  glm::vec<N, float> vector(const json& value, const std::string& at, double limit) const {
    if (!value.is_array() || value.size() != N) fail(at, "expected an array of " + std::to_string(N) + " numbers");
    glm::vec<N, float> v;
    for (int k = 0; k < N; ++k) v[k] = bounded(value[static_cast<size_t>(k)], at + "/" + std::to_string(k), limit);
    return v;
  }

  glm::vec3 direction(const json& value, const std::string& at) const {
    const glm::vec3 v = vector<3>(value, at, kMaxComponent);
    if (glm::length(v) < 1e-6f) fail(at, "must not be the zero vector");
    return glm::normalize(v);
  }

  glm::vec3 color(const json& value, const std::string& at) const {
    const glm::vec3 c = vector<3>(value, at, kMaxLight);
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f)))) fail(at, "colour components must be >= 0 (linear RGB)");
    return c;
  }

  SceneAsset asset(const json& value, const std::string& at) const {
    object(value, at, {"name", "gltf", "role", "translation", "rotation", "scale", "deformation"});
    SceneAsset a;
    a.name = string(member(value, at, "name"), at + "/name");
    a.gltf = existing_file(member(value, at, "gltf"), at + "/gltf", folder_);
    const std::string role = string(member(value, at, "role"), at + "/role");
    if (role == "tissue")
      a.role = AssetRole::Tissue;
    else if (role == "tool")
      a.role = AssetRole::Tool;
    else if (role == "bone")
      a.role = AssetRole::Bone;
    else if (role == "marker")
      a.role = AssetRole::Marker;
    else
      fail(at + "/role", "\"" + role + "\", expected tissue, tool, bone or marker");
    if (value.contains("translation"))
      a.translation = vector<3>(value["translation"], at + "/translation", kMaxLength_m);
    if (value.contains("rotation")) {
      const glm::vec4 q = vector<4>(value["rotation"], at + "/rotation", kMaxComponent);  // x, y, z, w as in glTF
      if (glm::length(q) < 1e-6f) fail(at + "/rotation", "the zero quaternion is not a rotation");
      a.rotation = glm::normalize(glm::quat(q.w, q.x, q.y, q.z));
    }
    if (value.contains("scale")) {
      a.scale = vector<3>(value["scale"], at + "/scale", kMaxComponent);
      if (glm::any(glm::lessThan(glm::abs(a.scale), glm::vec3(float(kMinScale)))))
        fail(at + "/scale", "a scale under " + shown(kMinScale) + " flattens the asset");
    }
    if (value.contains("deformation")) {
      if (a.role != AssetRole::Tissue) fail(at + "/deformation", "only tissue deforms");
      if (a.scale.x != a.scale.y || a.scale.y != a.scale.z)
        fail(at + "/scale", "a deformable tissue needs a uniform scale (its field is isotropic)");
      a.deformation = tissue(value["deformation"], at + "/deformation");
    }
    return a;
  }

  // Every key optional: TissueParams' defaults are a soft tissue of a few kPa.
  TissueParams tissue(const json& value, const std::string& at) const {
    object(value, at, {"shear_modulus_Pa", "poisson_ratio", "radius_m", "falloff", "lateral_loads"});
    TissueParams t;
    auto read = [&](const char* key, double& into, double lo, double hi, const char* range) {
      if (!value.contains(key)) return;
      into = number(value[key], at + "/" + key);
      if (!(into > lo && into <= hi)) fail(at + "/" + key, std::string("must be in ") + range);
    };
    read("shear_modulus_Pa", t.material.shear_modulus_Pa, 0.0, 1e9, "(0, 1e9] Pa");
    read("poisson_ratio", t.material.poisson_ratio, -1e-12, 0.5, "[0, 0.5]");
    read("radius_m", t.radius_m, 0.0, 1.0, "(0, 1] m");
    read("falloff", t.falloff, 1.0, 100.0, "(1, 100]");
    if (value.contains("lateral_loads")) {
      const json& n = value["lateral_loads"];
      if (!n.is_number_integer() || n.get<int>() < 0 || n.get<int>() > 7)
        fail(at + "/lateral_loads", "expected a whole number from 0 to 7");
      t.lateral_loads = n.get<int>();
    }
    return t;
  }

  Camera camera(const json& value, const std::string& at) const {
    object(value, at, {"position", "target", "up", "fov_y_deg", "near", "far"});
    Camera c;
    c.position = vector<3>(member(value, at, "position"), at + "/position", kMaxLength_m);
    c.target = vector<3>(member(value, at, "target"), at + "/target", kMaxLength_m);
    if (glm::length(c.target - c.position) < 1e-6f) fail(at + "/target", "equals the position");
    if (value.contains("up")) c.up = direction(value["up"], at + "/up");
    if (glm::length(glm::cross(c.up, glm::normalize(c.target - c.position))) < 1e-3f)
      fail(at + "/up", "is parallel to the viewing direction");
    if (value.contains("fov_y_deg")) c.fov_y_deg = bounded(value["fov_y_deg"], at + "/fov_y_deg", 180.0);
    if (c.fov_y_deg <= 0.0f || c.fov_y_deg >= 180.0f) fail(at + "/fov_y_deg", "must be in (0, 180) degrees");
    if (value.contains("near")) c.near_m = bounded(value["near"], at + "/near", kMaxLength_m);
    if (value.contains("far")) c.far_m = bounded(value["far"], at + "/far", kMaxLength_m);
    if (c.near_m <= 0.0f) fail(at + "/near", "must be > 0");
    if (c.far_m <= c.near_m) fail(at + "/far", "must be greater than near");
    if (double(c.far_m) > kMaxDepthRatio * double(c.near_m))
      fail(at + "/far", "must be at most " + shown(kMaxDepthRatio) + " times near (" + shown(c.near_m) + ")");
    return c;
  }

  Lights lights(const json& value, const std::string& at) const {
    object(value, at, {"directional", "ambient"});
    Lights lights;
    if (value.contains("directional")) {
      const json& list = value["directional"];
      if (!list.is_array() || list.size() > Lights::kMax)
        fail(at + "/directional", "expected an array of at most " + std::to_string(Lights::kMax) + " lights");
      for (size_t i = 0; i < list.size(); ++i) {
        const std::string where = at + "/directional/" + std::to_string(i);
        object(list[i], where, {"direction", "color", "intensity"});
        DirectionalLight light;
        light.direction = direction(member(list[i], where, "direction"), where + "/direction");
        if (list[i].contains("color")) light.color = color(list[i]["color"], where + "/color");
        if (list[i].contains("intensity"))
          light.intensity = bounded(list[i]["intensity"], where + "/intensity", kMaxLight);
        if (light.intensity < 0.0f) fail(where + "/intensity", "must be >= 0");
        lights.directional.push_back(light);
      }
    }
    if (value.contains("ambient")) lights.ambient = color(value["ambient"], at + "/ambient");
    return lights;
  }

  fs::path folder_;
};

}  // namespace

glm::mat4 SceneAsset::transform() const {
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

Scene load_scene(const fs::path& file) {
  return SceneReader(file.string(), fs::absolute(file).parent_path()).scene(io::read_json_file<AssetError>(file));
}

Camera framing_camera(const Bounds& bounds, float aspect) {
  if (bounds.empty()) throw std::invalid_argument("framing_camera: empty bounds (nothing to frame)");
  if (!(aspect > 0.0f)) throw std::invalid_argument("framing_camera: aspect must be > 0");
  Camera camera;
  camera.up = {0.0f, 1.0f, 0.0f};  // glTF is Y-up
  camera.fov_y_deg = 45.0f;
  camera.target = (bounds.min + bounds.max) * 0.5f;
  const float radius = std::max(glm::length(bounds.max - bounds.min) * 0.5f, 1e-4f);
  // The bounding sphere fits in the view cone of the narrower of the two half-angles.
  const float half_y = glm::radians(camera.fov_y_deg) * 0.5f;
  const float half_x = std::atan(std::tan(half_y) * aspect);
  const float distance = radius / std::sin(std::min(half_x, half_y));
  // A three-quarter view from the front (+z), a little from the right and above.
  camera.position = camera.target + distance * glm::normalize(glm::vec3(0.5f, 0.4f, 1.0f));
  camera.near_m = 0.95f * (distance - radius);
  camera.far_m = 1.05f * (distance + radius);
  return camera;
}

Lights default_lights() {
  Lights lights;
  lights.directional = {
      {glm::normalize(glm::vec3(-0.4f, -0.6f, -0.7f)), glm::vec3(1.0f, 0.97f, 0.92f), 1.0f},  // key, warm
      {glm::normalize(glm::vec3(0.6f, 0.3f, -0.4f)), glm::vec3(0.85f, 0.9f, 1.0f), 0.35f},    // fill, cool
  };
  lights.ambient = glm::vec3(0.12f);
  return lights;
}

}  // namespace needle::engine
