#include "haptics/anatomy/lattice_field.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics::anatomy {

int Lattice::floor_index(double x) const { return int(std::floor(x / spacing_m + 1e-9)); }
int Lattice::ceil_index(double x) const { return int(std::ceil(x / spacing_m - 1e-9)); }

LatticeField::LatticeField(const Lattice& lattice, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int margin,
                           double fill_m)
    : lattice_(lattice) {
  size_t total = 1;
  for (int a = 0; a < 3; ++a) {
    first_[size_t(a)] = lattice.floor_index(lo[a] + lattice.origin[a]) - margin;
    count_[size_t(a)] = lattice.ceil_index(hi[a] + lattice.origin[a]) + margin - first_[size_t(a)] + 1;
    total *= size_t(count_[size_t(a)]);
  }
  values_.assign(total, lattice.quanta(fill_m));
}

Eigen::Vector3d LatticeField::position(int i, int j, int k) const {
  return lattice_.spacing_m * Eigen::Vector3d(i, j, k);
}

int16_t LatticeField::at(int i, int j, int k, int16_t outside) const {
  if (i < first_[0] || j < first_[1] || k < first_[2] || i >= first_[0] + count_[0] || j >= first_[1] + count_[1] ||
      k >= first_[2] + count_[2])
    return outside;
  return values_[index(i, j, k)];
}

template <class F>
void LatticeField::for_nodes(const std::array<int, 3>& lo, const std::array<int, 3>& hi, F f) {
  std::array<int, 3> a{}, b{};
  for (size_t d = 0; d < 3; ++d) {
    a[d] = std::max(lo[d], first_[d]);
    b[d] = std::min(hi[d], first_[d] + count_[d] - 1);
    if (a[d] > b[d]) return;
  }
  for (int k = a[2]; k <= b[2]; ++k)
    for (int j = a[1]; j <= b[1]; ++j) {
      int16_t* row = values_.data() + index(a[0], j, k);
      for (int i = a[0]; i <= b[0]; ++i) f(i, j, k, row[i - a[0]]);
    }
}

void LatticeField::assign_beneath(const std::function<double(double x, double y, double& dzdx, double& dzdy)>& height,
                                  double offset_m) {
  for (int j = 0; j < count_[1]; ++j)
    for (int i = 0; i < count_[0]; ++i) {
      const Eigen::Vector3d column = shape_point(first_[0] + i, first_[1] + j, first_[2]);
      double dzdx = 0.0, dzdy = 0.0;
      const double top = height(column.x(), column.y(), dzdx, dzdy);
      const double inverse_norm = 1.0 / std::sqrt(1.0 + dzdx * dzdx + dzdy * dzdy);
      for (int k = 0; k < count_[2]; ++k) {
        const double z = column.z() + lattice_.spacing_m * k;
        values_[index(first_[0] + i, first_[1] + j, first_[2] + k)] =
            lattice_.quanta((z - top) * inverse_norm - offset_m);
      }
    }
}

void LatticeField::add(const ShapePrimitive& p, double reach_m) {
  Eigen::Vector3d lo, hi;
  primitive_bounds(p, lo, hi);
  std::array<int, 3> a{}, b{};
  for (int d = 0; d < 3; ++d) {
    a[size_t(d)] = lattice_.floor_index(lo[d] + lattice_.origin[d] - reach_m);
    b[size_t(d)] = lattice_.ceil_index(hi[d] + lattice_.origin[d] + reach_m);
  }
  for_nodes(a, b, [&](int i, int j, int k, int16_t& v) {
    v = std::min(v, lattice_.quanta(primitive_phi(p, shape_point(i, j, k))));
  });
}

void LatticeField::add(std::span<const ShapePrimitive> ps, double reach_m) {
  for (const ShapePrimitive& p : ps) add(p, reach_m);
}

void LatticeField::subtract(const LatticeField& other) {
  const std::array<int, 3> last{other.first_[0] + other.count_[0] - 1, other.first_[1] + other.count_[1] - 1,
                                other.first_[2] + other.count_[2] - 1};
  for_nodes(other.first_, last, [&](int i, int j, int k, int16_t& v) {
    v = std::max<int16_t>(v, int16_t(-other.values_[other.index(i, j, k)]));
  });
}

void LatticeField::intersect(const LatticeField& other, int offset_quanta) {
  const std::array<int, 3> last{first_[0] + count_[0] - 1, first_[1] + count_[1] - 1, first_[2] + count_[2] - 1};
  for_nodes(first_, last, [&](int i, int j, int k, int16_t& v) {
    const int outer = int(other.at(i, j, k, 32767)) + offset_quanta;
    v = int16_t(std::clamp(std::max(int(v), outer), -32767, 32767));
  });
}

bool LatticeField::empty() const {
  return std::none_of(values_.begin(), values_.end(), [](int16_t v) { return v <= 0; });
}

std::shared_ptr<const SdfGrid> LatticeField::grid() const {
  return std::make_shared<const SdfGrid>(position(first_[0], first_[1], first_[2]), lattice_.spacing_m, count_,
                                         lattice_.quantum_m, values_);
}

}  // namespace needle::haptics::anatomy
