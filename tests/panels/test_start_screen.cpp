// The start screen drawn headless against goldens at 1280x720 and 1920x1080 (the text grows with
// the window: 13 px, then 20 px), and its keyboard: every choice on it is reachable by a key.
#include <gtest/gtest.h>
#include <imgui.h>

#include "engine/gpu_device.hpp"
#include "image_compare.hpp"
#include "ui/panel_picture.hpp"
#include "ui/start_screen.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

ui::StartState screen() {
  ui::StartState s;
  ui::set_trainee_name(s, "ana");
  s.known_trainees = {"ana", "bo", "Carla"};
  s.tasks = {
      {"Penetrable sphere: insert, pivot 45 degrees about the tip, insert deeper to the target (thesis 4.4)",
       "Needle into soft tissue: steer in along a planned line, turn the needle about its tip inside the tissue, "
       "reach a target and pull out.",
       "", "last 81, passed   best 85   3 done"},
      {"Rigid sphere: touch, align with the normal, press and hold, release (thesis 4.3)",
       "Contact with a rigid surface: touch a point, line the needle up with the surface normal, press with a steady "
       "force in a band, let go.",
       "", std::nullopt},
      {"", "", "assets/tasks/x.json: /steps/2/condition/marker: no marker named \"targte\"", std::nullopt}};
  s.devices = {
      {"mouse", "Mouse", "cursor: move   wheel or Up/Down: in and out   right button held: turn about the tip", true},
      {"keyboard", "Keyboard", "arrows: move", true},
      {"gamepad:0", "Gamepad 0 (Xbox Controller)", "left stick: move", true},
      {"falcon", "Falcon (none connected)", "no Falcon connected", false}};
  return s;
}

class StartScreen : public VulkanTest {
 protected:
  // Draws `state` at `extent`, checks the text size ImGui used and the picture against the golden
  // `name` (tests/README.md: a pixel differs past 8 counts in a channel, at most 0.2% may).
  void expect_golden(engine::Extent extent, ui::StartState& state, float font_px, const char* name) {
    float font = 0;
    const engine::RgbaImage image = ui::panel_picture(device(), extent, [&] {
      ui::draw_start_screen(state);
      font = ImGui::GetFontSize();
    });
    EXPECT_EQ(font, font_px);
    EXPECT_TRUE(matches_golden(image, name));
  }
};

TEST_F(StartScreen, At1280x720MatchesGolden) {
  ui::StartState s = screen();
  expect_golden({1280, 720}, s, 13.0f, "start_screen_1280x720");
}

TEST_F(StartScreen, At1920x1080TheTextIsLargerAndMatchesGolden) {
  ui::StartState s = screen();
  s.device = 2;
  s.notice =
      "settings.json: /device: unknown device \"phantom\"; the file was set aside as "
      "settings.json.damaged-20260101T000000Z";
  expect_golden({1920, 1080}, s, 20.0f, "start_screen_1920x1080");
}

TEST(StartScreenKeys, EveryChoiceIsReachableByKey) {
  ui::StartState s = screen();
  using K = ui::StartKey;
  EXPECT_EQ(ui::start_key(s, K::kDown, false), ui::StartAction::kNone);
  EXPECT_EQ(s.task, 1u);
  ui::start_key(s, K::kDown, false);
  ui::start_key(s, K::kDown, false);
  EXPECT_EQ(s.task, 0u) << "round the list";
  ui::start_key(s, K::kUp, false);
  EXPECT_EQ(s.task, 2u);

  ui::start_key(s, K::kRight, false);
  ui::start_key(s, K::kRight, false);
  EXPECT_EQ(s.device, 2u);
  ui::start_key(s, K::kRight, false);
  EXPECT_EQ(s.device, 0u) << "the Falcon that is not connected is passed over";
  ui::start_key(s, K::kLeft, false);
  EXPECT_EQ(s.device, 2u);

  ui::start_key(s, K::kPageDown, false);
  EXPECT_EQ(ui::trainee_name(s), "bo");
  ui::start_key(s, K::kPageUp, false);
  ui::start_key(s, K::kPageUp, false);
  EXPECT_EQ(ui::trainee_name(s), "Carla");
  ui::start_key(s, K::kPractice, false);
  EXPECT_TRUE(s.practice) << "P: practice";
  ui::start_key(s, K::kPractice, true);
  EXPECT_TRUE(s.practice) << "a p typed in the name field is a letter";
  ui::start_key(s, K::kPractice, false);
  EXPECT_FALSE(s.practice);
  ui::start_key(s, K::kTab, false);
  EXPECT_TRUE(s.focus_name);

  // The broken task cannot start: the notice says why.
  EXPECT_EQ(ui::start_key(s, K::kEnter, false), ui::StartAction::kNone);
  EXPECT_NE(s.notice.find("does not load"), std::string::npos) << s.notice;
  ui::start_key(s, K::kDown, false);
  EXPECT_EQ(ui::start_key(s, K::kEnter, false), ui::StartAction::kStart);
  // While the name field has the keys only Enter answers here.
  EXPECT_EQ(ui::start_key(s, K::kDown, true), ui::StartAction::kNone);
  EXPECT_EQ(s.task, 0u);
  EXPECT_EQ(ui::start_key(s, K::kEnter, true), ui::StartAction::kStart);
  EXPECT_EQ(ui::start_key(s, K::kEscape, true), ui::StartAction::kNone) << "Escape leaves the field, it does not quit";
  EXPECT_TRUE(s.leave_name);
  EXPECT_EQ(ui::trainee_name(s), "Carla") << "and keeps the name";
  EXPECT_EQ(ui::start_key(s, K::kEscape, false), ui::StartAction::kQuit);
}

TEST(StartScreenKeys, NoStartWithoutAName) {
  ui::StartState s = screen();
  ui::set_trainee_name(s, "   ");
  EXPECT_EQ(ui::trainee_name(s), "");
  EXPECT_EQ(ui::start_key(s, ui::StartKey::kEnter, false), ui::StartAction::kNone);
  EXPECT_NE(s.notice.find("Type your name"), std::string::npos) << s.notice;
  ui::set_trainee_name(s, "  dee ");
  EXPECT_EQ(ui::trainee_name(s), "dee");
}

}  // namespace
}  // namespace needle::test
