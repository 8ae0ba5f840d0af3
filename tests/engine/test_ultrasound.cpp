// The ultrasound pass on lavapipe against the double-precision scan-line model
// (engine::trace_scan_lines): every interface, needle wall and shadow of every line, the image's
// bright rows at the interfaces and its dark shadow columns, speckle that stays put, layers that
// move with the tissue; all under the validation layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>

#include "engine/ultrasound/echo_model.hpp"
#include "engine/ultrasound/ultrasound_pass.hpp"
#include "engine/vulkan/command_buffer.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "tests/support/scan_lines.hpp"
#include "ultrasound_fixture.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

// float on the GPU against double: scene coordinates near 0.33 m are float-spaced by 3e-8 m, and
// the GPU places a crossing by interpolating φ between two samples (exact for planes) where the
// reference bisects; 2 µm is 1/50 of a sample.
constexpr double kDepthTolerance_m = 2e-6;

class UltrasoundTest : public VulkanTest {
 protected:
  // The GPU's scan lines and the reference's agree for this scene, probe and needle.
  void expect_lines_match(engine::UltrasoundView& view, const engine::UltrasoundProbe& probe,
                          const engine::NeedleLoad* needle) {
    view.render(probe, needle);
    expect_scan_lines_match(view.scan_lines(), engine::trace_scan_lines(view.scene(), probe, needle, view.settings()),
                            kDepthTolerance_m, probe.depth_m / view.settings().samples);
  }
};

TEST_F(UltrasoundTest, TheGpuScanLinesAreTheReferencesInTheLayeredBlock) {
  engine::UltrasoundView view(device(), block_scene());
  const engine::NeedleLoad in_plane = in_plane_needle(), out_of_plane = out_of_plane_needle();
  expect_lines_match(view, block_probe(), nullptr);
  expect_lines_match(view, block_probe(), &in_plane);
  expect_lines_match(view, block_probe(), &out_of_plane);
  // Every line crosses gel→skin→fat→muscle→bone; the needle in plane meets a run of lines.
  const std::vector<engine::ScanLine> lines =
      engine::trace_scan_lines(view.scene(), block_probe(), &in_plane, view.settings());
  ASSERT_EQ(lines[128].interfaces.size(), 4u);
  EXPECT_NEAR(lines[128].interfaces[0].depth_m, 0.0, 1e-9);
  EXPECT_NEAR(lines[128].interfaces[1].depth_m, 0.002, 1e-9);
  EXPECT_NEAR(lines[128].interfaces[2].depth_m, 0.012, 1e-9);
  EXPECT_NEAR(lines[128].interfaces[3].depth_m, 0.040, 1e-9);
  EXPECT_NEAR(lines[128].shadow_depth_m, 0.041, 0.001);  // bone's 225 dB/cm round trip: dark within 2 mm
  int needle_lines = 0;
  for (const engine::ScanLine& l : lines) needle_lines += !std::isinf(l.needle_depth_m);
  EXPECT_GT(needle_lines, 100);
}

