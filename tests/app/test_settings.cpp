// The settings file: where it lives, a round trip, the defaults without one, a damaged file set
// aside with a message naming it, a newer one left alone, a write that cannot happen.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "app/settings.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Settings, LiveInTheUsersConfigFolder) {
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string kept = old ? old : "";
  setenv("XDG_CONFIG_HOME", "/tmp/cfg", 1);
  EXPECT_EQ(app::default_settings_file(), fs::path("/tmp/cfg/needle-sim/settings.json"));
  unsetenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if (home) {
    EXPECT_EQ(app::default_settings_file(), fs::path(home) / ".config/needle-sim/settings.json");
  }
  if (old) setenv("XDG_CONFIG_HOME", kept.c_str(), 1);
}

TEST(Settings, RoundTripAndDefaultsWithoutAFile) {
  const fs::path dir = process_folder(output_dir() / "settings_round_trip");
  const fs::path file = dir / "new_folder" / "settings.json";
  const app::LoadedSettings none = app::load_settings(file);
  EXPECT_TRUE(none.notice.empty());
  EXPECT_TRUE(none.writable);
  EXPECT_EQ(none.settings.device.text(), "mouse");
  EXPECT_EQ(none.settings.window.width, 1280u);
  EXPECT_TRUE(none.settings.trainee.empty());

  app::Settings s;
  s.trainee = "Ana María";
  s.device = haptics::DeviceSpec::parse("gamepad:1");
  s.window = {1920, 1080};
  app::save_settings(file, s);  // makes the folder
  const std::string text = text_of(file);
  EXPECT_NE(text.find("\"version\": 1"), std::string::npos) << text;
  EXPECT_NE(text.find("\"section\": \"off\""), std::string::npos) << text;
  const app::LoadedSettings back = app::load_settings(file);
  EXPECT_TRUE(back.notice.empty()) << back.notice;
  EXPECT_EQ(back.settings.trainee, "Ana María");
  EXPECT_EQ(back.settings.device.text(), "gamepad:1");
  EXPECT_EQ(back.settings.window.width, 1920u);
  EXPECT_EQ(back.settings.window.height, 1080u);
  for (const fs::directory_entry& e : fs::directory_iterator(file.parent_path()))
    EXPECT_EQ(e.path().filename(), "settings.json") << "no temporary file is left";
}

TEST(Settings, TheRenderScaleRoundTrips) {
  const fs::path file = process_folder(output_dir() / "settings_render_scale") / "settings.json";
  app::Settings s;
  app::save_settings(file, s);
  EXPECT_NE(text_of(file).find("\"render_scale\": \"auto\""), std::string::npos) << text_of(file);
  EXPECT_FALSE(app::load_settings(file).settings.render_scale);
  s.render_scale = 0.7f;
  app::save_settings(file, s);
  const app::LoadedSettings back = app::load_settings(file);
  EXPECT_TRUE(back.notice.empty()) << back.notice;
  EXPECT_FLOAT_EQ(back.settings.render_scale.value_or(0.0f), 0.7f);
}

TEST(Settings, TheViewsRoundTrip) {
  const fs::path file = process_folder(output_dir() / "settings_views") / "settings.json";
  app::Settings s;
  s.views.section = engine::Section::Mode::Translucent;
  s.views.ultrasound = true;
  s.views.probe = {0.004, -0.002, 0.0872664626};  // 4 mm along, 2 mm back across, turned 5°
  app::save_settings(file, s);
  const std::string text = text_of(file);
  EXPECT_NE(text.find("\"section\": \"translucent\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"turn_deg\": 5."), std::string::npos) << text;  // degrees in the file
  const app::LoadedSettings back = app::load_settings(file);
  EXPECT_TRUE(back.notice.empty()) << back.notice;
  EXPECT_EQ(back.settings.views.section, engine::Section::Mode::Translucent);
  EXPECT_TRUE(back.settings.views.ultrasound);
  EXPECT_DOUBLE_EQ(back.settings.views.probe.along_m, 0.004);
  EXPECT_DOUBLE_EQ(back.settings.views.probe.across_m, -0.002);
  EXPECT_NEAR(back.settings.views.probe.turn_rad, 0.0872664626, 1e-15);
  s.views = {};  // off, closed, unmoved: what a file without "views" gives
  app::save_settings(file, s);
  EXPECT_EQ(app::load_settings(file).settings.views, app::ViewSettings{});
  std::ofstream(file) << "{\"version\": 1}";
  EXPECT_EQ(app::load_settings(file).settings.views, app::ViewSettings{});
}

