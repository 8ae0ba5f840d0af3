// The syringe hand (docs/DEVICES.md, "The syringe hand") without a display or a device: the desk's
// mappings of a key, a button and a trigger to the thumb's force; the device around the needle's
// that adds the plunger to every reading, from the app's thread or from a simulated second position
// device; and the syringe in the servo tick (SyringeServoStep) around a needle step.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>

#include "haptics/devices/desk_mapping.hpp"
#include "haptics/devices/syringe_hand.hpp"
#include "haptics/realtime/syringe_servo_step.hpp"

namespace needle::haptics {
namespace {

TEST(PlungerMapping, AKeyHeldPressesWithAForceRisingToItsHoldAndLettingGoAtOnce) {
  PlungerMapping key;
  key.held(true, 0.05);
  EXPECT_DOUBLE_EQ(key.force_N(), PlungerMapping::kHeldForce_N * 0.05 / PlungerMapping::kRise_s);
  for (int k = 0; k < 20; ++k) key.held(true, 0.1);
  EXPECT_DOUBLE_EQ(key.force_N(), PlungerMapping::kHeldForce_N);
  key.held(false, 0.016);
  EXPECT_EQ(key.force_N(), 0.0);
  key.held(true, 10.0);  // a long frame rises as much as GamepadMapping::kMaxStep_s
  EXPECT_DOUBLE_EQ(key.force_N(), PlungerMapping::kHeldForce_N * GamepadMapping::kMaxStep_s / PlungerMapping::kRise_s);
  key.held(true, std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isfinite(key.force_N()));
}

TEST(PlungerMapping, ATriggerPressesInProportionPastItsDeadZone) {
  PlungerMapping trigger;
  trigger.trigger(-1.0);  // released
  EXPECT_EQ(trigger.force_N(), 0.0);
  trigger.trigger(1.0);  // fully pulled
  EXPECT_DOUBLE_EQ(trigger.force_N(), PlungerMapping::kHeldForce_N);
  trigger.trigger(0.0);  // half pulled: (0.5 - 0.05) / 0.95 of the way
  EXPECT_NEAR(trigger.force_N(), PlungerMapping::kHeldForce_N * 0.45 / 0.95, 1e-12);
}

TEST(PlungerMapping, WithASyringeTheGamepadsRightTriggerDrawsBackWhileTheLeftBumperIsHeld) {
  GamepadMapping pad({}, true);
  const double start = pad.pose().position_m[2];
  GamepadState s;
  s.axes[GamepadState::kRightTrigger] = 1.0f;
  s.axes[GamepadState::kLeftTrigger] = 1.0f;  // the plunger's: moves nothing
  pad.update(s, 0.05);
  EXPECT_NEAR(pad.pose().position_m[2] - start, GamepadMapping::kSpeed_m_per_s * 0.05, 1e-12);
  s.buttons[GamepadState::kLeftBumper] = 1;
  pad.update(s, 0.05);
  EXPECT_NEAR(pad.pose().position_m[2], start, 1e-12);
  // Without a syringe the left trigger draws back as before.
  GamepadMapping plain;
  GamepadState back;
  back.axes[GamepadState::kLeftTrigger] = 1.0f;
  plain.update(back, 0.05);
  EXPECT_NEAR(plain.pose().position_m[2] - start, -GamepadMapping::kSpeed_m_per_s * 0.05, 1e-12);
}

// A position device standing for the needle's Falcon, or the syringe hand's second one: its handle
// where the test puts it, its last command kept.
class SimulatedPositionDevice : public HapticDevice {
 public:
  explicit SimulatedPositionDevice(double max_force_n) {
    caps_.name = "simulated";
    caps_.max_force_n = max_force_n;
  }
  void open() override { opened = true; }
  void close() noexcept override { opened = false; }
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  void read(DeviceReading& out) noexcept override {
    out.connected = connected;
    out.position_m[2] = z;
  }
  void write(const DeviceCommand& c) noexcept override { last = c; }

  double z = 0.05;
  uint32_t connected = 1;
  bool opened = false;
  DeviceCommand last;

