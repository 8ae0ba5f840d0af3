// The trainee panel drawn headless over an empty view: mid-task (step, instruction, force
// gauge, live metrics, loop rate) and at the end (score, breakdown, advice; at 1920x1080 with the
// start screen's Retry, Next task and Back), against goldens (tests/README.md: a pixel differs
// past 8 counts in a channel, at most 0.2% may).
#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>

#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/scene.hpp"
#include "engine/ui_pass.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/guidance_overlay.hpp"
#include "ui/step_banner.hpp"
#include "ui/trainee_gauges.hpp"
#include "ui/trainee_panel.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

const std::filesystem::path kTask = test::source_dir() / "assets/tasks/penetrable_sphere.json";

// A result with the score's six components at these fractions of their weight.
training::SessionResult result_of(double total, bool passed, const double (&fractions)[6]) {
  training::SessionResult result;
  result.score.total = total;
  result.score.passed = passed;
  const char* names[6] = {"completion", "tip_error", "axis_deviation", "lateral_load", "peak_force", "time"};
  const double weights[6] = {30, 15, 10, 10, 10, 25};
  for (int i = 0; i < 6; ++i) result.score.components.push_back({names[i], fractions[i], weights[i]});
  return result;
}

// A state with the tip on the task's entry marker (the approach step's condition), the needle along
// the approach's planned axis (each shipped one in the x-z plane: the body x axis pitched about y).
haptics::ToolSnapshot at_entry(const training::Task& task) {
  haptics::ToolSnapshot s;
  const training::Vec3 entry = task.markers[size_t(task.marker_index("entry"))].position;
  for (int i = 0; i < 3; ++i) s.needle_tip_m[i] = entry[i];
  const training::Vec3& d = task.markers[size_t(task.steps[0].guidance.axis)].direction;
  const double pitch = std::atan2(-d[2], d[0]);
  s.needle_orientation[0] = std::cos(pitch / 2), s.needle_orientation[2] = std::sin(pitch / 2);
  return s;
}

// The view's live parts from the newest state, as the app fills them (TaskSession::draw_panel): its
// time, the step's cue in the task's scene's camera axes and in words.
void live(ui::TraineeView& view, const training::Task& task, const haptics::ToolSnapshot& s) {
  const size_t step = std::min(view.step.value_or(view.progress->current_step()), task.steps.size() - 1);
  view.now_s = s.time_s;
  view.cue = training::step_cue(task, step, s, ui::view_axes(engine::load_scene(task.scene).camera));
  view.cue_lines = training::cue_lines(task, step, s, *view.cue);
}

class TraineePanel : public VulkanTest {
 protected:
  engine::RgbaImage draw(const ui::TraineeView& view, engine::Extent extent = {480, 420}) {
    engine::HeadlessTarget target(device(), extent);
    engine::SceneRenderer renderer(device(), target, {1});
    engine::GpuScene scene(renderer, engine::Model{}, engine::Scene{});
    engine::UiPass ui(renderer, nullptr);
    engine::RgbaImage image;
    for (int frame = 0; frame < 2; ++frame) {  // ImGui sizes auto-fitting windows on the first frame
      ui.begin_frame(extent, 1.0f / 60.0f);
      ui::draw_trainee_panel(view);
      engine::FrameParams params = scene.frame_params();
      params.overlay = ui.end_frame();
      renderer.draw(target, params, frame == 1 ? &image : nullptr);
    }
    return image;
  }
};

TEST_F(TraineePanel, MidTaskMatchesGolden) {
  training::Task task = training::load_task(kTask);
  training::TaskProgress progress(task);
  haptics::ToolSnapshot start;
  progress.feed(start);  // step 1 active
  ui::TraineeView view{&task, &progress};
  view.step_metrics.tip_error_m = 0.0123;
  view.step_metrics.axis_deviation_deg = 4.5;
  view.step_metrics.lateral_load_Ns = 0.08;
  view.step_metrics.peak_hand_force_N = 1.4;
  view.step_metrics.path_length_m = 0.052;
  view.needle = {.along_N = 0.0, .sideways_N = 0.0, .rigid_N = 1.1, .total_N = 1.1};
  view.hand_force_N = 1.1;
  view.loop_rate_hz = 1000.0;
  live(view, task, start);
  EXPECT_TRUE(matches_golden(draw(view, {480, 520}), "panel_trainee_running"));
}

TEST_F(TraineePanel, ResultMatchesGolden) {
  training::Task task = training::load_task(kTask);
  training::TaskProgress progress(task);
  training::SessionResult result = result_of(62.0, false, {1.0, 0.4, 0.2, 0.9, 1.0, 0.8});
  result.score.reasons_failed = {"score 62 is below the pass mark 70"};
  ui::TraineeView view{&task, &progress};
  view.result = &result;
  view.loop_rate_hz = 999.8;
  view.fault = "energy growth";
  EXPECT_TRUE(matches_golden(draw(view), "panel_trainee_result"));
}

