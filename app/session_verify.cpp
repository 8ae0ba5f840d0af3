#include "app/session_verify.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "app/default_db.hpp"
#include "app/session_rig.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "training/sessions/recording_identity.hpp"
#include "training/sessions/session_review.hpp"
#include "training/tasks/patient_session.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += (out.empty() ? "" : "\n") + line;
  return out;
}

// A folder of its own for one replay's scenario, removed when it goes.
struct ScratchFolder {
  fs::path dir;
  explicit ScratchFolder(int64_t id) {
    static std::atomic<unsigned> serial{0};
    dir = fs::temp_directory_path() / ("needle-sim-verify-" + std::to_string(::getpid()) + "-" +
                                       std::to_string(serial++) + "-" + std::to_string(id));
    fs::create_directories(dir);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
};

}  // namespace

training::SessionResult replay_result(const fs::path& recording, const fs::path& scratch, std::string& task_name) {
  RigOptions options;
  options.device = {haptics::DeviceSpec::Kind::kReplay, std::nullopt, recording.string()};
  options.out_dir = scratch;
  training::Task task = session_task({}, options.device);
  task_name = task.name;
  SessionRig rig(task, options);
  training::apply_patient(task, rig.scenario());  // the recorded patient's landmarks
  if (!rig.can_complete())
    throw haptics::RecordingError(recording.string() +
                                  ": its run did not run to its end (cut short, or stopped): a complete session's "
                                  "recording ends with its run");
  // As TaskSession runs a replay headless: one tick, then its sample scored, to the recording's end.
  haptics::LoopConfig config;
  config.rate_hz = rig.rate_hz();
  config.sample_capacity = 1 << 10;
  haptics::HapticLoop loop(rig.device(), rig.safety_limits(), config);
  training::SessionScorer scorer(task);
  const uint64_t ticks = *rig.ticks();
  loop.submit(haptics::LoopCommand::set_step(&rig.step()));
  loop.submit(haptics::LoopCommand::start(ticks));
  haptics::TickSample sample;
  for (uint64_t k = 0; k < ticks; ++k) {
    loop.run_unpaced(1);
    while (loop.samples().pop(sample)) scorer.feed(sample);
  }
  return scorer.result();
}

VerifiedSession verify_session(const training::SessionStore& store, const fs::path& db, int64_t id) {
  VerifiedSession v;
  training::SessionCheck& check = v.check;
  check.session_id = id;
  const Clock::time_point t0 = Clock::now();
  fs::path fetched;  // a server's copy of the recording, removed once replayed
  try {
    const training::StoredSession stored = store.load(id);
    check.score = stored.info.score;
    check.digest = training::result_digest(stored);
    if (!stored.info.complete)
      throw std::runtime_error("incomplete: its run ended before the task did, and no score is stored");
    if (stored.info.recording_path.empty())
      throw std::runtime_error("no recording (the session was stored without one)");
    const fs::path file = locate_recording(store, db, stored.info, fetched);
    const haptics::SessionHeader header = haptics::read_header(file.string());  // unreadable: unverifiable
    std::vector<std::string> differences;
    try {  // another session's recording: the store does not hold what was recorded for it
      const std::string unchecked = training::check_recording_identity(file.string(), header, stored.info);
      if (!unchecked.empty()) v.notes.push_back(unchecked);
    } catch (const haptics::RecordingError& e) {
      differences.push_back(std::string("recording: ") + e.what());
    }
    if (differences.empty()) {
      const ScratchFolder scratch(id);
      std::string task;
      const training::SessionResult replay = replay_result(file, scratch.dir, task);
      if (task != stored.info.task)
        differences.push_back("task: stored \"" + stored.info.task + "\", recording \"" + task + "\"");
      for (std::string& d : training::result_differences(stored, replay)) differences.push_back(std::move(d));
    }
    check.outcome = differences.empty() ? training::CheckOutcome::kVerified : training::CheckOutcome::kMismatch;
    check.detail = joined(differences);
  } catch (const training::StoredValueError& e) {  // a score no run stores: altered, whatever the replay says
    check.outcome = training::CheckOutcome::kMismatch;
    check.detail = e.what();
  } catch (const std::exception& e) {
    check.outcome = training::CheckOutcome::kUnverifiable;
    check.detail = e.what();
  }
  std::error_code ignored;
  if (!fetched.empty()) fs::remove(fetched, ignored);
  v.replay_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return v;
}

std::vector<VerifiedSession> verify_sessions(const std::string& location, const std::vector<int64_t>& ids, int jobs,
                                             const std::function<void(const VerifiedSession&)>& done) {
  std::vector<VerifiedSession> out(ids.size());
  std::atomic<size_t> next{0};
  std::mutex report;
  std::string failed;  // a thread's store that could not be opened
  const auto work = [&] {
    try {
      const std::unique_ptr<training::SessionStore> store = open_existing_db(location);
      for (size_t k = next++; k < ids.size(); k = next++) {
        out[k] = verify_session(*store, location, ids[k]);
        const std::lock_guard<std::mutex> lock(report);
        done(out[k]);
      }
    } catch (const std::exception& e) {
      const std::lock_guard<std::mutex> lock(report);
      failed = e.what();
      next = ids.size();
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < std::max(1, std::min<int>(jobs, int(ids.size()))); ++j) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (!failed.empty()) throw std::runtime_error(failed);
  return out;
}

}  // namespace needle::app
