#include <gtest/gtest.h>

#include "haptics/devices/falcon/falcon_device.hpp"
#include "haptics/devices/falcon/falcon_hotplug.hpp"

namespace needle::haptics::falcon {
namespace {

// Without hardware only the bookkeeping can be checked: the watcher starts and stops
// cleanly, explains itself when hotplug is unavailable, and counts the Falcons already
// plugged in as arrivals (LIBUSB_HOTPLUG_ENUMERATE), which is none on a CI machine.
TEST(DeviceFalconHotplug, WatcherStartsStopsAndCountsWhatIsPresent) {
  FalconHotplug watcher;
  if (!watcher.supported()) {
    EXPECT_FALSE(watcher.reason().empty());
    GTEST_SKIP() << watcher.reason();
  }
  EXPECT_EQ(watcher.arrivals(), static_cast<uint64_t>(find_falcons().count));
  EXPECT_EQ(watcher.departures(), 0u);
}

}  // namespace
}  // namespace needle::haptics::falcon