// From the start screen, at 1920x1080: the text at 20 px, the panel as much wider, and the
// choices at the end under it.
TEST_F(TraineePanel, ResultWithTheStartScreensChoicesAt1920x1080MatchesGolden) {
  training::Task task = training::load_task(kTask);
  training::TaskProgress progress(task);
  const training::SessionResult result = result_of(86.0, true, {1.0, 0.8, 0.7, 0.9, 1.0, 0.6});
  ui::TraineeView view{&task, &progress};
  view.result = &result;
  view.loop_rate_hz = 1000.0;
  view.controls = "cursor: move   wheel or Up/Down: in and out   right button held: turn about the tip";
  view.choices = {{"Retry (R)", [] {}}, {"Next task (N)", [] {}}, {"Back (Esc)", [] {}}};
  EXPECT_TRUE(matches_golden(draw(view, {1920, 1080}), "panel_trainee_result_choices_1920x1080"));
}

// The layered target mid-task: step 3 (to the target), the tip in the muscle with the
// skin punctured; the panel names the layer and the punctures.
TEST_F(TraineePanel, LayeredTargetShowsTheLayerAndThePuncturesMatchesGolden) {
  const training::Task task = training::load_task(test::source_dir() / "assets/tasks/layered_target.json");
  training::TaskProgress progress(task);
  haptics::ToolSnapshot s = at_entry(task);
  progress.feed(s);           // the approach done
  s.needle_tip_m[2] -= 0.02;  // 20 mm deep, in the muscle
  s.contact = haptics::ContactState::kTissue;
  s.tissue.tip_layer = task.layer_index("muscle");
  s.tissue.punctured_layers =
      (1u << task.layer_index("skin")) | (1u << task.layer_index("fat")) | (1u << task.layer_index("muscle"));
  s.tissue.axial_force_N = 0.8;
  for (const double t : {0.1, 0.4, 0.5}) {  // through_skin held 0.2 s, then to_target begun
    s.time_s = t;
    progress.feed(s);
  }
  ASSERT_EQ(progress.current_step(), 2u);
  ui::TraineeView view{&task, &progress};
  view.tissue = s.tissue;
  view.step_metrics.tip_error_m = 0.0142;
  view.step_metrics.axis_deviation_deg = 3.1;
  view.needle = {.along_N = 0.8, .sideways_N = 0.12, .rigid_N = 0.0, .total_N = std::hypot(0.8, 0.12)};
  view.hand_force_N = view.needle.total_N;
  view.loop_rate_hz = 1000.0;
  s.time_s = 9.0;
  live(view, task, s);
  EXPECT_TRUE(matches_golden(draw(view, {480, 560}), "panel_trainee_layered_target"));
}

// The epidural with the layer names hidden (an assessment run): the dura punctured in the loss of
// resistance step ends it with the reason, the layers shown by number, the punctures counted.
TEST_F(TraineePanel, EpiduralDuralPunctureWithTheNamesHiddenMatchesGolden) {
  training::Task task = training::load_task(test::source_dir() / "assets/tasks/epidural.json");
  task.hide_layer_names = true;
  training::TaskProgress progress(task);
  haptics::ToolSnapshot s = at_entry(task);
  progress.feed(s);  // the approach done
  s.contact = haptics::ContactState::kTissue;
  uint32_t passed = 0;
  for (const char* layer : {"skin", "subcutaneous fat", "supraspinous ligament", "interspinous ligament"})
    passed |= 1u << task.layer_index(layer);
  s.tissue.punctured_layers = passed;
  s.tissue.tip_layer = task.layer_index("interspinous ligament");
  for (const double t : {0.1, 0.4}) {  // in the interspinous ligament 0.3 s: the ligaments step done
    s.time_s = t;
    progress.feed(s);
  }
  passed |= 1u << task.layer_index("ligamentum flavum") | 1u << task.layer_index("epidural space");
  s.tissue.punctured_layers = passed;
  s.tissue.tip_layer = task.layer_index("epidural space");
  s.time_s = 0.6;
  progress.feed(s);
  ASSERT_EQ(progress.current_step(), 2u);
  s.time_s = 0.7;
  s.tissue.punctured_layers = passed | 1u << task.layer_index("dura");
  s.tissue.tip_layer = task.layer_index("dura");
  progress.feed(s);  // through the dura: the step ends forbidden_puncture
  ASSERT_EQ(progress.records()[2].outcome, training::StepOutcome::kForbiddenPuncture);
  ui::TraineeView view{&task, &progress};
  view.step = 2;  // the failed step, as the panel shows it for a moment
  view.tissue = s.tissue;
  view.needle = {.along_N = 0.0, .sideways_N = 0.05, .rigid_N = 0.0, .total_N = 0.05};
  view.hand_force_N = task.force_scale * view.needle.total_N;
  view.loop_rate_hz = 1000.0;
  live(view, task, s);
  EXPECT_TRUE(matches_golden(draw(view, {480, 520}), "panel_trainee_epidural_hidden_names"));
}