// A needle that turns through the image plane (entering 0.4 mm in front of it, crossing it 2 cm
// along, slope 1:50) is one straight line of walls across the image, on the GPU and in the
// reference: each line's wall depth on the straight line fitted through all of them within 5 µm
// (the GPU's 2 µm against the reference, and its float), short of the tip, past which the lines
// within the needle's radius meet its end. Taking, among the shaft's points within its radius
// of the line, the one nearest the image plane instead, the wall jumps by 2 r tan(30°) = 0.9 mm
// from one end of that band to the other where the needle crosses the plane: a kink.
TEST_F(UltrasoundTest, TheNeedlesLineIsStraightWhereItCrossesTheImagePlane) {
  engine::UltrasoundView view(device(), block_scene());
  const engine::UltrasoundProbe probe = block_probe();
  const engine::NeedleLoad needle =
      needle_along({0.305, -0.0004, 0.07}, {std::cos(0.5236), 0.02, -std::sin(0.5236)}, 0.04);
  view.render(probe, &needle);
  const std::vector<engine::ScanLine> gpu = view.scan_lines();
  const std::vector<engine::ScanLine> cpu = engine::trace_scan_lines(view.scene(), probe, &needle, view.settings());
  for (const auto* lines : {&cpu, &gpu}) {
    std::vector<glm::dvec2> walls;  // (lateral position, wall depth), along the shaft short of its tip
    const double tip_x = glm::dot(needle.tip - glm::dvec3(probe.position), glm::dvec3(probe.lateral));
    for (uint32_t i = 0; i < lines->size(); ++i) {
      const double x = glm::dot(engine::echo::line_origin(probe, view.settings(), i) - probe.position, probe.lateral);
      if (std::isinf((*lines)[i].needle_depth_m) || x > tip_x) continue;
      walls.push_back({x, (*lines)[i].needle_depth_m});
    }
    ASSERT_GT(walls.size(), 100u) << (lines == &cpu ? "reference" : "GPU");
    // Least squares z = a + b x.
    double sx = 0, sz = 0, sxx = 0, sxz = 0;
    for (const glm::dvec2& w : walls) sx += w.x, sz += w.y, sxx += w.x * w.x, sxz += w.x * w.y;
    const double n = double(walls.size()), b = (n * sxz - sx * sz) / (n * sxx - sx * sx), a = (sz - b * sx) / n;
    double worst = 0.0;
    for (const glm::dvec2& w : walls) worst = std::max(worst, std::abs(w.y - (a + b * w.x)));
    EXPECT_LT(worst, 5e-6) << (lines == &cpu ? "reference" : "GPU") << ": a wall " << worst * 1e3 << " mm off the line";
  }
}

TEST_F(UltrasoundTest, TheGpuScanLinesAreTheReferencesUnderHalfABonePlate) {
  engine::UltrasoundView view(device(), half_bone_scene(), {128, 256});
  expect_lines_match(view, block_probe(), nullptr);
  // The plate lies under x > 0.33: the right half of the lines (the array runs along +x).
  const std::vector<engine::ScanLine> lines = view.scan_lines();
  for (size_t i = 0; i < lines.size(); ++i)
    EXPECT_EQ(std::isinf(lines[i].shadow_depth_m), i < lines.size() / 2) << "line " << i;
}

// The thesis's sphere, deformable as in assets/scenes/penetrable_sphere.json, pressed 6 mm
// straight down at its top, under a 60 mm probe.
struct PressedSphere {
  engine::EchoScene scene;
  engine::UltrasoundProbe probe;
  engine::NeedleLoad press;
};
PressedSphere pressed_sphere() {
  PressedSphere p;
  p.scene.layers = {{"tissue", {{engine::EchoPrimitive::Kind::Sphere, {0.4, 0.0, 0.0}, {}, 0.1}}, false, {}}};
  p.scene.deformation = engine::TissueParams{};
  p.probe.position = {0.4, 0.0, 0.12};
  p.probe.depth_m = 0.06;
  p.press.contact = engine::NeedleContact::Touching;
  p.press.axis = {0.0, 0.0, -1.0};
  p.press.surface_point = {0.4, 0.0, 0.1};
  p.press.tip = {0.4, 0.0, 0.094};
  return p;
}

TEST_F(UltrasoundTest, TheLayersMoveWithTheTissue) {
  const PressedSphere p = pressed_sphere();
  engine::UltrasoundView view(device(), p.scene, {128, 512});
  expect_lines_match(view, p.probe, &p.press);
  // The middle line meets the surface at the tip (the dimple's floor, docs/DEFORMATION.md), not at rest.
  const engine::ScanLine middle = view.scan_lines()[64];
  ASSERT_FALSE(middle.interfaces.empty());
  EXPECT_NEAR(middle.interfaces[0].depth_m, 0.026, 2e-4);
  expect_lines_match(view, p.probe, nullptr);
  EXPECT_NEAR(view.scan_lines()[64].interfaces[0].depth_m, 0.02, 2e-4);
}