 private:
  DeviceCapabilities caps_;
};

TEST(SyringeHand, TheAppsThumbForceReachesEveryReading) {
  auto needle = std::make_unique<SimulatedPositionDevice>(9.0);
  SimulatedPositionDevice* inner = needle.get();
  SyringeHandDevice hand(std::move(needle));
  hand.open();
  EXPECT_TRUE(inner->opened);
  EXPECT_FALSE(hand.has_second());
  EXPECT_EQ(hand.capabilities().name, "simulated");
  std::thread app([&hand] { hand.set_thumb_force(7.5); });  // the app's thread
  app.join();
  DeviceReading r;
  hand.read(r);
  EXPECT_EQ(r.plunger_input, uint32_t(PlungerInput::kThumbForce));
  EXPECT_EQ(r.plunger_force_n, 7.5);
  EXPECT_EQ(r.position_m[2], 0.05) << "the needle's reading is the needle device's";
  hand.set_thumb_force(std::numeric_limits<double>::quiet_NaN());
  hand.read(r);
  EXPECT_EQ(r.plunger_force_n, 0.0);
  hand.set_thumb_force(-3.0);
  hand.read(r);
  EXPECT_EQ(r.plunger_force_n, 0.0);
  hand.close();
  EXPECT_FALSE(inner->opened);
}

TEST(SyringeHand, ASecondDevicesHandlePushedAwayPressesThePlungerThroughTheSpring) {
  auto second = std::make_unique<SimulatedPositionDevice>(2.0);
  SimulatedPositionDevice* thumb = second.get();
  SyringeHandDevice hand(std::make_unique<SimulatedPositionDevice>(9.0), std::move(second));
  hand.open();
  hand.home();
  DeviceReading r;
  hand.read(r);
  EXPECT_EQ(r.plunger_input, uint32_t(PlungerInput::kHandlePosition));
  EXPECT_EQ(r.plunger_position_m, 0.0) << "the plunger starts where the handle is";
  thumb->z = 0.045;  // pushed 5 mm away from the trainee (the Falcon's -z)
  hand.read(r);
  EXPECT_NEAR(r.plunger_position_m, 0.005, 1e-15);
  // The spring between the handle and a plunger that has travelled 2 mm: k (5 - 2) mm.
  EXPECT_NEAR(plunger_thumb_force(r, 0.002), kPlungerCouplingStiffness_N_per_m * 0.003, 1e-12);
  EXPECT_EQ(plunger_thumb_force(r, 0.007), 0.0) << "a plunger ahead of the handle is not pulled";
  DeviceCommand c;
  c.plunger_force_n = 1.5;
  hand.write(c);
  EXPECT_EQ(thumb->last.space, CommandSpace::kTaskForce);
  EXPECT_EQ(thumb->last.force_n[2], 1.5) << "pushed back towards the trainee";
  c.plunger_force_n = 3.0;
  hand.write(c);
  EXPECT_EQ(thumb->last.force_n[2], 2.0) << "saturated at the second device's force";
  thumb->connected = 0;
  hand.read(r);
  EXPECT_EQ(r.connected, 0u) << "the syringe hand gone is the session's device gone";
}

// The needle's step as a stub: it puts the needle's opening in `layer`.
class StubNeedleStep : public ServoStep {
 public:
  void step(const DeviceReading&, double, DeviceCommand&, ToolSnapshot& state) noexcept override {
    state.syringe.layer = layer;
  }
  int layer = -1;
};

TEST(SyringeServoStep, TheThumbsReadingAndTheTissueAtTheOpeningDriveThePlunger) {
  Scenario scenario;
  scenario.syringe = SyringeParams{};
  const LayerShape slab = LayerShape::slab(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.01);
  const LayerShape below = LayerShape::slab(Eigen::Vector3d(0, 0, -0.01), Eigen::Vector3d::UnitZ(), 0.01);
  scenario.scene.tissue = TissueModel({{"ligament", slab, {}, std::nullopt, LayerInjection{150e3, 1e13}},
                                       {"space", below, {}, std::nullopt, LayerInjection{1e3, 1e9}}});
  StubNeedleStep needle;
  SyringeServoStep step(needle, scenario);
  DeviceReading reading;
  reading.plunger_input = uint32_t(PlungerInput::kThumbForce);
  reading.plunger_force_n = 11.0;
  DeviceCommand command;
  ToolSnapshot state;
  needle.layer = 0;
  for (int k = 0; k < 10; ++k) step.step(reading, 0.001, command, state);
  const double area = scenario.syringe->plunger_area_m2;
  EXPECT_EQ(state.syringe.fluid, uint32_t(SyringeFluid::kSaline));
  EXPECT_EQ(state.syringe.layer, 0);
  EXPECT_DOUBLE_EQ(state.syringe.pressure_Pa, 11.0 / area);
  EXPECT_EQ(state.syringe.travel_m, 0.0);
  EXPECT_EQ(command.plunger_force_n, 0.0) << "a thumb force needs no push back";
  needle.layer = 1;  // into the space: the closed form of docs/TISSUE.md
  step.step(reading, 0.001, command, state);
  const double r = lumen_resistance_Pa_s_per_m3(*scenario.syringe) + 1e9;
  const double v = (11.0 - area * 1e3) / (scenario.syringe->thumb_damping_Ns_per_m + area * area * r);
  EXPECT_NEAR(state.syringe.travel_m, v * 0.001, 1e-15);
  EXPECT_NEAR(command.plunger_travel_m, state.syringe.travel_m, 0.0);
  // A handle: the spring's force is the thumb's and is pushed back.
  reading.plunger_input = uint32_t(PlungerInput::kHandlePosition);
  reading.plunger_position_m = state.syringe.travel_m + 0.004;
  needle.layer = 0;
  step.step(reading, 0.001, command, state);
  EXPECT_NEAR(state.syringe.thumb_force_N, kPlungerCouplingStiffness_N_per_m * 0.004, 1e-9);
  EXPECT_EQ(command.plunger_force_n, state.syringe.thumb_force_N);
}

}  // namespace
}  // namespace needle::haptics
