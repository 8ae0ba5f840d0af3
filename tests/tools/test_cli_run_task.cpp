// `needle-sim run` headless, the README's main job: a scripted operator does the guided task on
// the simulated device; the run writes score.json (the keys other tools read), the pictures of
// its key moments and of the score panel, and a complete session in the database. The good
// script passes; the sloppy one fails.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "tests/engine/image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

nlohmann::json run_task(const std::string& operator_spec, const fs::path& dir) {
  fs::remove_all(dir);
  ProcessResult r = run_needle_sim("run --headless --size 320x240 --operator " + operator_spec +
                                   " --trainee ana --out " + quoted(dir) + " --db " + quoted(dir / "sessions.db"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  return nlohmann::json::parse(std::ifstream(dir / "score.json"));
}

TEST(CliRunTask, GoodOperatorPassesAndEverythingIsWritten) {
  const fs::path dir = test_output_dir("cli_run_task") / "good";
  nlohmann::json score = run_task("good", dir);
  for (const char* key : {"score", "passed", "metrics", "steps"}) EXPECT_TRUE(score.contains(key)) << key;
  EXPECT_TRUE(score["passed"].get<bool>()) << score.dump(2);
  for (const char* picture : {"final.png", "score_panel.png", "step_1_approach.png"}) {
    EXPECT_TRUE(fs::is_regular_file(dir / picture)) << picture;
  }
  // The task has no ultrasound probe: no ultrasound image is made.
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().rfind("ultrasound", 0), 0u) << entry.path();
  training::SessionStore store(dir / "sessions.db");
  std::vector<training::SessionInfo> sessions = store.sessions();
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_TRUE(sessions[0].complete);
  EXPECT_EQ(sessions[0].trainee, "ana");
  EXPECT_DOUBLE_EQ(sessions[0].score, score["score"].get<double>());
}

// Grey speckle (R = G = B, brighter than the panels' grey) in a share of a picture's rectangle.
double speckle_share(const engine::RgbaImage& image, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
  size_t speckle = 0, pixels = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x) {
      const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
      ++pixels;
      speckle += p[0] == p[1] && p[1] == p[2] && p[0] > 60;
    }
  return double(speckle) / double(pixels);
}

