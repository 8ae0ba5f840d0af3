// The plots' labels never overlap or leave their plot: the tick labels and the x axis's name of the
// cohort's learning curves, a session's time plots and the force–depth plot, and the force–depth
// plot's layer names, at the smallest supported size (a 1280x720 review window, 13 px text).
#include <gtest/gtest.h>
#include <imgui.h>

#include "engine/render_target.hpp"
#include "engine/ui_pass.hpp"
#include "tests/support/test_paths.hpp"
#include "training/tasks/task.hpp"
#include "ui/plot_frame.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

// Every label inside the rectangle [lo, hi] and none over another.
void expect_apart_and_inside(const std::vector<ui::PlotLabel>& labels, ImVec2 lo, ImVec2 hi, const std::string& what) {
  for (size_t i = 0; i < labels.size(); ++i) {
    const ui::PlotLabel& l = labels[i];
    EXPECT_GE(l.at.x, lo.x - 0.01f) << what << ": \"" << l.text << "\" leaves on the left";
    EXPECT_LE(l.at.x + l.size.x, hi.x + 0.01f) << what << ": \"" << l.text << "\" is cut on the right";
    EXPECT_GE(l.at.y, lo.y - 0.01f) << what << ": \"" << l.text << "\" leaves at the top";
    EXPECT_LE(l.at.y + l.size.y, hi.y + 0.01f) << what << ": \"" << l.text << "\" leaves at the bottom";
    for (size_t j = 0; j < i; ++j)
      EXPECT_FALSE(l.overlaps(labels[j])) << what << ": \"" << l.text << "\" over \"" << labels[j].text << "\"";
  }
}

class PlotLabels : public VulkanTest {
 protected:
  // Calls `body` inside a window `width` pixels wide, in a 1280x720 UI frame.
  template <class Body>
  void in_window(float width, Body body) {
    const engine::Extent extent{1280, 720};
    engine::HeadlessTarget target(device(), extent);
    engine::SceneRenderer renderer(device(), target, {1});
    engine::UiPass ui(renderer, nullptr);
    ui.begin_frame(extent, 1.0f / 60.0f);
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(width, 700.0f));
    ImGui::Begin("plot", nullptr, ImGuiWindowFlags_NoDecoration);
    body();
    ImGui::End();
    ui.end_frame();
  }
};

// The review's panels are 0.46 of a 1280-pixel window (589 px) and the class view's curves half of it.
TEST_F(PlotLabels, TickLabelsAndTheAxisNameStayApartAndInside) {
  struct Case {
    const char* what;
    float width;
    double x_lo, x_hi, y_lo, y_hi;
    const char* x_label;
    bool whole_x;
  };
  for (const Case& c : {Case{"learning curve", 620.0f, 0.5, 3.5, 0.0, 100.0, "attempt", true},
                        Case{"learning curve, one attempt", 300.0f, 0.5, 1.5, 0.0, 24.0, "attempt", true},
                        Case{"time plot", 589.0f, 0.0, 54.0, 0.0, 3.1, "t (s)", false},
                        Case{"time plot, zoomed", 589.0f, 12.25, 14.75, -1.5, 2.0, "t (s)", false},
                        Case{"force-depth", 589.0f, 0.0, 62.0, 0.0, 9.4, "depth (mm)", false},
                        Case{"narrow force-depth", 200.0f, 0.0, 62.0, 0.0, 1234.5, "depth (mm)", false}}) {
    in_window(c.width, [&] {
      const ui::PlotFrame f = ui::plot_frame(c.x_lo, c.x_hi, c.y_lo, c.y_hi, 120.0f);
      const std::vector<ui::PlotLabel> labels = ui::plot_frame_labels(f, c.x_label, c.whole_x);
      expect_apart_and_inside(labels, f.origin, ImVec2(f.origin.x + f.width, f.origin.y + f.height), c.what);
      ASSERT_FALSE(labels.empty());
      EXPECT_EQ(labels.back().text, c.x_label) << c.what << ": the axis is always named";
    });
  }
}

// The epidural's layers along its midline, 0.5 to 5 mm apart where the flavum, the epidural space
// and the dura meet: each name beside its line, none over another, none cut at the plot's edge.
TEST_F(PlotLabels, TheLayerNamesOfTheForceDepthPlotStayApartAndInside) {
  const training::Task task = training::load_task(source_dir() / "assets/tasks/epidural.json");
  const int axis = task.marker_index("midline_axis");
  ASSERT_GE(axis, 0);
  std::vector<double> depths_mm;
  std::vector<std::string> names;
  for (const training::LayerStart& s : task.layer_starts[size_t(axis)]) {
    if (s.layer < 0) continue;
    depths_mm.push_back(std::max(0.0, s.depth_m * 1000.0));
    names.push_back(task.layers[size_t(s.layer)].name);
  }
  ASSERT_GE(names.size(), 7u);
  in_window(589.0f, [&] {
    const ui::PlotFrame f = ui::plot_frame(0.0, depths_mm.back() + 2.0, 0.0, 9.4, 160.0f);
    std::vector<float> xs;
    for (double d : depths_mm) xs.push_back(f.sx(d));
    const std::vector<ui::PlotLabel> labels = ui::line_labels(f, xs, names);
    EXPECT_EQ(labels.size(), names.size()) << "every layer named";
    expect_apart_and_inside(labels, f.p0, f.p1, "layer names");
  });
}

}  // namespace
}  // namespace needle::test
