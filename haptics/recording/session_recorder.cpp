#include "haptics/recording/session_recorder.hpp"

#include <cerrno>
#include <cstring>

namespace needle::haptics {

SessionRecorder::SessionRecorder(const std::string& path, const SessionHeader& header, SpscRing<TickSample>& samples,
                                 SampleSink sink)
    : path_(path), samples_(samples), sink_(std::move(sink)) {
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) throw RecordingError(path + ": cannot be created: " + std::strerror(errno));
  const std::vector<uint8_t> head = encode_header(header);
  if (std::fwrite(head.data(), 1, head.size(), file_) != head.size() || std::fflush(file_) != 0) {
    std::fclose(file_);
    throw RecordingError(path + ": header: cannot be written: " + std::strerror(errno));
  }
  buffer_.reserve(256 * session_record_bytes());
}

SessionRecorder::~SessionRecorder() {
  try {
    stop();
  } catch (...) {
    // Destructors must not throw; error() keeps the cause for whoever asks.
  }
  if (file_ != nullptr) std::fclose(file_);
}

std::size_t SessionRecorder::drain() {
  auto write_buffer = [this] {
    if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
      throw RecordingError(path_ + ": records: cannot be written: " + std::strerror(errno));
    buffer_.clear();
  };
  std::size_t count = 0;
  TickSample sample;
  while (samples_.pop(sample)) {
    encode_record(sample, buffer_);
    ++count;
    if (sink_) sink_(sample);
    if (buffer_.size() + session_record_bytes() > buffer_.capacity()) write_buffer();
  }
  write_buffer();
  if (std::fflush(file_) != 0) throw RecordingError(path_ + ": records: cannot be flushed: " + std::strerror(errno));
  written_.fetch_add(count, std::memory_order_relaxed);
  return count;
}

void SessionRecorder::start() {
  stop_ = false;
  thread_ = std::thread([this] {
    while (!stop_.load()) {
      std::this_thread::sleep_for(kPassInterval);
      try {
        drain();
      } catch (const std::exception& e) {
        error_ = e.what();
        failed_ = true;
        return;
      }
    }
  });
}

void SessionRecorder::stop() {
  if (thread_.joinable()) {
    stop_ = true;
    thread_.join();
  }
  if (!failed_ && file_ != nullptr) drain();
}

std::string SessionRecorder::error() const { return failed_.load() ? error_ : std::string(); }

}  // namespace needle::haptics
