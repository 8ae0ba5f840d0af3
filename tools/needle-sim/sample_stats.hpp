// Order statistics of a batch of timings, for benchmark tables.
#pragma once

#include <vector>

namespace needle::cli {

// Nearest-rank percentile (q in [0, 1]) of the samples; 0 when there are none.
double percentile(std::vector<double> samples, double q);

}  // namespace needle::cli
