// Limits on what an input file may ask of a run, shared by the readers of every format: a
// scenario's length and its operator's waypoint times, a recording's length, the run that plays
// them; how large and how deeply nested a file may be; the ranges numbers are checked against. A
// number past a limit is an error naming the file, never a run that does not end.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace needle::io {

// The longest session a run, a scenario or a recording may describe: 30 minutes. A guided task
// lasts minutes; past this a file is taken to be wrong (a waypoint at t = 1e308, a recording
// that grows without end), not a session.
inline constexpr double kMaxSessionSeconds = 1800.0;

// How far from the world's origin (the robot base frame of the thesis, metres) a position in a
// task, scenario, operator script or recording may lie: 10 m. Design value: a training station
// is a desk-top device and the tissue in front of it, a few decimetres across; 10 m is past any
// room, so a position beyond it is a typo or an attack (1e300), never a place.
inline constexpr double kWorldExtent_m = 10.0;

// The largest component of a direction (an axis, a normal, a probe's beams), normalized on
// reading: its components say which way, not how far. Design value: 1e6 lets any way be written
// while refusing 1e300, whose square overflows and leaves no direction at all.
inline constexpr double kMaxDirectionComponent = 1e6;

// The largest text file a reader takes (task, scene, scenario, parameter set, operator script,
// URDF, settings): 16 MiB. Design value: the largest shipped file is under 100 KiB; the limit
// turns `/dev/zero`-like input (endless, or a file of gigabytes) into an error before it is read.
inline constexpr std::uintmax_t kMaxTextFileBytes = 16u << 20;

// How deeply a JSON or XML document may nest its values or elements: 64 levels. Design value:
// the deepest shipped file nests 7 (a scenario's layer's shape's point), a glTF about 6 (a
// material's extension); readers and copies of a document recurse once a level, so a document
// nested 100,000 deep would overflow the stack before any key is checked.
inline constexpr int kMaxNestingDepth = 64;

// A closed or half-open interval a number read from a file must lie in, with its unit, said in
// errors as "(0, 1800] s".
struct Range {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;  // (lo, hi] rather than [lo, hi]
  const char* unit = "";

  bool contains(double x) const { return (lo_open ? x > lo : x >= lo) && x <= hi; }
  std::string text() const {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%c%g, %g]%s%s", lo_open ? '(' : '[', lo, hi, *unit ? " " : "", unit);
    return buffer;
  }
};

// A number as an error message quotes it: 1e+300, 0.002, -3.
inline std::string number_text(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

// The ranges every format shares.
inline constexpr Range kSessionTimeRange{0.0, kMaxSessionSeconds, false, "s"};     // a time within a session
inline constexpr Range kSessionDurationRange{0.0, kMaxSessionSeconds, true, "s"};  // a length of time within one
inline constexpr Range kWorldCoordinateRange{-kWorldExtent_m, kWorldExtent_m, false, "m"};
inline constexpr Range kDirectionComponentRange{-kMaxDirectionComponent, kMaxDirectionComponent, false, ""};

}  // namespace needle::io
