#include <gtest/gtest.h>

#include "haptics/devices/mouse_device.hpp"

namespace needle::haptics {
namespace {

TEST(DeviceMouse, CursorAndScrollMapOntoTheWorkspace) {
  MouseMapping m;  // x, y in [-0.1, 0.1] m, z in [0, 0.2] m, 2 mm per step
  MouseDevice mouse(m);
  DeviceReading r;
  mouse.read(r);
  EXPECT_EQ(r.position_m[0], 0.0);
  EXPECT_EQ(r.position_m[2], 0.1) << "centre of the depth range before any scroll";
  mouse.set_pointer(0.5, -1.0);
  mouse.add_depth_steps(3);
  mouse.set_buttons(1);
  mouse.read(r);
  EXPECT_NEAR(r.position_m[0], 0.05, 1e-15);   // three quarters across [-0.1, 0.1]
  EXPECT_NEAR(r.position_m[1], -0.1, 1e-15);
  EXPECT_NEAR(r.position_m[2], 0.106, 1e-15);  // 0.1 + 3 x 2 mm
  EXPECT_EQ(r.buttons, 1u);
  EXPECT_EQ(r.connected, 1u);
}

TEST(DeviceMouse, InputOutsideTheWindowOrRangeIsClamped) {
  MouseDevice mouse;
  mouse.set_pointer(7.0, -3.0);
  mouse.add_depth_steps(1000);  // far past the top: 50 steps reach it
  mouse.add_depth_steps(-1);    // one step back down is felt at once
  DeviceReading r;
  mouse.read(r);
  EXPECT_NEAR(r.position_m[0], 0.1, 1e-15);
  EXPECT_NEAR(r.position_m[1], -0.1, 1e-15);
  EXPECT_NEAR(r.position_m[2], 0.198, 1e-12);
}

TEST(DeviceMouse, EveryReadIsFreshAndTheDeviceCannotPush) {
  MouseDevice mouse;
  DeviceReading a, b;
  mouse.read(a);
  mouse.read(b);
  EXPECT_EQ(b.sequence, a.sequence + 1);
  EXPECT_EQ(mouse.capabilities().actuated_axes, 0u);
  EXPECT_EQ(mouse.capabilities().max_force_n, 0.0);
  EXPECT_EQ(mouse.capabilities().command_space, CommandSpace::kNone);
}

}  // namespace
}  // namespace needle::haptics
