// `needle-sim run` through the haptic loop: every session is recorded beside the database, and a
// recording replayed with --device replay:FILE reproduces the simulation state bit for bit and
// the score exactly. Devices that need a trainee refuse to run without a window, and a bad
// recording is an error naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "haptics/recording/session_format.hpp"
#include "tests/support/desk_plan.hpp"
#include "tests/support/test_paths.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

struct RunOutput {
  ProcessResult process;
  nlohmann::json score;
};

RunOutput run_headless(const std::string& arguments, const fs::path& out, const fs::path& db) {
  fs::remove_all(out);
  RunOutput run;
  run.process = run_needle_sim("run --headless --size 160x120 --trainee ana " + arguments + " --out " + quoted(out) +
                               " --db " + quoted(db));
  EXPECT_EQ(run.process.exit_code, 0) << run.process.output;
  EXPECT_EQ(run.process.output.find("Vulkan validation"), std::string::npos) << run.process.output;
  if (run.process.exit_code == 0) run.score = nlohmann::json::parse(std::ifstream(out / "score.json"));
  return run;
}

struct ReplayCase {
  const char* task;
  const char* operator_spec;
};

void PrintTo(const ReplayCase& c, std::ostream* os) { *os << c.task << " with the " << c.operator_spec << " operator"; }

class RunReplay : public testing::TestWithParam<ReplayCase> {};

TEST_P(RunReplay, ReplayingARecordedRunReproducesItsStateAndScore) {
  const fs::path dir =
      test_output_dir("cli_run_devices") / (std::string(GetParam().task) + "_" + GetParam().operator_spec);
  fs::remove_all(dir);
  const fs::path db = dir / "sessions.db";
  const std::string task = (test::source_dir() / "assets/tasks" / (std::string(GetParam().task) + ".json")).string();
  const RunOutput live =
      run_headless("--task " + quoted(fs::path(task)) + " --operator " + GetParam().operator_spec, dir / "live", db);
  ASSERT_TRUE(live.score.contains("recording"));
  // score.json's layered-tissue keys: the punctures in order, the metrics, each step's failure.
  ASSERT_TRUE(live.score.contains("punctures")) << live.score.dump();
  for (const char* key :
       {"punctures", "overshoot_m", "bone_contacts", "bone_peak_force_N", "redirections", "forbidden_punctures"})
    EXPECT_TRUE(live.score["metrics"].contains(key)) << key;
  for (const nlohmann::json& step : live.score["steps"]) EXPECT_TRUE(step.contains("failure")) << step.dump();
  if (std::string(GetParam().task) == "epidural") {
    ASSERT_FALSE(live.score["punctures"].empty());
    for (const char* key : {"layer", "t_s", "depth_m", "peak_force_N"})
      EXPECT_TRUE(live.score["punctures"][0].contains(key)) << key;
    EXPECT_EQ(live.score["punctures"][0]["layer"], "skin");
    EXPECT_GE(live.score["metrics"]["punctures"].get<int>(), 3);  // skin and the ligaments at least
  }
  if (std::string(GetParam().task) == "epidural" && std::string(GetParam().operator_spec) == "sloppy") {
    EXPECT_FALSE(live.score["passed"].get<bool>());
    EXPECT_GE(live.score["metrics"]["bone_contacts"].get<int>(), 1) << "the upper lamina, named in the metrics";
    EXPECT_GT(live.score["metrics"]["bone_peak_force_N"].get<double>(), 0.0);
  }
  const fs::path recording = live.score["recording"].get<std::string>();
  EXPECT_EQ(recording.parent_path(), fs::absolute(dir / "recordings"));

  const RunOutput replay =
      run_headless("--device " + quoted(fs::path("replay:" + recording.string())), dir / "replay", db);
  ASSERT_TRUE(replay.score.contains("recording"));
  nlohmann::json live_score = live.score, replay_score = replay.score;
  live_score.erase("recording");
  replay_score.erase("recording");
  EXPECT_EQ(replay_score, live_score);  // every metric, step and component, exactly

  const haptics::Session a = haptics::read_session(recording.string());
  const haptics::Session b = haptics::read_session(replay.score["recording"].get<std::string>());
  EXPECT_EQ(a.header.device, "sim");
  EXPECT_EQ(b.header.device, "replay:" + recording.string());
  EXPECT_EQ(b.header.rate_hz, a.header.rate_hz);
  ASSERT_EQ(b.records.size(), a.records.size());
  ASSERT_GT(a.records.size(), 10000u);
  size_t differing = 0;
  for (size_t k = 0; k < a.records.size(); ++k) {
    if (std::memcmp(&a.records[k].state, &b.records[k].state, sizeof a.records[k].state) != 0) ++differing;
  }
  EXPECT_EQ(differing, 0u) << "ticks whose simulation state differs between the run and its replay";

  training::SessionStore store(db);
  const std::vector<training::SessionInfo> sessions = store.sessions();  // newest first
  ASSERT_EQ(sessions.size(), 2u);
  EXPECT_EQ(sessions[1].recording_path, recording.string());
  EXPECT_EQ(sessions[1].device, std::string("sim (") + GetParam().task + "_" + GetParam().operator_spec + ")");
  EXPECT_EQ(sessions[0].device.rfind("replay of sim", 0), 0u) << sessions[0].device;
  EXPECT_TRUE(sessions[0].complete);
  EXPECT_DOUBLE_EQ(sessions[0].score, sessions[1].score);
}

