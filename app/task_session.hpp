// A guided task session through the haptic loop: the rig's device and step in HapticLoop, every
// tick recorded (<db folder>/recordings/) and, through the recorder's sink, scored and tracked
// for the 3D view; stored as a session, with score.json. Headless it runs the loop unpaced on
// the calling thread (a scripted or replayed session as fast as the machine goes); in a window
// the loop and the recorder run on their own threads in real time.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/messages.hpp"
#include "app/recording_upload.hpp"
#include "app/session_feed.hpp"
#include "app/session_rig.hpp"
#include "engine/extent.hpp"
#include "engine/scene.hpp"
#include "engine/scene_renderer.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "haptics/recording/session_recorder.hpp"
#include "training/sessions/session_store.hpp"
#include "ui/trainee_panel.hpp"

namespace needle::app {

// When a session goes to the session store (docs/SESSIONS.md, "Sessions that count").
enum class StoreWhen {
  kUnderWay,  // once its first step has ended: a window opened and closed before leaves nothing
  kAlways,    // from its start, whatever happens (run --store)
  kNever,     // not at all (run --frames, a scripted look at the window, without --store)
};

struct TaskSessionOptions {
  std::filesystem::path task;  // unused for replay:FILE, which runs the task its recording keeps
  RigOptions rig;              // its out_dir and camera are set from here and the task's scene
  std::string trainee;
  std::filesystem::path db;        // an SQLite file or a postgresql:// URI (app/default_db.hpp)
  std::string station;             // the station's name, stored with the session
  std::filesystem::path local_db;  // with a server: this station's own file, where a session the
                                   // server missed is kept for sync (default: default_db())
  std::filesystem::path out_dir;
  Messages messages;  // what the session tells its user (the start, notes, the score)
  StoreWhen store = StoreWhen::kUnderWay;
  bool practice = false;  // untimed steps (training::practice_task); a replay's is its recording's
};

class TaskSession {
 public:
  // Loads the task and its scene, builds the rig, opens the recording and the session store (checked
  // before anything runs), and, for StoreWhen::kAlways, the session in it (incomplete until
  // finish()); otherwise the session is stored once it is under way (store_once_under_way()).
  // Writes OUT/scenario.json, the scenario that runs, and removes an OUT/score.json of an earlier run.
  // A session that was never stored leaves no recording behind.
  explicit TaskSession(TaskSessionOptions options);
  ~TaskSession();
  TaskSession(const TaskSession&) = delete;
  TaskSession& operator=(const TaskSession&) = delete;

  const training::Task& task() const { return task_; }
  const engine::Scene& scene() const { return scene_; }
  haptics::DeskDevice* desk() { return rig_->desk(); }
  haptics::SyringeHandDevice* syringe_hand() { return rig_->syringe_hand(); }
  const haptics::DeviceSpec& device_spec() const { return options_.rig.device; }
  std::optional<ToolStart> tool_start() const { return rig_->tool_start(); }
  // Seconds the session lasts when its device has an end (script, recording), else nullopt.
  std::optional<double> duration_s() const;
  // The most ticks it runs: its device's end, bounded (but for a replay) by how long the task can
  // last (training::session_time_bound_s), for a device without an end that bound.
  uint64_t tick_budget() const { return tick_budget_; }

  // Headless: every tick of the device back to back on this thread; on_step_end(k) runs right
  // after the tick that ended step k. Throws std::logic_error for a device without an end.
  void run_offline(const std::function<void(size_t step)>& on_step_end);
  // Window: launches the loop and recorder threads; returns the loop's one real-time line.
  std::string start_realtime();
  // The device has given all it has, or every step has ended.
  bool over() const;
  // Stores the session (incomplete) once its first step has ended, under StoreWhen::kUnderWay;
  // called each frame and after each headless tick. Returns whether the session is in the store.
  bool store_once_under_way();

