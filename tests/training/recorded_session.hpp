// A stored session with a recording, made as a run makes one: a shipped task done by its
// scripted operator in the closed-loop simulation, every tick written to a recording file as the
// haptic loop's TickSample (joint-space `sim` device: the master's joint angles in the reading,
// joint torques in the command), scored, and stored with the recording's path. Review, report and
// panel tests share it.
#pragma once

#include <unistd.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <string>

#include "haptics/recording/session_format.hpp"
#include "haptics/sim/closed_loop.hpp"
#include "training/scoring/session_scorer.hpp"
#include "training/sessions/session_store.hpp"
#include "training/tasks/scripted_operator.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {

// A fresh folder under `parent` for one test process: ctest runs each test of a suite as a
// process of its own, in parallel, so the files a suite fixture makes must not be shared.
inline std::filesystem::path process_folder(const std::filesystem::path& parent) {
  const std::filesystem::path dir = parent / std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

struct RecordedSessionSpec {
  std::string task = "penetrable_sphere";  // assets/tasks/<task>.json
  std::string operator_spec = "good";
  std::string trainee = "ana";
  bool finish = true;  // false: left incomplete, as a run that died
};

struct RecordedSession {
  int64_t id = 0;
  training::SessionResult result;
  std::filesystem::path recording;  // absolute
  size_t samples = 0;
};

// The state the haptic loop would publish for one tick of the closed-loop simulation (tests run
// the simulation directly; the product runs it through the loop).
inline haptics::ToolSnapshot snapshot_of(const haptics::TickRecord& r) {
  haptics::ToolSnapshot s;
  s.time_s = r.t;
  for (int i = 0; i < 3; ++i) {
    s.needle_tip_m[i] = r.x_v[i];
    s.environment_force_n[i] = r.force_v[i];
    s.operator_force_n[i] = r.force_h[i];
  }
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), r.needle_v);
  s.needle_orientation[0] = q.w();
  s.needle_orientation[1] = q.x();
  s.needle_orientation[2] = q.y();
  s.needle_orientation[3] = q.z();
  using haptics::ContactMode, haptics::ContactState;
  s.contact = r.mode == ContactMode::Free         ? ContactState::kFree
              : r.mode == ContactMode::Holonomic ? ContactState::kRigidSurface
                                                  : ContactState::kTissue;
  s.multiplier_count = r.mode == ContactMode::Free ? 0 : r.mode == ContactMode::Holonomic ? 1 : 2;
  s.multipliers[0] = r.lambda_v[0];
  s.multipliers[1] = r.lambda_v[1];
  return s;
}

// The TickSample the haptic loop publishes for one simulated tick of a joint-space device.
inline haptics::TickSample tick_sample(const haptics::TickRecord& r, uint64_t tick) {
  haptics::TickSample s;
  s.tick = tick;
  s.state = snapshot_of(r);
  s.state.tick = tick;
  const uint32_t n = uint32_t(std::min<Eigen::Index>(r.q_v.size(), haptics::kMaxSnapshotJoints));
  s.state.joint_count = n;
  s.reading.joint_count = n;
  s.reading.connected = 1;
  s.reading.sequence = tick + 1;
  s.command.space = haptics::CommandSpace::kJointTorque;
  s.command.joint_count = n;
  for (uint32_t j = 0; j < n; ++j) {
    s.state.virtual_q[j] = r.q_v[j];
    s.reading.joint_rad[j] = r.q_m[j];
    s.command.torque_nm[j] = j < r.tau_m.size() ? r.tau_m[j] : 0.0;
  }
  return s;
}

// Runs the task, writes `db folder`/recordings/<trainee>_<operator>.nrec and stores the session
// in `db` with the recording's path relative to the database's folder, as runs do.
inline RecordedSession record_session(const std::filesystem::path& db, const RecordedSessionSpec& spec = {}) {
  namespace fs = std::filesystem;
  const training::Task task = training::load_task(test::source_dir() / "assets/tasks" / (spec.task + ".json"));
  const fs::path folder = fs::absolute(db).parent_path();
  const fs::path relative = fs::path("recordings") / (spec.trainee + "_" + spec.operator_spec + ".nrec");
  fs::create_directories(folder / "recordings");
  const haptics::Scenario scenario = training::scenario_with_operator(task, training::operator_script_path(task, spec.operator_spec),
                                                                folder / (spec.trainee + "_" + spec.operator_spec + "_scenario.json"));
  training::SessionScorer scorer(task);
  haptics::SessionHeader header;
  header.rate_hz = 1.0 / scenario.period_s;
  header.device = "sim";
  std::vector<uint8_t> bytes = haptics::encode_header(header);
  uint64_t tick = 0;
  haptics::run_closed_loop(scenario, false, [&](const haptics::TickRecord& r) {
    const haptics::TickSample s = tick_sample(r, tick++);
    scorer.feed(s);
    haptics::encode_record(s, bytes);
  });
  std::ofstream(folder / relative, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  training::SessionStore store(db);
  RecordedSession out;
  out.id = store.begin_session(spec.trainee, task, "sim (" + spec.operator_spec + ")", relative.string());
  out.result = scorer.result();
  if (spec.finish) store.finish_session(out.id, out.result);
  out.recording = folder / relative;
  out.samples = tick;
  return out;
}

}  // namespace needle::test
