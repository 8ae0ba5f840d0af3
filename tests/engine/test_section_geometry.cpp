// The section view checked against the geometry, not against another picture (docs/RENDERING.md,
// "Section view"): every pixel whose ray meets the cut plane inside a structure, more than a pixel
// and a half from its outline, shows that structure's cut face in the colour the lighting model
// gives a surface of the structure's material facing the viewer; the needle lying in the plane
// shows as one continuous shaft. The same assertions hold on any Vulkan device. Under the
// validation layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <string>
#include <vector>

#include "engine/gltf_loader.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/passes/translucent_pass.hpp"
#include "engine/render_target.hpp"
#include "picture_geometry.hpp"
#include "task_sections.hpp"
#include "tests/support/test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

constexpr engine::Extent kSize{320, 240};
// Channel counts between a cut face's pixel and its closed form: float rounding on the device.
constexpr int kFaceTolerance = 3;

// A tissue structure as the scene places it: an axis-aligned box (the layered block, the lumbar
// section) or a ball (the thesis sphere), with the colour of its cut face before lighting.
struct Solid {
  std::string name;
  bool ball = false;
  glm::dvec3 min{0.0}, max{0.0};  // box; ball: centre (min) and radius (max.x)
  engine::Material material;
  glm::dvec3 base{1.0};  // linear: the material's factor times its texture's middle
  // How deep `p` lies inside, the distance to the nearest face; negative outside.
  double depth(const glm::dvec3& p) const {
    if (ball) return max.x - glm::length(p - min);
    const glm::dvec3 in = glm::min(p - min, max - p);
    return std::min({in.x, in.y, in.z});
  }
};

// The scene's tissue structures, one per primitive instance, in drawing order.
std::vector<Solid> solids_of(const engine::Scene& scene, bool balls) {
  std::vector<Solid> solids;
  for (const engine::SceneAsset& asset : scene.assets) {
    if (asset.role != engine::AssetRole::Tissue) continue;
    const engine::Model model = engine::load_gltf(asset.gltf);
    for (const engine::MeshInstance& instance : model.instances) {
      const engine::Primitive& p = model.primitives[instance.primitive];
      const glm::dmat4 to_world = glm::dmat4(asset.transform()) * glm::dmat4(instance.world);
      Solid s;
      s.name = instance.node_name;
      s.min = glm::dvec3(1e9), s.max = glm::dvec3(-1e9);
      for (const engine::MeshVertex& v : p.vertices) {
        const glm::dvec3 w = glm::dvec3(to_world * glm::dvec4(glm::dvec3(v.position), 1.0));
        s.min = glm::min(s.min, w), s.max = glm::max(s.max, w);
      }
      if (balls) {
        const glm::dvec3 centre = 0.5 * (s.min + s.max);
        s.ball = true;
        s.max = glm::dvec3(0.5 * (s.max.x - s.min.x));
        s.min = centre;
      }
      s.material = p.material >= 0 ? model.materials[size_t(p.material)] : engine::Material{};
      s.base = glm::dvec3(s.material.base_color_factor);
      if (s.material.base_color_texture >= 0) {  // bilinear at uv (0.5, 0.5), in linear light
        const engine::Texture& t = model.textures[size_t(s.material.base_color_texture)];
        glm::dvec3 mean(0.0);
        for (uint32_t y : {t.height / 2 - 1, t.height / 2})
          for (uint32_t x : {t.width / 2 - 1, t.width / 2})
            for (int c = 0; c < 3; ++c)
              mean[c] += srgb_decode(t.rgba8[(size_t(y) * t.width + x) * 4 + size_t(c)]) / 4.0;
        s.base *= mean;
      }
      solids.push_back(s);
    }
  }
  return solids;
}

struct FaceCheck {
  size_t checked = 0;  // pixels inside a structure's cut, away from its outline
  size_t wrong = 0;    // of those, not in that structure's colour
  int worst = 0;
  std::string first_wrong;
};