// Linear interpolation between nodes h apart errs by h²/8 times the displacement's second
// derivative: a quarter of the spacing, a sixteenth of the error; a node at every sample, none;
// and the spacing chosen for the deformation keeps within its tolerance.
TEST(UltrasoundModel, RestNodesInterpolateTheExactRestPositionsToSecondOrder) {
  const PressedSphere p = pressed_sphere();
  const auto error = [&](uint32_t spacing) {
    engine::UltrasoundSettings settings{128, 512};
    settings.rest_node_spacing = spacing;
    return engine::rest_interpolation_error(p.scene, p.probe, p.press, settings);
  };
  EXPECT_EQ(error(1), 0.0);
  const double e4 = error(4), e16 = error(16);
  EXPECT_GT(e4, 0.0);
  EXPECT_GT(e16 / e4, 12.0);
  EXPECT_LT(e16 / e4, 20.0);
  const uint32_t chosen = engine::rest_node_spacing(p.scene, p.probe, p.press, {128, 512});
  EXPECT_EQ(chosen, 2u) << "a 6 mm dimple in a tissue whose loads spread over 10 mm";
  EXPECT_LE(error(0), engine::echo::kRestTolerance_m);
}

// The GPU's nodes are the rest positions the image needs: its image from nodes 4 samples apart is
// the one with a node at every sample (the exact rest positions) but for the few scatterer cells
// whose boundary lies within the interpolation's micrometres of a sample.
TEST_F(UltrasoundTest, ADeformedImageFromRestNodesIsTheOneWithANodeAtEverySample) {
  const PressedSphere p = pressed_sphere();
  engine::UltrasoundSettings exact_settings{128, 512}, node_settings{128, 512};
  exact_settings.rest_node_spacing = 1;
  node_settings.rest_node_spacing = 4;
  engine::UltrasoundView exact(device(), p.scene, exact_settings), nodes(device(), p.scene, node_settings);
  exact.render(p.probe, &p.press);
  nodes.render(p.probe, &p.press);
  const engine::RgbaImage a = exact.image(), b = nodes.image();
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t unlike = 0, grey = 0;
  double difference = 0.0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    const int d = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
    unlike += d > 1 ? 1 : 0;
    difference += d;
    grey += a.pixels[i] > 0 ? 1 : 0;
  }
  const size_t pixels = a.pixels.size() / 4;
  EXPECT_GT(grey, pixels / 4) << "the tissue's speckle fills the image";
  EXPECT_LT(unlike, pixels / 100) << "pixels more than a count apart (0.4 % measured)";
  EXPECT_LT(difference / double(pixels), 0.1) << "mean grey difference, counts (0.04 measured)";
}