INSTANTIATE_TEST_SUITE_P(Tasks, RunReplay,
                         testing::Values(ReplayCase{"penetrable_sphere", "good"}, ReplayCase{"rigid_sphere", "sloppy"},
                                         ReplayCase{"layered_target", "good"}, ReplayCase{"epidural", "good"},
                                         ReplayCase{"epidural", "sloppy"}),
                         [](const auto& info) {
                           return std::string(info.param.task) + "_" + info.param.operator_spec;
                         });

// `needle-sim run --device mouse` in a window without panels, its session and recording in `dir`.
std::string mouse_session(const fs::path& dir, const std::string& options) {
  fs::remove_all(dir);
  return test::needle_sim_exe().string() + " run --device mouse --no-hud " + options + " --out " + quoted(dir) +
         " --db " + quoted(dir / "sessions.db");
}

TEST(CliRunDevices, TraineeDevicesNeedTheWindowAndBadOptionsAreUsageErrors) {
  const fs::path dir = test_output_dir("cli_run_devices") / "usage";
  for (const char* arguments : {"--device mouse", "--device falcon", "--rate 100", "--rate 20000",
                                "--device mouse --operator good", "--scene x.json --device mouse"}) {
    ProcessResult r = run_needle_sim(std::string("run --headless ") + arguments + " --out " + quoted(dir) + " --db " +
                                     quoted(dir / "s.db"));
    EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.output;
  }
  ProcessResult window = run_needle_sim("run --headless --device mouse");
  EXPECT_NE(window.output.find("needs the window"), std::string::npos) << window.output;
}

TEST(CliRunDevices, ABadRecordingIsAnErrorNamingTheFile) {
  const fs::path dir = test_output_dir("cli_run_devices") / "bad_recording";
  fs::create_directories(dir);
  const fs::path missing = dir / "missing.nrec";
  ProcessResult r = run_needle_sim("run --headless --device " + quoted(fs::path("replay:" + missing.string())));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(missing.string()), std::string::npos) << r.output;

  // A recording without the context needle-sim run writes (another program's, or version 1).
  const fs::path bare = dir / "bare.nrec";
  const std::vector<uint8_t> header = haptics::encode_header({haptics::kSessionFormatVersion, 500.0, 0, "sim", ""});
  std::ofstream(bare, std::ios::binary)
      .write(reinterpret_cast<const char*>(header.data()), std::streamsize(header.size()));
  r = run_needle_sim("run --headless --device " + quoted(fs::path("replay:" + bare.string())));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(bare.string() + ": header: context"), std::string::npos) << r.output;

  // A replay runs its recording's own task.
  r = run_needle_sim("run --headless --task t.json --device " + quoted(fs::path("replay:" + bare.string())));
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

