#include "haptics/sim/sim_output.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "io/write_file.hpp"

namespace needle::haptics {

void write_ticks_csv(const std::string& path, const std::vector<TickRecord>& ticks, int dof) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error(path + ": cannot write");
  std::string header = "t";
  for (const char* robot : {"q_m", "q_v"})
    for (int i = 1; i <= dof; ++i) header += "," + std::string(robot) + std::to_string(i);
  for (const char* v : {"x_m", "x_v", "F_h", "F_v"})
    for (const char* axis : {"_x", "_y", "_z"}) header += "," + std::string(v) + axis;
  header += ",lambda_v1,lambda_v2,lambda_m1,lambda_m2,phi,psi1,psi2,energy,mode\n";
  std::fputs(header.c_str(), f.get());
  for (const TickRecord& r : ticks) {
    std::fprintf(f.get(), "%.6f", r.t);
    for (const VecN* q : {&r.q_m, &r.q_v})
      for (int i = 0; i < dof; ++i) std::fprintf(f.get(), ",%.9g", (*q)[i]);
    for (const Eigen::Vector3d* v : {&r.x_m, &r.x_v, &r.force_h, &r.force_v})
      for (int i = 0; i < 3; ++i) std::fprintf(f.get(), ",%.9g", (*v)[i]);
    std::fprintf(f.get(), ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%s\n", r.lambda_v[0], r.lambda_v[1], r.lambda_m[0],
                 r.lambda_m[1], r.phi, r.psi[0], r.psi[1], r.energy, contact_mode_name(r.mode));
  }
  if (std::ferror(f.get())) throw std::runtime_error(path + ": write failed");
}

void write_summary_json(const std::string& path, const SimSummary& summary) {
  io::write_file(path, summary.to_json().dump(2) + "\n");
}

}  // namespace needle::haptics