// The sloppy epidural's result: its faults named in the panel, the bone
// contacts with their peak and the redirection, beside the failed reasons (the run's numbers:
// `needle-sim run --headless --task assets/tasks/epidural.json --operator sloppy`).
TEST_F(TraineePanel, EpiduralSloppyResultNamesTheBoneContactsAndRedirection) {
  const training::Task task = training::load_task(test::source_dir() / "assets/tasks/epidural.json");
  training::TaskProgress progress(task);
  training::SessionResult result = result_of(37.4, false, {0.5, 1.0, 0.0, 0.0, 0.0, 0.8});
  result.overall.bone_contacts = 4;
  result.overall.bone_peak_force_N = 23.7;
  result.overall.redirections = 1;
  result.score.reasons_failed = {"score 37.4 below the pass mark 70", "2 step(s) not completed",
                                 "peak force 23.7 N above the safe limit 3.3 N"};
  ui::TraineeView view{&task, &progress};
  view.result = &result;
  view.loop_rate_hz = 500.0;
  EXPECT_TRUE(matches_golden(draw(view, {480, 480}), "panel_trainee_epidural_sloppy_result"));
}

// A dural puncture is named too: the count and the step's reason.
TEST_F(TraineePanel, EpiduralDuralPunctureResultNamesIt) {
  const training::Task task = training::load_task(test::source_dir() / "assets/tasks/epidural.json");
  training::TaskProgress progress(task);
  training::SessionResult result = result_of(50.0, false, {0.75, 1.0, 0.5, 0.0, 0.0, 0.8});
  result.overall.forbidden_punctures = 1;
  result.score.reasons_failed = {"step loss_of_resistance: dura punctured (forbidden)"};
  ui::TraineeView view{&task, &progress};
  view.result = &result;
  view.loop_rate_hz = 500.0;
  EXPECT_TRUE(matches_golden(draw(view, {480, 420}), "panel_trainee_epidural_dural_puncture_result"));
}

// The penetrable sphere's insert step, 16 s into its 20: the countdown orange with 4 s left, the cues
// in words (how deep still, how far off the axis and which way to turn), the distance, angle and
// depth gauges, the sideways load past its warning (orange) and the force at the hand over the safe
// line (red, in words), at the two supported sizes over the whole window.
TEST_F(TraineePanel, CuesCountdownAndWarningsAt1280x720And1920x1080MatchGoldens) {
  const training::Task task = training::load_task(kTask);
  training::TaskProgress progress(task);
  haptics::ToolSnapshot s = at_entry(task);
  s.time_s = 2.0;
  progress.feed(s);  // the approach completed at 2 s
  ASSERT_EQ(progress.current_step(), 1u);
  // 12 mm along the insertion axis (0.7071, 0, -0.7071), in tissue, the needle 10 deg steeper.
  for (int i = 0; i < 3; ++i) s.needle_tip_m[i] += 0.012 * (i == 0 ? 0.70711 : i == 2 ? -0.70711 : 0.0);
  const double pitch = (45.0 + 10.0) * 3.141592653589793 / 180.0;
  s.needle_orientation[0] = std::cos(pitch / 2), s.needle_orientation[2] = std::sin(pitch / 2);
  s.contact = haptics::ContactState::kTissue;
  s.time_s = 18.0;
  progress.feed(s);
  ASSERT_EQ(progress.current_step(), 1u);
  ui::TraineeView view{&task, &progress};
  view.step_metrics.lateral_load_Ns = 2.4;
  view.step_metrics.peak_hand_force_N = 3.6;
  view.needle = {.along_N = 1.2, .sideways_N = 1.8, .rigid_N = 0.0, .total_N = std::hypot(1.2, 1.8)};
  view.hand_force_N = 3.6;  // over the safe 3 N
  view.loop_rate_hz = 1000.0;
  live(view, task, s);
  ASSERT_GE(view.cue_lines.size(), 2u);
  EXPECT_TRUE(matches_golden(draw(view, {1280, 720}), "panel_trainee_cues_1280x720"));
  EXPECT_TRUE(matches_golden(draw(view, {1920, 1080}), "panel_trainee_cues_1920x1080"));
}

