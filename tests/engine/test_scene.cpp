// Scene files: the committed scenes, transforms, the framing camera, and faulty files whose
// errors must name the file and the JSON pointer.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <numbers>

#include "engine/gltf_loader.hpp"
#include "engine/scene.hpp"
#include "engine/screen_projection.hpp"
#include "test_gltf_fixtures.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::engine {
namespace {
using namespace testing;
namespace fs = std::filesystem;

const fs::path kScenes = test::source_dir() / "assets" / "scenes";

glm::mat4 view_projection(const Camera& c, float aspect) {
  return glm::perspective(glm::radians(c.fov_y_deg), aspect, c.near_m, c.far_m) *
         glm::lookAt(c.position, c.target, c.up);
}

// Largest |x|, |y| in normalized device coordinates over `points`; fails if any is outside the depth range.
float max_ndc_extent(const Camera& camera, float aspect, const std::vector<glm::vec3>& points) {
  const glm::mat4 vp = view_projection(camera, aspect);
  float extent = 0.0f;
  for (const glm::vec3& p : points) {
    const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
    EXPECT_GT(clip.w, 0.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    EXPECT_GT(ndc.z, -1.0f) << "in front of the near plane";
    EXPECT_LT(ndc.z, 1.0f) << "beyond the far plane";
    extent = std::max({extent, std::abs(ndc.x), std::abs(ndc.y)});
  }
  return extent;
}

std::vector<glm::vec3> box_corners(const Bounds& b) {
  std::vector<glm::vec3> corners;
  for (int k = 0; k < 8; ++k)
    corners.emplace_back(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z);
  return corners;
}

TEST(Scene, CommittedScenesLoadAndTheirCamerasSeeEveryAsset) {
  for (const char* name : {"thesis_sphere.json", "tissue_block.json"}) {
    const Scene scene = load_scene(kScenes / name);
    ASSERT_EQ(scene.assets.size(), 2u) << name;
    EXPECT_EQ(scene.assets[1].role, AssetRole::Tool) << name;
    EXPECT_EQ(scene.camera.up, glm::vec3(0, 0, 1)) << name;  // world frame: z up
    EXPECT_LE(scene.lights.directional.size(), Lights::kMax);
    for (const SceneAsset& asset : scene.assets) {
      EXPECT_TRUE(asset.gltf.is_absolute());
      const Model model = load_gltf(asset.gltf);
      std::vector<glm::vec3> corners;
      for (const glm::vec3& c : box_corners(model.world_bounds))
        corners.emplace_back(asset.transform() * glm::vec4(c, 1));
      EXPECT_LT(max_ndc_extent(scene.camera, 16.0f / 9.0f, corners), 1.0f) << name << ": " << asset.name;
    }
  }
}

TEST(Scene, ThesisSceneNeedleTipPointsAtTheSphere) {
  const Scene scene = load_scene(kScenes / "thesis_sphere.json");
  const glm::mat4 needle = scene.assets[1].transform();
  const glm::vec3 tip = needle * glm::vec4(0, 0, 0, 1);
  const glm::vec3 axis = glm::normalize(glm::vec3(needle * glm::vec4(1, 0, 0, 0)));  // x5
  const glm::vec3 to_center = glm::vec3(0.4f, 0.0f, 0.0f) - tip;
  EXPECT_GT(glm::length(to_center), 0.1f);  // outside the sphere
  // Distance from the centre to the needle's line is below the radius: advancing hits the sphere.
  EXPECT_LT(glm::length(glm::cross(axis, to_center)), 0.1f);
  EXPECT_GT(glm::dot(axis, to_center), 0.0f);
}

TEST(Scene, AssetTransformIsTranslationRotationScale) {
  SceneAsset asset;
  asset.translation = {1, 2, 3};
  asset.rotation = glm::angleAxis(std::numbers::pi_v<float> / 2, glm::vec3(0, 0, 1));
  asset.scale = {2, 3, 4};
  // (1, 1, 1) -> scaled (2, 3, 4) -> turned 90 degrees about z (-3, 2, 4) -> moved (-2, 4, 7).
  const glm::vec3 p = asset.transform() * glm::vec4(1, 1, 1, 1);
  EXPECT_NEAR(p.x, -2.0f, 1e-6);
  EXPECT_NEAR(p.y, 4.0f, 1e-6);
  EXPECT_NEAR(p.z, 7.0f, 1e-6);
}

TEST(Scene, FramingCameraFitsTheBoundingSphereTightlyInBothDirections) {
  const Bounds bounds{{0.3f, -0.1f, -0.1f}, {0.5f, 0.1f, 0.1f}};
  const glm::vec3 center(0.4f, 0.0f, 0.0f);
  const float radius = glm::length(bounds.max - bounds.min) / 2;
  for (float aspect : {16.0f / 9.0f, 1.0f, 9.0f / 16.0f}) {
    const Camera camera = framing_camera(bounds, aspect);
    EXPECT_EQ(camera.up, glm::vec3(0, 1, 0));
    // Points of the bounding sphere seen edge-on, i.e. on its silhouette cone: they must reach the
    // frame's narrower edge (tight) without leaving it.
    const glm::vec3 view = glm::normalize(camera.target - camera.position);
    const float d = glm::length(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(view, camera.up)), up = glm::cross(right, view);
    std::vector<glm::vec3> silhouette;
    for (int k = 0; k < 360; ++k) {
      const float t = glm::radians(float(k));
      const glm::vec3 radial = std::cos(t) * right + std::sin(t) * up;
      // Tangent point from the eye: offset towards the eye by r^2/d, ring radius r sqrt(1 - r^2/d^2).
      silhouette.push_back(center - view * (radius * radius / d) +
                           radial * radius * std::sqrt(1 - radius * radius / (d * d)));
    }
    const float extent = max_ndc_extent(camera, aspect, silhouette);
    EXPECT_LE(extent, 1.0f + 1e-4f) << "aspect " << aspect;
    EXPECT_GE(extent, 1.0f - 1e-3f) << "aspect " << aspect;
    // Near and far hug the sphere.
    EXPECT_LT(camera.near_m, d - radius);
    EXPECT_GT(camera.near_m, 0.9f * (d - radius));
    EXPECT_GT(camera.far_m, d + radius);
    EXPECT_LT(camera.far_m, 1.1f * (d + radius));
  }
}

TEST(Scene, DefaultLightsAreAKeyAFillAndAmbient) {
  const Lights lights = default_lights();
  ASSERT_EQ(lights.directional.size(), 2u);
  EXPECT_GT(lights.directional[0].intensity, lights.directional[1].intensity);
  for (const DirectionalLight& light : lights.directional) EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-6);
  EXPECT_GT(lights.ambient.x, 0.0f);
}

class SceneFaults : public ::testing::Test {
 protected:
  TempDir dir{"scene"};
  fs::path file = dir / "scene.json";
  SceneFaults() {
    write_text(dir / "a.gltf", "{}");
    base = {{"assets", {{{"name", "a"}, {"gltf", "a.gltf"}, {"role", "tissue"}}}},
            {"camera", {{"position", {0, -1, 0}}, {"target", {0, 0, 0}}}}};
  }
  void expect_error(const nlohmann::json& scene, std::initializer_list<std::string> fragments) {
    write_text(file, scene.dump());
    expect_asset_error([&] { load_scene(file); }, file.string(), fragments);
  }
  nlohmann::json base;
};

TEST_F(SceneFaults, TheUnbrokenBaseLoadsWithDefaultLights) {
  write_text(file, base.dump());
  const Scene scene = load_scene(file);
  EXPECT_EQ(scene.assets[0].gltf, fs::canonical(dir / "a.gltf"));
  EXPECT_EQ(scene.lights.directional.size(), default_lights().directional.size());
}

TEST_F(SceneFaults, MissingFileAndBadJson) {
  expect_asset_error([&] { load_scene(dir / "absent.json"); }, (dir / "absent.json").string(), {"/", "not found"});
  write_text(file, "{\"assets\": [");
  expect_asset_error([&] { load_scene(file); }, file.string(), {"/", "parse error"});
}

TEST_F(SceneFaults, UnknownKeysAreRejectedWithTheirPointer) {
  nlohmann::json scene = base;
  scene["colour"] = 1;
  expect_error(scene, {"/colour", "unknown key"});
  scene = base;
  scene["assets"][0]["position"] = {0, 0, 0};
  expect_error(scene, {"/assets/0/position", "unknown key"});
  scene = base;
  scene["lights"] = {{"directional", {{{"direction", {0, 0, -1}}, {"colour", {1, 1, 1}}}}}};
  expect_error(scene, {"/lights/directional/0/colour", "unknown key"});
}

TEST_F(SceneFaults, WrongTypesAndValues) {
  nlohmann::json scene = base;
  scene["camera"]["fov_y_deg"] = "wide";
  expect_error(scene, {"/camera/fov_y_deg", "expected a number, got string"});
  scene = base;
  scene["assets"][0]["translation"] = {0, 0};
  expect_error(scene, {"/assets/0/translation", "3 numbers"});
  scene = base;
  scene["assets"][0]["rotation"] = {0, 0, 0, 0};
  expect_error(scene, {"/assets/0/rotation", "zero quaternion"});
  scene = base;
  scene["assets"][0]["role"] = "organ";
  expect_error(scene, {"/assets/0/role", "tissue, tool, bone or marker"});
  scene = base;
  scene["camera"]["far"] = 0.001;
  expect_error(scene, {"/camera/far", "greater than near"});
  scene = base;
  scene["assets"] = nlohmann::json::array();
  expect_error(scene, {"/assets", "non-empty array"});
}

// Numbers a float cannot hold or a picture cannot use: far = 1e39 rendered blank, a rotation of
// 1e308 components made the asset vanish. Each is refused with its pointer and the range.
TEST_F(SceneFaults, NumbersOutOfRangeAreRefused) {
  nlohmann::json scene = base;
  scene["camera"]["far"] = 1e39;
  expect_error(scene, {"/camera/far", "must be within ±10000, got 1e+39"});
  scene = base;
  scene["camera"]["near"] = 1e-9;
  scene["camera"]["far"] = 10;
  expect_error(scene, {"/camera/far", "must be at most 1e+07 times near"});
  scene = base;
  scene["assets"][0]["rotation"] = {1e308, 1e308, 1e308, 1e308};
  expect_error(scene, {"/assets/0/rotation/0", "must be within ±1e+06, got 1e+308"});
  scene = base;
  scene["assets"][0]["translation"] = {0, -3e38, 0};
  expect_error(scene, {"/assets/0/translation/1", "must be within ±10000"});
  scene = base;
  scene["assets"][0]["scale"] = {1, 1e-30, 1};
  expect_error(scene, {"/assets/0/scale", "a scale under 1e-06 flattens the asset"});
  scene = base;
  scene["camera"]["position"] = {0, -1e300, 0};
  expect_error(scene, {"/camera/position/1", "must be within ±10000"});
  scene = base;
  scene["lights"] = {{"directional", {{{"direction", {0, 0, -1}}, {"intensity", 1e30}}}}};
  expect_error(scene, {"/lights/directional/0/intensity", "must be within ±1000"});
}

TEST_F(SceneFaults, MissingGltfAndDuplicateNames) {
  nlohmann::json scene = base;
  scene["assets"][0]["gltf"] = "absent.gltf";
  expect_error(scene, {"/assets/0/gltf", "file not found"});
  scene = base;
  scene["assets"].push_back(base["assets"][0]);
  expect_error(scene, {"/assets/1/name", "used twice"});
}

// A scene lists at most 256 assets: 50,000 needles (7 MB) had drawn no frame after a minute.
TEST_F(SceneFaults, AtMost256Assets) {
  nlohmann::json scene = base;
  for (int i = 1; i < 256; ++i) {
    scene["assets"].push_back(base["assets"][0]);
    scene["assets"].back()["name"] = "a" + std::to_string(i);
  }
  write_text(file, scene.dump());
  EXPECT_EQ(load_scene(file).assets.size(), 256u);
  scene["assets"].push_back(base["assets"][0]);
  scene["assets"].back()["name"] = "a256";
  expect_error(scene, {"/assets", "at most 256 assets"});
}

TEST_F(SceneFaults, AtMostFourDirectionalLights) {
  nlohmann::json scene = base;
  scene["lights"] = {{"directional", nlohmann::json::array()}};
  for (int i = 0; i < 5; ++i) scene["lights"]["directional"].push_back({{"direction", {0, 0, -1}}});
  expect_error(scene, {"/lights/directional", "at most 4"});
}

}  // namespace
}  // namespace needle::engine

