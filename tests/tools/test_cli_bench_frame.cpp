// `needle-sim bench frame --json`: the row keys other tools read, a window row under a virtual
// display, and what it says when there is no display.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace needle::test {
namespace {

TEST(CliBenchFrame, OffscreenRowsCarryTheContractKeysAndEveryPass) {
  const auto json_path = test_output_dir("cli_bench_frame") / "offscreen.json";
  ProcessResult r = run_needle_sim(
      "bench frame --contents tissue:20 --sizes 64x48 --targets offscreen --frames 16 "
      "--warmup 2 --json " +
      quoted(json_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  const nlohmann::json rows = nlohmann::json::parse(std::ifstream(json_path));
  ASSERT_EQ(rows.size(), 1u);
  const nlohmann::json& row = rows[0];
  for (const char* key : {"size", "target", "frame_ms_median", "frame_ms_p95", "frame_ms_p99", "passes"}) {
    EXPECT_TRUE(row.contains(key)) << key;
  }
  EXPECT_EQ(row["size"], "64x48");
  EXPECT_EQ(row["target"], "offscreen");
  EXPECT_LE(row["frame_ms_median"].get<double>(), row["frame_ms_p95"].get<double>());
  // lavapipe writes timestamps: each pass has its CPU and its device time.
  for (const char* pass : {"scene_record_cpu", "ui_record_cpu", "ui_build_cpu", "acquire_wait", "present_wait",
                           "scene_device", "ui_device", "deformation_device"}) {
    EXPECT_TRUE(row["passes"].contains(pass)) << pass;
  }
}

TEST(CliBenchFrame, TheViewsRowDrawsTheSectionAndTheUltrasoundValidationClean) {
  const auto json_path = test_output_dir("cli_bench_frame") / "views.json";
  ProcessResult r = run_needle_sim(
      "bench frame --contents sphere_ultrasound --sizes 320x240 --targets offscreen --frames 10 "
      "--warmup 2 --views section,ultrasound --variants 'sweep=1;default' --json " +
      quoted(json_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  const nlohmann::json rows = nlohmann::json::parse(std::ifstream(json_path));
  ASSERT_EQ(rows.size(), 2u) << "the whole image every frame, and the window's sweep, in turn";
  for (const nlohmann::json& row : rows) {
    EXPECT_EQ(row["views"], "section,ultrasound");
    EXPECT_TRUE(row["passes"].contains("deformation_device"));  // the ultrasound's passes are recorded there
  }
  // The ultrasound images a task's layers: a bare tissue has none; an unknown view is refused.
  EXPECT_EQ(run_needle_sim("bench frame --contents tissue:20 --targets offscreen --views ultrasound").exit_code, 2);
  EXPECT_EQ(run_needle_sim("bench frame --targets offscreen --views xray").exit_code, 2);
  EXPECT_EQ(run_needle_sim("bench frame --targets offscreen --variants sweep=0").exit_code, 2);
}

TEST(CliBenchFrame, VariantsTakeTurnsInOneRowGroupAndTheScaledOneTimesItsUpscale) {
  const auto json_path = test_output_dir("cli_bench_frame") / "variants.json";
  ProcessResult r = run_needle_sim(
      "bench frame --contents tissue:20 --sizes 64x48 --targets offscreen --frames 10 "
      "--warmup 2 --variants 'scale=1;scale=0.5;default' --render-scale 0.7 --json " +
      quoted(json_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  const nlohmann::json rows = nlohmann::json::parse(std::ifstream(json_path));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0]["variant"], "scale=1");
  EXPECT_DOUBLE_EQ(rows[0]["render_scale"].get<double>(), 1.0);
  EXPECT_FALSE(rows[0]["passes"].contains("upscale_device"));
  EXPECT_NEAR(rows[1]["render_scale"].get<double>(), 0.5, 1e-6);
  EXPECT_TRUE(rows[1]["passes"].contains("upscale_device"));
  EXPECT_NEAR(rows[2]["render_scale"].get<double>(), 0.7, 1e-6) << "default: the frame's own, here --render-scale";
  for (const char* bad : {"--render-scale 0.1", "--render-scale fast", "--variants scale=2", "--variants tint=red"})
    EXPECT_EQ(run_needle_sim(std::string("bench frame --targets offscreen ") + bad).exit_code, 2) << bad;
  EXPECT_EQ(run_needle_sim("run --render-scale 1.5").exit_code, 2);
}

TEST(CliBenchFrame, WindowRowsDrawTheTaskInAWindow) {
  const auto json_path = test_output_dir("cli_bench_frame") / "window.json";
  ProcessResult r = run_on_virtual_display(test::needle_sim_exe().string() +
                                           " bench frame --contents penetrable_sphere --sizes 320x240 --targets window "
                                           "--frames 16 --warmup 2 --json " +
                                           quoted(json_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  const nlohmann::json rows = nlohmann::json::parse(std::ifstream(json_path));
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0]["target"], "window");
  EXPECT_EQ(rows[0]["content"], "penetrable_sphere");
  EXPECT_GT(rows[0]["passes"]["present_wait"].get<double>(), 0.0);
}

TEST(CliBenchFrame, WithoutADisplayTheWindowRowsSaySo) {
  ProcessResult r =
      run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + test::needle_sim_exe().string() + " bench frame --frames 10");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--targets offscreen"), std::string::npos) << r.output;
  EXPECT_EQ(run_needle_sim("bench frame --views ultrasound").exit_code, 2);
}

}  // namespace
}  // namespace needle::test