// The trainee's mouse end to end: xdotool moves the cursor in the window to the left, and the
// recorded needle tip comes to rest under it, in free space (docs/DEVICES.md, "Desk devices").
// No panels: over a panel the mouse belongs to the panel, and at this size they cover the view.
TEST(CliRunDevices, TheTipComesToRestUnderTheMouseCursor) {
  const fs::path dir = test_output_dir("cli_run_devices") / "mouse";
  const std::string run =
      mouse_session(dir, "--size 400x300 --frames 600 --store");  // a --frames run is stored when asked
  const fs::path log = test_output_dir("cli_run_devices") / "mouse.log";
  // Once the loop runs (its real-time line, on the first frame: a loaded machine may take seconds
  // to get there), centre the cursor, then move it 100 px left: two thirds of half the height, -6.7 cm.
  const std::string drive = "for i in \\$(seq 300); do grep -q '^real-time' " + quoted(log) +
                            " && break; sleep 0.1; done; "
                            "id=\\$(xdotool search --sync --name '^needle-sim\\$' | head -1); xdotool mousemove "
                            "--window \\$id 200 150; sleep 0.5; "
                            "xdotool mousemove --window \\$id 100 150; sleep 1";
  ProcessResult r = run_on_virtual_display(run + " > " + quoted(log) + " 2>&1 & " + drive +
                                           "; wait \\$!; rc=\\$?; cat " + quoted(log) + "; exit \\$rc");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;

  training::SessionStore store(dir / "sessions.db");
  ASSERT_EQ(store.sessions().size(), 1u);
  const training::SessionInfo session = store.sessions()[0];
  EXPECT_EQ(session.device, "mouse");
  EXPECT_FALSE(session.complete);  // closed before the task ended
  const haptics::Session recording = haptics::read_session(session.recording_path);
  ASSERT_GT(recording.records.size(), 500u) << "under half a second of 1 kHz ticks";
  EXPECT_EQ(recording.header.rate_hz, 1000.0);

  // The cursor was centred (its reading the workspace's centre), then put at (100, 150): a second
  // later the tip has come to rest under it, as the scene's camera shows it in the 400x300 window.
  size_t centred = recording.records.size();
  for (size_t k = 0; k < recording.records.size(); ++k) {
    if (recording.records[k].reading.position_m[0] == 0.0) centred = k;
  }
  ASSERT_LT(centred, recording.records.size()) << "the cursor was never centred";
  const haptics::TickSample& last = recording.records.back();
  const engine::Camera camera = engine::load_scene(source_dir() / "assets/scenes/penetrable_sphere.json").camera;
  const glm::vec3 tip(float(last.state.needle_tip_m[0]), float(last.state.needle_tip_m[1]),
                      float(last.state.needle_tip_m[2]));
  const std::optional<glm::vec2> on_screen = engine::project_to_screen(camera, {400, 300}, tip);
  ASSERT_TRUE(on_screen);
  EXPECT_NEAR(on_screen->x, 100.0, 2.0) << "the tip under the cursor, within 2 px";
  EXPECT_NEAR(on_screen->y, 150.0, 2.0);
}

// The --device values `run --help` documents, each with a test below: the help cannot offer a
// value this suite does not try.
TEST(CliRunDevices, TheHelpListsExactlyTheDevicesTestedHere) {
  const ProcessResult help = run_needle_sim("run --help");
  ASSERT_EQ(help.exit_code, 0) << help.output;
  EXPECT_NE(help.output.find("--device sim|mouse|keyboard|gamepad[:N]|falcon[:N]|replay:FILE"), std::string::npos)
      << help.output;
}

