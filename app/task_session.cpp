#include "app/task_session.hpp"

#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <ctime>

#include "app/default_db.hpp"
#include "app/patient_meshes.hpp"
#include "app/ultrasound_window.hpp"
#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/ui_pass.hpp"
#include "haptics/safety/fault_cause.hpp"
#include "io/file_write.hpp"
#include "training/sessions/postgres_connection.hpp"
#include "training/sessions/session_export.hpp"
#include "training/sessions/store_location.hpp"
#include "training/tasks/patient_session.hpp"
#include "ui/guidance_overlay.hpp"
#include "ui/syringe_gauge.hpp"

namespace needle::app {
namespace fs = std::filesystem;

namespace {

// This station's own file: the database itself, or with a server where a session is kept for sync.
fs::path local_db(const TaskSessionOptions& options) {
  if (!training::is_postgres_uri(options.db.string())) return options.db;
  return options.local_db.empty() ? default_db() : options.local_db;
}

// A database location with its folder made, when it is a file: SQLite makes the file, not the folder.
std::string with_folder(const fs::path& location) {
  if (!training::is_postgres_uri(location.string()) && location.has_parent_path())
    io::make_folder(location.parent_path());
  return location.string();
}

// (options) => the store the session begins in: the one named, or, when that is a server that
// cannot be reached at a known host (refused, or no answer within the connect timeout:
// training::ServerUnreachable), this station's own file, with `offline` saying why (the session is
// kept there for sync when it ends). Any other failure (an unknown host, a certificate or password
// refused, a database the server lacks) is an error before the run.
std::unique_ptr<training::SessionStore> open_store(const TaskSessionOptions& options, std::string& offline) {
  try {
    return std::make_unique<training::SessionStore>(with_folder(options.db));
  } catch (const training::ServerUnreachable& e) {
    offline = e.what();
    return std::make_unique<training::SessionStore>(with_folder(local_db(options)));
  }
}

// `options` with the uid of the session it will store, which its recording names too.
TaskSessionOptions with_session_uid(TaskSessionOptions options) {
  if (options.rig.session_uid.empty()) options.rig.session_uid = training::new_session_uid();
  return options;
}

// The session's rig, and the task given the landmarks of the patient the rig's scenario runs on (a
// random patient's own) before anything scores it.
std::unique_ptr<SessionRig> rig_on_patient(training::Task& task, const RigOptions& options) {
  auto rig = std::make_unique<SessionRig>(task, options);
  training::apply_patient(task, rig->scenario());
  return rig;
}

TaskSessionOptions with_task_settings(TaskSessionOptions options, const engine::Scene& scene) {
  options.rig.out_dir = options.out_dir;
  options.rig.camera = scene.camera;
  return options;
}

}  // namespace

std::string file_name_part(const std::string& name) {
  std::string part;
  for (char c : name.substr(0, training::kMaxNameBytes))
    part += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return part.empty() ? "task" : part;
}

fs::path new_recording_path(const fs::path& db, const std::string& task_name) {
  const std::string task = file_name_part(task_name);
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", std::gmtime(&now));
  const fs::path dir = fs::absolute(db).parent_path() / "recordings";
  io::make_folder(dir);
  const std::string stem = task + "_" + stamp + "_" + std::to_string(::getpid());
  fs::path path = dir / (stem + ".nrec");
  for (int n = 2; fs::exists(path); ++n) path = dir / (stem + "_" + std::to_string(n) + ".nrec");
  return path;
}

TaskSession::TaskSession(TaskSessionOptions options)
    : options_(with_session_uid(std::move(options))),
      task_(session_task(options_.task, options_.rig.device, options_.practice)),
      scene_(engine::load_scene(task_.scene)),
      rig_(rig_on_patient(task_, with_task_settings(options_, scene_).rig)),
      store_(open_store(options_, offline_)),
      recording_path_(new_recording_path(local_db(options_), task_.name)),
      feed_(task_) {
  scene_ = with_patient(std::move(scene_), rig_->scenario());  // the patient the rig runs, drawn
  haptics::LoopConfig config;
  config.rate_hz = rig_->rate_hz();
  config.sample_capacity = 1 << 15;  // 33 s at 1 kHz: room for the recorder's worst stall
  loop_ = std::make_unique<haptics::HapticLoop>(rig_->device(), rig_->safety_limits(), config);
  const bool replay = options_.rig.device.kind == haptics::DeviceSpec::Kind::kReplay;
  const uint64_t bound = static_cast<uint64_t>(std::llround(training::session_time_bound_s(task_) * rig_->rate_hz()));
  tick_budget_ = rig_->ticks() ? (replay ? *rig_->ticks() : std::min(*rig_->ticks(), bound)) : bound;
  recorder_ = std::make_unique<haptics::SessionRecorder>(
      recording_path_.string(),
      haptics::SessionHeader{haptics::kSessionFormatVersion, rig_->rate_hz(), static_cast<int64_t>(std::time(nullptr)),
                             options_.rig.device.text(), rig_->context()},
      loop_->samples(), [this](const haptics::TickSample& s) { feed_.consume(s); });
  // A practice run says so where the instructor reads what a session ran on.
  new_session_ = {options_.trainee,
                  task_.name,
                  task_.title,
                  task_.source,
                  rig_->description() + (task_.practice ? " (practice)" : ""),
                  recording_path_.string(),
                  options_.station,
                  options_.rig.session_uid,
                  training::utc_timestamp()};
  loop_->submit(haptics::LoopCommand::set_step(&rig_->step()));
  std::error_code ignored;
  fs::remove(options_.out_dir / "score.json", ignored);  // never an earlier run's score beside this run's pictures
  const Messages& say = options_.messages;
  say.say(formatted("task %s on %s, trainee %s, station %s", task_.name.c_str(), rig_->description().c_str(),
                    options_.trainee.c_str(), options_.station.c_str()));
  if (options_.store == StoreWhen::kAlways) begin_stored();
  say.say("recording " + recording_path_.string());
  if (!offline_.empty())
    say.say("note: the server could not be reached (" + offline_ +
            "): the session is kept in this station's file for needle-sim sync");
  for (const std::string& note : rig_->notes()) say.say("note: " + note);
  if (rig_->ticks() && tick_budget_ < *rig_->ticks())
    say.say(
        formatted("note: the operator script runs %.1f s, past the latest end of the task (%.1f s: its steps' time "
                  "limits plus %.0f s): the run stops there",
                  *duration_s(), double(tick_budget_) / rig_->rate_hz(), training::kTaskEndMargin_s));
}

TaskSession::~TaskSession() {
  stop_threads(false);
  if (session_ == 0 && !finished_) drop_unstored();  // closed before it was under way
}

void TaskSession::drop_unstored() {
  std::error_code ignored;
  fs::remove(recording_path_, ignored);
  options_.messages.say("the session is not stored: " + unstored_reason() + "; its recording is removed");
}

void TaskSession::begin_stored() {
  try {
    session_ = store_->begin_session(new_session_);
  } catch (const training::ServerLost& e) {
    // Lost before the session began on it (a session is stored once its first step ends): begun in
    // this station's file instead, as when the server could not be reached at the start.
    offline_ = e.what();
    store_ = std::make_unique<training::SessionStore>(with_folder(local_db(options_)));
    session_ = store_->begin_session(new_session_);
    options_.messages.say("note: the server could not be reached (" + offline_ +
                          "): the session is kept in this station's file for needle-sim sync");
  }
  if (store_->engine() == training::SqlEngine::kPostgres)
    upload_ = std::make_unique<RecordingUpload>(options_.db.string(), session_, recording_path_);
  if (loop_->running() && upload_) upload_->start();
  options_.messages.say(formatted("session %lld in %s", static_cast<long long>(session_), store_->name().c_str()));
}

bool TaskSession::store_once_under_way() {
  if (session_ == 0 && options_.store == StoreWhen::kUnderWay && feed_.first_step_ended()) begin_stored();
  return session_ != 0;
}

std::string TaskSession::unstored_reason() const {
  if (options_.store == StoreWhen::kNever) return "a run with --frames is stored only with --store";
  return "it ended before its first step did (--store keeps such a session)";
}

std::optional<double> TaskSession::duration_s() const {
  if (!rig_->ticks()) return std::nullopt;
  return double(*rig_->ticks()) / rig_->rate_hz();
}

void TaskSession::run_offline(const std::function<void(size_t)>& on_step_end) {
  if (!rig_->ticks())
    throw std::logic_error("a session on " + options_.rig.device.text() + " runs only in real time, in a window");
  const uint64_t ticks = tick_budget_;
  loop_->submit(haptics::LoopCommand::start(ticks));
  // One tick and one recorder pass at a time, so a step's picture shows the tick that ended it.
  // With a server, the recording goes to it every RecordingUpload::kPeriod of session time.
  const uint64_t upload_ticks =
      std::max<uint64_t>(1, uint64_t(rig_->rate_hz() * RecordingUpload::kPeriod.count() / 1000.0));
  for (uint64_t k = 0; k < ticks; ++k) {
    loop_->run_unpaced(1);
    recorder_->drain();
    if (upload_ && (k + 1) % upload_ticks == 0) upload_->send_new();
    for (size_t step : feed_.take_ended_steps()) on_step_end(step);
    store_once_under_way();
    options_.messages.advance(double(k + 1) / rig_->rate_hz(), double(ticks) / rig_->rate_hz());
  }
}

std::string TaskSession::start_realtime() {
  const std::string line = loop_->launch();
  recorder_->start();
  if (upload_) upload_->start();  // else begin_stored() starts it
  loop_->apply(haptics::LoopCommand::start(tick_budget_));
  return line;
}

bool TaskSession::over() const { return feed_.samples() >= tick_budget_ || (!rig_->ticks() && feed_.task_finished()); }

void TaskSession::stop_threads(bool ran_to_end) {
  if (loop_) loop_->shutdown();
  if (recorder_) recorder_->stop(ran_to_end);  // the last pass: every sample the loop made is scored
  if (upload_) {
    upload_->stop();
    upload_->send_new();  // the rest, with the end mark
  }
}

std::string TaskSession::store_result() {
  if (!offline_.empty()) {  // begun in this station's file: finished there, kept for the server
    store_->finish_session(session_, *result_);
    store_->keep_for_server(session_, training::shown_location(options_.db.string()));
    return "the server could not be reached when the session began (" + offline_ + "): the session is kept in " +
           store_->name() + " as session " + std::to_string(session_) + "; needle-sim sync --db URI --local " +
           local_db(options_).string() + " sends it";
  }
  std::string server_error = upload_ && !upload_->error().empty() ? "sending the recording: " + upload_->error() : "";
  if (server_error.empty()) {
    try {
      store_->finish_session(session_, *result_);
      return "";
    } catch (const std::exception& e) {
      if (store_->engine() != training::SqlEngine::kPostgres) throw;
      server_error = e.what();
    }
  }
  // The server was lost: the session is kept in this station's own file, by the same uid.
  const fs::path local = local_db(options_);
  training::SessionStore station(with_folder(local));
  const int64_t id = station.begin_session(new_session_);
  station.finish_session(id, *result_);
  station.keep_for_server(id, store_->name());
  return "the server could not be reached (" + server_error + "): the session is kept in " + local.string() +
         " as session " + std::to_string(id) + "; needle-sim sync --db URI --local " + local.string() + " sends it";
}

const training::SessionResult* TaskSession::finish() {
  if (finished_) return result_ ? &*result_ : nullptr;
  finished_ = true;
  stop_threads(rig_->can_complete());  // a replay that stays incomplete records that it did
  if (!recorder_->error().empty()) throw std::runtime_error("recording stopped: " + recorder_->error());
  if (recorder_->dropped() > 0)
    options_.messages.say(
        formatted("warning: the recorder fell behind and %llu ticks were dropped from the recording and "
                  "the score",
                  static_cast<unsigned long long>(recorder_->dropped())));
  if (!rig_->can_complete()) {
    if (!store_once_under_way()) {
      drop_unstored();
      return nullptr;
    }
    if (upload_) upload_->send_new();
    options_.messages.say(formatted("session %lld stays incomplete: no score is stored and no score.json written",
                                    static_cast<long long>(session_)));
    return nullptr;
  }
  result_ = feed_.result();
  // The score is written even when the store fails: the session's record must not be lost.
  std::string store_error, kept;
  const bool stored = store_once_under_way();
  if (upload_) upload_->send_new();  // the whole recording, when the session was stored only now
  try {
    if (stored) kept = store_result();
  } catch (const std::exception& e) {
    store_error = e.what();
  }
  const fs::path score_file = options_.out_dir / "score.json";
  nlohmann::json score = training::result_json(*result_);
  score["recording"] = stored ? nlohmann::json(recording_path_.string()) : nlohmann::json(nullptr);
  score["stored"] = stored && store_error.empty();
  score["kept_for_sync"] = !kept.empty();  // stored in the station's own file, not yet on the server
  if (!stored) score["not_stored"] = unstored_reason();
  try {
    io::write_file(score_file, score.dump(2) + "\n");
  } catch (const io::WriteError& e) {
    if (store_error.empty()) throw;
    throw std::runtime_error(std::string(e.what()) + "; and the session could not be stored: " + store_error +
                             " (its recording is " + recording_path_.string() + ")");
  }
  const Messages& say = options_.messages;
  say.say(formatted("score %.0f / 100: %s", result_->score.total, result_->score.passed ? "passed" : "not passed"));
  for (const std::string& why : result_->score.reasons_failed) say.say("  " + why);
  say.say("wrote " + score_file.string());
  if (!stored) drop_unstored();
  if (!kept.empty()) say.say("note: " + kept);
  if (!store_error.empty())
    throw std::runtime_error("the session could not be stored: " + store_error + "; its score is in " +
                             score_file.string() + " and its recording is " + recording_path_.string());
  return &*result_;
}

void TaskSession::reset_fault() {
  if (loop_->running()) loop_->submit(haptics::LoopCommand::reset_fault());
}

void TaskSession::draw_panel(std::optional<size_t> step, const char* controls, const std::vector<ui::Choice>& choices) {
  feed_.read([&](const training::SessionScorer& scorer, const haptics::ToolSnapshot& last) {
    const size_t shown = std::min(step.value_or(scorer.progress().current_step()), task_.steps.size() - 1);
    ui::TraineeView view{&task_, &scorer.progress()};
    view.step = step;
    view.step_metrics = scorer.step_metrics(shown);
    view.now_s = last.time_s;
    view.cue = training::step_cue(task_, shown, last, ui::view_axes(scene_.camera));
    view.cue_lines = training::cue_lines(task_, shown, last, *view.cue);
    ui::set_forces(view, last, task_.force_scale);
    if (task_.layers.size() > 1) view.tissue = last.tissue;
    const haptics::LoopStatsSummary stats = loop_->stats();
    view.loop_rate_hz = loop_->running() ? stats.rate_hz : rig_->rate_hz();
    if (last.fault != 0) view.fault = haptics::fault_cause_name(static_cast<haptics::FaultCause>(last.fault));
    if (loop_->running()) view.reset_fault = [this] { reset_fault(); };
    view.controls = controls;
    view.choices = choices;
    if (result_) view.result = &*result_;
    ui::draw_trainee_panel(view);
    if (!result_) ui::draw_guidance({&task_, shown, training::vec3(last.needle_tip_m), scene_.camera});
    if (const haptics::SyringeServoStep* syringe = rig_->syringe_step(); syringe && !result_) {
      const auto axis = haptics::needle_axis(last);
      ui::draw_syringe_gauge({last.syringe,
                              haptics::syringe_stroke_m(syringe->params()),
                              training::vec3(last.needle_tip_m),
                              {axis[0], axis[1], axis[2]},
                              scene_.camera});
    }
  });
}

std::optional<engine::Section> task_section(const training::Task& task, engine::Section::Mode mode) {
  if (!task.section_plane) return std::nullopt;
  const training::Vec3 &p = task.section_plane->point, &n = task.section_plane->normal;
  return engine::Section{mode, glm::vec3(float(p[0]), float(p[1]), float(p[2])),
                         glm::vec3(float(n[0]), float(n[1]), float(n[2]))};
}

int run_task_headless(TaskSessionOptions options, engine::Extent size, int msaa,
                      std::optional<engine::Section::Mode> section) {
  const fs::path out_dir = options.out_dir;
  TaskSession run(std::move(options));
  engine::GpuDevice device;
  engine::HeadlessTarget target(device, size);
  engine::SceneRenderer renderer(device, target, {msaa});
  engine::GpuScene scene(renderer, run.scene());
  engine::UiPass ui(renderer, nullptr);
  // The task's ultrasound image, in its window in each picture and on its own beside it; none
  // made in a task without a probe.
  std::optional<UltrasoundWindow> ultrasound;
  if (run.task().ultrasound_probe) ultrasound.emplace(device, run.task());
  auto shoot = [&](const std::string& name, std::optional<size_t> step = std::nullopt) {
    engine::RgbaImage image;
    for (int frame = 0; frame < 2; ++frame) {  // ImGui fits its auto-sized windows on the first frame
      ui.begin_frame(target.extent(), 1.0f / 60.0f);
      run.draw_panel(step);
      const engine::NeedleLoad needle = run.needle();
      engine::FrameParams params = scene.frame_params(&needle);
      if (ultrasound) ultrasound->draw_panel(needle, params.camera);
      if (section)
        params.section = task_section(run.task(), *section)
                             .value_or(engine::section_through_needle(params.camera, &needle, *section));
      params.overlay = ui.end_frame();
      if (ultrasound) ultrasound->add_to_frame(params, renderer, target.extent(), needle);
      renderer.draw(target, params, frame == 1 ? &image : nullptr);
    }
    engine::write_png(out_dir / (name + ".png"), image);
  };
  auto sonogram = [&](const std::string& name) {
    if (ultrasound) engine::write_png(out_dir / (name + ".png"), ultrasound->picture(run.needle()));
  };
  run.run_offline([&](size_t k) {
    shoot("step_" + std::to_string(k + 1) + "_" + run.task().steps[k].id, k);
    sonogram("ultrasound_step_" + std::to_string(k + 1));
  });
  shoot("final");
  sonogram("ultrasound_final");
  if (run.finish()) shoot("score_panel");
  run.messages().say("wrote the pictures of the run in " + out_dir.string());
  return 0;
}

}  // namespace needle::app
