#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "haptics/devices/replay_device.hpp"
#include "haptics/realtime/servo_tick.hpp"
#include "haptics/realtime/sim_session.hpp"
#include "haptics/recording/session_recorder.hpp"
#include "haptics/sim/stress_cases.hpp"
#include "sim_fixtures.hpp"
#include "test_realtime_fakes.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::haptics {
namespace {

using testing::ScriptedDevice;
using testing::SpringStep;

constexpr double kRate = 1000.0;

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("needle_" + std::to_string(::getpid()) + "_" + name)).string();
}

SafetyLimits limits() {
  SafetyLimits l;
  l.max_force_n = 5.0;
  return l;
}

// Runs `ticks` ticks of SpringStep on `device` directly (no thread), keeping every sample.
std::vector<TickSample> run_ticks(HapticDevice& device, int ticks, SessionRecorder* recorder,
                                  SpscRing<TickSample>& ring) {
  SpringStep step;
  SafetyMonitor safety(limits());
  SeqLock<ToolSnapshot> snapshots;
  ServoTick tick(device, safety, snapshots, ring);
  tick.set_step(&step);
  std::vector<TickSample> kept;
  for (int k = 0; k < ticks; ++k) {
    tick.run(TickTiming{static_cast<uint64_t>(k), int64_t(k) * 1000000, 1000000, false}, 1.0 / kRate);
    kept.push_back(tick.last_sample());
    if (recorder != nullptr && k % 500 == 499) recorder->drain();  // as the recorder thread would
  }
  if (recorder != nullptr) recorder->drain();
  return kept;
}