// Headless, a device a trainee moves is refused as a usage error saying it needs the window,
// before anything is stored; an index out of range or a replay without its file is refused too.
TEST(CliRunDevices, EveryTraineeDeviceIsRefusedHeadlessSayingItNeedsTheWindow) {
  const fs::path dir = test_output_dir("cli_run_devices") / "headless_refusals";
  fs::remove_all(dir);
  for (const char* device : {"mouse", "keyboard", "gamepad", "gamepad:1", "falcon", "falcon:1"}) {
    const ProcessResult r = run_needle_sim(std::string("run --headless --device ") + device + " --out " + quoted(dir) +
                                           " --db " + quoted(dir / "s.db"));
    EXPECT_EQ(r.exit_code, 2) << device << "\n" << r.output;
    EXPECT_NE(
        r.output.find(std::string("--device ") + device + ": a trainee's device needs the window (drop --headless)"),
        std::string::npos)
        << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "s.db")) << "nothing stored for a refused run";
  struct Case {
    const char* device;
    const char* says;
  };
  for (const Case& c :
       {Case{"gamepad:16", "an index from 0 to 15"}, Case{"falcon:x", "an index from 0 to 15"},
        Case{"replay:", "expected a recording file after replay:"}, Case{"keyboard:1", "keyboard takes nothing"},
        Case{"sim:x.json", "a task's sim runs the task's own scenario"}}) {
    const ProcessResult r = run_needle_sim(std::string("run --headless --device ") + c.device);
    EXPECT_EQ(r.exit_code, 2) << c.device << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << r.output;
  }
}

// `run --device keyboard ARGUMENTS` in the window for `frames` frames, xdotool putting the pointer
// over it (without a window manager the keys go to the window under it) and then running `keys`;
// the session's recording, the store having kept (--store) one session on the keyboard.
haptics::Session keyboard_session_in_window(const fs::path& dir, const std::string& arguments, int frames,
                                            const std::string& keys) {
  fs::remove_all(dir);
  const std::string run = test::needle_sim_exe().string() + " run --device keyboard " + arguments +
                          " --no-hud --size 400x300 --frames " + std::to_string(frames) + " --store --out " +
                          quoted(dir) + " --db " + quoted(dir / "sessions.db");
  const std::string drive =
      "id=\\$(xdotool search --sync --name '^needle-sim\\$' | head -1); xdotool mousemove --window \\$id 200 150; "
      "sleep 1; " +
      keys;
  const ProcessResult r = run_on_virtual_display(run + " & " + drive + "; wait");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  training::SessionStore store(dir / "sessions.db");
  if (store.sessions().size() != 1u) {
    ADD_FAILURE() << "expected one session: " << r.output;
    return {};
  }
  EXPECT_EQ(store.sessions()[0].device, "keyboard");
  return haptics::read_session(store.sessions()[0].recording_path);
}

// `run --device keyboard` in the window: xdotool's key presses reach the device, one step of the
// pose a press (1 mm, 1 degree), as the recording shows. No panels: the keys are the device's.
TEST(CliRunDevices, TheKeyboardMovesTheNeedleInTheWindow) {
  const fs::path dir = test_output_dir("cli_run_devices") / "keyboard";
  const haptics::Session recording =
      keyboard_session_in_window(dir, "", 600, "xdotool key --delay 100 Left Left Right w w w d; sleep 1");
  EXPECT_EQ(recording.header.device, "keyboard");
  ASSERT_FALSE(recording.records.empty());
  const haptics::DeviceReading& last = recording.records.back().reading;
  // W pushes in along the needle, 1 mm a press, from the reach's centre at 0.1 m deep: along its axis
  // in the newest state, which in free space is its start direction (the wrist not yet turned) to
  // within the coupling's lag, under 0.1 deg here: 3 mm along it within 5 um of 3 mm along the start.
  const DeskStart start = desk_start(source_dir() / "assets/tasks/penetrable_sphere.json", "keyboard", dir / "plan");
  const haptics::NeedleDirection along = app::needle_direction(start, haptics::DeskPose{});
  const double* d = along.device;
  EXPECT_NEAR(last.position_m[0], -0.001 + 0.003 * d[0], 5e-6) << "Left, Left, Right, and W along the needle";
  EXPECT_NEAR(last.position_m[1], 0.003 * d[1], 5e-6);
  EXPECT_NEAR(last.position_m[2], 0.1 + 0.003 * d[2], 5e-6) << "W pushes in along the needle";
  EXPECT_NEAR(last.joint_rad[0], 3.141592653589793 / 180.0, 1e-9) << "D swings";
}

