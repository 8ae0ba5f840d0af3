// Bounded single-producer single-consumer queue. push never blocks: when the ring is full
// the new element is dropped and counted, so the producer (the haptic loop) keeps its
// timing and the consumer learns exactly how many elements it missed.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace needle::haptics {

template <typename T>
class SpscRing {
 public:
  // Capacity is rounded up to a power of two; storage is allocated here, never later.
  explicit SpscRing(std::size_t capacity) : mask_(round_up(capacity) - 1), slots_(new T[mask_ + 1]) {}

  std::size_t capacity() const noexcept { return mask_ + 1; }

  // Producer thread only. False (and the overflow counter advances) when full.
  bool push(const T& value) noexcept {
    const uint64_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) > mask_) {
      overflow_.store(overflow_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
      return false;
    }
    slots_[head & mask_] = value;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer thread only.
  bool pop(T& out) noexcept {
    const uint64_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    out = slots_[tail & mask_];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

  // Any thread.
  uint64_t pushed() const noexcept { return head_.load(std::memory_order_acquire); }
  uint64_t overflowed() const noexcept { return overflow_.load(std::memory_order_relaxed); }

 private:
  static std::size_t round_up(std::size_t n) {
    std::size_t p = 2;
    while (p < n) p <<= 1;
    return p;
  }

  const std::size_t mask_;
  std::unique_ptr<T[]> slots_;
  alignas(64) std::atomic<uint64_t> head_{0};
  alignas(64) std::atomic<uint64_t> tail_{0};
  alignas(64) std::atomic<uint64_t> overflow_{0};
};

}  // namespace needle::haptics