// Every pixel whose ray meets the plane inside a solid, more than 1.5 pixels' footprint from its
// faces, against the closed form of that solid's cut face (the last solid holding the point, as
// the caps draw them).
FaceCheck check_cut_faces(const engine::RgbaImage& image, const engine::FrameParams& params,
                          const std::vector<Solid>& solids) {
  const engine::Section& section = *params.section;
  const glm::dvec3 n = glm::normalize(glm::dvec3(section.normal)), point(section.point);
  FaceCheck check;
  for (int y = 0; y < int(kSize.height); ++y) {
    for (int x = 0; x < int(kSize.width); ++x) {
      const glm::dvec3 p = on_plane(pixel_ray(params.camera, kSize, x, y), point, n);
      const double footprint = std::max(glm::length(on_plane(pixel_ray(params.camera, kSize, x + 1, y), point, n) - p),
                                        glm::length(on_plane(pixel_ray(params.camera, kSize, x, y + 1), point, n) - p));
      const Solid* holder = nullptr;
      for (const Solid& s : solids)
        if (s.depth(p) > 0.0) holder = &s;
      if (!holder || holder->depth(p) < 1.5 * footprint) continue;
      ++check.checked;
      const glm::ivec3 expected = lit_counts(holder->material, holder->base, n, p, params.camera, params.lights);
      const int d = max_channel_difference(rgb(image, x, y), expected);
      check.worst = std::max(check.worst, d);
      if (d > kFaceTolerance && check.wrong++ == 0) {
        const glm::ivec3 got = rgb(image, x, y);
        check.first_wrong = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") in " + holder->name + ": (" +
                            std::to_string(got.x) + ", " + std::to_string(got.y) + ", " + std::to_string(got.z) +
                            ") against (" + std::to_string(expected.x) + ", " + std::to_string(expected.y) + ", " +
                            std::to_string(expected.z) + ")";
      }
    }
  }
  return check;
}

struct CutScene {
  const char* scene;
  bool balls;
  bool through_needle;  // the plane through a needle standing in the scene's middle, else y = const
};
void PrintTo(const CutScene& c, std::ostream* os) {
  *os << c.scene << (c.through_needle ? " through the needle" : " fixed");
}

class CutFaces : public VulkanTest, public ::testing::WithParamInterface<CutScene> {};

TEST_P(CutFaces, EveryPixelOfACutFaceIsItsStructuresColour) {
  const CutScene& c = GetParam();
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  const engine::Scene file = engine::load_scene(test::source_dir() / "assets/scenes" / c.scene);
  engine::GpuScene scene(renderer, file);
  const std::vector<Solid> solids = solids_of(file, c.balls);
  engine::FrameParams params = scene.frame_params(nullptr);
  std::erase_if(params.items, [](const engine::DrawItem& item) { return !item.sectioned; });  // no tool in front
  params.camera.position = params.camera.target + 0.7f * (params.camera.position - params.camera.target);
  // A needle standing straight down through the camera's target, or the plane y = target.y.
  engine::NeedleLoad needle;
  needle.contact = engine::NeedleContact::Inserted;
  needle.axis = {0.0, 0.0, -1.0};
  needle.tip = glm::dvec3(params.camera.target);
  engine::Section section = engine::section_through_needle(params.camera, &needle);
  if (!c.through_needle)
    section.normal = {0.0f, params.camera.position.y > params.camera.target.y ? 1.0f : -1.0f, 0.0f};
  params.section = section;
  engine::RgbaImage image;
  ASSERT_TRUE(renderer.draw(target, params, &image));
  const FaceCheck check = check_cut_faces(image, params, solids);
  EXPECT_GT(check.checked, 4000u) << "too few pixels of cut faces to judge";
  EXPECT_EQ(check.wrong, 0u) << check.wrong << " of " << check.checked << " pixels not their structure's colour (worst "
                             << check.worst << "), first " << check.first_wrong;
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, CutFaces,
    ::testing::Values(CutScene{"lumbar_section.json", false, true}, CutScene{"lumbar_section.json", false, false},
                      CutScene{"tissue_block_task.json", false, true}, CutScene{"tissue_block_task.json", false, false},
                      CutScene{"penetrable_sphere.json", true, true}),
    [](const ::testing::TestParamInfo<CutScene>& info) {
      std::string name = std::string(info.param.scene).substr(0, std::string(info.param.scene).find('.'));
      return name + (info.param.through_needle ? "_through_needle" : "_fixed_plane");
    });

// The layered block deformed by a needle pushed sideways, cut through it, at the window's size
// without MSAA: where the deformation moves the layers, no pixel of a cut face shows anything
// but its layer's colour. Each pixel whose ray meets the plane inside the block (4 mm in from its
// outside) is given the layer whose closed-form cut colour it has there (within the lighting's
// spread over the plane); one
// whose eight neighbours are, six or more of them, a layer's while it is not is a speckle
// (pixels within 6 of the needle's projected axis aside: its outline). A cut drawn from the
// layers' back faces instead lets the muscle's top face fight the fat's floor there: about 150
// red speckles in the fat in the three frames.
class CutSpeckles : public VulkanTest {};