// `run --device keyboard` on the epidural task, with its syringe, in the window: the space bar held
// (xdotool keydown, 1.5 s, keyup) presses the plunger with the force PlungerMapping makes of it,
// rising to its hold and let go, as the recording shows tick by tick.
TEST(CliRunDevices, TheSpaceBarPressesTheSyringesPlunger) {
  const haptics::Session recording = keyboard_session_in_window(
      test_output_dir("cli_run_devices") / "space_bar", "--task " + quoted(source_dir() / "assets/tasks/epidural.json"),
      1600, "xdotool keydown space; sleep 1.5; xdotool keyup space; sleep 1");
  ASSERT_FALSE(recording.records.empty());
  double most = 0.0;
  bool rising = false;
  for (const haptics::TickSample& s : recording.records) {
    EXPECT_EQ(s.reading.plunger_input, uint32_t(haptics::PlungerInput::kThumbForce));
    EXPECT_EQ(s.state.syringe.thumb_force_N, s.reading.plunger_force_n);
    most = std::max(most, s.reading.plunger_force_n);
    rising = rising || (s.reading.plunger_force_n > 0.0 && s.reading.plunger_force_n < 6.0);
  }
  EXPECT_DOUBLE_EQ(most, 12.0) << "held past the rise's second: the key's hold";
  EXPECT_TRUE(rising) << "the force rises while the key is held";
  EXPECT_EQ(recording.records.back().reading.plunger_force_n, 0.0) << "let go with the key";
  EXPECT_GT(recording.records.back().state.syringe.travel_m, 0.0) << "the needle in the open: the saline left";
}

// `run --device DEVICE` for each device in one virtual display (one xvfb-run: its clean-up can
// fail when many run at once), each command's exit code after its output as "exit N".
std::string run_each_in_the_window(const std::vector<std::string>& devices, const fs::path& dir) {
  std::string script;
  for (const std::string& device : devices)
    script += test::needle_sim_exe().string() + " run --device " + device + " --size 200x150 --frames 5 --out " +
              quoted(dir) + " --db " + quoted(dir / "sessions.db") + "; echo exit \\$?; ";
  return run_on_virtual_display(script).output;
}

// The output has a line holding `says` from a command that exited with 1.
bool refused_with(const std::string& output, const std::string& says) {
  const size_t at = output.find(says);
  return at != std::string::npos && output.find("\nexit 1\n", at) == output.find('\n', at);
}

// `run --device gamepad[:N]` in the window with no pad present (the virtual display has none):
// refused before a session begins, naming what is missing.
TEST(CliRunDevices, AGamepadThatIsNotThereIsRefusedNamingIt) {
  const fs::path dir = test_output_dir("cli_run_devices") / "gamepad";
  fs::remove_all(dir);
  const std::string output = run_each_in_the_window({"gamepad", "gamepad:3"}, dir);
  EXPECT_TRUE(refused_with(
      output, "needle-sim run: error: gamepad: none connected (no gamepad with a standard mapping is present)"))
      << output;
  EXPECT_TRUE(refused_with(output, "needle-sim run: error: gamepad:3: no such gamepad connected")) << output;
  EXPECT_FALSE(fs::exists(dir / "sessions.db")) << "no session begun for a device that is not there";
}