// Without speckle, the image is the scan-line model blurred by the point spread function: each
// interface the reference finds is the brightest row within the pulse's length around it.
TEST_F(UltrasoundTest, TheImagesBrightRowsAreTheReferencesInterfaces) {
  engine::UltrasoundSettings settings;
  settings.speckle = false;
  engine::UltrasoundView view(device(), block_scene(), settings);
  const engine::UltrasoundProbe probe = block_probe();
  view.render(probe, nullptr);
  const engine::RgbaImage image = view.image();
  const double sample_m = probe.depth_m / settings.samples;
  const int reach = 3;  // samples either side: the axial PSF's radius at 7.5 MHz
  const std::vector<engine::ScanLine> lines = engine::trace_scan_lines(view.scene(), probe, nullptr, settings);
  int checked = 0;
  for (uint32_t line = 0; line < settings.lines; line += 16) {
    for (const engine::EchoInterface& e : lines[line].interfaces) {
      const double expected = e.depth_m / sample_m - 0.5;
      if (expected < reach) continue;  // the face's own echo has no row above it
      int brightest = int(std::lround(expected));
      for (int j = int(expected) - reach; j <= int(expected) + reach; ++j)
        if (image.at(line, uint32_t(j))[0] > image.at(line, uint32_t(brightest))[0]) brightest = j;
      EXPECT_LE(std::abs(brightest - expected), 1.0) << "line " << line << " depth " << e.depth_m;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 16 * 3);
}

// Below the plate's surface the shadowed lines are black; the others still show muscle.
TEST_F(UltrasoundTest, ShadowColumnsAreDarkAndTheOthersAreNot) {
  engine::UltrasoundView view(device(), half_bone_scene());
  const engine::UltrasoundProbe probe = block_probe();
  view.render(probe, nullptr);
  const engine::RgbaImage image = view.image();
  const std::vector<engine::ScanLine> lines = engine::trace_scan_lines(view.scene(), probe, nullptr, view.settings());
  const double sample_m = probe.depth_m / view.settings().samples;
  // Rows from 2 mm under the plate's surface (25 mm) to 2 mm above the muscle's floor (40 mm).
  const uint32_t first = uint32_t(0.027 / sample_m), last = uint32_t(0.038 / sample_m);
  for (uint32_t line = 8; line + 8 < view.settings().lines; line += 8) {
    // Lines whose lateral point spread function reaches across the plate's edge are neither.
    if (std::isinf(lines[line - 8].shadow_depth_m) != std::isinf(lines[line + 8].shadow_depth_m)) continue;
    double sum = 0.0;
    for (uint32_t j = first; j <= last; ++j) sum += image.at(line, j)[0];
    const double mean = sum / (last - first + 1);
    if (std::isinf(lines[line].shadow_depth_m)) {
      EXPECT_GT(mean, 40.0) << "line " << line;
    } else {
      EXPECT_LT(mean, 2.0) << "line " << line;
    }
  }
}

TEST_F(UltrasoundTest, SpeckleStaysPutWhileTheProbeStaysPut) {
  engine::UltrasoundView view(device(), block_scene());
  engine::UltrasoundProbe probe = block_probe();
  view.render(probe, nullptr);
  const engine::RgbaImage first = view.image();
  view.render(probe, nullptr);
  EXPECT_EQ(view.image().pixels, first.pixels);
  probe.position.y += 0.001;  // a millimetre across the plane: other scatterers
  view.render(probe, nullptr);
  EXPECT_NE(view.image().pixels, first.pixels);
}

// A frame records the passes only when the image would change: the same probe and needle again
// record nothing (the image shown is already theirs); a moved needle or probe records them, and
// a recorder never run leaves the next frame to record. render() always makes the image.
TEST_F(UltrasoundTest, AFrameRecordsThePassesOnlyWhenTheProbeOrTheNeedleMoved) {
  engine::UltrasoundView view(device(), block_scene());
  const auto run = [&](const engine::CommandRecorder& recorder) {
    view.pass().context().submit_and_wait([&](VkCommandBuffer cmd) { recorder(engine::CommandBuffer{cmd}); });
  };
  engine::UltrasoundProbe probe = block_probe();
  engine::NeedleLoad needle = in_plane_needle();
  const engine::CommandRecorder first = view.record(probe, &needle);
  ASSERT_TRUE(first);
  run(first);
  const engine::RgbaImage before = view.image();
  EXPECT_FALSE(view.record(probe, &needle));

  needle.tip += 0.002 * needle.axis;  // 2 mm deeper: the wall's echo moves
  const engine::CommandRecorder deeper = view.record(probe, &needle);
  ASSERT_TRUE(deeper);
  run(deeper);
  EXPECT_NE(view.image().pixels, before.pixels);
  EXPECT_FALSE(view.record(probe, &needle));

  probe.position.x += 0.001;
  EXPECT_TRUE(view.record(probe, &needle));
  EXPECT_TRUE(view.record(probe, &needle));  // the first was never run
  view.render(block_probe(), &needle);       // render: whatever was recorded
  const engine::RgbaImage rendered = view.image();
  view.render(block_probe(), &needle);
  EXPECT_EQ(view.image().pixels, rendered.pixels);
}

// A sweep over two frames: the first image whole, then after a move half the lines a frame, each
// slice exactly the lines (picture columns) of the whole image for the new probe while the other
// slice keeps the old probe's; after both slices the image is the whole new one and nothing more
// is recorded. The reference is a view without a sweep rendering each probe's whole image.
TEST_F(UltrasoundTest, ASweepMakesTheImageASliceOfLinesAFrame) {
  engine::UltrasoundSettings swept;
  swept.sweep_frames = 2;
  engine::UltrasoundView view(device(), block_scene(), swept), whole(device(), block_scene());
  const auto run = [&](const engine::CommandRecorder& recorder) {
    ASSERT_TRUE(recorder);
    view.pass().context().submit_and_wait([&](VkCommandBuffer cmd) { recorder(engine::CommandBuffer{cmd}); });
  };
  const engine::NeedleLoad needle = in_plane_needle();
  const engine::UltrasoundProbe before = block_probe();
  engine::UltrasoundProbe after = before;
  after.position.y += 0.001;  // a millimetre across the plane: other scatterers on every line
  whole.render(before, &needle);
  const engine::RgbaImage old_image = whole.image();
  whole.render(after, &needle);
  const engine::RgbaImage new_image = whole.image();

  // Whether columns [from, to) of `image` are those of `reference`.
  const auto columns_match = [](const engine::RgbaImage& image, const engine::RgbaImage& reference, uint32_t from,
                                uint32_t to) {
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = from; x < to; ++x)
        for (int c = 0; c < 4; ++c)
          if (image.pixels[(size_t(y) * image.width + x) * 4 + c] !=
              reference.pixels[(size_t(y) * image.width + x) * 4 + c])
            return false;
    return true;
  };
  const uint32_t lines = view.settings().lines, half = lines / 2;
  const uint32_t reach = engine::echo::kMaxKernelRadius;  // the lateral kernel's, or more
  ASSERT_FALSE(columns_match(new_image, old_image, 0, half - reach)) << "the move changes the first slice's lines";
  ASSERT_FALSE(columns_match(new_image, old_image, half + reach, lines)) << "and the second's";

  run(view.record(before, &needle));
  EXPECT_EQ(view.image().pixels, old_image.pixels) << "the first image is whole";
  EXPECT_FALSE(view.record(before, &needle));

  run(view.record(after, &needle));
  const engine::RgbaImage first_half = view.image();
  EXPECT_TRUE(columns_match(first_half, new_image, 0, half - reach));
  EXPECT_TRUE(columns_match(first_half, old_image, half + reach, lines));

  run(view.record(after, &needle));  // the other slice, though nothing moved since
  EXPECT_EQ(view.image().pixels, new_image.pixels);
  EXPECT_FALSE(view.record(after, &needle));

  view.set_sweep_frames(2);  // as it was: nothing to make again
  EXPECT_FALSE(view.record(after, &needle));
  view.set_sweep_frames(1);  // another sweep: every line made again, here at once
  run(view.record(after, &needle));
  EXPECT_EQ(view.image().pixels, new_image.pixels);
  EXPECT_FALSE(view.record(after, &needle));
  EXPECT_THROW(view.set_sweep_frames(0), std::invalid_argument);
}

