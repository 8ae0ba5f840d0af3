// Device specs as a user types them: every documented form parses to its kind and prints back
// the same; anything else is refused naming the text and what was expected.
#include <gtest/gtest.h>

#include <string>

#include "haptics/devices/device_spec.hpp"

namespace needle::haptics {
namespace {

using Kind = DeviceSpec::Kind;

TEST(DeviceSpec, EveryDocumentedFormParsesAndPrintsBack) {
  struct Case {
    const char* text;
    DeviceSpec spec;
  };
  for (const Case& c :
       {Case{"sim", {Kind::kSim}}, Case{"sim:a/b.json", {Kind::kSim, std::nullopt, "a/b.json"}},
        Case{"mouse", {Kind::kMouse}}, Case{"keyboard", {Kind::kKeyboard}}, Case{"gamepad", {Kind::kGamepad}},
        Case{"gamepad:0", {Kind::kGamepad, 0}}, Case{"gamepad:15", {Kind::kGamepad, 15}},
        Case{"falcon", {Kind::kFalcon}}, Case{"falcon:2", {Kind::kFalcon, 2}},
        Case{"replay:/data/x:y.nrec", {Kind::kReplay, std::nullopt, "/data/x:y.nrec"}}}) {
    const DeviceSpec parsed = DeviceSpec::parse(c.text);
    EXPECT_EQ(parsed, c.spec) << c.text;
    EXPECT_EQ(parsed.text(), c.text);
  }
}

TEST(DeviceSpec, WhoMovesTheNeedle) {
  for (const char* desk : {"mouse", "keyboard", "gamepad", "gamepad:3"}) {
    EXPECT_TRUE(DeviceSpec::parse(desk).desk()) << desk;
    EXPECT_TRUE(DeviceSpec::parse(desk).live()) << desk;
  }
  EXPECT_FALSE(DeviceSpec::parse("falcon:1").desk());
  EXPECT_TRUE(DeviceSpec::parse("falcon:1").live());
  for (const char* scripted : {"sim", "replay:a.nrec"}) {
    EXPECT_FALSE(DeviceSpec::parse(scripted).desk()) << scripted;
    EXPECT_FALSE(DeviceSpec::parse(scripted).live()) << scripted;
  }
  EXPECT_EQ(DeviceSpec{}.text(), "sim") << "the default";
}

TEST(DeviceSpec, AnythingElseIsRefusedNamingTheTextAndTheForms) {
  struct Case {
    const char* text;
    const char* says;
  };
  for (const Case& c :
       {Case{"", "empty"}, Case{"phantom", "unknown device"}, Case{"Mouse", "unknown device"},
        Case{"replay:", "expected a recording file after replay:"},
        Case{"replay", "expected a recording file after replay:"}, Case{"sim:", "expected a scenario file after sim:"},
        Case{"gamepad:", "an index from 0 to 15"}, Case{"gamepad:x", "an index from 0 to 15"},
        Case{"gamepad:16", "an index from 0 to 15"}, Case{"gamepad:-1", "an index from 0 to 15"},
        Case{"gamepad:01", "an index from 0 to 15"}, Case{"falcon:123", "an index from 0 to 15"},
        Case{"falcon: 1", "an index from 0 to 15"}, Case{"mouse:1", "mouse takes nothing after ':'"},
        Case{"keyboard:", "keyboard takes nothing after ':'"}}) {
    try {
      DeviceSpec::parse(c.text);
      ADD_FAILURE() << "accepted '" << c.text << "'";
    } catch (const DeviceSpecError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("device '" + std::string(c.text) + "': ", 0), 0u) << what;
      EXPECT_NE(what.find(c.says), std::string::npos) << what;
      EXPECT_NE(what.find(kDeviceSpecForms), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace needle::haptics
