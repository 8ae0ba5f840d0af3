#include <gtest/gtest.h>

#include <string>

#include "haptics/devices/falcon/falcon_device.hpp"

namespace needle::haptics::falcon {
namespace {

TEST(DeviceFalcon, MissingFirmwareFileIsNamed) {
  FalconOptions options;
  options.firmware_path = "/nonexistent/novint.bin";
  FalconDevice falcon(options);
  try {
    falcon.open();
    FAIL() << "open succeeded without a firmware file";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/novint.bin"), std::string::npos) << e.what();
  }
}

// CI machines have no Falcon: open() must say so clearly rather than crash or hang.
TEST(DeviceFalcon, AbsentDeviceGivesAClearError) {
  if (find_falcons().count > 0) GTEST_SKIP() << "a Falcon is plugged in";
  FalconDevice falcon(FalconOptions{});
  try {
    falcon.open();
    FAIL() << "open succeeded without a device";
  } catch (const DeviceError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("falcon: ", 0), 0u) << what;
    EXPECT_TRUE(what.find("0403:cb48") != std::string::npos || what.find("libusb") != std::string::npos) << what;
  }
  DeviceReading r;
  falcon.read(r);
  EXPECT_EQ(r.connected, 0u) << "an unopened Falcon reads as disconnected";
}

}  // namespace
}  // namespace needle::haptics::falcon