TEST_F(CutSpeckles, TheDeformedLayersShowNoSpeckleOfAnother) {
  constexpr engine::Extent kWindow{1280, 720};
  engine::HeadlessTarget target(device(), kWindow);
  engine::RendererSettings settings;
  settings.msaa_samples = 1;
  engine::SceneRenderer renderer(device(), target, settings);
  const engine::Scene file = engine::load_scene(test::source_dir() / "assets/scenes/tissue_block_task.json");
  engine::GpuScene scene(renderer, file);
  const std::vector<Solid> solids = solids_of(file, false);
  // The block, less 4 mm on every side: the deformation moves its outer surfaces by less, so the
  // plane there holds cut faces only, never the skin's top behind a dimple.
  glm::dvec3 block_min(1e9), block_max(-1e9);
  for (const Solid& solid : solids)
    block_min = glm::min(block_min, solid.min), block_max = glm::max(block_max, solid.max);
  block_min += 0.004, block_max -= 0.004;
  int speckles = 0;
  size_t judged = 0;
  for (double x : {0.33, 0.36, 0.375}) {
    engine::NeedleLoad needle;
    needle.contact = engine::NeedleContact::Inserted;
    needle.surface_point = {x, -0.045, 0.07};
    needle.axis = glm::normalize(glm::dvec3(0.2, 0.3, -1.0));
    needle.tip = needle.surface_point + 0.02 * needle.axis;
    needle.lateral_force_on_tissue_N = {0.5, 0.5, 0.0};
    engine::FrameParams params = scene.frame_params(&needle);
    params.section = engine::section_through_needle(params.camera, &needle);
    engine::RgbaImage image;
    ASSERT_TRUE(renderer.draw(target, params, &image));
    const glm::dvec3 n = glm::normalize(glm::dvec3(params.section->normal)), point(params.section->point);
    // Each pixel's nearest layer by colour, -1 where it is none's (the needle, the block's sides).
    std::vector<int> layer(size_t(kWindow.width) * kWindow.height, -1);
    for (int py = 0; py < int(kWindow.height); ++py) {
      for (int px = 0; px < int(kWindow.width); ++px) {
        const glm::dvec3 p = on_plane(pixel_ray(params.camera, kWindow, px, py), point, n);
        if (glm::any(glm::lessThan(p, block_min)) || glm::any(glm::greaterThan(p, block_max))) continue;
        int best = -1, best_d = kFaceTolerance + 12;  // the speckles are a layer's colour, within its lighting's spread
        for (size_t k = 0; k < solids.size(); ++k) {
          const int d = max_channel_difference(
              rgb(image, px, py), lit_counts(solids[k].material, solids[k].base, n, p, params.camera, params.lights));
          if (d < best_d) best = int(k), best_d = d;
        }
        layer[size_t(py) * kWindow.width + px] = best;
      }
    }
    const glm::vec2 tip = *engine::project_to_screen(params.camera, kWindow, glm::vec3(needle.tip));
    const glm::vec2 hub =
        *engine::project_to_screen(params.camera, kWindow, glm::vec3(needle.tip - 0.095 * needle.axis));
    auto near_needle = [&](int px, int py) {
      const glm::vec2 p(px + 0.5f, py + 0.5f), d = hub - tip;
      const float t = std::clamp(glm::dot(p - tip, d) / glm::dot(d, d), 0.0f, 1.0f);
      return glm::length(p - (tip + t * d)) < 6.0f;
    };
    for (int py = 1; py + 1 < int(kWindow.height); ++py) {
      for (int px = 1; px + 1 < int(kWindow.width); ++px) {
        if (near_needle(px, py)) continue;
        std::map<int, int> around;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            if (dx || dy) ++around[layer[size_t(py + dy) * kWindow.width + px + dx]];
        const int own = layer[size_t(py) * kWindow.width + px];
        judged += own >= 0;
        for (const auto& [other, count] : around) speckles += other >= 0 && other != own && count >= 6;
      }
    }
  }
  EXPECT_GT(judged, 30000u);
  EXPECT_EQ(speckles, 0) << speckles << " pixels of one layer's cut among another's";
}

// The needle of a task's section view (task_sections.hpp) in the cut: along its projected axis,
// from the end of its tip's cone to where it leaves the view of the cut (in plane: 2 cm above the
// skin; out of plane: 1 mm before it crosses the plane, beyond which the cut face hides it),
// every pixel is the needle's as the needle alone draws it: one continuous shaft, no piece of it
// hidden by a cap or another structure.
class NeedleInTheCut : public VulkanTest, public ::testing::WithParamInterface<TaskSection> {};

