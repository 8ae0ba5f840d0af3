// `needle-sim render` and `needle-sim run` as a user calls them: exit codes, one-line errors,
// the PNG written, no validation message, and the window path under Xvfb.
#include <gtest/gtest.h>

#include "cli_process.hpp"
#include "engine/rgba_image.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

const std::filesystem::path kAssets = test::source_dir() / "assets";

size_t line_count(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

TEST(CliRender, HelpListsTheOptionsAndExitsZero) {
  ProcessResult r = run_needle_sim("render --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("--gltf FILE"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--size WxH"), std::string::npos) << r.output;
}

TEST(CliRender, UsageErrorsExitTwoWithOneLine) {
  for (const char* args :
       {"render --out x.png", "render --scene a.json --gltf b.gltf --out x.png",
        "render --scene a.json --out x.png --size 12by4", "render --scene a.json --out x.png --bogus"}) {
    ProcessResult r = run_needle_sim(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_EQ(line_count(r.output), 1u) << args << "\n" << r.output;
  }
}

TEST(CliRender, MissingFileExitsOneNamingIt) {
  ProcessResult r = run_needle_sim("render --gltf /nonexistent/model.gltf --out x.png");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_count(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/model.gltf"), std::string::npos) << r.output;
}

// The largest size the option allows needs more memory than the CPU device gives: said as too
// large for this device, not as a raw Vulkan result.
TEST(CliRender, ASizeTooLargeForTheDeviceIsSaidSo) {
  const ProcessResult r =
      run_needle_sim("render --gltf " + quoted(source_dir() / "assets/needle.gltf") + " --size 16384x16384 --out " +
                     quoted(test_output_dir("cli_render") / "huge.png"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("needle-sim render: error: a 16384x16384 image"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is too large for this device (llvmpipe"), std::string::npos) << r.output;
}

TEST(CliRender, SceneRendersToAPngOfTheRequestedSize) {
  auto out = test_output_dir("cli_render") / "thesis_sphere.png";
  std::filesystem::remove(out);
  ProcessResult r = run_needle_sim("render --scene " + quoted(kAssets / "scenes" / "thesis_sphere.json") + " --out " +
                                   quoted(out) + " --size 200x100");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Vulkan device:"), std::string::npos) << r.output;
  engine::RgbaImage image = engine::read_png(out);
  EXPECT_EQ(image.width, 200u);
  EXPECT_EQ(image.height, 100u);
}

TEST(CliRun, HeadlessSceneRunWritesItsPicture) {
  auto dir = test_output_dir("cli_run_scene");
  std::filesystem::remove(dir / "scene.png");
  ProcessResult r = run_needle_sim("run --headless --scene " + quoted(kAssets / "scenes" / "penetrable_sphere.json") +
                                   " --size 160x120 --out " + quoted(dir));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  EXPECT_EQ(engine::read_png(dir / "scene.png").width, 160u);
}

// The window path under Xvfb: one frame presented through the swapchain, captured before
// present, must match the headless render of the same scene (same passes, other target).
TEST(CliRun, WindowUnderXvfbPresentsWhatHeadlessRenders) {
  if (run_command("command -v xvfb-run").exit_code != 0)
    GTEST_FAIL() << "xvfb-run is not installed (tools/setup.sh installs xvfb)";
  auto dir = test_output_dir("cli_window");
  auto shot = dir / "window.png", headless = dir / "headless.png";
  std::filesystem::remove(shot);
  auto scene = quoted(kAssets / "scenes" / "thesis_sphere.json");
  ProcessResult window = run_command("NEEDLE_VALIDATION=1 xvfb-run -a -s '-screen 0 1024x768x24' " +
                                     test::needle_sim_exe().string() + " run --scene " + scene +
                                     " --size 320x240 --msaa 1 --no-hud --frames 3 --screenshot " + quoted(shot));
  ASSERT_EQ(window.exit_code, 0) << window.output;
  EXPECT_NE(window.output.find("presented 3 frames"), std::string::npos) << window.output;
  EXPECT_EQ(window.output.find("Vulkan validation"), std::string::npos) << window.output;
  ProcessResult off = run_needle_sim("render --scene " + scene + " --size 320x240 --msaa 1 --out " + quoted(headless));
  ASSERT_EQ(off.exit_code, 0) << off.output;

  engine::RgbaImage a = engine::read_png(shot), b = engine::read_png(headless);
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  // Same device, same passes: allow 2 counts per channel for format/resolve differences.
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) {
      if (std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > 2) {
        ++differing;
        break;
      }
    }
  }
  EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace needle::test
