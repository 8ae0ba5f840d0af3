#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "haptics/realtime/latency_histogram.hpp"

namespace needle::haptics {
namespace {

TEST(RealtimeHistogram, BucketsTileTheRangeWithoutGapsOrOverlap) {
  for (int b = 0; b + 1 < LatencyHistogram::kBuckets - 1; ++b) {
    EXPECT_EQ(LatencyHistogram::bucket_high(b) + 1, LatencyHistogram::bucket_low(b + 1)) << "bucket " << b;
    EXPECT_EQ(LatencyHistogram::bucket_of(LatencyHistogram::bucket_low(b)), b);
    EXPECT_EQ(LatencyHistogram::bucket_of(LatencyHistogram::bucket_high(b)), b);
  }
}

TEST(RealtimeHistogram, SmallValuesAreExact) {
  LatencyHistogram h;
  for (uint64_t v : {3u, 3u, 3u, 17u}) h.record(v);
  EXPECT_EQ(h.percentile(0.5), 3.0);
  EXPECT_EQ(h.percentile(1.0), 17.0);
}

// Percentiles against the exact order statistics of the same data (nearest rank).
TEST(RealtimeHistogram, PercentilesWithinOneBucketOfTheSortedData) {
  std::mt19937_64 rng(1);
  std::lognormal_distribution<double> dist(std::log(20000.0), 1.0);  // ~20 us, heavy tail
  std::vector<uint64_t> values(100000);
  LatencyHistogram h;
  for (auto& v : values) {
    v = static_cast<uint64_t>(dist(rng));
    h.record(v);
  }
  std::sort(values.begin(), values.end());
  for (double q : {0.5, 0.99, 0.999}) {
    const auto rank = static_cast<std::size_t>(std::ceil(q * values.size()));
    const double exact = static_cast<double>(values[rank - 1]);
    EXPECT_NEAR(h.percentile(q), exact, exact / 32.0 + 1.0) << "q = " << q;
  }
  const LatencySummary s = h.summary();
  EXPECT_EQ(s.count, values.size());
  EXPECT_EQ(s.max_ns, static_cast<double>(values.back()));
  double sum = 0.0;
  for (auto v : values) sum += static_cast<double>(v);
  EXPECT_NEAR(s.mean_ns, sum / values.size(), 1e-6 * s.mean_ns);
}

TEST(RealtimeHistogram, ClearEmptiesIt) {
  LatencyHistogram h;
  h.record(1000);
  h.clear();
  EXPECT_EQ(h.summary().count, 0u);
  EXPECT_EQ(h.percentile(0.5), 0.0);
}

}  // namespace
}  // namespace needle::haptics