namespace needle::engine {
namespace {

// The layered tasks' scenes at the start screen's and headless picture size, 960x540:
// the tool where it starts (the tip and 20 mm of its shaft, the needle's body -x) and the tissue's
// top centre lie inside the picture, 20 px from its edges (before, the tool started above it).
TEST(SceneFraming, TheLayeredScenesShowTheToolWhereItStartsAt960x540) {
  const Extent extent{960, 540};
  for (const char* name : {"tissue_block_task.json", "lumbar_section.json"}) {
    const Scene scene = load_scene(test::source_dir() / "assets/scenes" / name);
    std::vector<glm::vec3> points;
    for (const SceneAsset& a : scene.assets) {
      if (a.role == AssetRole::Tool) {
        points.push_back(a.translation);
        points.push_back(a.translation + a.rotation * glm::vec3(-0.02f, 0.0f, 0.0f));
      }
      if (a.role == AssetRole::Tissue) points.push_back(a.translation);
    }
    ASSERT_EQ(points.size(), 3u) << name;
    for (const glm::vec3& p : points) {
      const std::optional<glm::vec2> s = project_to_screen(scene.camera, extent, p);
      ASSERT_TRUE(s.has_value()) << name;
      EXPECT_GE(s->x, 20.0f) << name;
      EXPECT_LE(s->x, 940.0f) << name;
      EXPECT_GE(s->y, 20.0f) << name << " at (" << p.x << ", " << p.y << ", " << p.z << ")";
      EXPECT_LE(s->y, 520.0f) << name;
    }
  }
}

}  // namespace
}  // namespace needle::engine