bool same_bits(const ToolSnapshot& a, const ToolSnapshot& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(RecordingReplay, ReplayReproducesTheSimulationStateBitForBit) {
  const std::string path = temp_path("replay.nsrec");
  SpscRing<TickSample> ring(1024);
  std::vector<TickSample> live;
  {
    ScriptedDevice device;
    SessionRecorder recorder(path, {kSessionFormatVersion, kRate, 1700000000, "scripted", ""}, ring);
    live = run_ticks(device, 3000, &recorder, ring);
    EXPECT_EQ(recorder.written(), 3000u);
    EXPECT_EQ(recorder.dropped(), 0u);
  }
  const Session session = read_session(path);
  EXPECT_EQ(session.header.device, "scripted");
  EXPECT_EQ(session.header.rate_hz, kRate);
  ASSERT_EQ(session.records.size(), live.size());
  EXPECT_TRUE(session.end.checksummed);
  EXPECT_TRUE(session.end.closed);
  EXPECT_EQ(session.end.trailing_bytes, 0u);

  ReplayDevice replay(path);
  replay.open();
  SpscRing<TickSample> replay_ring(4096);
  const std::vector<TickSample> again = run_ticks(replay, 3000, nullptr, replay_ring);
  EXPECT_TRUE(replay.finished());
  int differing = 0;
  for (std::size_t k = 0; k < live.size(); ++k) {
    if (!same_bits(again[k].state, live[k].state) || !same_bits(session.records[k].state, live[k].state)) ++differing;
    EXPECT_EQ(std::memcmp(again[k].command.force_n, live[k].command.force_n, sizeof live[k].command.force_n), 0);
  }
  EXPECT_EQ(differing, 0);
  // The state moved: a replay that reproduced nothing would not pass the check above, but
  // make sure the comparison was not between constants.
  EXPECT_NE(live.front().state.needle_tip_m[2], live.back().state.needle_tip_m[2]);
  std::filesystem::remove(path);
}

TEST(RecordingReplay, AChangedInputChangesTheReplayedState) {
  // The converse: move one recorded reading by a nanometre and the state diverges (a single
  // ulp can be absorbed by rounding in the integrator).
  const std::string path = temp_path("perturbed.nsrec");
  SpscRing<TickSample> ring(4096);
  {
    ScriptedDevice device;
    SessionRecorder recorder(path, {kSessionFormatVersion, kRate, 0, "scripted", ""}, ring);
    run_ticks(device, 200, &recorder, ring);
  }
  Session session = read_session(path);
  ReplayDevice original(path);
  original.open();
  SpscRing<TickSample> r1(4096), r2(4096);
  const auto first = run_ticks(original, 200, nullptr, r1);
  // Rewrite the file with reading 100 moved.
  session.records[100].reading.position_m[0] += 1e-9;
  {
    SpscRing<TickSample> rewrite(4096);
    for (const auto& s : session.records) rewrite.push(s);
    SessionRecorder recorder(path, session.header, rewrite);
  }
  ReplayDevice nudged(path);
  nudged.open();
  const auto second = run_ticks(nudged, 200, nullptr, r2);
  EXPECT_TRUE(same_bits(first[99].state, second[99].state));
  EXPECT_FALSE(same_bits(first[199].state, second[199].state));
  std::filesystem::remove(path);
}

TEST(RecordingReplay, EveryDrainIsOnDiskBeforeTheRecorderCloses) {
  const std::string path = temp_path("flush.nsrec");
  SpscRing<TickSample> ring(64);
  SessionRecorder recorder(path, {kSessionFormatVersion, kRate, 0, "scripted", ""}, ring);
  TickSample s;
  for (uint64_t k = 0; k < 10; ++k) {
    s.tick = k;
    ring.push(s);
  }
  EXPECT_EQ(recorder.drain(), 10u);
  // Read through another handle while the recorder is still open, as after a kill.
  const Session seen = read_session(path);
  ASSERT_EQ(seen.records.size(), 10u);
  EXPECT_FALSE(seen.end.closed);  // no end mark yet: read as a file cut after its last whole block
  EXPECT_EQ(seen.records[9].tick, 9u);
  std::filesystem::remove(path);
}

TEST(RecordingReplay, ThreadedRecorderWritesEverySampleByStop) {
  const std::string path = temp_path("thread.nsrec");
  SpscRing<TickSample> ring(8192);
  SessionRecorder recorder(path, {kSessionFormatVersion, kRate, 0, "scripted", ""}, ring);
  recorder.start();
  TickSample s;
  for (uint64_t k = 0; k < 5000; ++k) {
    s.tick = k;
    ring.push(s);
  }
  recorder.stop();
  EXPECT_EQ(recorder.error(), "");
  EXPECT_EQ(recorder.written() + recorder.dropped(), 5000u);
  EXPECT_EQ(read_session(path).records.size(), recorder.written());
  std::filesystem::remove(path);
}

// The same with the thesis controller: record a `sim` session into the tissue, replay its
// device stream into a fresh controller, and every tick's state must match bit for bit.
TEST(RecordingReplay, ControllerReplayIsBitForBit) {
  const std::string path = temp_path("sim.nsrec");
  const std::string scenario = needle::test::source_dir().string() + "/assets/scenarios/nonholonomic_needle.json";
  constexpr double kSimRate = 500.0;
  constexpr uint64_t kTicks = 3000;  // 6 s
  std::vector<ToolSnapshot> live;
  SafetyLimits limits;  // the replay runs under the recorded device's limits, as `run` replays
  {
    SimSession sim(scenario, kSimRate);
    sim.device().open();
    limits = safety_limits_for(sim.device().capabilities());
    testing::TickRig rig(sim.device(), sim.step(), limits, 4096);
    SessionRecorder recorder(path, {kSessionFormatVersion, kSimRate, 0, "sim:" + scenario, ""}, rig.samples);
    for (uint64_t k = 0; k < kTicks; ++k) {
      rig.run(k, 1, 1.0 / kSimRate);
      live.push_back(rig.tick.last_sample().state);
    }
  }
  ReplayDevice replay(path);
  replay.open();
  SimSession fresh(scenario, kSimRate);  // only its controller step is used
  testing::TickRig rig(replay, fresh.step(), limits, 4096);
  uint64_t differing = 0;
  bool entered_tissue = false;
  for (uint64_t k = 0; k < kTicks; ++k) {
    rig.run(k, 1, 1.0 / kSimRate);
    differing += !same_bits(rig.tick.last_sample().state, live[k]);
    entered_tissue = entered_tissue || live[k].contact == ContactState::kTissue;
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_TRUE(entered_tissue);
  std::filesystem::remove(path);
}

// A hand pushing the rigid sphere at twice the device's force limit: the device holds the force back,
// and every such tick says so in the recording (ToolSnapshot::limits, kLimitForce), so the review and
// the score can name it; in free motion before the push no tick does.
TEST(RecordingReplay, ATickTheDeviceHeldAtItsForceLimitIsMarkedInTheRecording) {
  const std::string path = temp_path("push.nsrec");
  const Scenario& h = test::scenario("holonomic_sphere");
  Scenario push = pressing(h, 2 * h.device.force_limit_N, 10.0);
  push.duration_s = 12.0;
  constexpr double kRate = 500.0;
  {
    SimSession sim(push, kRate);
    sim.device().open();
    testing::TickRig rig(sim.device(), sim.step(), safety_limits_for(sim.device().capabilities()), 8192);
    SessionRecorder recorder(path, {kSessionFormatVersion, kRate, 0, "sim", ""}, rig.samples);
    for (uint64_t k = 0; k < uint64_t(push.duration_s * kRate); ++k) {
      rig.run(k, 1, 1.0 / kRate);
      recorder.drain();
    }
  }
  const Session session = read_session(path);
  uint64_t held = 0, held_in_free_motion = 0;
  for (const TickSample& s : session.records) {
    const bool limited = (s.state.limits & kLimitForce) != 0;
    held += limited;
    held_in_free_motion += limited && s.state.time_s < 3.0;  // the approach, before the surface
  }
  EXPECT_GT(held, 100u) << "pushing at twice the limit for seconds";
  EXPECT_EQ(held_in_free_motion, 0u);
  std::filesystem::remove(path);
}

TEST(RecordingReplay, TheSinkSeesEverySampleInTickOrder) {
  const std::string path = temp_path("sink.nsrec");
  SpscRing<TickSample> ring(1024);
  std::vector<uint64_t> seen;
  ScriptedDevice device;
  {
    SessionRecorder recorder(path, {kSessionFormatVersion, kRate, 0, "scripted", ""}, ring,
                             [&seen](const TickSample& s) { seen.push_back(s.tick); });
    run_ticks(device, 1200, &recorder, ring);
  }
  ASSERT_EQ(seen.size(), 1200u);
  for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], k);
  std::filesystem::remove(path);
}

TEST(RecordingReplay, ASinkThatThrowsStopsTheThreadWithItsMessage) {
  const std::string path = temp_path("sink_fails.nsrec");
  SpscRing<TickSample> ring(64);
  SessionRecorder recorder(path, {kSessionFormatVersion, kRate, 0, "scripted", ""}, ring,
                           [](const TickSample&) { throw std::runtime_error("scorer refused"); });
  TickSample s;
  ring.push(s);
  recorder.start();
  while (recorder.error().empty()) std::this_thread::sleep_for(SessionRecorder::kPassInterval);
  recorder.stop();
  EXPECT_EQ(recorder.error(), "scorer refused");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace needle::haptics