// The review window (1200 x 700, under Xvfb and the validation layer) of session 1 of the database
// in `dir`, at its end; no picture when it fails or validation speaks.
engine::RgbaImage review_screenshot(const fs::path& dir) {
  const fs::path shot = dir / "review.png";
  const ProcessResult r =
      run_command("NEEDLE_VALIDATION=1 xvfb-run -a -s '-screen 0 1280x800x24' " + test::needle_sim_exe().string() +
                  " review --size 1200x700 --frames 4 --screenshot " + quoted(shot) + " --session 1 --db " +
                  quoted(dir / "sessions.db"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  return r.exit_code == 0 ? engine::read_png(shot) : engine::RgbaImage{};
}

// A task with an ultrasound probe writes the probe's image beside each step's picture, at the
// probe's proportions: in the insert step the needle lies in the image plane, a bright line. The
// instructor's review replays the session with the image at the scrubbed time (the end: the
// needle withdrawn), top right of the 3D view.
TEST(CliRunTask, AnUltrasoundTaskWritesTheProbesImageAtEachStep) {
  const fs::path dir = test_output_dir("cli_run_task") / "ultrasound";
  fs::remove_all(dir);
  ProcessResult r = run_needle_sim("run --headless --size 320x240 --task " +
                                   quoted(source_dir() / "assets/tasks/sphere_ultrasound.json") + " --out " +
                                   quoted(dir) + " --db " + quoted(dir / "sessions.db"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  for (const char* picture :
       {"ultrasound_step_1.png", "ultrasound_step_2.png", "ultrasound_step_3.png", "ultrasound_final.png"}) {
    ASSERT_TRUE(fs::is_regular_file(dir / picture)) << picture;
  }
  const engine::RgbaImage insert = engine::read_png(dir / "ultrasound_step_2.png");
  EXPECT_EQ(insert.height, 512u);  // the image's samples; 50 mm wide by 50 mm deep
  EXPECT_EQ(insert.width, 512u);
  EXPECT_TRUE(matches_golden(insert, "ultrasound_sphere_task_insert"));

  const engine::RgbaImage review = review_screenshot(dir);
  ASSERT_EQ(review.width, 1200u);
  // The image: 0.45 of the height (315 px square) under the window's title, from the right edge.
  EXPECT_GT(speckle_share(review, 1200 - 300, 100, 1200 - 40, 300), 0.3);
}

// A layered task has no probe of its own, but its layers carry ultrasound parameters: the
// instructor's review replays its session with the image of a probe following the needle (the
// window's, as the trainee's U key opens it), at the scrubbed time (the end), top right.
TEST(CliRunTask, TheReviewOfALayeredTaskShowsTheUltrasoundImage) {
  const fs::path dir = test_output_dir("cli_run_task") / "layered_review";
  fs::remove_all(dir);
  ProcessResult r = run_needle_sim("run --headless --size 320x240 --task " +
                                   quoted(source_dir() / "assets/tasks/layered_target.json") + " --out " + quoted(dir) +
                                   " --db " + quoted(dir / "sessions.db"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const engine::RgbaImage review = review_screenshot(dir);
  ASSERT_EQ(review.width, 1200u);
  // The image: 0.45 of the height, 60 mm deep by 40 mm wide (210 px), from the right edge.
  EXPECT_GT(speckle_share(review, 1200 - 200, 100, 1200 - 40, 300), 0.3);
}

// In the window, a task with a probe opens the ultrasound window beside the 3D view: its image
// (grey speckle, R = G = B) fills the room the window keeps on the left; validation-clean.
TEST(CliRunTask, TheWindowShowsTheUltrasoundImageBesideTheView) {
  const fs::path dir = test_output_dir("cli_run_task") / "ultrasound_window";
  fs::remove_all(dir);
  const fs::path shot = dir / "window.png";
  ProcessResult r = run_command(
      "NEEDLE_VALIDATION=1 xvfb-run -a -s '-screen 0 1024x768x24' " + test::needle_sim_exe().string() + " run --task " +
      quoted(source_dir() / "assets/tasks/sphere_ultrasound.json") + " --size 640x480 --frames 4 --screenshot " +
      quoted(shot) + " --out " + quoted(dir) + " --db " + quoted(dir / "sessions.db"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  const engine::RgbaImage image = engine::read_png(shot);
  // The left third, rows 30 % to 70 %: the image's middle (0.45 of the height, at half height).
  EXPECT_GT(speckle_share(image, 20, image.height * 3 / 10, image.width / 3, image.height * 7 / 10), 1.0 / 3.0);
}

TEST(CliRunTask, SloppyOperatorFailsThePassMark) {
  nlohmann::json score = run_task("sloppy", test_output_dir("cli_run_task") / "sloppy");
  EXPECT_FALSE(score["passed"].get<bool>()) << score.dump(2);
}

// In a window the task plays in real time; closed after a few frames, long before the task ends, it
// is no session: nothing stored, its recording removed, the run says so. With --store it leaves its
// session incomplete and the database readable.
TEST(CliRunTask, WindowClosedMidTaskIsStoredOnlyWithStore) {
  const fs::path dir = test_output_dir("cli_run_task") / "window";
  fs::remove_all(dir);
  const auto run = [&](const std::string& flags) {
    return run_command("NEEDLE_VALIDATION=1 xvfb-run -a -s '-screen 0 1024x768x24' " + test::needle_sim_exe().string() +
                       " run --size 480x360 --frames 5 " + flags + " --out " + quoted(dir) + " --db " +
                       quoted(dir / "sessions.db"));
  };
  const ProcessResult look = run("");
  ASSERT_EQ(look.exit_code, 0) << look.output;
  EXPECT_NE(
      look.output.find("the session is not stored: a run with --frames is stored only with --store; its recording is "
                       "removed"),
      std::string::npos)
      << look.output;
  EXPECT_TRUE(training::SessionStore(dir / "sessions.db").sessions().empty());
  EXPECT_TRUE(fs::is_empty(dir / "recordings")) << "no recording left of a session that never happened";

  const ProcessResult kept = run("--store");
  ASSERT_EQ(kept.exit_code, 0) << kept.output;
  EXPECT_NE(kept.output.find("presented 5 frames"), std::string::npos) << kept.output;
  EXPECT_EQ(kept.output.find("Vulkan validation"), std::string::npos) << kept.output;
  training::SessionStore store(dir / "sessions.db");
  ASSERT_EQ(store.sessions().size(), 1u);
  EXPECT_FALSE(store.sessions()[0].complete);
  EXPECT_TRUE(fs::exists(store.sessions()[0].recording_path));
  EXPECT_FALSE(fs::exists(dir / "score.json"));
}

TEST(CliRunTask, UnknownOperatorAndDeviceAreClearErrors) {
  ProcessResult missing = run_needle_sim("run --headless --operator /nonexistent/script.json --out " +
                                         quoted(test_output_dir("cli_run_task") / "bad"));
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(missing.output.find("/nonexistent/script.json"), std::string::npos) << missing.output;
  EXPECT_EQ(run_needle_sim("run --headless --device mouse").exit_code, 2);
  EXPECT_EQ(run_needle_sim("run --headless --section sideways").exit_code, 2);
  // A device nobody knows is said to be unknown, with the list, not that it "needs the window".
  const ProcessResult nonsense = run_needle_sim("run --headless --device nonsense");
  EXPECT_EQ(nonsense.exit_code, 2) << nonsense.output;
  EXPECT_NE(
      nonsense.output.find("--device: device 'nonsense': unknown device (expected sim, mouse, keyboard, gamepad[:N], "
                           "falcon[:N] or replay:FILE)"),
      std::string::npos)
      << nonsense.output;
  // A script with a hand mass of 0: the error names the script and the pointer in it.
  const fs::path dir = test_output_dir("cli_run_task") / "massless";
  fs::create_directories(dir);
  std::ofstream(dir / "massless.json")
      << R"({"hand": {"mass_kg": 0, "waypoints": [{"t": 0, "p": [0.3, 0, 0.2], "dir": [1, 0, 0]}]}})";
  const ProcessResult massless = run_needle_sim(
      "run --headless --task " + quoted(source_dir() / "assets/tasks/rigid_sphere.json") + " --operator " +
      quoted(dir / "massless.json") + " --out " + quoted(dir / "out") + " --db " + quoted(dir / "s.db"));
  EXPECT_EQ(massless.exit_code, 1) << massless.output;
  EXPECT_NE(massless.output.find((dir / "massless.json").string() + ": /hand/mass_kg: must be in (0, 10] kg"),
            std::string::npos)
      << massless.output;
}

}  // namespace
}  // namespace needle::test
