// The desk devices (mouse, keyboard, gamepad) below the window system: each mapping from plain
// input values to a pose, and the device that hands the pose to the loop.
#include <gtest/gtest.h>

#include <cmath>

#include "haptics/devices/desk_mapping.hpp"

namespace needle::haptics {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(DeviceDesk, ThePoseIsReadAsPositionAndTwoWristJoints) {
  DeskDevice desk(DeviceSpec{DeviceSpec::Kind::kKeyboard});
  DeviceReading r;
  desk.read(r);
  EXPECT_EQ(r.position_m[0], 0.0);
  EXPECT_EQ(r.position_m[2], 0.1) << "the workspace's centre before any input";
  DeskPose pose;
  pose.position_m[0] = 0.05;
  pose.wrist_rad[0] = 0.3;
  pose.wrist_rad[1] = -0.2;
  desk.set_pose(pose);
  desk.set_buttons(1);
  DeviceReading s;
  desk.read(s);
  EXPECT_EQ(s.sequence, r.sequence + 1) << "every read is fresh";
  EXPECT_EQ(s.position_m[0], 0.05);
  EXPECT_EQ(s.joint_count, 2u);
  EXPECT_EQ(s.joint_rad[0], 0.3);
  EXPECT_EQ(s.joint_rad[1], -0.2);
  EXPECT_EQ(s.buttons, 1u);
  EXPECT_EQ(s.connected, 1u);
  EXPECT_EQ(desk.capabilities().name, "keyboard");
  EXPECT_EQ(desk.capabilities().actuated_axes, 0u);
  EXPECT_EQ(desk.capabilities().max_force_n, 0.0);
  EXPECT_EQ(desk.capabilities().command_space, CommandSpace::kNone);
}

TEST(DeviceDesk, APoseOutsideTheReachIsClampedAndNonFiniteValuesAreRefused) {
  DeskDevice desk(DeviceSpec{DeviceSpec::Kind::kMouse});
  DeskPose pose;
  pose.position_m[0] = 7.0;
  pose.position_m[1] = std::nan("");
  pose.wrist_rad[0] = 10.0;
  pose.wrist_rad[1] = -3.0;
  desk.set_pose(pose);
  DeviceReading r;
  desk.read(r);
  EXPECT_EQ(r.position_m[0], 0.2);
  EXPECT_EQ(r.position_m[1], 0.0) << "a NaN goes to the centre, never to the loop";
  EXPECT_NEAR(r.joint_rad[0], M_PI, 1e-15);
  EXPECT_NEAR(r.joint_rad[1], -80.0 * kDeg, 1e-15);
}

TEST(DeviceDesk, AnInputThatIsGoneReadsAsDisconnected) {
  DeskDevice pad(DeviceSpec{DeviceSpec::Kind::kGamepad, 0});
  pad.set_connected(false);  // unplugged: the safety monitor latches a disconnection fault
  DeviceReading r;
  pad.read(r);
  EXPECT_EQ(r.connected, 0u);
  pad.set_connected(true);
  pad.read(r);
  EXPECT_EQ(r.connected, 1u);
}

TEST(DeviceDesk, OnlyADeskSpecMakesADeskDevice) {
  EXPECT_EQ(DeskDevice(DeviceSpec::parse("gamepad:3")).spec(), (DeviceSpec{DeviceSpec::Kind::kGamepad, 3}));
  for (const char* spec : {"sim", "falcon", "replay:a.nrec"})
    EXPECT_THROW(DeskDevice{DeviceSpec::parse(spec)}, DeviceError) << spec;
}

TEST(DeviceDeskMouse, CursorAndWheelMapOntoTheWorkspaceAlikeAcrossAndUp) {
  MouseMapping mouse;               // 0.1 m for half the window's height, either way; 2 mm a notch
  mouse.pointer(1.5, -1.0, false);  // at the right edge of a 3:2 window, at its bottom
  mouse.scroll(3);
  EXPECT_NEAR(mouse.pose().position_m[0], 0.15, 1e-15);
  EXPECT_NEAR(mouse.pose().position_m[1], -0.1, 1e-15);
  EXPECT_NEAR(mouse.pose().position_m[2], 0.106, 1e-15);  // 0.1 + 3 x 2 mm
}

TEST(DeviceDeskMouse, InputOutsideTheRangeIsClamped) {
  MouseMapping mouse;
  mouse.pointer(7.0, -3.0, false);
  mouse.scroll(1000);  // far past the top: 50 notches reach it
  mouse.scroll(-1);    // one notch back down is felt at once
  EXPECT_NEAR(mouse.pose().position_m[0], 0.2, 1e-15);
  EXPECT_NEAR(mouse.pose().position_m[1], -0.2, 1e-15);
  EXPECT_NEAR(mouse.pose().position_m[2], 0.198, 1e-12);
}

TEST(DeviceDeskMouse, WithTheButtonHeldMotionTurnsTheWristAndTheHandleStays) {
  MouseMapping mouse;
  mouse.pointer(0.0, 0.0, false);
  mouse.pointer(-0.2, 0.1, false);
  const DeskPose before = mouse.pose();
  mouse.pointer(-0.2, 0.1, true);  // pressed where it was: nothing turns yet
  mouse.pointer(0.3, -0.1, true);  // half a window's height right, a fifth down
  EXPECT_EQ(mouse.pose().position_m[0], before.position_m[0]);
  EXPECT_EQ(mouse.pose().position_m[1], before.position_m[1]);
  EXPECT_NEAR(mouse.pose().wrist_rad[0], 0.25 * M_PI, 1e-12) << "right: the hub swings clockwise, 90 deg a half height";
  EXPECT_NEAR(mouse.pose().wrist_rad[1], -0.1 * M_PI, 1e-12) << "down: the hub tilts towards the viewer";
  // The app puts the cursor back where the turn began: the handle goes on from there.
  mouse.pointer(-0.2, 0.1, false);
  EXPECT_EQ(mouse.pose().position_m[0], before.position_m[0]);
  mouse.pointer(-0.1, 0.1, false);
  EXPECT_NEAR(mouse.pose().position_m[0], before.position_m[0] + 0.01, 1e-15);
  EXPECT_NEAR(mouse.pose().wrist_rad[0], 0.25 * M_PI, 1e-12);
}

// The cursor's ray at the handle's depth (a pinhole view): the camera 0.3 m from the tool's start,
// a 40 deg field of view; a point h across at depth d is under the cursor at h / ((0.3 + d) tan 20).
TEST(DeviceDeskMouse, TheHandleIsWhereTheCursorsRayMeetsItsDepth) {
  const MouseView view{std::tan(20.0 * M_PI / 180.0), 0.3};
  MouseMapping mouse({}, view);
  mouse.pointer(0.5, -0.25, false);
  const double at_start = 0.3 * std::tan(20.0 * M_PI / 180.0);
  EXPECT_NEAR(mouse.pose().position_m[0], 0.5 * at_start, 1e-15);
  EXPECT_NEAR(mouse.pose().position_m[1], -0.25 * at_start, 1e-15);
  // The wheel along a needle pointing into the view and down (unit (0, -0.6, 0.8)): 5 notches, 1 cm.
  mouse.set_needle_direction({{0.0, -0.6, 0.8}});
  mouse.scroll(5);
  EXPECT_NEAR(mouse.pose().position_m[1], -0.25 * at_start - 0.006, 1e-15);
  EXPECT_NEAR(mouse.pose().position_m[2], 0.1 + 0.008, 1e-15);
  // The cursor for the handle now, at its new depth 8 mm further: the cursor there puts it back.
  double x = 0.0, y = 0.0;
  mouse.cursor_at_handle(x, y);
  const double deeper = (0.3 + 0.008) * std::tan(20.0 * M_PI / 180.0);
  EXPECT_NEAR(x, 0.5 * at_start / deeper, 1e-12);
  EXPECT_NEAR(y, (-0.25 * at_start - 0.006) / deeper, 1e-12);
  const DeskPose before = mouse.pose();
  mouse.pointer(x, y, false);
  EXPECT_NEAR(mouse.pose().position_m[0], before.position_m[0], 1e-15);
  EXPECT_NEAR(mouse.pose().position_m[1], before.position_m[1], 1e-15);
}

TEST(DeviceDeskMouse, ReleasedElsewhereTheHandleMovesOnFromWhereItStayed) {
  MouseMapping mouse;
  mouse.pointer(0.0, 0.0, false);
  mouse.pointer(0.0, 0.0, true);
  mouse.pointer(0.4, 0.0, true);
  mouse.pointer(0.4, 0.0, false);  // the cursor was not put back
  EXPECT_EQ(mouse.pose().position_m[0], 0.0);
  mouse.pointer(0.5, 0.0, false);
  EXPECT_NEAR(mouse.pose().position_m[0], 0.01, 1e-15);
}

TEST(DeviceDeskKeyboard, EachPressIsOneStepAndShiftAFifth) {
  KeyboardMapping keys;
  keys.press(DeskKey::kRight, false);
  keys.press(DeskKey::kRight, false);
  keys.press(DeskKey::kUp, true);
  keys.press(DeskKey::kIn, false);
  keys.press(DeskKey::kSwingRight, false);
  keys.press(DeskKey::kTiltToward, true);
  EXPECT_NEAR(keys.pose().position_m[0], 0.002, 1e-15);
  EXPECT_NEAR(keys.pose().position_m[1], 0.0002, 1e-15);
  EXPECT_NEAR(keys.pose().position_m[2], 0.101, 1e-15);
  EXPECT_NEAR(keys.pose().wrist_rad[0], 1.0 * kDeg, 1e-15);
  EXPECT_NEAR(keys.pose().wrist_rad[1], -0.2 * kDeg, 1e-15);
  for (DeskKey key :
       {DeskKey::kLeft, DeskKey::kLeft, DeskKey::kDown, DeskKey::kOut, DeskKey::kSwingLeft, DeskKey::kTiltAway})
    keys.press(key, false);
  EXPECT_NEAR(keys.pose().position_m[0], 0.0, 1e-15);
  EXPECT_NEAR(keys.pose().wrist_rad[1], 0.8 * kDeg, 1e-15);
  for (int i = 0; i < 200; ++i) keys.press(DeskKey::kTiltAway, false);
  EXPECT_NEAR(keys.pose().wrist_rad[1], 80.0 * kDeg, 1e-15) << "the tilt stops at its limit";
  keys.press(DeskKey::kTiltToward, false);
  EXPECT_NEAR(keys.pose().wrist_rad[1], 79.0 * kDeg, 1e-12) << "and comes back at once";
}

// W and S go along the needle, not into the screen: a needle pointing down the screen and 30 deg
// into it, (0, -cos 30, sin 30).
TEST(DeviceDeskKeyboard, InAndOutGoAlongTheNeedle) {
  KeyboardMapping keys;
  keys.set_needle_direction({{0.0, -std::cos(M_PI / 6), std::sin(M_PI / 6)}});
  keys.press(DeskKey::kIn, false);
  keys.press(DeskKey::kIn, false);
  keys.press(DeskKey::kOut, true);
  EXPECT_NEAR(keys.pose().position_m[0], 0.0, 1e-15);
  EXPECT_NEAR(keys.pose().position_m[1], -0.0018 * std::cos(M_PI / 6), 1e-15);
  EXPECT_NEAR(keys.pose().position_m[2], 0.1 + 0.0018 * std::sin(M_PI / 6), 1e-15);
}

TEST(DeviceDeskGamepad, DeadZonesAreCutAndTheRestRescaled) {
  double x = 0.1, y = -0.1;  // inside the 0.15 radius
  stick_past_dead_zone(x, y, 0.15);
  EXPECT_EQ(x, 0.0);
  EXPECT_EQ(y, 0.0);
  x = 0.575, y = 0.0;  // halfway from the dead zone's edge to full
  stick_past_dead_zone(x, y, 0.15);
  EXPECT_NEAR(x, 0.5, 1e-12);
  x = 1.0, y = 1.0;  // a corner is full deflection, not more
  stick_past_dead_zone(x, y, 0.15);
  EXPECT_NEAR(std::hypot(x, y), 1.0, 1e-12);
  EXPECT_EQ(trigger_past_dead_zone(-1.0, 0.05), 0.0);
  EXPECT_EQ(trigger_past_dead_zone(-0.95, 0.05), 0.0);
  EXPECT_NEAR(trigger_past_dead_zone(1.0, 0.05), 1.0, 1e-12);
  x = std::nan(""), y = 0.9;
  stick_past_dead_zone(x, y, 0.15);
  EXPECT_EQ(x, 0.0) << "a NaN axis counts as centred";
}

TEST(DeviceDeskGamepad, DeflectionIsARate) {
  GamepadMapping pad;
  GamepadState s;
  s.axes[GamepadState::kLeftX] = 1.0f;         // full right
  s.axes[GamepadState::kLeftY] = -1.0f;        // full up (y points down)
  s.axes[GamepadState::kRightTrigger] = 1.0f;  // pushing in
  s.axes[GamepadState::kRightX] = 1.0f;
  for (int frame = 0; frame < 50; ++frame) pad.update(s, 0.02);  // one second
  // Both stick axes full is a radial deflection of 1 along the diagonal.
  EXPECT_NEAR(pad.pose().position_m[0], 0.02 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(pad.pose().position_m[1], 0.02 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(pad.pose().position_m[2], 0.1 + 0.02, 1e-12);
  EXPECT_NEAR(pad.pose().wrist_rad[0], 30.0 * kDeg, 1e-12);
  EXPECT_EQ(pad.pose().wrist_rad[1], 0.0);

  GamepadState rest;  // released: nothing moves, however long
  const DeskPose held = pad.pose();
  for (int frame = 0; frame < 50; ++frame) pad.update(rest, 0.02);
  EXPECT_EQ(pad.pose().position_m[2], held.position_m[2]);

  GamepadMapping stalled;
  stalled.update(s, 5.0);  // a frame that took 5 s moves as far as one of 0.1 s
  EXPECT_NEAR(stalled.pose().position_m[2], 0.1 + 0.02 * 0.1, 1e-12);
}

TEST(DeviceDeskGamepad, StartResetsAFaultOncePerPress) {
  GamepadMapping pad;
  GamepadState s;
  EXPECT_FALSE(pad.take_fault_reset());
  s.buttons[GamepadState::kStart] = 1;
  pad.update(s, 0.02);
  pad.update(s, 0.02);  // still held
  EXPECT_TRUE(pad.take_fault_reset());
  EXPECT_FALSE(pad.take_fault_reset());
  s.buttons[GamepadState::kStart] = 0;
  pad.update(s, 0.02);
  s.buttons[GamepadState::kStart] = 1;
  pad.update(s, 0.02);
  EXPECT_TRUE(pad.take_fault_reset());
}

}  // namespace
}  // namespace needle::haptics
