// Rendering checked against closed forms: the sRGB encoding of the background, the lighting
// model on a flat quad, depth testing, back-face culling and alpha blending.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/offscreen.hpp"
#include "picture_geometry.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

using engine::AlphaMode;
using engine::Material;
using engine::Model;

constexpr engine::Extent kSize{64, 48};
// mesh.frag's specular term with n = l = v, roughness 1 (shininess 0), metallic 0:
// F0 * (shininess + 8) / (8 pi) with F0 = 0.04.
constexpr double kHeadOnSpecular = 0.04 * 8.0 / 25.1327;

// A square of side 2*half in the plane z = z0, facing +z (counter-clockwise seen from +z).
void add_quad(Model& model, float z0, float half, const Material& material) {
  engine::Primitive p;
  for (auto [x, y] : {std::pair{-half, -half}, {half, -half}, {half, half}, {-half, half}}) {
    engine::MeshVertex v;
    v.position = {x, y, z0};
    v.normal = {0, 0, 1};
    p.vertices.push_back(v);
  }
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = int(model.materials.size());
  model.materials.push_back(material);
  model.instances.push_back({uint32_t(model.primitives.size()), glm::mat4(1.0f), "quad"});
  model.primitives.push_back(std::move(p));
}

Material matte(glm::vec4 color) {
  Material m;
  m.base_color_factor = color;
  m.metallic_factor = 0.0f;
  m.roughness_factor = 1.0f;
  return m;
}

// Camera on +z looking at the origin; one light travelling along -z (head-on); ambient 0.1.
engine::Scene head_on_scene() {
  engine::Scene scene;
  scene.camera.position = {0, 0, 1};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 1, 0};
  scene.camera.near_m = 0.1f;
  scene.camera.far_m = 10.0f;
  scene.lights.directional = {{{0, 0, -1}, {1, 1, 1}, 1.0f}};
  scene.lights.ambient = glm::vec3(0.1f);
  scene.background = {0.2f, 0.4f, 0.6f};
  return scene;
}

class RenderShading : public VulkanTest {
 protected:
  engine::RgbaImage render(const Model& model, const engine::Scene& scene) {
    return engine::render_model_offscreen(device(), model, kSize, scene);
  }
  static const uint8_t* centre(const engine::RgbaImage& image) { return image.at(image.width / 2, image.height / 2); }
};

TEST_F(RenderShading, EmptySceneIsTheBackgroundInSrgb) {
  engine::Scene scene = head_on_scene();
  Model empty;
  engine::RgbaImage image = render(empty, scene);
  ASSERT_EQ(image.width, kSize.width);
  for (uint32_t y : {0u, kSize.height - 1}) {
    for (uint32_t x : {0u, kSize.width - 1}) {
      EXPECT_NEAR(image.at(x, y)[0], srgb_count(0.2), 1);
      EXPECT_NEAR(image.at(x, y)[1], srgb_count(0.4), 1);
      EXPECT_NEAR(image.at(x, y)[2], srgb_count(0.6), 1);
      EXPECT_EQ(image.at(x, y)[3], 255);
    }
  }
}

TEST_F(RenderShading, HeadOnLitQuadMatchesTheLightingModel) {
  Model model;
  add_quad(model, 0.0f, 1.0f, matte({0.5f, 0.25f, 1.0f, 1.0f}));
  engine::RgbaImage image = render(model, head_on_scene());
  // ambient * base + radiance * (base + specular)
  for (int c = 0; c < 3; ++c) {
    double base = std::array{0.5, 0.25, 1.0}[size_t(c)];
    EXPECT_NEAR(centre(image)[c], srgb_count(0.1 * base + base + kHeadOnSpecular), 1) << "channel " << c;
  }
}

TEST_F(RenderShading, NearerSurfaceHidesFartherOneWhateverTheDrawOrder) {
  for (bool near_first : {true, false}) {
    Model model;
    Material red = matte({1, 0, 0, 1}), green = matte({0, 1, 0, 1});
    if (near_first) {
      add_quad(model, 0.2f, 1.0f, red);
      add_quad(model, 0.0f, 1.0f, green);
    } else {
      add_quad(model, 0.0f, 1.0f, green);
      add_quad(model, 0.2f, 1.0f, red);
    }
    engine::RgbaImage image = render(model, head_on_scene());
    // Red quad, head-on: red = 0.1 + 1 + specular (saturates), green = specular only.
    EXPECT_EQ(centre(image)[0], 255) << "near_first=" << near_first;
    EXPECT_NEAR(centre(image)[1], srgb_count(kHeadOnSpecular), 1) << "near_first=" << near_first;
  }
}

TEST_F(RenderShading, BackFacesAreCulledUnlessDoubleSided) {
  engine::Scene scene = head_on_scene();
  scene.camera.position = {0, 0, -1};  // behind the quad, which faces +z
  for (bool double_sided : {false, true}) {
    Model model;
    Material m = matte({1, 1, 1, 1});
    m.double_sided = double_sided;
    add_quad(model, 0.0f, 1.0f, m);
    engine::RgbaImage image = render(model, scene);
    if (double_sided) {
      // Its back face is lit through the flipped normal (+z -> -z), away from the light: ambient only.
      EXPECT_NEAR(centre(image)[0], srgb_count(0.1), 1);
    } else {
      EXPECT_NEAR(centre(image)[0], srgb_count(0.2), 1);  // the background shows through
    }
  }
}

TEST_F(RenderShading, BlendedSurfaceMixesWithWhatLiesBehind) {
  Model model;
  add_quad(model, 0.0f, 1.0f, matte({0, 0, 0, 1}));  // black backdrop
  Material glass = matte({1, 1, 1, 0.25f});
  glass.alpha_mode = AlphaMode::Blend;
  add_quad(model, 0.2f, 1.0f, glass);
  engine::Scene scene = head_on_scene();
  scene.lights.directional.clear();
  scene.lights.ambient = glm::vec3(1.0f);  // colour = base exactly
  engine::RgbaImage image = render(model, scene);
  // 0.25 * white + 0.75 * black, blended as the target holds them, sRGB-encoded (a UNORM target,
  // docs/RENDERING.md, "Colour"): white encodes to 255, black to 0.
  EXPECT_NEAR(centre(image)[0], 0.25 * 255.0, 1);
}

TEST_F(RenderShading, MaskedTexelsBelowTheCutoffAreDiscarded) {
  Model model;
  Material cut = matte({1, 0, 0, 0.4f});
  cut.alpha_mode = AlphaMode::Mask;
  cut.alpha_cutoff = 0.5f;
  add_quad(model, 0.0f, 1.0f, cut);
  engine::RgbaImage image = render(model, head_on_scene());
  EXPECT_NEAR(centre(image)[0], srgb_count(0.2), 1);  // background
}

}  // namespace
}  // namespace needle::test
