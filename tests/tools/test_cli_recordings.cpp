// Recordings an instructor can trust, through needle-sim as a user runs it: a damaged recording is
// refused by replay and report naming the file and the byte offset, an edited header too; a cut
// one replays up to its cut and is stored incomplete, saying so; an empty one is an error; a
// replay scores the task as it was recorded, not as its file is now; what is not a recording is
// refused at once. Offsets come from the format's layout (haptics/recording/session_format.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_process.hpp"
#include "haptics/recording/session_format.hpp"
#include "haptics/recording/session_recorder.hpp"
#include "tests/support/process_folder.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

struct RunOutput {
  ProcessResult process;
  fs::path out;
  std::optional<nlohmann::json> score;  // OUT/score.json when there is one
};

RunOutput run(const std::string& arguments, const fs::path& out, const fs::path& db) {
  RunOutput r{run_needle_sim("run --headless --size 160x120 --trainee ana " + arguments + " --out " + quoted(out) +
                             " --db " + quoted(db)),
              out, std::nullopt};
  if (fs::exists(out / "score.json")) r.score = nlohmann::json::parse(std::ifstream(out / "score.json"));
  return r;
}

RunOutput replay(const fs::path& recording, const fs::path& out, const fs::path& db, const std::string& options = "") {
  return run("--device " + quoted(fs::path("replay:" + recording.string())) + options, out, db);
}

// A headless run of `task` (a shipped one's name, or a file) by `op`; its recording.
fs::path live_run(const fs::path& dir, const std::string& task, const std::string& op) {
  const fs::path file =
      task.find('/') == std::string::npos ? source_dir() / "assets/tasks" / (task + ".json") : fs::path(task);
  const RunOutput live = run("--task " + quoted(file) + " --operator " + op, dir / "live", dir / "sessions.db");
  EXPECT_EQ(live.process.exit_code, 0) << live.process.output;
  return live.score ? fs::path((*live.score)["recording"].get<std::string>()) : fs::path();
}

// Where block `k` starts in a headless run's recording: the run drains the ring every tick, so
// each block holds one record.
uint64_t block_offset(const std::vector<uint8_t>& recording, uint64_t k) {
  uint32_t header_bytes = 0;
  std::memcpy(&header_bytes, &recording[12], 4);
  return header_bytes + k * (haptics::kBlockHeaderBytes + haptics::session_record_bytes());
}

bool says(const ProcessResult& r, const std::string& text) { return r.output.find(text) != std::string::npos; }

TEST(CliRecordings, DamageIsRefusedByReplayAndReportNamingTheFileAndTheOffset) {
  const fs::path dir = process_folder(test_output_dir("cli_recordings") / "damage");
  const fs::path recording = live_run(dir, "rigid_sphere", "sloppy");
  ASSERT_FALSE(recording.empty());
  const std::vector<uint8_t> good = file_bytes(recording);
  const uint64_t block = block_offset(good, 3000);
  const fs::path copy = dir / "copy.nrec";
  const std::string damaged =
      copy.string() + ": block at byte " + std::to_string(block) + ": records checksum mismatch (damaged)";

  std::vector<uint8_t> bad = good;  // 0xFF over a record
  std::fill(bad.begin() + long(block) + 30, bad.begin() + long(block) + 300, 0xFF);
  write_bytes(copy, bad);
  RunOutput r = replay(copy, dir / "ff", dir / "sessions.db");
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  EXPECT_TRUE(says(r.process, damaged)) << r.process.output;
  EXPECT_FALSE(r.score);

  bad = good;  // a NaN over a recorded double
  const double nan = std::nan("");
  // reading.position_m[0]: after tick, three times, sequence (8 bytes each) and five u32 flags
  std::memcpy(&bad[block + haptics::kBlockHeaderBytes + 60], &nan, 8);
  write_bytes(copy, bad);
  r = replay(copy, dir / "nan", dir / "sessions.db");
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  EXPECT_TRUE(says(r.process, damaged)) << r.process.output;

  bad = good;  // the rate, 500 Hz made 1000 Hz
  const double rate = 1000.0;
  std::memcpy(&bad[24], &rate, 8);
  write_bytes(copy, bad);
  r = replay(copy, dir / "rate", dir / "sessions.db");
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  EXPECT_TRUE(says(r.process, copy.string() + ": header: checksum mismatch: the header was changed or damaged"))
      << r.process.output;

  // Nothing refused was stored: the database holds the live session alone.
  training::SessionStore store(dir / "sessions.db");
  EXPECT_EQ(store.sessions().size(), 1u);

  // The report of the live session whose recording was damaged since: the metrics, then exit 1.
  bad = good;
  bad[block + haptics::kBlockHeaderBytes + 100] ^= 0x01;
  write_bytes(recording, bad);
  const ProcessResult report =
      run_needle_sim("report --session 1 --db " + quoted(dir / "sessions.db") + " --out " + quoted(dir / "report"));
  EXPECT_EQ(report.exit_code, 1) << report.output;
  EXPECT_TRUE(says(report, recording.string() + ": block at byte " + std::to_string(block) +
                               ": records checksum mismatch (damaged)"))
      << report.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "report" / "session_1.json"));
  EXPECT_FALSE(fs::exists(dir / "report" / "plot_force.png"));
}