// As many layers as the shaders take: ten nested spheres (each inside the one before) and, in the
// innermost, six small disjoint ones side by side under the probe, 70 mm deep. A line's walk follows each layer
// on its own and leaves those before the one that holds a sample (docs/RENDERING.md, "How the passes
// find the layers"): every line meets the reference's interfaces, between the same layers, in the
// same intervals between two samples (a sphere's φ is not linear along a beam that grazes it), at
// rest and with a needle pressing the tissue (its rest positions).
TEST_F(UltrasoundTest, TheMostLayersTheShadersTakeAreEachFoundWhereTheReferenceFindsThem) {
  engine::EchoScene scene;
  const glm::dvec3 centre{0.33, 0.0, 0.035};
  for (int k = 0; k < 10; ++k)
    scene.layers.push_back({"shell " + std::to_string(k),
                            {{engine::EchoPrimitive::Kind::Sphere, centre, {}, 0.030 - 0.0025 * k}},
                            false,
                            k % 2 ? kFat : kMuscle});
  for (int k = 0; k < 6; ++k)
    scene.layers.push_back(
        {"bead " + std::to_string(k),
         {{engine::EchoPrimitive::Kind::Sphere, centre + glm::dvec3(0.002 * k - 0.005, 0.0, 0.0), {}, 0.0008}},
         false,
         kBone});
  ASSERT_EQ(scene.layers.size(), engine::EchoScene::kMaxLayers);
  scene.deformation = engine::TissueParams{};
  engine::UltrasoundView view(device(), scene, {128, 512});
  engine::NeedleLoad press;
  press.contact = engine::NeedleContact::Touching;
  press.axis = {0.0, 0.0, -1.0};
  press.surface_point = {0.33, 0.0, 0.065};
  press.tip = {0.33, 0.0, 0.062};
  for (const engine::NeedleLoad* needle : std::array<const engine::NeedleLoad*, 2>{nullptr, &press}) {
    engine::UltrasoundProbe probe = block_probe();
    probe.depth_m = 0.07;  // past the shells' bottom
    view.render(probe, needle);
    const std::vector<engine::ScanLine> cpu = engine::trace_scan_lines(scene, probe, needle, view.settings());
    const double sample_m = probe.depth_m / view.settings().samples;
    expect_scan_lines_match(view.scan_lines(), cpu, sample_m, sample_m);
    size_t most = 0;
    for (const engine::ScanLine& line : cpu) most = std::max(most, line.interfaces.size());
    EXPECT_EQ(most, 22u) << "the middle lines cross the ten shells both ways and a bead";
  }
  EXPECT_TRUE(device().validation_messages().empty()) << device().validation_messages().front();
}

