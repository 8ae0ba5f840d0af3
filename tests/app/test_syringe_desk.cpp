// The syringe's plunger pressed from a desk, below the window system: the gamepad's left trigger
// and the space bar held, through their mapping (haptics::PlungerMapping) into the syringe hand of
// the rig `needle-sim run --device gamepad|keyboard` builds for the epidural task, through the haptic
// loop: the thumb's force the syringe is pressed with is the mapping's, and the plunger moves (the
// needle starts in the open, where the saline leaves freely). The window's own space bar, driven by
// xdotool, is in tests/tools/test_cli_run_devices.cpp.
#include <gtest/gtest.h>

#include "app/session_rig.hpp"
#include "engine/scene.hpp"
#include "haptics/devices/desk_mapping.hpp"
#include "haptics/realtime/haptic_loop.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

struct Pressed {
  double thumb_N = 0.0;   // the syringe's thumb force on the last tick
  double travel_m = 0.0;  // the plunger's travel then
};

// `press(t)` gives the mapping's force at t (s); it is set on the syringe hand every 16 ticks (a
// frame), the loop runs `seconds` at 1 kHz.
template <typename Press>
Pressed run_pressing(const std::string& device, double seconds, Press press) {
  const training::Task task = training::load_task(source_dir() / "assets/tasks/epidural.json");
  app::RigOptions options;
  options.device = haptics::DeviceSpec::parse(device);
  options.camera = engine::load_scene(task.scene).camera;
  options.out_dir = process_folder(output_dir() / "syringe_desk" / device);
  app::SessionRig rig(task, options);
  EXPECT_NE(rig.syringe_hand(), nullptr);
  EXPECT_NE(rig.syringe_step(), nullptr);
  if (!rig.syringe_hand()) return {};
  haptics::LoopConfig config;
  config.rate_hz = 1000.0;
  config.sample_capacity = 1 << 12;
  haptics::HapticLoop loop(rig.device(), rig.safety_limits(), config);
  loop.submit(haptics::LoopCommand::set_step(&rig.step()));
  loop.submit(haptics::LoopCommand::start());
  haptics::TickSample sample;
  Pressed out;
  for (long k = 0; k < long(seconds * 1000.0); ++k) {
    if (k % 16 == 0) rig.syringe_hand()->set_thumb_force(press(double(k) / 1000.0));
    loop.run_unpaced(1);
    while (loop.samples().pop(sample)) {
      EXPECT_EQ(sample.reading.plunger_input, uint32_t(haptics::PlungerInput::kThumbForce));
      EXPECT_EQ(sample.state.syringe.thumb_force_N, sample.reading.plunger_force_n)
          << "the syringe is pressed with the reading's force";
      out = {sample.state.syringe.thumb_force_N, sample.state.syringe.travel_m};
    }
  }
  return out;
}

TEST(SyringeDesk, TheGamepadsLeftTriggerPressesThePlunger) {
  haptics::PlungerMapping trigger;
  const Pressed p = run_pressing("gamepad", 0.5, [&](double) {
    trigger.trigger(0.0);  // half pulled
    return trigger.force_N();
  });
  EXPECT_NEAR(p.thumb_N, haptics::PlungerMapping::kHeldForce_N * 0.45 / 0.95, 1e-12);
  EXPECT_GT(p.travel_m, 0.0);
}

TEST(SyringeDesk, TheSpaceBarHeldPressesThePlungerRisingToItsHold) {
  haptics::PlungerMapping key;
  double last_t = 0.0;
  const Pressed p = run_pressing("keyboard", 1.5, [&](double t) {
    key.held(true, t - last_t);
    last_t = t;
    return key.force_N();
  });
  EXPECT_DOUBLE_EQ(p.thumb_N, haptics::PlungerMapping::kHeldForce_N);  // held past the rise's second
  EXPECT_GT(p.travel_m, 0.0);
}

}  // namespace
}  // namespace needle::test
