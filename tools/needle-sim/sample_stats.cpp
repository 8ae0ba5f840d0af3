#include "sample_stats.hpp"

#include <algorithm>
#include <cmath>

namespace needle::cli {

double percentile(std::vector<double> samples, double q) {
  if (samples.empty()) return 0.0;
  size_t rank = size_t(std::ceil(std::clamp(q, 0.0, 1.0) * double(samples.size())));
  size_t index = rank == 0 ? 0 : rank - 1;
  std::nth_element(samples.begin(), samples.begin() + long(index), samples.end());
  return samples[index];
}

}  // namespace needle::cli