TEST_P(NeedleInTheCut, TheShaftIsOneContinuousPiece) {
  const TaskSection& c = GetParam();
  constexpr engine::Extent kLarge{640, 480};
  constexpr double kTipCone_m = 0.004;  // asset-gen's needle: the tip's cone, then the shaft
  engine::HeadlessTarget target(device(), kLarge);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene scene(renderer, engine::load_scene(test::source_dir() / "assets/scenes" / c.scene));
  const engine::NeedleLoad needle = task_needle(c);
  engine::FrameParams params = task_frame(scene, needle);
  engine::FrameParams alone = params;
  std::erase_if(alone.items, [](const engine::DrawItem& item) { return item.sectioned; });
  params.section = task_section(c, params.camera, needle);
  engine::RgbaImage cut, reference;
  ASSERT_TRUE(renderer.draw(target, params, &cut));
  ASSERT_TRUE(renderer.draw(target, alone, &reference));
  // Distances back from the tip: from the shaft's start (in plane) or 1 mm before the crossing
  // (out of plane) to 2 cm above the skin.
  const double crossing = c.depth - (-c.entry_y / needle.axis.y);
  const double near = c.in_plane ? kTipCone_m : crossing + 0.001, far = c.depth + 0.02;
  const std::optional<glm::vec2> a =
      engine::project_to_screen(params.camera, kLarge, glm::vec3(needle.tip - near * needle.axis));
  const std::optional<glm::vec2> b =
      engine::project_to_screen(params.camera, kLarge, glm::vec3(needle.tip - far * needle.axis));
  ASSERT_TRUE(a && b);
  const int steps = int(std::ceil(2.0 * glm::length(*b - *a)));
  ASSERT_GT(steps, 40) << "the shaft is too short on the screen to judge";
  int gaps = 0, worst = 0;
  for (int i = 0; i <= steps; ++i) {
    const glm::vec2 at = *a + (*b - *a) * (float(i) / float(steps)) - 0.5f;  // pixel centres at integers
    const int x = int(std::lround(at.x)), y = int(std::lround(at.y));
    const int d = max_channel_difference(rgb(cut, x, y), rgb(reference, x, y));
    worst = std::max(worst, d);
    gaps += d > 8;
  }
  EXPECT_EQ(gaps, 0) << gaps << " of " << steps + 1 << " points of the shaft not the needle's (worst " << worst << ")";
}

INSTANTIATE_TEST_SUITE_P(Tasks, NeedleInTheCut, kTaskSections, task_section_name);

// The translucent mode against its closed form (weighted blended transparency of one layer is
// exact): where a ray meets the thesis sphere's front once, the pixel is kTranslucentAlpha of the
// sphere's lit colour there over the rest of what lies behind it, the background or the needle as
// it draws alone (blended on the encoded values, as the targets hold them).
class TranslucentTissue : public VulkanTest {};

