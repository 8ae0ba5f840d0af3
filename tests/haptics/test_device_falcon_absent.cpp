#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

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

TEST(DeviceFalcon, AFirmwarePathThatIsNotARegularFileIsRefusedBeforeItIsOpened) {
  const std::string fifo = ::testing::TempDir() + "/falcon_fifo_" + std::to_string(::getpid()) + ".bin";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path :
       {fifo, std::string("/dev/zero")}) {  // a pipe nobody writes would block; zeros never end
    FalconOptions options;
    options.firmware_path = path;
    FalconDevice falcon(options);
    try {
      falcon.open();
      ADD_FAILURE() << path;
    } catch (const DeviceError& e) {
      EXPECT_EQ(std::string(e.what()),
                "falcon: firmware file " + path + ": not a regular file (a device, a pipe or a folder)");
    }
  }
  ::unlink(fifo.c_str());
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