TEST(Settings, ADamagedFileIsSetAsideWithAMessageNamingIt) {
  const fs::path dir = process_folder(output_dir() / "settings_damaged");
  const fs::path file = dir / "settings.json";
  struct Case {
    const char* text;
    const char* says;
  };
  for (const Case& c :
       {Case{"{\"version\": 1, \"trainee\": \"ana\"", "not valid JSON"},
        Case{"{\"version\": 1, \"colour\": \"red\"}", "/colour: unknown key"},
        Case{"{\"version\": 1, \"device\": \"phantom\"}", "/device: unknown device \"phantom\""},
        Case{"{\"version\": 1, \"device\": \"gamepad:16\"}", "/device: unknown device \"gamepad:16\""},
        Case{"{\"version\": 1, \"device\": \"sim\"}", "/device: device \"sim\" is no trainee's device"},
        Case{"{\"version\": 1, \"window\": {\"width\": 10, \"height\": 720}}", "/window/width"},
        Case{"{\"version\": 1, \"views\": {\"xray\": true}}", "/views/xray: unknown key"},
        Case{"{\"version\": 1, \"views\": {\"section\": \"sliced\"}}",
             "/views/section: \"sliced\": expected off, cut or translucent"},
        Case{"{\"version\": 1, \"views\": {\"ultrasound\": 1}}", "/views/ultrasound: expected true or false"},
        Case{"{\"version\": 1, \"views\": {\"probe\": {\"along_m\": 2}}}", "/views/probe/along_m"},
        Case{"{\"version\": 1, \"views\": {\"probe\": {\"turn_deg\": \"left\"}}}", "/views/probe/turn_deg"},
        Case{"{\"version\": 1, \"render_scale\": \"fast\"}",
             "/render_scale: expected \"auto\" or a number in [0.25, 1]"},
        Case{"{\"version\": 1, \"render_scale\": 0.1}", "/render_scale: must be in [0.25, 1]"},
        Case{"{\"trainee\": \"ana\"}", "/version: missing"}, Case{"[1, 2]", "expected an object"}}) {
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) fs::remove(e.path());
    std::ofstream(file) << c.text;
    const app::LoadedSettings loaded = app::load_settings(file);
    EXPECT_NE(loaded.notice.find(file.string()), std::string::npos) << loaded.notice;
    EXPECT_NE(loaded.notice.find(c.says), std::string::npos) << loaded.notice;
    EXPECT_NE(loaded.notice.find("set aside as " + file.string() + ".damaged-"), std::string::npos) << loaded.notice;
    EXPECT_TRUE(loaded.settings.trainee.empty()) << "nothing of a damaged file is used";
    EXPECT_FALSE(fs::exists(file));
    int aside = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) aside += text_of(e.path()) == c.text;
    EXPECT_EQ(aside, 1) << "the damaged file is kept as it was";
  }
}

TEST(Settings, ANewerFileIsLeftAloneAndNotOverwritten) {
  const fs::path dir = process_folder(output_dir() / "settings_newer");
  const fs::path file = dir / "settings.json";
  std::ofstream(file) << "{\"version\": 7, \"hologram\": true}";
  const app::LoadedSettings loaded = app::load_settings(file);
  EXPECT_FALSE(loaded.writable);
  EXPECT_NE(loaded.notice.find("newer needle-sim"), std::string::npos) << loaded.notice;
  EXPECT_EQ(text_of(file), "{\"version\": 7, \"hologram\": true}");
}

TEST(Settings, AWriteThatCannotHappenNamesTheFile) {
  const fs::path dir = process_folder(output_dir() / "settings_unwritable");
  std::ofstream(dir / "a_file") << "x";
  const fs::path file = dir / "a_file" / "settings.json";  // its folder is a file
  try {
    app::save_settings(file, {});
    FAIL() << "wrote under a file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": cannot write"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace needle::test