TEST_F(UltrasoundTest, AScenePastTheShadersLimitsIsRefused) {
  engine::EchoScene many = block_scene();
  while (many.layers.size() <= engine::EchoScene::kMaxLayers) many.layers.push_back(many.layers.back());
  EXPECT_THROW(engine::UltrasoundView(device(), many), std::invalid_argument);
  EXPECT_THROW(engine::UltrasoundView(device(), block_scene(), {0, 512}), std::invalid_argument);
}

TEST(UltrasoundModel, ThePictureHasTheProbesProportions) {
  engine::RgbaImage image{2, 4, std::vector<uint8_t>(32, 0)};
  for (uint32_t y = 0; y < 4; ++y) image.pixels[(y * 2 + 1) * 4] = 200;  // the right line bright
  engine::UltrasoundProbe probe;
  probe.width_m = 0.04;
  probe.depth_m = 0.02;
  const engine::RgbaImage picture = engine::to_picture(image, probe);
  EXPECT_EQ(picture.width, 8u);
  EXPECT_EQ(picture.height, 4u);
  EXPECT_EQ(picture.at(0, 0)[0], 0);
  EXPECT_EQ(picture.at(7, 3)[0], 200);
  EXPECT_GT(picture.at(4, 0)[0], 0);
  EXPECT_LT(picture.at(4, 0)[0], 200);
}

TEST(UltrasoundModel, TheFollowingProbeLiesOverTheTipWithTheNeedleAlongItsArray) {
  engine::UltrasoundProbe probe = block_probe();
  const engine::NeedleLoad needle = out_of_plane_needle();  // along +y, down
  const engine::UltrasoundProbe follow = engine::probe_following(probe, needle);
  EXPECT_NEAR(glm::length(follow.lateral - glm::dvec3(0.0, 1.0, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(follow.position.z, probe.position.z, 1e-12);  // still on the skin
  EXPECT_NEAR(follow.position.x, needle.tip.x, 1e-12);
  EXPECT_NEAR(follow.position.y, needle.tip.y, 1e-12);
  engine::NeedleLoad down = needle;
  down.axis = probe.direction;  // along the beam: no plane to follow
  EXPECT_EQ(engine::probe_following(probe, down).position, probe.position);
}

}  // namespace
}  // namespace needle::test
