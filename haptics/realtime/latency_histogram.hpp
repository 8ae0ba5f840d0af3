// Lock-free histogram of durations in nanoseconds: one writer (the loop) records, any
// thread reads percentiles. Log-linear buckets, 32 per power of two, so a percentile is
// known to within 1/32 (3 %) of its value; values below 32 ns are exact. The maximum is
// kept exactly.
#pragma once

#include <atomic>
#include <cstdint>

namespace needle::haptics {

struct LatencySummary {
  uint64_t count = 0;
  double p50_ns = 0.0;
  double p99_ns = 0.0;
  double p999_ns = 0.0;
  double max_ns = 0.0;
  double mean_ns = 0.0;
};

class LatencyHistogram {
 public:
  static constexpr int kSubBuckets = 32;
  static constexpr int kMaxExponent = 40;  // 2^40 ns, about 18 minutes; larger values clamp
  static constexpr int kBuckets = kSubBuckets + (kMaxExponent - 5) * kSubBuckets;

  // Writer thread only: no allocation, no lock.
  void record(uint64_t ns) noexcept;
  // Writer thread only (the loop applies a reset command).
  void clear() noexcept;

  // Any thread. The value below which a fraction q of the records lie, as the midpoint of
  // its bucket (clamped to the maximum); 0 when empty.
  double percentile(double q) const noexcept;
  LatencySummary summary() const noexcept;

  static int bucket_of(uint64_t ns) noexcept;
  static uint64_t bucket_low(int bucket) noexcept;
  static uint64_t bucket_high(int bucket) noexcept;  // inclusive

 private:
  std::atomic<uint64_t> counts_[kBuckets] = {};
  std::atomic<uint64_t> total_{0};
  std::atomic<uint64_t> sum_ns_{0};
  std::atomic<uint64_t> max_ns_{0};
};

}  // namespace needle::haptics