TEST(CliRecordings, ACutRecordingReplaysIncompleteAndAnEmptyOneIsAnError) {
  const fs::path dir = process_folder(test_output_dir("cli_recordings") / "cut");
  const fs::path recording = live_run(dir, "rigid_sphere", "good");
  ASSERT_FALSE(recording.empty());
  const std::vector<uint8_t> good = file_bytes(recording);
  const uint64_t cut = block_offset(good, 2000) + 100;  // in tick 2000's block
  const fs::path cut_file = dir / "cut.nrec";
  write_bytes(cut_file, {good.begin(), good.begin() + long(cut)});
  // Cut 2 s in, before the first step (the touch) ended: stored only when asked (--store).
  RunOutput r = replay(cut_file, dir / "cut", dir / "sessions.db", " --store");
  EXPECT_EQ(r.process.exit_code, 0) << r.process.output;
  EXPECT_TRUE(says(r.process, "note: " + cut_file.string() + ": cut at byte " +
                                  std::to_string(block_offset(good, 2000)) + " after 2000 ticks"))
      << r.process.output;
  EXPECT_TRUE(says(r.process, "stays incomplete")) << r.process.output;
  EXPECT_FALSE(r.score) << "a cut replay has no score";
  {
    training::SessionStore store(dir / "sessions.db");
    const std::vector<training::SessionInfo> sessions = store.sessions();  // newest first
    ASSERT_EQ(sessions.size(), 2u);
    EXPECT_TRUE(sessions[1].complete);
    EXPECT_FALSE(sessions[0].complete);
    // The replay's own recording holds the 2000 ticks it ran, closed as a session that did not end.
    const haptics::Session again = haptics::read_session(sessions[0].recording_path);
    EXPECT_EQ(again.records.size(), 2000u);
    EXPECT_TRUE(again.end.closed);
    EXPECT_FALSE(again.end.ran_to_end);
  }

  // The report of the live session once its recording is cut: the plots up to the cut, said.
  write_bytes(recording, {good.begin(), good.begin() + long(cut)});
  const ProcessResult report =
      run_needle_sim("report --session 1 --db " + quoted(dir / "sessions.db") + " --out " + quoted(dir / "report"));
  EXPECT_EQ(report.exit_code, 0) << report.output;
  EXPECT_TRUE(says(report, "note: " + recording.string() + ": cut at byte")) << report.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "report" / "plot_force.png"));

  // A header and no tick, as a run killed in its first tick leaves: nothing to replay.
  write_bytes(cut_file, {good.begin(), good.begin() + long(block_offset(good, 0))});
  r = replay(cut_file, dir / "empty", dir / "sessions.db");
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  EXPECT_TRUE(says(r.process, cut_file.string() + ": no ticks recorded (its run stopped before its first tick)"))
      << r.process.output;
  EXPECT_FALSE(r.score);
}

