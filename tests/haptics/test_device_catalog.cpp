#include <gtest/gtest.h>

#include <string>

#include "haptics/devices/device_catalog.hpp"

namespace needle::haptics {
namespace {

TEST(DeviceCatalog, SpecsBuildTheirBackends) {
  const auto made = [](const char* spec) { return make_device(DeviceSpec::parse(spec), {})->capabilities().name; };
  EXPECT_EQ(made("mouse"), "mouse");
  EXPECT_EQ(made("keyboard"), "keyboard");
  EXPECT_EQ(made("gamepad:1"), "gamepad:1");
  EXPECT_EQ(made("falcon"), "falcon");
  EXPECT_EQ(made("falcon:2"), "falcon");
  EXPECT_EQ(made("replay:/tmp/x.nsrec"), "replay:/tmp/x.nsrec");
}

TEST(DeviceCatalog, TheSimulatedMasterIsNotBuiltHere) {
  try {
    make_device(DeviceSpec::parse("sim:a.json"), {});
    FAIL();
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("sim:a.json"), std::string::npos) << e.what();
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