TEST_F(TranslucentTissue, OneLayerLetsThreeQuartersOfWhatIsBehindThrough) {
  constexpr double kAlpha = engine::kTranslucentAlpha;
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  const engine::Scene file = engine::load_scene(test::source_dir() / "assets/scenes/penetrable_sphere.json");
  engine::GpuScene scene(renderer, file);
  const Solid sphere = solids_of(file, true).at(0);
  // The needle 2 cm past the sphere's centre, drawn where it is but pushing nothing (free): the
  // sphere keeps its shape, so its front surface is the closed form's.
  engine::NeedleLoad needle;
  needle.axis = glm::normalize(glm::dvec3(1.0, 0.0, -0.35));
  needle.tip = sphere.min + 0.02 * needle.axis;
  engine::FrameParams params = scene.frame_params(&needle);
  engine::FrameParams alone = params;
  std::erase_if(alone.items, [](const engine::DrawItem& item) { return item.sectioned; });
  params.section = engine::section_through_needle(params.camera, &needle, engine::Section::Mode::Translucent);
  engine::RgbaImage image, needle_alone;
  ASSERT_TRUE(renderer.draw(target, params, &image));
  ASSERT_TRUE(renderer.draw(target, alone, &needle_alone));

  // The sphere's lit front where the pixel's ray meets it, if it does 10 % inside its outline.
  const double radius = sphere.max.x;
  auto front = [&](int x, int y) -> std::optional<glm::ivec3> {
    const Ray ray = pixel_ray(params.camera, kSize, x, y);
    const double along = glm::dot(sphere.min - ray.origin, ray.direction);
    const double miss = glm::length(ray.origin + along * ray.direction - sphere.min);
    if (miss > 0.9 * radius) return std::nullopt;
    const glm::dvec3 p = ray.origin + (along - std::sqrt(radius * radius - miss * miss)) * ray.direction;
    return lit_counts(sphere.material, sphere.base, glm::normalize(p - sphere.min), p, params.camera, params.lights);
  };
  auto over = [&](const glm::ivec3& layer, const glm::ivec3& behind) {
    return glm::ivec3(glm::round(kAlpha * glm::dvec3(layer) + (1.0 - kAlpha) * glm::dvec3(behind)));
  };
  const glm::ivec3 background(srgb_count(params.background.r), srgb_count(params.background.g),
                              srgb_count(params.background.b));
  // Over the background: every pixel of the sphere's inner 90 % the needle alone leaves background.
  size_t checked = 0, wrong = 0;
  int worst = 0;
  for (int y = 0; y < int(kSize.height); ++y) {
    for (int x = 0; x < int(kSize.width); ++x) {
      const std::optional<glm::ivec3> layer = front(x, y);
      if (!layer || rgb(needle_alone, x, y) != background) continue;
      const int d = max_channel_difference(rgb(image, x, y), over(*layer, background));
      ++checked, wrong += d > kFaceTolerance, worst = std::max(worst, d);
    }
  }
  EXPECT_GT(checked, 10000u);
  EXPECT_EQ(wrong, 0u) << wrong << " of " << checked << " pixels of the sphere over the background (worst " << worst
                       << ")";
  // Over the needle: along its axis, from 5 mm above the tip to 2 cm deep.
  checked = wrong = 0, worst = 0;
  for (double back = 0.005; back <= 0.05; back += 0.0005) {
    const std::optional<glm::vec2> at =
        engine::project_to_screen(params.camera, kSize, glm::vec3(needle.tip - back * needle.axis));
    ASSERT_TRUE(at);
    const int x = int(at->x), y = int(at->y);
    const std::optional<glm::ivec3> layer = front(x, y);
    if (!layer) continue;
    const int d = max_channel_difference(rgb(image, x, y), over(*layer, rgb(needle_alone, x, y)));
    ++checked, wrong += d > kFaceTolerance, worst = std::max(worst, d);
  }
  EXPECT_GT(checked, 40u);
  EXPECT_EQ(wrong, 0u) << wrong << " of " << checked << " points of the needle under the sphere (worst " << worst
                       << ")";
}

// Order independence: the lumbar section's eleven structures and the layered block overlapping
// them, drawn in either order, give the same picture (to the rounding of half floats).
TEST_F(TranslucentTissue, TheOrderOfTheDrawsDoesNotMatter) {
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene lumbar(renderer, engine::load_scene(test::source_dir() / "assets/scenes/lumbar_section.json"));
  engine::GpuScene block(renderer, engine::load_scene(test::source_dir() / "assets/scenes/tissue_block_task.json"));
  engine::FrameParams params = lumbar.frame_params(nullptr);
  const engine::FrameParams other = block.frame_params(nullptr);
  std::erase_if(params.items, [](const engine::DrawItem& item) { return !item.sectioned; });
  for (const engine::DrawItem& item : other.items)
    if (item.sectioned) params.items.push_back(item);
  params.items.back().transform =
      glm::translate(glm::mat4(1.0f), glm::vec3(0.01f, 0.005f, -0.01f)) * params.items.back().transform;
  params.section = engine::Section{engine::Section::Mode::Translucent};
  engine::RgbaImage forward, backward;
  ASSERT_TRUE(renderer.draw(target, params, &forward));
  std::reverse(params.items.begin(), params.items.end());
  ASSERT_TRUE(renderer.draw(target, params, &backward));
  int worst = 0;
  size_t covered = 0;
  const glm::ivec3 background(srgb_count(params.background.r), srgb_count(params.background.g),
                              srgb_count(params.background.b));
  for (int y = 0; y < int(kSize.height); ++y)
    for (int x = 0; x < int(kSize.width); ++x) {
      worst = std::max(worst, max_channel_difference(rgb(forward, x, y), rgb(backward, x, y)));
      covered += rgb(forward, x, y) != background;
    }
  EXPECT_GT(covered, 15000u);
  EXPECT_LE(worst, 1);
}

}  // namespace
}  // namespace needle::test
