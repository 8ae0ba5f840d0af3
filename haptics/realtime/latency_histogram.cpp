#include "haptics/realtime/latency_histogram.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace needle::haptics {
namespace {

// Only the loop writes, so a relaxed load-add-store is enough and avoids a locked RMW.
void bump(std::atomic<uint64_t>& a, uint64_t by) noexcept {
  a.store(a.load(std::memory_order_relaxed) + by, std::memory_order_relaxed);
}

}  // namespace

int LatencyHistogram::bucket_of(uint64_t ns) noexcept {
  if (ns < kSubBuckets) return static_cast<int>(ns);
  const int exponent = std::bit_width(ns) - 1;  // >= 5
  if (exponent >= kMaxExponent) return kBuckets - 1;
  const int shift = exponent - 5;
  return kSubBuckets + shift * kSubBuckets + static_cast<int>((ns >> shift) - kSubBuckets);
}

uint64_t LatencyHistogram::bucket_low(int bucket) noexcept {
  if (bucket < kSubBuckets) return static_cast<uint64_t>(bucket);
  const int shift = (bucket - kSubBuckets) / kSubBuckets;
  const uint64_t mantissa = static_cast<uint64_t>((bucket - kSubBuckets) % kSubBuckets + kSubBuckets);
  return mantissa << shift;
}

uint64_t LatencyHistogram::bucket_high(int bucket) noexcept {
  if (bucket < kSubBuckets) return static_cast<uint64_t>(bucket);
  const int shift = (bucket - kSubBuckets) / kSubBuckets;
  return bucket_low(bucket) + ((uint64_t{1} << shift) - 1);
}

void LatencyHistogram::record(uint64_t ns) noexcept {
  bump(counts_[bucket_of(ns)], 1);
  bump(sum_ns_, ns);
  if (ns > max_ns_.load(std::memory_order_relaxed)) max_ns_.store(ns, std::memory_order_relaxed);
  bump(total_, 1);
}

void LatencyHistogram::clear() noexcept {
  for (auto& c : counts_) c.store(0, std::memory_order_relaxed);
  total_.store(0, std::memory_order_relaxed);
  sum_ns_.store(0, std::memory_order_relaxed);
  max_ns_.store(0, std::memory_order_relaxed);
}

double LatencyHistogram::percentile(double q) const noexcept {
  // Sum the buckets first: a reader racing the writer sees a slightly older histogram,
  // never an inconsistent rank.
  uint64_t total = 0;
  for (const auto& c : counts_) total += c.load(std::memory_order_relaxed);
  if (total == 0) return 0.0;
  const auto rank = std::max<uint64_t>(1, static_cast<uint64_t>(std::ceil(q * static_cast<double>(total))));
  const double max_ns = static_cast<double>(max_ns_.load(std::memory_order_relaxed));
  uint64_t seen = 0;
  for (int b = 0; b < kBuckets; ++b) {
    seen += counts_[b].load(std::memory_order_relaxed);
    if (seen >= rank) {
      const double mid = 0.5 * static_cast<double>(bucket_low(b) + bucket_high(b));
      return std::min(mid, max_ns);
    }
  }
  return max_ns;
}

LatencySummary LatencyHistogram::summary() const noexcept {
  LatencySummary s;
  s.count = total_.load(std::memory_order_relaxed);
  s.p50_ns = percentile(0.50);
  s.p99_ns = percentile(0.99);
  s.p999_ns = percentile(0.999);
  s.max_ns = static_cast<double>(max_ns_.load(std::memory_order_relaxed));
  s.mean_ns =
      s.count ? static_cast<double>(sum_ns_.load(std::memory_order_relaxed)) / static_cast<double>(s.count) : 0.0;
  return s;
}

}  // namespace needle::haptics
