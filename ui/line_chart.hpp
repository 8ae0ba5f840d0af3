// A line chart drawn on the CPU into an image, for the pictures command-line tools write into
// docs/ (no Vulkan device needed): axes with ticks and labels, lines, and labelled vertical
// markers. Text is stb_easy_font's bitmap font, scaled.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/rgba_image.hpp"

namespace needle::ui {

struct ChartLine {
  std::string name;  // in the legend
  std::vector<double> x, y;
  std::array<uint8_t, 3> colour{30, 90, 200};
};

struct ChartMarker {  // a dashed vertical line with a label
  double x = 0.0;
  std::string label;
};

struct LineChart {
  std::string title, x_label, y_label;
  std::vector<ChartLine> lines;
  std::vector<ChartMarker> markers;
};

// The chart on a white background, `width` × `height` pixels (at least 200 × 150). The axes span
// the lines and markers, and y always includes 0.
engine::RgbaImage draw_line_chart(const LineChart& chart, uint32_t width, uint32_t height);

}  // namespace needle::ui
