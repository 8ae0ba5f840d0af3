// The instructor's review window as a whole under Xvfb (`needle-sim review`): its picture at the
// two supported sizes against goldens, Esc and its Quit button closing it, and one click on a row
// opening that session.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_process.hpp"
#include "engine/rgba_image.hpp"
#include "image_compare.hpp"
#include "tests/app/recorded_session.hpp"
#include "tests/support/test_paths.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

// Two sessions recorded by the scripted operators, stored again with fixed times and their
// recordings under fixed names, so that the window's picture is the same whenever it is taken:
// session 1 the penetrable sphere (good), session 2 the rigid sphere (sloppy).
class CliReviewWindow : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = process_folder(test_output_dir("cli_review_window"));
    const fs::path scratch = dir_ / "scratch" / "sessions.db";
    fs::create_directories(scratch.parent_path());
    fs::create_directories(dir_ / "db");
    db_ = dir_ / "db" / "sessions.db";
    training::SessionStore store(db_.string());
    int n = 0;
    for (const RecordedSessionSpec& spec : {RecordedSessionSpec{"penetrable_sphere", "good", "ana"},
                                            RecordedSessionSpec{"rigid_sphere", "sloppy", "ben"}}) {
      const RecordedSession s = record_session(scratch, spec);
      const training::StoredSession stored = training::SessionStore(scratch.string()).load(s.id);
      const fs::path recording = dir_ / "db" / ("session_" + std::to_string(++n) + ".nrec");
      fs::copy_file(s.recording, recording, fs::copy_options::overwrite_existing);
      const training::SessionInfo& i = stored.info;
      const int64_t id =
          store.begin_session({i.trainee, i.task, i.task_title, i.task_source, i.device, recording.string(),
                               "station-1", i.uid, "2026-03-0" + std::to_string(n) + "T10:00:00Z"});
      store.finish_session(id, s.result, "2026-03-0" + std::to_string(n) + "T10:01:00Z");
    }
  }
  static std::string review(const std::string& options) {
    return "NEEDLE_VALIDATION=1 " + needle_sim_exe().string() + " review --db " + quoted(db_) + " " + options;
  }
  // `script` (sh) on a virtual display of its own, large enough for a 1920x1080 window.
  static ProcessResult on_screen(const std::string& script) {
    static int n = 0;
    const fs::path file = dir_ / ("script_" + std::to_string(++n) + ".sh");
    std::ofstream(file) << script << "\n";
    return run_command("xvfb-run -a -s '-screen 0 1920x1200x24' sh " + quoted(file));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static inline fs::path dir_, db_;
};

// The whole window, session 1 chosen: the table, the score's breakdown in words, the metric table,
// the replay's 3D view at the session's end and the replay bar, all inside the window; the goldens
// looked at when made (tests/README.md).
TEST_F(CliReviewWindow, TheWholeWindowAt1280x720And1920x1080MatchesGoldens) {
  for (const auto& [width, height] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const fs::path shot = dir_ / ("review_" + size + ".png");
    const ProcessResult r =
        on_screen(review("--session 1 --size " + size + " --frames 8 --screenshot " + quoted(shot)));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
    EXPECT_TRUE(matches_golden(engine::read_png(shot), "review_window_" + size));
  }
}

// Esc closes the window; so does its Quit button (at the right end of the tabs' bar: 13 px text in a
// 1280x720 window, the bar 589 px wide). Each within the 60 s the script gives it.
TEST_F(CliReviewWindow, EscAndTheQuitButtonCloseIt) {
  const std::string open = review("--size 1280x720") +
                           " & app=$!; id=$(xdotool search --sync --name '^needle-sim review$' | head -1); "
                           "xdotool mousemove --window $id 300 400; sleep 3; ";
  const std::string wait =
      "; for i in $(seq 600); do kill -0 $app 2>/dev/null || break; sleep 0.1; done; "
      "if kill -0 $app 2>/dev/null; then echo STILL OPEN; kill $app; fi; wait $app; echo exit $?";
  const ProcessResult esc = on_screen(open + "xdotool key Escape" + wait);
  EXPECT_EQ(esc.output.find("STILL OPEN"), std::string::npos) << esc.output;
  EXPECT_NE(esc.output.find("exit 0"), std::string::npos) << esc.output;
  const ProcessResult quit =
      on_screen(open + "xdotool mousemove --window $id 545 17; sleep 0.5; xdotool click 1" + wait);
  EXPECT_EQ(quit.output.find("STILL OPEN"), std::string::npos) << quit.output;
  EXPECT_NE(quit.output.find("exit 0"), std::string::npos) << quit.output;
}

// One click on a row opens its session: the window opened on session 1, a click on session 2's row
// (the table's first, newest first), the pointer moved off the table; the last frame is the window
// opened on session 2 and clicked alike.
TEST_F(CliReviewWindow, OneClickOnARowOpensItsSession) {
  // Kept beside the test's output, to look at when they differ.
  const fs::path clicked = test_output_dir("cli_review_window") / "clicked.png",
                 opened = test_output_dir("cli_review_window") / "opened.png";
  const ProcessResult click =
      on_screen(review("--session 1 --size 1280x720 --frames 400 --screenshot " + quoted(clicked)) +
                " & app=$!; id=$(xdotool search --sync --name '^needle-sim review$' | head -1); "
                "sleep 2; xdotool mousemove --window $id 60 115; sleep 0.3; xdotool click 1; sleep 0.3; "
                "xdotool mousemove --window $id 900 300; wait $app");
  ASSERT_EQ(click.exit_code, 0) << click.output;
  // Opened on session 2, its row clicked the same way (the table's panel then has the focus too).
  const ProcessResult direct =
      on_screen(review("--session 2 --size 1280x720 --frames 400 --screenshot " + quoted(opened)) +
                " & app=$!; id=$(xdotool search --sync --name '^needle-sim review$' | head -1); "
                "sleep 2; xdotool mousemove --window $id 60 115; sleep 0.3; xdotool click 1; sleep 0.3; "
                "xdotool mousemove --window $id 900 300; wait $app");
  ASSERT_EQ(direct.exit_code, 0) << direct.output;
  const engine::RgbaImage a = engine::read_png(clicked), b = engine::read_png(opened);
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_LT(double(differing_pixels(a, b)), kMaxDifferingFraction * a.width * a.height)
      << "the click did not open session 2";
}

}  // namespace
}  // namespace needle::test