TEST(CliRecordings, AReplayScoresTheTaskAsRecordedNotAsItsFileIsNow) {
  const fs::path dir = process_folder(test_output_dir("cli_recordings") / "task");
  // The shipped rigid task, its scene and scenario made absolute so the copy can live here.
  nlohmann::json task = nlohmann::json::parse(std::ifstream(source_dir() / "assets/tasks/rigid_sphere.json"));
  for (const char* key : {"scene", "scenario"})
    task[key] = (source_dir() / "assets/tasks" / task[key].get<std::string>()).lexically_normal().string();
  const fs::path task_file = dir / "rigid_copy.json";
  std::ofstream(task_file) << task.dump(2);
  fs::copy_file(source_dir() / "assets/tasks/rigid_sphere_good.json", dir / "good.json");
  const fs::path recording = live_run(dir, task_file.string(), (dir / "good.json").string());
  ASSERT_FALSE(recording.empty());
  const nlohmann::json live = nlohmann::json::parse(std::ifstream(dir / "live" / "score.json"));
  ASSERT_TRUE(live["passed"].get<bool>());

  task["scoring"]["pass_score"] = 100.0;  // would fail every session
  std::ofstream(task_file) << task.dump(2);
  const RunOutput r = replay(recording, dir / "replay", dir / "sessions.db");
  ASSERT_EQ(r.process.exit_code, 0) << r.process.output;
  EXPECT_TRUE(says(r.process, "note: " + task_file.string() +
                                  " has changed since the recording: the replay runs the task "
                                  "as it was recorded"))
      << r.process.output;
  ASSERT_TRUE(r.score);
  nlohmann::json a = live, b = *r.score;
  a.erase("recording"), b.erase("recording");
  EXPECT_EQ(a, b);
}

// `from` written again as `to` through the recorder (checksums and end mark as a run writes them),
// with `edit` applied to its context's scenario gains.
void rewrite_gains(const fs::path& from, const fs::path& to, const std::function<void(nlohmann::json&)>& edit) {
  haptics::Session session = haptics::read_session(from.string());
  nlohmann::json context = nlohmann::json::parse(session.header.context);
  edit(context["scenario"]["gains"]);
  session.header.context = context.dump();
  haptics::SpscRing<haptics::TickSample> ring(session.records.size() + 1);
  haptics::SessionRecorder recorder(to.string(), session.header, ring);
  for (const haptics::TickSample& record : session.records) ASSERT_TRUE(ring.push(record));
  recorder.stop(session.end.ran_to_end);
  ASSERT_EQ(recorder.error(), "");
}

// A recording of a live run of the shipped task `task` (its good script) whose scenario's gains are
// edited by `edit` first, and the run's score without its "recording" key.
struct LiveRecording {
  fs::path recording;
  nlohmann::json score;
};

LiveRecording record_under_gains(const fs::path& dir, const std::string& task_name,
                                 const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json task = nlohmann::json::parse(std::ifstream(source_dir() / "assets/tasks" / (task_name + ".json")));
  const fs::path scenario_file =
      (source_dir() / "assets/tasks" / task["scenario"].get<std::string>()).lexically_normal();
  nlohmann::json scenario = nlohmann::json::parse(std::ifstream(scenario_file));
  for (const char* key : {"master_urdf", "virtual_urdf"})
    scenario[key] = (scenario_file.parent_path() / scenario[key].get<std::string>()).lexically_normal().string();
  if (scenario.contains("tissue") &&
      scenario["tissue"].contains("layers"))  // parameter files, from the scenario's folder
    for (nlohmann::json& layer : scenario["tissue"]["layers"])
      if (layer.contains("parameters") && layer["parameters"].is_string())
        layer["parameters"] =
            (scenario_file.parent_path() / layer["parameters"].get<std::string>()).lexically_normal().string();
  edit(scenario["gains"]);
  std::ofstream(dir / "scenario.json") << scenario.dump(2);
  task["scene"] = (source_dir() / "assets/tasks" / task["scene"].get<std::string>()).lexically_normal().string();
  task["scenario"] = (dir / "scenario.json").string();
  const fs::path task_file = dir / "task.json";
  std::ofstream(task_file) << task.dump(2);
  fs::copy_file(source_dir() / "assets/tasks" / (task_name + "_good.json"), dir / "good.json",
                fs::copy_options::overwrite_existing);
  LiveRecording out;
  out.recording = live_run(dir, task_file.string(), (dir / "good.json").string());
  if (out.recording.empty()) return out;
  out.score = nlohmann::json::parse(std::ifstream(dir / "live" / "score.json"));
  out.score.erase("recording");
  return out;
}

