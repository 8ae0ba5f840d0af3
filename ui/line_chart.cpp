#include "ui/line_chart.hpp"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "training/sessions/session_series.hpp"  // axis_ticks

namespace needle::ui {
namespace {

using Rgb = std::array<uint8_t, 3>;
constexpr Rgb kInk{40, 40, 48}, kGrid{225, 225, 232}, kMarker{150, 110, 40};
constexpr float kTextScale = 2.0f;  // stb_easy_font glyphs are about 7 px high

class Canvas {
 public:
  Canvas(uint32_t width, uint32_t height)
      : image_{width, height, std::vector<uint8_t>(size_t(width) * height * 4, 255)} {}

  void blend(int x, int y, const Rgb& c, float alpha) {
    if (x < 0 || y < 0 || x >= int(image_.width) || y >= int(image_.height) || alpha <= 0.0f) return;
    uint8_t* p = &image_.pixels[(size_t(y) * image_.width + size_t(x)) * 4];
    for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(p[k] + (c[size_t(k)] - p[k]) * std::min(alpha, 1.0f)));
  }

  void fill(float x0, float y0, float x1, float y1, const Rgb& c) {
    for (int y = int(std::floor(y0)); y < int(std::ceil(y1)); ++y)
      for (int x = int(std::floor(x0)); x < int(std::ceil(x1)); ++x) blend(x, y, c, 1.0f);
  }

  // Antialiased segment of the given width: each pixel covered by its distance to the segment.
  void line(float x0, float y0, float x1, float y1, const Rgb& c, float width) {
    const float r = 0.5f * width;
    const float dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    for (int y = int(std::floor(std::min(y0, y1) - r - 1)); y <= int(std::ceil(std::max(y0, y1) + r + 1)); ++y)
      for (int x = int(std::floor(std::min(x0, x1) - r - 1)); x <= int(std::ceil(std::max(x0, x1) + r + 1)); ++x) {
        const float px = float(x) + 0.5f - x0, py = float(y) + 0.5f - y0;
        const float t = len2 > 0.0f ? std::clamp((px * dx + py * dy) / len2, 0.0f, 1.0f) : 0.0f;
        const float d = std::hypot(px - t * dx, py - t * dy);
        blend(x, y, c, r + 0.5f - d);
      }
  }

  // Text with its top-left corner at (x, y).
  void text(float x, float y, const std::string& s, const Rgb& c) {
    static char quads[64000];
    unsigned char colour[4] = {c[0], c[1], c[2], 255};
    std::string copy = s;
    const int n = stb_easy_font_print(0.0f, 0.0f, copy.data(), colour, quads, sizeof quads);
    for (int q = 0; q < n; ++q) {
      const float* v0 = reinterpret_cast<const float*>(quads + q * 64);
      const float* v2 = reinterpret_cast<const float*>(quads + q * 64 + 32);
      fill(x + v0[0] * kTextScale, y + v0[1] * kTextScale, x + v2[0] * kTextScale, y + v2[1] * kTextScale, c);
    }
  }

  static float text_width(const std::string& s) {
    std::string copy = s;
    return float(stb_easy_font_width(copy.data())) * kTextScale;
  }

  engine::RgbaImage take() { return std::move(image_); }

 private:
  engine::RgbaImage image_;
};

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return text;
}

}  // namespace

engine::RgbaImage draw_line_chart(const LineChart& chart, uint32_t width, uint32_t height) {
  if (width < 200 || height < 150) throw std::invalid_argument("a line chart needs at least 200 x 150 pixels");
  Range x, y;
  y.add(0.0);
  for (const ChartLine& l : chart.lines) {
    for (double v : l.x) x.add(v);
    for (double v : l.y) y.add(v);
  }
  for (const ChartMarker& m : chart.markers) x.add(m.x);
  if (!(x.hi > x.lo)) x.hi = x.lo + 1.0;
  if (!(y.hi > y.lo)) y.hi = y.lo + 1.0;
  const double pad = 0.06 * (y.hi - y.lo);
  y.hi += pad;
  if (y.lo < 0.0) y.lo -= pad;

  Canvas canvas(width, height);
  const float left = 90.0f, right = float(width) - 30.0f, top = 56.0f, bottom = float(height) - 62.0f;
  auto sx = [&](double v) { return float(left + (v - x.lo) / (x.hi - x.lo) * (right - left)); };
  auto sy = [&](double v) { return float(bottom - (v - y.lo) / (y.hi - y.lo) * (bottom - top)); };

  for (double v : training::axis_ticks(y.lo, y.hi, 8)) {
    canvas.line(left, sy(v), right, sy(v), kGrid, 1.0f);
    const std::string label = number(v);
    canvas.text(left - 10.0f - Canvas::text_width(label), sy(v) - 7.0f, label, kInk);
  }
  for (double v : training::axis_ticks(x.lo, x.hi, 10)) {
    canvas.line(sx(v), bottom, sx(v), bottom + 6.0f, kInk, 1.5f);
    const std::string label = number(v);
    canvas.text(sx(v) - 0.5f * Canvas::text_width(label), bottom + 12.0f, label, kInk);
  }
  canvas.line(left, sy(0.0), right, sy(0.0), {160, 160, 170}, 1.5f);
  // Markers: dashed, labels staggered over four rows so that close ones stay readable.
  for (size_t k = 0; k < chart.markers.size(); ++k) {
    const float mx = sx(chart.markers[k].x);
    for (float yy = top; yy < bottom; yy += 10.0f) canvas.line(mx, yy, mx, std::min(yy + 5.0f, bottom), kMarker, 1.5f);
    const float w = Canvas::text_width(chart.markers[k].label);
    const float tx = mx + 4.0f + w <= float(width) - 4.0f ? mx + 4.0f : mx - 4.0f - w;  // left of it at the right edge
    canvas.text(tx, top + 4.0f + 18.0f * float(k % 4), chart.markers[k].label, kMarker);
  }
  for (const ChartLine& l : chart.lines)
    for (size_t i = 1; i < std::min(l.x.size(), l.y.size()); ++i)
      canvas.line(sx(l.x[i - 1]), sy(l.y[i - 1]), sx(l.x[i]), sy(l.y[i]), l.colour, 2.0f);
  canvas.line(left, top, left, bottom, kInk, 1.5f);
  canvas.line(left, bottom, right, bottom, kInk, 1.5f);

  canvas.text(left, 14.0f, chart.title, kInk);
  canvas.text(0.5f * (left + right) - 0.5f * Canvas::text_width(chart.x_label), float(height) - 26.0f, chart.x_label,
              kInk);
  canvas.text(8.0f, top - 22.0f, chart.y_label, kInk);
  float legend_x = right;  // right-aligned, in the title row
  for (auto it = chart.lines.rbegin(); it != chart.lines.rend(); ++it) {
    legend_x -= Canvas::text_width(it->name) + 34.0f;
    canvas.line(legend_x, 21.0f, legend_x + 22.0f, 21.0f, it->colour, 3.0f);
    canvas.text(legend_x + 28.0f, 14.0f, it->name, kInk);
  }
  return canvas.take();
}

}  // namespace needle::ui
