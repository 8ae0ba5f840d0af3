// The class view's pictures show every trainee: up to 24 learning curves each look unlike every
// other (colour, dash, mark), and a legend too long for one row wraps onto more, every entry inside
// the width; the report's learning-curve picture of 24 trainees against a golden.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "image_compare.hpp"
#include "training/sessions/session_series.hpp"
#include "ui/cohort_panel.hpp"
#include "ui/panel_picture.hpp"
#include "ui/plot_frame.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

TEST(PlotStyles, TwentyFourTraineesLookPairwiseDifferent) {
  std::set<std::tuple<ImU32, ui::Dash, ui::Mark>> seen;
  std::set<ImU32> colours;
  for (size_t k = 0; k < ui::kTraineeStyles; ++k) {
    const ui::LineStyle s = ui::trainee_style(k);
    EXPECT_TRUE(seen.insert({s.colour, s.dash, s.mark}).second) << "trainee " << k << " looks like an earlier one";
    EXPECT_NE(s.mark, ui::Mark::kNone) << "every attempt is marked";
    colours.insert(s.colour);
  }
  EXPECT_EQ(colours.size(), 8u);  // eight hues, each in three dashes with their marks
  for (size_t k = 0; k < 8; ++k)  // a hue's three looks differ in dash and in mark
    EXPECT_EQ(
        (std::set<ui::Dash>{ui::trainee_style(k).dash, ui::trainee_style(k + 8).dash, ui::trainee_style(k + 16).dash}
             .size()),
        3u);
  const ui::LineStyle again = ui::trainee_style(ui::kTraineeStyles), first = ui::trainee_style(0);
  EXPECT_EQ(std::tie(again.colour, again.dash, again.mark), std::tie(first.colour, first.dash, first.mark))
      << "the 25th repeats the first, as documented";
}

TEST(PlotLegend, RowsPlaceEveryEntryWithinTheWidth) {
  // 24 entries of 70 to 116 pixels in 860 (the report's plot): rows of at most 860, in order.
  std::vector<float> widths;
  for (int k = 0; k < 24; ++k) widths.push_back(70.0f + float((k * 7) % 47));
  const float width = 860.0f, gap = 8.0f;
  const std::vector<int> rows = ui::legend_rows(widths, width, gap);
  ASSERT_EQ(rows.size(), widths.size());
  EXPECT_EQ(rows.front(), 0);
  EXPECT_GE(rows.back(), 2) << "24 names do not fit on one or two rows";
  std::vector<float> used(size_t(rows.back()) + 1, 0.0f);
  for (size_t k = 0; k < rows.size(); ++k) {
    if (k > 0) EXPECT_TRUE(rows[k] == rows[k - 1] || rows[k] == rows[k - 1] + 1) << k;
    float& u = used[size_t(rows[k])];
    u += (u > 0.0f ? gap : 0.0f) + widths[k];
    EXPECT_LE(u, width) << "entry " << k << " passes the right edge";
  }
  for (size_t r = 0; r + 1 < used.size(); ++r) {  // a row ends only when the next entry would not fit
    const size_t first_of_next = size_t(std::find(rows.begin(), rows.end(), int(r + 1)) - rows.begin());
    EXPECT_GT(used[r] + gap + widths[first_of_next], width) << "row " << r;
  }
  // Wider than the width: a row of its own, never dropped.
  EXPECT_EQ(ui::legend_rows({50.0f, 900.0f, 50.0f}, width, gap), (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(ui::legend_rows({}, width, gap).empty());
}

// The report's PNG of a task's learning curves (report --cohort: 900 x 360) for a class of 24,
// each trainee's attempts a line of its own look, the legend on three rows naming all 24.
class LearningCurvesPicture : public VulkanTest {};

TEST_F(LearningCurvesPicture, TwentyFourTraineesAllShownMatchesGolden) {
  training::Plot plot;
  plot.title = "Score over attempts: pivot_drill";
  plot.unit = "points";
  plot.x_label = "attempt";
  for (int k = 0; k < 24; ++k) {
    char name[16];
    std::snprintf(name, sizeof name, "trainee-%02d", k + 1);
    training::Series line{name, {}, {}};
    for (int a = 0; a < 3 + k % 3; ++a) {
      line.t.push_back(a + 1);
      line.v.push_back(30.0 + 2.5 * k + 8.0 * a);
    }
    plot.lines.push_back(line);
  }
  const engine::Extent size{900, 360};
  EXPECT_TRUE(matches_golden(
      ui::panel_picture(
          device(), size,
          [&] {
            ui::draw_learning_curve_window(plot, {ImVec2(0, 0), ImVec2(float(size.width), float(size.height))});
          }),
      "panel_cohort_24"));
}

}  // namespace
}  // namespace needle::test