// `run --device falcon[:N]` in the window with no Falcon on the bus: refused naming the device,
// before a session begins.
TEST(CliRunDevices, AFalconThatIsNotThereIsRefusedNamingIt) {
  const fs::path dir = test_output_dir("cli_run_devices") / "falcon";
  fs::remove_all(dir);
  const std::string output = run_each_in_the_window({"falcon", "falcon:1"}, dir);
  const size_t second = output.find("exit ");
  ASSERT_NE(second, std::string::npos) << output;
  EXPECT_TRUE(refused_with(output.substr(0, second + 7), "needle-sim run: error: falcon: ")) << "falcon\n" << output;
  EXPECT_TRUE(refused_with(output.substr(second), "needle-sim run: error: falcon: ")) << "falcon:1\n" << output;
  EXPECT_FALSE(fs::exists(dir / "sessions.db"));
}

// `run --device replay:FILE` in the window: the recording plays in real time, closed after a few
// frames its session stays incomplete.
TEST(CliRunDevices, AReplayPlaysInTheWindow) {
  const fs::path dir = test_output_dir("cli_run_devices") / "replay_window";
  fs::remove_all(dir);
  const RunOutput live = run_headless("--task " + quoted(source_dir() / "assets/tasks/rigid_sphere.json"), dir / "live",
                                      dir / "sessions.db");
  ASSERT_TRUE(live.score.contains("recording"));
  const std::string recording = live.score["recording"].get<std::string>();
  const ProcessResult r = run_on_virtual_display(
      test::needle_sim_exe().string() + " run --device " + quoted(fs::path("replay:" + recording)) +
      " --size 200x150 --frames 5 --store --out " + quoted(dir / "replay") + " --db " + quoted(dir / "sessions.db"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("presented 5 frames"), std::string::npos) << r.output;
  training::SessionStore store(dir / "sessions.db");
  ASSERT_EQ(store.sessions().size(), 2u);
  EXPECT_EQ(store.sessions()[0].device.rfind("replay of sim", 0), 0u) << store.sessions()[0].device;
  EXPECT_FALSE(store.sessions()[0].complete) << "closed before its end";
}

// A run killed mid-task (SIGKILL: no destructor, no last pass) leaves an incomplete session, a
// readable database and a recording whose every tick up to the last flushed pass is intact. Stored
// from its start (--store): killed before its first step ended it would otherwise not be stored.
TEST(CliRunDevices, AKilledRunLeavesItsRecordingAndAnIncompleteSession) {
  const fs::path dir = test_output_dir("cli_run_devices") / "killed";
  const std::string run = mouse_session(dir, "--size 200x150 --store");
  // Kill once the recording holds over a second of ticks (10 s at most).
  const std::string kill_later = "for i in \\$(seq 200); do [ \\$(cat " + quoted(dir) +
                                 "/recordings/*.nrec 2>/dev/null | wc -c) -gt 700000 ] && break; sleep 0.05; done; "
                                 "kill -9 \\$pid";
  ProcessResult r = run_on_virtual_display(run + " & pid=\\$!; " + kill_later + "; wait \\$pid; echo killed \\$?");
  EXPECT_NE(r.output.find("killed 137"), std::string::npos) << r.output;  // 128 + SIGKILL

  training::SessionStore store(dir / "sessions.db");
  ASSERT_EQ(store.sessions().size(), 1u);
  EXPECT_FALSE(store.sessions()[0].complete);
  const haptics::Session recording = haptics::read_session(store.sessions()[0].recording_path);
  // Cut after its last whole block: all of the over 700 kB it held but a block cut short, if any.
  EXPECT_FALSE(recording.end.closed);
  ASSERT_GE(recording.end.whole_bytes + recording.end.trailing_bytes, 700000u);
  EXPECT_LT(recording.end.trailing_bytes, haptics::kBlockHeaderBytes + 256 * haptics::session_record_bytes());
  ASSERT_GT(recording.records.size(), 500u);
  const uint64_t first = recording.records[0].tick;  // the loop counts its idle ticks before the start too
  for (size_t k = 0; k < recording.records.size(); ++k) ASSERT_EQ(recording.records[k].tick, first + k) << "a gap";
}

}  // namespace
}  // namespace needle::test