// The replay of `recording` with `edit` applied to its context's gains.
RunOutput replay_with_gains(const fs::path& dir, const fs::path& recording, const std::string& name,
                            const std::function<void(nlohmann::json&)>& edit) {
  rewrite_gains(recording, dir / (name + ".rec"), edit);
  const RunOutput r = replay(dir / (name + ".rec"), dir / name, dir / "sessions.db");
  EXPECT_EQ(r.process.exit_code, 0) << r.process.output;
  return r;
}

nlohmann::json without_recording(const std::optional<nlohmann::json>& score) {
  if (!score) return nullptr;
  nlohmann::json s = *score;
  s.erase("recording");
  return s;
}

// Whether two recordings sent the device the same command at every tick.
bool same_commands(const fs::path& a, const fs::path& b) {
  const haptics::Session x = haptics::read_session(a.string()), y = haptics::read_session(b.string());
  if (x.records.size() != y.records.size()) return false;
  for (size_t i = 0; i < x.records.size(); ++i) {
    const haptics::DeviceCommand &p = x.records[i].command, &q = y.records[i].command;
    if (!std::equal(std::begin(p.torque_nm), std::end(p.torque_nm), std::begin(q.torque_nm)) ||
        !std::equal(std::begin(p.force_n), std::end(p.force_n), std::begin(q.force_n)))
      return false;
  }
  return true;
}

// A recording made before the tool law existed has no "law" in its context's gains: it replays
// under the thesis law it was made with and scores as it did then. Made here as such a recording
// was: a run under the thesis law whose context then loses the key. The control: the same
// recording naming the tool law scores otherwise, so the replay does depend on the law.
TEST(CliRecordings, ARecordingMadeBeforeTheToolLawReplaysUnderTheThesisLaw) {
  const fs::path dir = process_folder(test_output_dir("cli_recordings") / "old_law");
  const LiveRecording live = record_under_gains(dir, "rigid_sphere", [](nlohmann::json& g) { g["law"] = "thesis"; });
  ASSERT_FALSE(live.recording.empty());
  const RunOutput old =
      replay_with_gains(dir, live.recording, "before_the_tool_law", [](nlohmann::json& g) { g.erase("law"); });
  EXPECT_EQ(without_recording(old.score), live.score);
  const RunOutput tool =
      replay_with_gains(dir, live.recording, "named_tool", [](nlohmann::json& g) { g["law"] = "tool"; });
  EXPECT_NE(without_recording(tool.score)["metrics"], live.score["metrics"]);
}

// A tool-law recording made before one of the tool law's springs names no `key` in its
// gains: it replays without the spring, i.e. the replay commands the device as the run did, tick for
// tick, and scores as it did. Made here as such a recording was: a run of `task` with the spring at 0
// whose context then loses the key. The control: the same recording naming `stiffness` commands the
// device otherwise. Returns the control's score.
nlohmann::json expect_replayed_without_the_spring(const std::string& folder, const std::string& task,
                                                  const std::string& key, double stiffness, LiveRecording& live) {
  const fs::path dir = process_folder(test_output_dir("cli_recordings") / folder);
  live = record_under_gains(dir, task, [&](nlohmann::json& g) {
    g["law"] = "tool";
    g[key] = 0.0;
  });
  if (live.recording.empty()) {
    ADD_FAILURE() << task << ": no recording";
    return nullptr;
  }
  const RunOutput old =
      replay_with_gains(dir, live.recording, "before_the_spring", [&](nlohmann::json& g) { g.erase(key); });
  if (!old.score) {
    ADD_FAILURE() << task << ": the replay without " << key << " scored nothing";
    return nullptr;
  }
  EXPECT_EQ(without_recording(old.score), live.score) << key;
  EXPECT_TRUE(same_commands(live.recording, (*old.score)["recording"].get<std::string>())) << key;
  const RunOutput spring =
      replay_with_gains(dir, live.recording, "named_spring", [&](nlohmann::json& g) { g[key] = stiffness; });
  if (!spring.score) {
    ADD_FAILURE() << task << ": the replay with " << key << " scored nothing";
    return nullptr;
  }
  EXPECT_FALSE(same_commands(live.recording, (*spring.score)["recording"].get<std::string>())) << key;
  return without_recording(spring.score);
}

