// A recording's context as a replay reads it: checked, and a context written before a key existed
// given the value its absence meant then (the thesis law, no tool-law springs, no desk wrist).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "haptics/control/gains.hpp"
#include "haptics/recording/recording_context.hpp"

namespace needle::haptics {
namespace {

using nlohmann::json;

SessionHeader header_with(const std::string& context, uint32_t version = kSessionFormatVersion) {
  SessionHeader h;
  h.version = version;
  h.rate_hz = 1000.0;
  h.device = "mouse";
  h.context = context;
  return h;
}

json current_context() {
  return {{"version", kRecordingContextVersion},
          {"task", "t.json"},
          {"task_text", "{}"},
          {"device", "mouse"},
          {"scenario",
           {{"gains",
             {{"law", "tool"},
              {"lateral_stiffness_N_per_m", 40.0},
              {"axial_stiffness_N_per_m", 5.0},
              {"passivity_max_damping_per_tick", 1.0}}}}},
          {"coupling", {{"workspace_scale", 1.0}, {"wrist", true}}},
          {"practice", true},
          {"safety_limits", {{"max_force_n", 3.3}}}};
}

TEST(RecordingContext, ACurrentContextIsReadAsWritten) {
  const json context = current_context();
  EXPECT_EQ(read_recording_context("r.nrec", header_with(context.dump())), context);
}

TEST(RecordingContext, AnOlderContextGetsWhatItsMissingKeysMeantThen) {
  json old = current_context();
  old["scenario"]["gains"] = json::object({{"force_scale", 1.0}});
  old["coupling"].erase("wrist");
  const json read = read_recording_context("r.nrec", header_with(old.dump()));
  const json& gains = read["scenario"]["gains"];
  EXPECT_EQ(control_law_named(gains["law"].get<std::string>()), ControlLaw::Thesis) << "recorded before the tool law";
  EXPECT_EQ(gains["lateral_stiffness_N_per_m"], 0.0);
  EXPECT_EQ(gains["axial_stiffness_N_per_m"], 0.0);
  EXPECT_EQ(gains["force_scale"], 1.0) << "the rest untouched";
  EXPECT_EQ(read["coupling"]["wrist"], false);
  old.erase("practice");
  EXPECT_EQ(read_recording_context("r.nrec", header_with(old.dump()))["practice"], false)
      << "recorded before practice runs";

  old.erase("coupling");  // joint to joint, as the first recordings of sim sessions
  EXPECT_TRUE(read_recording_context("r.nrec", header_with(old.dump()))["coupling"].is_null());
}

TEST(RecordingContext, AContextThatCannotRebuildItsSessionIsRefusedNamingTheFile) {
  struct Case {
    SessionHeader header;
    const char* says;
  };
  json wrong_version = current_context();
  wrong_version["version"] = "2";
  json no_text = current_context();
  no_text.erase("task_text");
  json bad_practice = current_context();
  bad_practice["practice"] = "yes";
  std::string practice_twice = current_context().dump();  // a reader would keep one of the two
  practice_twice.insert(practice_twice.size() - 1, ",\"practice\":true,\"practice\":false");
  for (const Case& c :
       {Case{header_with(current_context().dump(), 2), "r.nrec: header: format version 2 has no checksums"},
        Case{header_with(""), "r.nrec: header: context: none (recorded by another program)"},
        Case{header_with("{not json"), "r.nrec: header: context: not valid JSON"},
        Case{header_with("[1]"), "r.nrec: header: context: expected version 2"},
        Case{header_with(wrong_version.dump()), "r.nrec: header: context: expected version 2"},
        Case{header_with(no_text.dump()), "r.nrec: header: context: missing \"task_text\""},
        Case{header_with(bad_practice.dump()), "r.nrec: header: context: practice is not true or false"},
        Case{header_with(practice_twice),
             "r.nrec: header: context: /practice: the key is given twice in its object"}}) {
    try {
      read_recording_context("r.nrec", c.header);
      ADD_FAILURE() << c.says;
    } catch (const RecordingError& e) {
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace needle::haptics
