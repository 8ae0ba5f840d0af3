#include "haptics/tissue/sdf_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace needle::haptics {
namespace {

std::string number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

SdfGrid::SdfGrid(const Eigen::Vector3d& origin, double spacing_m, const std::array<int, 3>& nodes, double quantum_m,
                 std::vector<int16_t> values)
    : origin_(origin), spacing_(spacing_m), nodes_(nodes), quantum_(quantum_m), values_(std::move(values)) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(origin_[a]) || std::abs(origin_[a]) > 10.0)
      throw SdfGridError("origin: each coordinate must be finite and within 10 m, got " + number(origin_[a]));
  if (!(spacing_ >= kMinSpacing_m && spacing_ <= kMaxSpacing_m))
    throw SdfGridError("spacing: must be in [" + number(kMinSpacing_m) + ", " + number(kMaxSpacing_m) + "] m, got " +
                       number(spacing_));
  if (!(quantum_ >= kMinQuantum_m && quantum_ <= kMaxQuantum_m))
    throw SdfGridError("quantum: must be in [" + number(kMinQuantum_m) + ", " + number(kMaxQuantum_m) + "] m, got " +
                       number(quantum_));
  int64_t count = 1;
  for (int a = 0; a < 3; ++a) {
    if (nodes_[a] < 2) throw SdfGridError("nodes: at least 2 along each axis, got " + std::to_string(nodes_[a]));
    count *= nodes_[a];
    if (count > kMaxNodes) throw SdfGridError("nodes: at most " + std::to_string(kMaxNodes) + " in all");
  }
  if (int64_t(values_.size()) != count)
    throw SdfGridError("values: expected " + std::to_string(count) + " (the nodes' product), got " +
                       std::to_string(values_.size()));
}

int16_t SdfGrid::quantise(double phi_m, double quantum_m) {
  const double q = std::round(phi_m / quantum_m);
  return int16_t(std::clamp(q, -32767.0, 32767.0));
}

SdfGrid SdfGrid::sample(const std::function<double(const Eigen::Vector3d&)>& phi, const Eigen::Vector3d& lo,
                        const Eigen::Vector3d& hi, double spacing_m, double quantum_m) {
  std::array<int, 3> n{};
  for (int a = 0; a < 3; ++a) n[size_t(a)] = std::max(2, int(std::ceil((hi[a] - lo[a]) / spacing_m - 1e-9)) + 1);
  std::vector<int16_t> values(static_cast<size_t>(n[0]) * static_cast<size_t>(n[1]) * static_cast<size_t>(n[2]));
  size_t at = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) values[at++] = quantise(phi(lo + spacing_m * Eigen::Vector3d(i, j, k)), quantum_m);
  return SdfGrid(lo, spacing_m, n, quantum_m, std::move(values));
}

void SdfGrid::locate(const Eigen::Vector3d& p, std::array<int, 3>& cell, Eigen::Vector3d& f) const {
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - origin_[a]) / spacing_;
    const int c = std::clamp(int(std::floor(u)), 0, nodes_[size_t(a)] - 2);
    cell[size_t(a)] = c;
    f[a] = std::clamp(u - c, 0.0, 1.0);
  }
}

std::array<double, 8> SdfGrid::corners(const Eigen::Vector3d& p, Eigen::Vector3d& f) const {
  std::array<int, 3> c{};
  locate(p, c, f);
  const size_t sx = 1, sy = size_t(nodes_[0]), sz = sy * size_t(nodes_[1]);
  const int16_t* v = values_.data() + index(c[0], c[1], c[2]);
  return {double(v[0]),  double(v[sx]),      double(v[sy]),      double(v[sy + sx]),
          double(v[sz]), double(v[sz + sx]), double(v[sz + sy]), double(v[sz + sy + sx])};
}

double SdfGrid::phi(const Eigen::Vector3d& x, double offset_m) const {
  const Eigen::Vector3d p = x.cwiseMax(origin_).cwiseMin(upper());
  Eigen::Vector3d f;
  const std::array<double, 8> v = corners(p, f);
  const double c00 = v[0] + f.x() * (v[1] - v[0]);
  const double c10 = v[2] + f.x() * (v[3] - v[2]);
  const double c01 = v[4] + f.x() * (v[5] - v[4]);
  const double c11 = v[6] + f.x() * (v[7] - v[6]);
  const double c0 = c00 + f.y() * (c10 - c00), c1 = c01 + f.y() * (c11 - c01);
  const double inside = quantum_ * (c0 + f.z() * (c1 - c0)) + offset_m;
  const double gap = (x - p).norm();
  return gap > 0.0 ? gap + std::max(inside, 0.0) : inside;
}

SurfaceSample SdfGrid::evaluate(const Eigen::Vector3d& x, double offset_m) const {
  const Eigen::Vector3d p = x.cwiseMax(origin_).cwiseMin(upper());
  Eigen::Vector3d f;
  const auto [v000, v100, v010, v110, v001, v101, v011, v111] = corners(p, f);
  const double fx = f.x(), fy = f.y(), fz = f.z(), gx = 1.0 - fx, gy = 1.0 - fy, gz = 1.0 - fz;
  const double value = gz * (gy * (gx * v000 + fx * v100) + fy * (gx * v010 + fx * v110)) +
                       fz * (gy * (gx * v001 + fx * v101) + fy * (gx * v011 + fx * v111));
  // ∂/∂f of the trilinear form, then d/dx = (1/h) ∂/∂f.
  const double dx = gz * (gy * (v100 - v000) + fy * (v110 - v010)) + fz * (gy * (v101 - v001) + fy * (v111 - v011));
  const double dy = gz * (gx * (v010 - v000) + fx * (v110 - v100)) + fz * (gx * (v011 - v001) + fx * (v111 - v101));
  const double dz = gy * (gx * (v001 - v000) + fx * (v101 - v100)) + fy * (gx * (v011 - v010) + fx * (v111 - v110));
  const double dxy = gz * (v110 - v010 - v100 + v000) + fz * (v111 - v011 - v101 + v001);
  const double dxz = gy * (v101 - v001 - v100 + v000) + fy * (v111 - v011 - v110 + v010);
  const double dyz = gx * (v011 - v001 - v010 + v000) + fx * (v111 - v101 - v110 + v100);
  const double scale = quantum_ / spacing_;
  SurfaceSample s;
  const Eigen::Vector3d outside = x - p;
  const double gap = outside.norm();
  s.phi = gap > 0.0 ? gap + std::max(quantum_ * value + offset_m, 0.0) : quantum_ * value + offset_m;
  const Eigen::Vector3d gradient = scale * Eigen::Vector3d(dx, dy, dz);
  const double length = gradient.norm();
  if (gap > 0.0) {
    s.gradient = outside / gap;  // beyond the box φ grows with the distance to it
  } else if (length > 1e-12) {
    s.gradient = gradient / length;
    const double h = scale / spacing_ / length;
    s.hessian << 0.0, dxy * h, dxz * h, dxy * h, 0.0, dyz * h, dxz * h, dyz * h, 0.0;
  }
  return s;
}

}  // namespace needle::haptics
