// Writes a session to disk from the loop's sample ring, on its own non-real-time thread.
// Each pass drains the ring, writes the records as blocks (each with its count and checksum,
// haptics/recording/session_format.hpp) and flushes them to the kernel, every kPassInterval
// (20 ms): a crash or kill of the process loses at most the samples of the current pass, well
// under 100 ms, and leaves a file that reads up to its last whole block. (Power loss is another
// matter: no fsync per pass; stop() syncs the file when it closes it.)
// The ring has one consumer, so whoever else needs every sample (the scoring) takes them from
// the recorder, through its sink, on the recorder's thread.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "haptics/realtime/tick_sample.hpp"
#include "haptics/recording/session_format.hpp"
#include "haptics/sync/spsc_ring.hpp"

namespace needle::haptics {

class SessionRecorder {
 public:
  static constexpr std::chrono::milliseconds kPassInterval{20};

  // Called with every sample, in tick order, after it is encoded.
  using SampleSink = std::function<void(const TickSample&)>;

  // Creates the file and writes the header; throws RecordingError naming the file.
  SessionRecorder(const std::string& path, const SessionHeader& header, SpscRing<TickSample>& samples,
                  SampleSink sink = {});
  ~SessionRecorder();
  SessionRecorder(const SessionRecorder&) = delete;
  SessionRecorder& operator=(const SessionRecorder&) = delete;

  // One pass on the calling thread: drain, write, feed the sink, flush. Returns the records
  // written. Throws RecordingError when the disk refuses the data, or what the sink throws.
  std::size_t drain();

  // Passes on a thread of its own until stop().
  void start();
  // Stops the thread, does a last pass, writes the end mark (`ran_to_end`: the session ran to
  // its end, not a window closed early), syncs the file to the disk and closes it. Once; never
  // throws: a failure is kept in error().
  void stop(bool ran_to_end = false);

  uint64_t written() const noexcept { return written_.load(std::memory_order_relaxed); }
  // Samples the loop had to drop because this recorder fell behind.
  uint64_t dropped() const noexcept { return samples_.overflowed(); }
  // Set when a pass or the close failed (disk full, the sink threw): the message, else empty.
  std::string error() const;

 private:
  std::string path_;
  SpscRing<TickSample>& samples_;
  SampleSink sink_;
  void write_block();  // the records in buffer_, behind their block header
  void close(bool ran_to_end);

  std::FILE* file_ = nullptr;
  std::vector<uint8_t> buffer_;  // a block header, then its records
  uint32_t block_records_ = 0;
  static constexpr uint32_t kBlockRecords = 256;
  std::atomic<uint64_t> written_{0};
  std::atomic<bool> stop_{false};
  std::atomic<bool> failed_{false};
  std::string error_;  // written before failed_ is set
  std::thread thread_;
};

}  // namespace needle::haptics
