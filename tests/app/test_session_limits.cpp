// Inputs that would run away: a session lasts at most as long as its task can (its steps' time
// limits plus a margin), however long its operator's script; a recording's file name is made from
// a safe form of the task's name, whatever the name holds.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "haptics/recording/session_format.hpp"
#include "recorded_session.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

TEST(SessionLimits, ARecordingIsNamedFromASafeFormOfTheTaskName) {
  const fs::path dir = process_folder(output_dir() / "recording_names");
  const fs::path recordings = fs::absolute(dir / "recordings");
  for (const std::string& name : {std::string("../../../escaped_rec"), std::string("a\0b/c", 5), std::string(300, 'n'),
                                  std::string(), std::string("penetrable_sphere")}) {
    const fs::path path = app::new_recording_path(dir / "sessions.db", name);
    EXPECT_EQ(path.parent_path(), recordings) << name;
    const std::string file = path.filename().string();
    EXPECT_EQ(file.find('\0'), std::string::npos);
    EXPECT_EQ(file.rfind(".nrec"), file.size() - 5) << file;
    EXPECT_EQ(file.find(".."), std::string::npos) << file;
    EXPECT_LE(file.size(), 64u + 40u) << file;
  }
  EXPECT_EQ(app::new_recording_path(dir / "sessions.db", "../../../escaped_rec")
                .filename()
                .string()
                .rfind("_________escaped_rec_", 0),
            0u);
}

TEST(SessionLimits, ARunEndsWhenItsTaskMustHaveEndedHoweverLongTheScript) {
  const fs::path dir = process_folder(output_dir() / "bounded_run");
  // The rigid task's good script with a last waypoint at 200 s, where the task (steps of 20, 20,
  // 20 and 15 s at most) has ended by 79 s.
  nlohmann::json script = nlohmann::json::parse(std::ifstream(source_dir() / "assets/tasks/rigid_sphere_good.json"));
  nlohmann::json last = script["hand"]["waypoints"].back();
  last["t"] = 200.0;
  script["hand"]["waypoints"].push_back(last);
  std::ofstream(dir / "long_script.json") << script.dump();

  app::TaskSessionOptions options;
  options.task = source_dir() / "assets/tasks/rigid_sphere.json";
  options.rig.operator_spec = (dir / "long_script.json").string();
  options.trainee = "ana";
  options.db = dir / "sessions.db";
  options.out_dir = dir / "out";
  std::string said;  // what the session tells its user
  options.messages.line = [&said](const std::string& line) { said += line + "\n"; };
  app::TaskSession session(options);
  EXPECT_NE(said.find("note: the operator script runs 204.0 s, past the latest end of the task (79.0 s"),
            std::string::npos)
      << said;
  ASSERT_TRUE(session.duration_s());
  EXPECT_DOUBLE_EQ(*session.duration_s(), 204.0);
  EXPECT_EQ(session.tick_budget(), 79u * 500u);
  session.run_offline([](size_t) {});
  EXPECT_EQ(session.samples(), 79u * 500u);
  const training::SessionResult* result = session.finish();
  ASSERT_NE(result, nullptr);
  EXPECT_TRUE(result->finished);
  EXPECT_EQ(haptics::read_session(session.recording_path().string()).records.size(), 79u * 500u);
}

}  // namespace
}  // namespace needle::test
