// The acceptance test of the trainee's screen: a script that knows only what the window shows does
// the penetrable sphere with the mouse, on its first attempt, and passes. It reads the window's pixels (xwd) and
// nothing else: the entry ring and the planned axis over the 3D view by their colours, the trainee panel's gauges by
// theirs (how far a bar is filled, against its own tolerance tick or band), the turn pad's dot (which way to turn), the
// step's progress bar; it moves the real mouse with xdotool. No file of the task, scene or scenario is read and no
// position is computed from them: where to go is where the marks are drawn, how far is how full the bars are, and
// what a notch or a drag does is learnt by making one and reading the gauges.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "cli_process.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/guidance_colours.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Rgb {
  int r = 0, g = 0, b = 0;
};

// A colour the panels draw with IM_COL32 as it reaches the screen: the UI pass takes it as linear
// and the window's frames are sRGB-encoded (the style's own colours are converted once and arrive
// as they are written).
int encoded(int linear) {
  const double x = linear / 255.0;
  return int(std::lround(255.0 * (x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055)));
}
Rgb on_screen(unsigned colour) {  // an IM_COL32: R in the low byte
  return {encoded(int(colour & 0xff)), encoded(int((colour >> 8) & 0xff)), encoded(int((colour >> 16) & 0xff))};
}

const Rgb kEntry = on_screen(ui::kEntryColour), kTarget = on_screen(ui::kTargetColour),
          kAxis = on_screen(ui::kAxisColour), kBand = on_screen(ui::kBandColour);
const Rgb kWhite{255, 255, 255};
// ImGui's dark style: a progress bar's fill (PlotHistogram, 0.90 0.70 0.00) and its frame (FrameBg,
// 0.16 0.29 0.48 at 0.54 over the window's background).
const Rgb kProgress{230, 179, 0}, kProgressFrame{32, 50, 77};

// The window as xwd gives it (ZPixmap, 32 bits a pixel, little-endian BGRX).
struct Screen {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;
  const Rgb& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  bool is(int x, int y, const Rgb& c, int tolerance = 14) const {
    const Rgb& p = at(x, y);
    return std::abs(p.r - c.r) <= tolerance && std::abs(p.g - c.g) <= tolerance && std::abs(p.b - c.b) <= tolerance;
  }
};

uint32_t big_endian(const std::string& d, size_t at) {
  return uint32_t(uint8_t(d[at])) << 24 | uint32_t(uint8_t(d[at + 1])) << 16 | uint32_t(uint8_t(d[at + 2])) << 8 |
         uint8_t(d[at + 3]);
}

Screen read_xwd(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string d((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Screen s;
  if (d.size() < 100) return s;
  const uint32_t header = big_endian(d, 0), width = big_endian(d, 16), height = big_endian(d, 20),
                 line = big_endian(d, 48), colours = big_endian(d, 76);
  const size_t start = header + size_t(colours) * 12;
  if (d.size() < start + size_t(line) * height) return s;
  s.width = int(width), s.height = int(height);
  s.pixels.resize(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const size_t i = start + size_t(y) * line + size_t(x) * 4;
      s.pixels[size_t(y) * width + x] = {uint8_t(d[i + 2]), uint8_t(d[i + 1]), uint8_t(d[i])};
    }
  return s;
}

// A bar of the trainee panel: where its filled part of colour `fill` ends, where its tick or band
// is, in pixels of one row.
struct Bar {
  int left = 0, fill_end = 0;  // the fill from left to fill_end
  int tick = -1;               // a white tick across it (a tolerance, the tip's depth), -1 when none
  int band_lo = -1, band_hi = -1;
};

// The row of the panel (x from `panel`, rows before `below`) with the most pixels of `fill`, read as a bar.
std::optional<Bar> find_bar(const Screen& s, int panel, const Rgb& fill, int below = -1) {
  int best_row = -1, best = 0;
  for (int y = 0; y < (below < 0 ? s.height : below); ++y) {
    int n = 0;
    for (int x = panel; x < s.width; ++x) n += s.is(x, y, fill);
    if (n > best) best = n, best_row = y;
  }
  if (best_row < 0 || best < 2) return std::nullopt;
  Bar b;
  b.left = s.width, b.fill_end = -1;
  for (int x = panel; x < s.width; ++x)
    if (s.is(x, best_row, fill)) b.left = std::min(b.left, x), b.fill_end = std::max(b.fill_end, x);
  for (int x = panel; x < s.width; ++x) {
    if (s.is(x, best_row, kWhite, 10) && b.tick < 0) b.tick = x;
    if (s.is(x, best_row, kBand)) {
      if (b.band_lo < 0) b.band_lo = x;
      b.band_hi = x;
    }
  }
  return b;
}

// The centre of a ring of colour `c` over the 3D view (left of `panel`), its label beside it on the
// `label_left` side: the ring is the cluster of that colour at the other end.
std::optional<std::pair<int, int>> find_ring(const Screen& s, int panel, const Rgb& c, bool label_left) {
  int lo_x = s.width, hi_x = -1;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < panel - 4; ++x)
      if (s.is(x, y, c, 10)) lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x);
  if (hi_x < 0) return std::nullopt;
  const int from = label_left ? hi_x - 22 : lo_x, to = label_left ? hi_x : lo_x + 22;
  int x0 = s.width, x1 = -1, y0 = s.height, y1 = -1;
  for (int y = 0; y < s.height; ++y)
    for (int x = std::max(0, from); x <= to; ++x)
      if (s.is(x, y, c, 10)) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  return std::pair{(x0 + x1) / 2, (y0 + y1) / 2};
}

