// The CPU line chart that `bench insertion --plot` writes into docs/: a rising line is drawn
// rising, a marker is drawn at its x, in the pixels the axes give them.
#include <gtest/gtest.h>

#include "ui/line_chart.hpp"

namespace needle::ui {
namespace {

bool is(const engine::RgbaImage& image, uint32_t x, uint32_t y, const std::array<uint8_t, 3>& c) {
  const uint8_t* p = image.at(x, y);
  return p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
}

TEST(LineChart, ARisingLineIsDrawnRisingAndAMarkerAtItsX) {
  const std::array<uint8_t, 3> red{200, 0, 0};
  LineChart chart{"title", "x", "y", {{"line", {0.0, 10.0}, {0.0, 5.0}, red}}, {{5.0, "half"}}};
  const engine::RgbaImage image = draw_line_chart(chart, 600, 400);
  ASSERT_EQ(image.width, 600u);
  ASSERT_EQ(image.height, 400u);
  // The line's fully covered pixels, column by column: one band per column, higher (smaller y)
  // as x grows, from the left end of the x axis to its right end.
  std::vector<std::pair<uint32_t, double>> centre;  // column, mean row of the line's pixels
  for (uint32_t x = 0; x < image.width; ++x) {
    double sum = 0.0;
    int n = 0;
    for (uint32_t y = 50; y < image.height; ++y)  // below the title row and its legend
      if (is(image, x, y, red)) sum += y, ++n;
    if (n > 0) centre.push_back({x, sum / n});
  }
  ASSERT_GT(centre.size(), 400u);  // most of the 600 px width
  for (size_t k = 1; k < centre.size(); ++k)
    EXPECT_LE(centre[k].second, centre[k - 1].second + 1e-9) << centre[k].first;
  EXPECT_GT(centre.front().second - centre.back().second, 200.0);  // it spans most of the 400 px height
  // The marker: a dashed vertical line halfway along the line's columns, in its brown (partly
  // covered pixels blend it with white, so any pixel clearly brown counts).
  const uint32_t mid = (centre.front().first + centre.back().first) / 2;
  int marker = 0;
  for (uint32_t x = mid - 3; x <= mid + 3; ++x)
    for (uint32_t y = 100; y < 330; ++y) marker += image.at(x, y)[0] > image.at(x, y)[2] + 40;
  EXPECT_GT(marker, 100);  // the line itself crosses these columns in a few pixels only
}

}  // namespace
}  // namespace needle::ui
