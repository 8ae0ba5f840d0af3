#include "haptics/sim/sim_output.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "io/file_write.hpp"

namespace needle::haptics {
namespace {

// A CSV field: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// printf onto the end of `out`.
[[gnu::format(printf, 2, 3)]] void append(std::string& out, const char* format, ...) {
  char buffer[64];
  va_list args;
  va_start(args, format);
  const int n = std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  out.append(buffer, size_t(std::min<int>(n, int(sizeof buffer) - 1)));
}

}  // namespace

void write_ticks_csv(const std::string& path, const std::vector<TickRecord>& ticks, int dof,
                     const TissueModel& tissue) {
  std::string csv = "t";
  for (const char* robot : {"q_m", "q_v"})
    for (int i = 1; i <= dof; ++i) csv += "," + std::string(robot) + std::to_string(i);
  for (const char* v : {"x_m", "x_v", "F_h", "F_v"})
    for (const char* axis : {"_x", "_y", "_z"}) csv += "," + std::string(v) + axis;
  csv +=
      ",lambda_v1,lambda_v2,lambda_m1,lambda_m2,phi,psi1,psi2,energy,mode,axial_force_N,layer,hand_work_J,world_stored_"
      "J\n";
  for (const TickRecord& r : ticks) {
    append(csv, "%.6f", r.t);
    for (const VecN* q : {&r.q_m, &r.q_v})
      for (int i = 0; i < dof; ++i) append(csv, ",%.9g", (*q)[i]);
    for (const Eigen::Vector3d* v : {&r.x_m, &r.x_v, &r.force_h, &r.force_v})
      for (int i = 0; i < 3; ++i) append(csv, ",%.9g", (*v)[i]);
    for (double x : {r.lambda_v[0], r.lambda_v[1], r.lambda_m[0], r.lambda_m[1], r.phi, r.psi[0], r.psi[1], r.energy})
      append(csv, ",%.9g", x);
    csv += std::string(",") + contact_mode_name(r.mode);
    append(csv, ",%.9g,", r.axial_force_N);
    csv += r.layer < 0 ? std::string() : csv_field(tissue.layer(r.layer).name);
    append(csv, ",%.9g,%.9g\n", r.hand_work_J, r.world_stored_J);
  }
  io::write_file(path, csv);
}

void write_summary_json(const std::string& path, const SimSummary& summary) {
  io::write_file(path, summary.to_json().dump(2) + "\n");
}

}  // namespace needle::haptics