// The window on a virtual display of the test's own, driven through xdotool and read through xwd.
class Desk {
 public:
  explicit Desk(const fs::path& dir) : dir_(dir) {
    for (display_ = 91; fs::exists("/tmp/.X" + std::to_string(display_) + "-lock"); ++display_) {
    }
    std::system(("Xvfb :" + std::to_string(display_) +
                 " -screen 0 1600x900x24 -nolisten tcp > /dev/null 2>&1 & echo $! > " + quoted(dir / "xvfb.pid"))
                    .c_str());
    for (int i = 0; i < 100 && !fs::exists("/tmp/.X11-unix/X" + std::to_string(display_)); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ~Desk() { std::system(("kill $(cat " + quoted(dir_ / "xvfb.pid") + ") 2>/dev/null").c_str()); }
  std::string env() const { return "DISPLAY=:" + std::to_string(display_) + " "; }
  std::string output(const std::string& command) const { return run_command(env() + command + " 2>/dev/null").output; }
  void run(const std::string& command) const { std::system((env() + command + " > /dev/null 2>&1").c_str()); }
  void start(const std::string& command) const { std::system((env() + command).c_str()); }  // its own redirections
  // The window's id, once it is there; its text says what went wrong when it never is.
  const std::string& find_window() {
    const std::string id = output("xdotool search --sync --name '^needle-sim$' | head -1");
    window_ = id.substr(0, id.find('\n'));
    return window_;
  }
  Screen grab() const {
    const fs::path file = dir_ / "screen.xwd";
    start("xwd -id " + window_ + " -silent > " + quoted(file) + " 2>/dev/null");
    return read_xwd(file);
  }
  // The cursor to (x, y) of the window as a hand moves it: in steps of a few pixels a frame or so
  // apart (the tip follows the cursor at once, and a jump would throw it at whatever lies between).
  void move(int x, int y) const {
    const auto [x0, y0] = cursor();
    const int parts = std::max(1, std::max(std::abs(x - x0), std::abs(y - y0)) / 6);
    std::string moves;
    for (int k = 1; k <= parts; ++k)
      moves += " mousemove --window " + window_ + " " + std::to_string(x0 + (x - x0) * k / parts) + " " +
               std::to_string(y0 + (y - y0) * k / parts) + " sleep 0.02";
    run("xdotool" + moves);
  }
  void wheel(int notches) const {
    if (notches != 0)
      run("xdotool click --repeat " + std::to_string(std::abs(notches)) + " --delay 30 " + (notches > 0 ? "4" : "5"));
  }
  // The right button held while the cursor moves (dx, dy) in small moves a frame or so apart (the
  // app turns the wrist by the cursor's motion from one frame to the next, and a turn spread over
  // frames is a turn a hand makes: gradual, `per_move` pixels a twentieth of a second), held a moment
  // before and after so the app sees the button go down where the cursor is and come up after the last move.
  void turn(int dx, int dy, int per_move = 4) const {
    const int parts = std::max(1, std::max(std::abs(dx), std::abs(dy)) / per_move);
    std::string moves;
    for (int k = 0; k < parts; ++k) {
      const int x = dx * (k + 1) / parts - dx * k / parts, y = dy * (k + 1) / parts - dy * k / parts;
      moves += " mousemove_relative -- " + std::to_string(x) + " " + std::to_string(y) + " sleep 0.05";
    }
    run("xdotool mousedown 3 sleep 0.12" + moves + " sleep 0.12 mouseup 3 sleep 0.1");
  }
  std::pair<int, int> cursor() const {
    const std::string out = output("xdotool getmouselocation --shell");
    int x = 0, y = 0;
    std::sscanf(out.c_str(), "X=%d Y=%d", &x, &y);
    const std::string geometry = output("xdotool getwindowgeometry --shell " + window_);
    int wx = 0, wy = 0;
    if (const size_t at = geometry.find("X="); at != std::string::npos) std::sscanf(geometry.c_str() + at, "X=%d", &wx);
    if (const size_t at = geometry.find("Y="); at != std::string::npos) std::sscanf(geometry.c_str() + at, "Y=%d", &wy);
    return {x - wx, y - wy};
  }

 private:
  fs::path dir_;
  int display_ = 91;
  std::string window_;
};

void settle(double seconds) { std::this_thread::sleep_for(std::chrono::milliseconds(int(seconds * 1000))); }

// The turn pad under the axis gauge: a square framed in the axis's colour, a dot the way the wrist
// must turn (right: clockwise as seen, up: the hub away), nearer the centre the nearer the axis.
struct Pad {
  int top = 0;                   // its frame's top row
  double right = 0.0, up = 0.0;  // the unit direction from its centre to the dot; 0, 0 with the dot on the centre
};

std::optional<Pad> find_pad(const Screen& s, int panel) {
  // The frame's two sides: the columns with a long vertical run of the axis's colour.
  int x0 = s.width, x1 = -1, y0 = s.height, y1 = -1;
  for (int x = panel; x < s.width; ++x)
    for (int y = 0, run = 0; y < s.height; ++y) {
      run = s.is(x, y, kAxis) ? run + 1 : 0;
      if (run >= 30) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y - run + 1), y1 = std::max(y1, y);
    }
  if (x1 - x0 < 30) return std::nullopt;
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  double far = 0.0, dx = 0.0, dy = 0.0;  // the dot: the pixel of the axis's colour inside the frame farthest out
  for (int y = y0 + 3; y <= y1 - 3; ++y)
    for (int x = x0 + 3; x <= x1 - 3; ++x)
      if (s.is(x, y, kAxis) && std::hypot(x - cx, y - cy) > far)
        far = std::hypot(x - cx, y - cy), dx = x - cx, dy = y - cy;
  Pad p;
  p.top = y0;
  if (far > 5.0) p.right = dx / far, p.up = -dy / far;  // beyond the dot's own radius round the centre
  return p;
}

// What the screen says now.
struct Reading {
  Screen screen;
  int panel = 0;     // the trainee panel's left edge
  int progress = 0;  // pixels of the progress bar filled
  int width = 0;     // the width of the panel's bars (the progress bar's, the gauges' alike)
  std::optional<Bar> distance, axis, depth;
  std::optional<Pad> pad;
};

Reading read(const Desk& desk) {
  Reading r;
  r.screen = desk.grab();
  const Screen& s = r.screen;
  // The panel: the right part of the window where the progress bar's frame is.
  r.panel = s.width;
  int right = -1;
  for (int y = 0; y < s.height; ++y)
    for (int x = s.width / 2; x < s.width; ++x)
      if (s.is(x, y, kProgressFrame, 4) || s.is(x, y, kProgress, 16))
        r.panel = std::min(r.panel, x), right = std::max(right, x);
  r.width = right - r.panel + 1;
  r.panel = std::max(0, r.panel - 10);
  if (const std::optional<Bar> p = find_bar(s, r.panel, kProgress)) r.progress = p->fill_end - p->left + 1;
  r.distance = find_bar(s, r.panel, kEntry);
  r.pad = find_pad(s, r.panel);
  r.axis = find_bar(s, r.panel, kAxis, r.pad ? r.pad->top - 1 : -1);  // the gauge is above the pad
  r.depth = find_bar(s, r.panel, kBand);
  return r;
}

// The length of a gauge's fill (0 when the bar shows none): the smaller, the nearer.
int fill(const std::optional<Bar>& b) { return b ? b->fill_end - b->left + 1 : 0; }

std::function<void(const std::string&)> log_;  // where the steps say how they went

// The wrist as the script has learnt it: pixels of drag (right button held) per pixel of the axis
// gauge's fill, measured by its first turn.
struct Wrist {
  double drag_per_fill = 0.0;
};

// How turn_onto_axis turns: in the air briskly, in the tissue slowly (each turn of the needle there
// pushes the tissue sideways, and a quick one loads it more) and read after the needle has followed.
struct Turning {
  double close = 0.0;     // done under this share of the tolerance tick
  double share = 1.0;     // of what the gauge says is left, a turn at a time
  double settle_s = 0.3;  // after each turn
  int per_move = 4;       // pixels of drag a twentieth of a second
};
// Turns the wrist towards the pad's dot by as much as the axis gauge says is left (all of the
// gauge's length when it reads full), `how.share` of it at a time, until the gauge's fill is under
// `how.close` of its tolerance tick (10 px at least, 1.4 deg), the step ends (the progress bar moves)
// or `until`. The first turn, in the air, learns the wrist's rate: a fixed drag, and how far the fill
// went down.
void turn_onto_axis(const Desk& desk, Wrist& wrist, int step_done_at, Clock::time_point until, const Turning& how) {
  for (int round = 0; round < 6 && Clock::now() < until; ++round) {
    const Reading r = read(desk);
    if (r.progress > step_done_at || !r.axis || !r.pad) return;
    const int f = fill(r.axis), tolerance = r.axis->tick >= 0 ? r.axis->tick - r.axis->left : 0;
    if (f <= std::max(10.0, how.close * tolerance) || (r.pad->right == 0.0 && r.pad->up == 0.0)) return;
    const bool full = f >= r.width - 4;
    double drag = 0.0;
    if (wrist.drag_per_fill <= 0.0) {
      drag = 80.0;
      desk.turn(int(std::lround(r.pad->right * drag)), int(std::lround(-r.pad->up * drag)), how.per_move);
      settle(how.settle_s);
      const int after = fill(read(desk).axis);
      if (!full && f - after > 10) wrist.drag_per_fill = drag / (f - after);
      log_("turn: " + std::to_string(f) + " px off, then " + std::to_string(after) + " after an 80 px drag");
      continue;
    }
    drag = how.share * wrist.drag_per_fill * (full ? r.width : f);
    desk.turn(int(std::lround(r.pad->right * drag)), int(std::lround(-r.pad->up * drag)), how.per_move);
    settle(how.settle_s);
    log_("turn: " + std::to_string(f) + " px off the axis, a drag of " + std::to_string(int(drag)) + " px");
  }
}

// The two ends of the planned axis drawn over the 3D view (the line of the axis's colour left of the
// panel, through the ring at `ring`): the one nearer the ring first (the line runs further into the
// tissue than out of it).
std::pair<std::pair<int, int>, std::pair<int, int>> axis_line_ends(const Reading& r, std::pair<int, int> ring) {
  std::pair<int, int> a = ring, b = ring;
  double da = 0.0, db = 0.0;
  for (int y = 0; y < r.screen.height; ++y)
    for (int x = 0; x < r.panel - 4; ++x)
      if (r.screen.is(x, y, kAxis, 10)) {
        const double d = std::hypot(x - ring.first, y - ring.second);
        if (d > da) da = d, a = {x, y};
      }
  for (int y = 0; y < r.screen.height; ++y)
    for (int x = 0; x < r.panel - 4; ++x)
      if (r.screen.is(x, y, kAxis, 10) &&
          (x - ring.first) * (a.first - ring.first) + (y - ring.second) * (a.second - ring.second) < 0) {
        const double d = std::hypot(x - ring.first, y - ring.second);
        if (d > db) db = d, b = {x, y};
      }
  return da < db ? std::pair{a, b} : std::pair{b, a};
}

// Every step completed and a pass (the pass mark 70, the peak force at the hand under the safe 3 N).
// The script's score is printed with how each step went; tests/README.md gives the scores measured.
TEST(CliFirstAttempt, AScriptThatReadsOnlyTheScreenPassesThePenetrableSphereWithTheMouse) {
  const fs::path dir = process_folder(test_output_dir("cli_first_attempt"));
  Desk desk(dir);
  desk.start(needle_sim_exe().string() + " run --device mouse --size 1280x720 --db " + quoted(dir / "sessions.db") +
             " --out " + quoted(dir / "out") + " > " + quoted(dir / "run.log") + " 2>&1 & echo $! > " +
             quoted(dir / "run.pid"));
  std::string said;
  const Clock::time_point began = Clock::now();
  const auto log = [&](const std::string& line) {
    char at[16];
    std::snprintf(at, sizeof at, "%5.1f s ", std::chrono::duration<double>(Clock::now() - began).count());
    said += at + line + "\n";
  };
  log_ = log;
  log("window " + desk.find_window());
  settle(0.6);  // the loop starts on the first frame

  // Approach. With the cursor on the entry ring the tip is on the line of sight through the entry,
  // beyond it or before it (as the needle starts, beyond, where that line has left the tissue), and
  // the distance gauge reads how far in depth alone. The needle starts
  // tilted into the screen, so a notch along it moves the tip in depth as well as across: a few
  // notches out (the cursor back on the ring) give the fill a notch takes off, and so how many notches
  // are left. Those are made with the tip half-way along the short part of the planned axis drawn
  // out of the tissue, in the air, the cursor put back there; then the wrist turns onto the axis, in
  // the air, and notches along the needle take the tip down the axis to the entry.
  Reading r = read(desk);
  const int approached = r.progress;
  const std::optional<std::pair<int, int>> entry = find_ring(r.screen, r.panel, kEntry, true);
  ASSERT_TRUE(entry) << said;
  const std::pair<int, int> out_end = axis_line_ends(r, *entry).first;
  const std::pair<int, int> above{(entry->first + out_end.first) / 2, (entry->second + out_end.second) / 2};
  log("approach: the entry at " + std::to_string(entry->first) + ", " + std::to_string(entry->second) +
      ", the axis out to " + std::to_string(out_end.first) + ", " + std::to_string(out_end.second));
  const auto notches_then_to = [&](int notches, std::pair<int, int> to) {  // then the distance gauge's fill
    desk.wheel(notches);
    settle(0.15);
    desk.move(to.first, to.second);
    settle(0.3);
    return double(fill(read(desk).distance));
  };
  const double d0 = notches_then_to(0, *entry);
  const int k = 4;
  const double d1 = notches_then_to(-k, *entry);  // out a few notches: nearer or further?
  const double per_notch = std::abs(d0 - d1) / k;
  log("approach: on the ring, distance " + std::to_string(int(d0)) + " then " + std::to_string(int(d1)) + " px");
  ASSERT_GT(per_notch, 1.0) << said;
  const int way = d1 < d0 ? -1 : 1, left = int(std::lround(d1 / per_notch));
  notches_then_to(0, above);
  notches_then_to(way * left, above);
  Wrist wrist;
  turn_onto_axis(desk, wrist, 1 << 30, Clock::now() + std::chrono::seconds(5), {});
  for (Clock::time_point until = Clock::now() + std::chrono::seconds(6);
       read(desk).progress == approached && Clock::now() < until;) {
    desk.wheel(1);
    settle(0.3);
  }
  r = read(desk);
  log("approach: progress " + std::to_string(r.progress) + ", off the axis " + std::to_string(fill(r.axis)) + " px");
  ASSERT_GT(r.progress, approached) << said;
  Clock::time_point until;

  // Insert: on along the needle, a few notches at a time while the depth gauge's tick (the tip) is
  // well short of its green band, then one at a time to the band's middle; held there.
  const int inserted = r.progress;
  until = Clock::now() + std::chrono::seconds(16);
  while (Clock::now() < until) {
    r = read(desk);
    if (r.progress > inserted || !r.depth || r.depth->tick < 0 || r.depth->band_lo < 0) break;
    const int middle = (r.depth->band_lo + r.depth->band_hi) / 2;
    if (r.depth->tick > r.depth->band_hi)
      desk.wheel(-1);
    else if (r.depth->tick < middle - (r.depth->band_hi - r.depth->band_lo) / 6)
      desk.wheel(r.depth->tick < r.depth->band_lo - 30 ? 3 : 1);
    settle(0.3);
  }
  r = read(desk);
  log("insert: progress " + std::to_string(r.progress));
  ASSERT_GT(r.progress, inserted) << said;

  // Pivot: the wrist towards the pad's dot by what the axis gauge says (its whole length when it
  // reads full), the hand still; in the tissue the needle follows slowly, so each turn is read after
  // it settles and the next is most of what is left, until well inside the tolerance.
  const int pivoted = r.progress;
  turn_onto_axis(desk, wrist, pivoted, Clock::now() + std::chrono::seconds(20),
                 {.close = 0.4, .share = 0.9, .settle_s = 0.8, .per_move = 2});
  for (until = Clock::now() + std::chrono::seconds(3); read(desk).progress == pivoted && Clock::now() < until;)
    settle(0.2);
  r = read(desk);
  log("pivot: progress " + std::to_string(r.progress));
  ASSERT_GT(r.progress, pivoted) << said;

  // Advance: in along the needle while the distance to the target shrinks, a notch at a time near
  // it; past its shortest, back a notch.
  const int advanced = r.progress;
  int best = fill(read(desk).distance);
  for (until = Clock::now() + std::chrono::seconds(14); Clock::now() < until;) {
    r = read(desk);
    if (r.progress > advanced || !r.distance) break;
    const int now = fill(r.distance), tolerance = r.distance->tick - r.distance->left;
    log("advance: distance " + std::to_string(now) + " px (tolerance at " + std::to_string(tolerance) +
        "), off the axis " + std::to_string(fill(r.axis)) + " px");
    if (now > best + 4) {
      desk.wheel(-1);
      settle(0.4);
      best = fill(read(desk).distance);
      continue;
    }
    best = std::min(best, now);
    desk.wheel(now > 3 * tolerance ? 2 : 1);
    settle(0.35);
  }
  r = read(desk);
  log("advance: progress " + std::to_string(r.progress));
  ASSERT_GT(r.progress, advanced) << said;

  // Withdraw: out along the needle, then the cursor up, away from the target.
  desk.wheel(-45);
  settle(0.5);
  const std::pair<int, int> at = desk.cursor();
  desk.move(at.first, std::max(5, at.second - 150));
  for (until = Clock::now() + std::chrono::seconds(10);
       !fs::exists(dir / "out" / "score.json") && Clock::now() < until;)
    settle(0.2);
  desk.run("kill $(cat " + quoted(dir / "run.pid") + ")");
  settle(1.0);

  ASSERT_TRUE(fs::exists(dir / "out" / "score.json")) << said << run_command("cat " + quoted(dir / "run.log")).output;
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(dir / "out" / "score.json"));
  for (const nlohmann::json& step : score["steps"])
    EXPECT_EQ(step["outcome"], "completed") << step["id"] << "\n" << said;
  EXPECT_TRUE(score["passed"].get<bool>()) << score.dump(2) << "\n" << said;
  std::printf("first attempt from the screen alone: score %.1f, %s\n%s", score["score"].get<double>(),
              score["passed"].get<bool>() ? "passed" : "not passed", said.c_str());
}

}  // namespace
}  // namespace needle::test