// The banner as a step ends: the approach completed (green, what comes next) at 1280x720; the insert
// step timed out (red, which limit and what it needed) at 1920x1080; gone after kBannerSeconds.
TEST_F(TraineePanel, StepBannersAt1280x720And1920x1080MatchGoldens) {
  const training::Task task = training::load_task(kTask);
  training::TaskProgress progress(task);
  haptics::ToolSnapshot s = at_entry(task);
  s.time_s = 3.0;
  progress.feed(s);  // the approach completed at 3 s
  ui::TraineeView view{&task, &progress};
  view.loop_rate_hz = 1000.0;
  s.time_s = 4.0;
  live(view, task, s);
  EXPECT_TRUE(matches_golden(draw(view, {1280, 720}), "panel_trainee_banner_completed_1280x720"));

  s.contact = haptics::ContactState::kTissue;  // at the surface, never deep enough: the insert step times out
  s.time_s = 23.0;
  progress.feed(s);
  ASSERT_EQ(progress.records()[1].outcome, training::StepOutcome::kTimedOut);
  s.time_s = 24.0;
  live(view, task, s);
  EXPECT_TRUE(matches_golden(draw(view, {1920, 1080}), "panel_trainee_banner_timed_out_1920x1080"));
}

// The turn pad's dot: the way to turn (clockwise as seen to the right, the hub away up), out from the
// centre as the square root of the angle over the pad's full reach, on the edge past it.
TEST(TurnPad, TheDotLiesTheWayToTurnAtTheRootOfTheAngle) {
  const auto expect_at = [](double turn, double tilt, double x, double y) {
    const ui::PadPoint p = ui::turn_pad_point(turn, tilt);
    EXPECT_NEAR(p.x, x, 1e-12) << turn << ", " << tilt;
    EXPECT_NEAR(p.y, y, 1e-12) << turn << ", " << tilt;
  };
  expect_at(0.0, 0.0, 0.0, 0.0);                               // on the axis: the centre
  expect_at(0.25 * ui::kTurnPadFull_deg, 0.0, 0.5, 0.0);       // a quarter of the reach: half-way out, right
  expect_at(-0.25 * ui::kTurnPadFull_deg, 0.0, -0.5, 0.0);     // anticlockwise: left
  expect_at(0.0, ui::kTurnPadFull_deg / 9.0, 0.0, 1.0 / 3.0);  // 5 of 45 deg: a third of the way, up
  expect_at(0.0, -ui::kTurnPadFull_deg, 0.0, -1.0);            // the full reach towards the viewer: the edge, down
  expect_at(9.0, 12.0, 0.6 * std::sqrt(15.0 / 45.0), 0.8 * std::sqrt(15.0 / 45.0));  // 15 deg, 3 : 4
  expect_at(30.0, -40.0, 0.6, -0.8);  // 50 deg, past the reach: on the edge
}

TEST(StepBanner, SaysWhatEndedAndWhyForAFewSeconds) {
  const training::Task task = training::load_task(kTask);
  training::TaskProgress progress(task);
  haptics::ToolSnapshot s = at_entry(task);
  s.time_s = 1.0;
  EXPECT_FALSE(ui::step_banner(task, progress, 1.0)) << "nothing ended yet";
  progress.feed(s);
  const std::optional<ui::StepBanner> done = ui::step_banner(task, progress, 2.0);
  ASSERT_TRUE(done);
  EXPECT_TRUE(done->completed);
  EXPECT_EQ(done->title, "Step 1 of 5 completed: approach");
  EXPECT_EQ(done->detail, "Next: " + task.steps[1].instruction);
  EXPECT_FALSE(ui::step_banner(task, progress, 1.0 + ui::kBannerSeconds + 0.01)) << "gone after its seconds";
  s.time_s = 21.0;  // the insert step's 20 s pass with the tip at the surface
  progress.feed(s);
  const std::optional<ui::StepBanner> late = ui::step_banner(task, progress, 21.5);
  ASSERT_TRUE(late);
  EXPECT_FALSE(late->completed);
  EXPECT_EQ(late->title, "Step 2 of 5 timed out: insert");
  EXPECT_EQ(late->detail,
            "The 20 s limit passed; the step needed the tip 25-35 mm deep along the planned axis, in the tissue, held "
            "0.5 s.");
}

TEST(WhatToImprove, TheTwoCostliestComponentsFirst) {
  training::Score score;
  score.components = {{"completion", 1.0, 30}, {"tip_error", 0.4, 15}, {"axis_deviation", 0.2, 10}, {"time", 0.95, 5}};
  // Lost: tip_error 9, axis_deviation 8, time 0.25 (under a point: not worth a word).
  EXPECT_EQ(ui::what_to_improve(score),
            (std::vector<std::string>{"Bring the tip closer to the target", "Keep the needle on the planned axis"}));
  score.components = {{"completion", 1.0, 30}};
  EXPECT_TRUE(ui::what_to_improve(score).empty());
}

}  // namespace
}  // namespace needle::test
