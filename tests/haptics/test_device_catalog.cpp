#include <gtest/gtest.h>

#include <string>

#include "haptics/devices/device_catalog.hpp"

namespace needle::haptics {
namespace {

TEST(DeviceCatalog, SpecsBuildTheirBackends) {
  EXPECT_EQ(make_device("mouse", {})->capabilities().name, "mouse");
  EXPECT_EQ(make_device("keyboard", {})->capabilities().name, "keyboard");
  EXPECT_EQ(make_device("gamepad:1", {})->capabilities().name, "gamepad:1");
  EXPECT_EQ(make_device("falcon", {})->capabilities().name, "falcon");
  EXPECT_EQ(make_device("falcon:2", {})->capabilities().name, "falcon");
  EXPECT_EQ(make_device("replay:/tmp/x.nsrec", {})->capabilities().name, "replay:/tmp/x.nsrec");
}

TEST(DeviceCatalog, UnknownOrMalformedSpecsAreNamed) {
  for (const std::string spec : {"phantom", "falcon:x", "replay:", "sim:a.json", "gamepad:x"}) {
    try {
      make_device(spec, {});
      FAIL() << spec;
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find(spec), std::string::npos) << e.what();
    }
  }
}

TEST(DeviceCatalog, ListsEveryBackendWithWhatItNeeds) {
  const auto backends = list_backends();
  ASSERT_EQ(backends.size(), 6u);
  EXPECT_EQ(backends[0].spec, "falcon[:N]");
  EXPECT_NE(backends[0].needs.find("0403:cb48"), std::string::npos);
  for (const auto& b : backends) {
    EXPECT_FALSE(b.status.empty()) << b.spec;
    EXPECT_FALSE(b.needs.empty()) << b.spec;
  }
}

}  // namespace
}  // namespace needle::haptics