// The master's lateral spring, in the sphere's tissue: it acts on the master only, so the score, made
// from the recorded hand and the replayed virtual needle, is the same with it, but for the time the
// master's command met the device's force limit, which the spring's pull changes.
TEST(CliRecordings, AToolLawRecordingMadeBeforeTheLateralSpringReplaysWithoutIt) {
  LiveRecording live;
  nlohmann::json spring =
      expect_replayed_without_the_spring("old_spring", "penetrable_sphere", "lateral_stiffness_N_per_m", 300.0, live);
  ASSERT_FALSE(spring.is_null());
  nlohmann::json live_metrics = live.score["metrics"];
  spring["metrics"].erase("force_limited_s");
  live_metrics.erase("force_limited_s");
  EXPECT_EQ(spring["metrics"], live_metrics);
}

// The spring along the needle, through the layered block's skin, fat and muscle (the sphere's tissue
// has no axial mechanics): it pulls the virtual needle too, so the replay's needle moves otherwise.
TEST(CliRecordings, AToolLawRecordingMadeBeforeTheAxialSpringReplaysWithoutIt) {
  LiveRecording live;
  const nlohmann::json spring =
      expect_replayed_without_the_spring("old_axial_spring", "layered_target", "axial_stiffness_N_per_m", 3000.0, live);
  ASSERT_FALSE(spring.is_null());
  EXPECT_NE(spring["metrics"], live.score["metrics"]);
}

TEST(CliRecordings, WhatIsNotARecordingIsRefusedAtOnce) {
  const fs::path dir = process_folder(test_output_dir("cli_recordings") / "not");
  const auto t0 = std::chrono::steady_clock::now();
  RunOutput r = replay("/dev/zero", dir / "zero", dir / "sessions.db");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  EXPECT_TRUE(says(r.process, "/dev/zero: not a regular file (a device or a pipe), not a recording"))
      << r.process.output;

  r = replay(dir, dir / "folder", dir / "sessions.db");
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  EXPECT_TRUE(says(r.process, dir.string() + ": is a folder, not a recording")) << r.process.output;

  // Format version 2 (no checksums, no task text): reviewable, not replayable.
  std::vector<uint8_t> v2 = {'N', 'E', 'E', 'D', 'L', 'R', 'E', 'C'};
  auto put = [&v2](const auto& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    v2.insert(v2.end(), p, p + sizeof value);
  };
  const std::string context = R"({"version": 1, "task": "t.json", "scenario": {}, "safety_limits": {}})";
  put(uint32_t{2}), put(uint32_t(haptics::session_record_bytes(1))), put(500.0), put(int64_t{0}), put(uint32_t{3});
  v2.insert(v2.end(), {'s', 'i', 'm'});
  put(uint32_t(context.size()));
  v2.insert(v2.end(), context.begin(), context.end());
  haptics::encode_record(haptics::TickSample{}, v2, 1);
  const fs::path old = dir / "old.nrec";
  write_bytes(old, v2);
  r = replay(old, dir / "old", dir / "sessions.db");
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  EXPECT_TRUE(says(r.process, old.string() +
                                  ": header: format version 2 has no checksums and does not keep its task: it "
                                  "can be reviewed (needle-sim report, review) but not replayed"))
      << r.process.output;
}

}  // namespace
}  // namespace needle::test