  // Stops the threads, scores, stores the session as complete and writes OUT/score.json (also
  // when the store fails: then it throws after, saying so). Once. Returns nullptr, storing and
  // writing nothing, when the session must stay incomplete (a replay of a recording cut short).
  const training::SessionResult* finish();
  bool finished() const { return finished_; }
  // Clears a latched safety fault (the panel's button, a gamepad's Start), while the loop runs.
  void reset_fault();

  engine::NeedleLoad needle() const { return feed_.needle(); }
  // The needle's axis in the newest state (world frame); before the first, the state's default.
  std::array<double, 3> needle_axis() const { return feed_.needle_axis(); }
  // The trainee panel of now (with the result once finished), describing `step` when given, with
  // how the device moves the needle (`controls`, one line) and buttons for `choices`.
  void draw_panel(std::optional<size_t> step = std::nullopt, const char* controls = nullptr,
                  const std::vector<ui::Choice>& choices = {});
  const std::filesystem::path& recording_path() const { return recording_path_; }
  const Messages& messages() const { return options_.messages; }
  int64_t session_id() const { return session_; }  // 0 until the session is in the store
  // Samples scored so far (every tick the recorder has handed on).
  uint64_t samples() const { return feed_.samples(); }

 private:
  void stop_threads(bool ran_to_end);
  // Begins the session in the store (and, with a server, the recording's upload).
  void begin_stored();
  // Why a session goes unstored; and, for one that was not, its recording removed and the user told:
  // a session that never happened leaves nothing behind.
  std::string unstored_reason() const;
  void drop_unstored();
  // Stores the finished session on the server, or, when it cannot be reached (or could not when the
  // run began), in this station's own file for needle-sim sync. Returns "" when stored on the
  // server, else what happened.
  std::string store_result();

  TaskSessionOptions options_;
  std::string offline_;  // why the server could not be reached when the session began; "": it was
  training::Task task_;
  engine::Scene scene_;
  std::unique_ptr<SessionRig> rig_;
  std::unique_ptr<training::SessionStore> store_;  // the server's, or this station's file when it was down
  std::filesystem::path recording_path_;
  training::NewSession new_session_;  // what begin_session stored, to keep it locally when needed
  int64_t session_ = 0;
  std::unique_ptr<RecordingUpload> upload_;  // with a server
  uint64_t tick_budget_ = 0;
  bool finished_ = false;
  std::unique_ptr<haptics::HapticLoop> loop_;
  std::unique_ptr<haptics::SessionRecorder> recorder_;

  SessionFeed feed_;  // the recorder's thread scores and tracks every sample into it
  std::optional<training::SessionResult> result_;
};

// A task name as part of a file name: letters, digits, '-' and '_' kept, anything else (a '/', a
// '.', a NUL) made '_', at most training::kMaxNameBytes characters. Task names are checked when a
// task loads (docs/TASKS.md); this holds whatever the name.
std::string file_name_part(const std::string& name);

// Where a new session of task `task_name` is recorded: <folder of `db`>/recordings/<name>_<UTC start>_
// <pid>[_<n>].nrec, the name made safe for a file name whatever it holds (no '/', '.', NUL; at most
// training::kMaxNameBytes characters), the number added when a session of the same task started in
// the same second in this process. Makes the folder.
std::filesystem::path new_recording_path(const std::filesystem::path& db, const std::string& task_name);

// The section view's plane a task fixes, in `mode` (docs/TASKS.md, "Section"); nullopt when the
// task fixes none (the view then cuts through the needle).
std::optional<engine::Section> task_section(const training::Task& task, engine::Section::Mode mode);

// Headless: runs the session through, writing OUT/step_<n>_<id>.png as each step ends,
// OUT/final.png and OUT/score_panel.png; in a task with an ultrasound probe also the probe's
// image, OUT/ultrasound_step_<n>.png and OUT/ultrasound_final.png. Returns 0.
// With `section`, every picture shows the section view: the task's own plane, else through the needle.
int run_task_headless(TaskSessionOptions options, engine::Extent size, int msaa,
                      std::optional<engine::Section::Mode> section = std::nullopt);

}  // namespace needle::app
