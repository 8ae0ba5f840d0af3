#include "haptics/recording/session_recorder.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace needle::haptics {

SessionRecorder::SessionRecorder(const std::string& path, const SessionHeader& header, SpscRing<TickSample>& samples,
                                 SampleSink sink)
    : path_(path), samples_(samples), sink_(std::move(sink)) {
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) throw RecordingError(path + ": cannot be created: " + std::strerror(errno));
  SessionHeader written = header;
  written.payload_version = kPayloadVersion;  // the records below are this build's, whatever the header came from
  const std::vector<uint8_t> head = encode_header(written);
  if (std::fwrite(head.data(), 1, head.size(), file_) != head.size() || std::fflush(file_) != 0) {
    const int error = errno;
    std::fclose(file_);
    file_ = nullptr;
    throw RecordingError(path + ": header: cannot be written: " + std::strerror(error));
  }
  buffer_.reserve(kBlockHeaderBytes + kBlockRecords * session_record_bytes());
  static_assert(kBlockRecords <= kMaxBlockRecords);
}

SessionRecorder::~SessionRecorder() { stop(); }

void SessionRecorder::write_block() {
  if (block_records_ == 0) return;
  encode_block_header(buffer_.data(), written_.load(std::memory_order_relaxed), block_records_);
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
    throw RecordingError(path_ + ": records: cannot be written: " + std::strerror(errno));
  written_.fetch_add(block_records_, std::memory_order_relaxed);
  buffer_.clear();
  block_records_ = 0;
}

std::size_t SessionRecorder::drain() {
  if (file_ == nullptr) throw RecordingError(path_ + ": records: the recording is closed");
  std::size_t count = 0;
  TickSample sample;
  while (samples_.pop(sample)) {
    if (block_records_ == 0) buffer_.resize(kBlockHeaderBytes);  // within the reserved capacity
    encode_record(sample, buffer_);
    ++block_records_;
    ++count;
    if (sink_) sink_(sample);
    if (block_records_ == kBlockRecords) write_block();
  }
  write_block();
  if (std::fflush(file_) != 0) throw RecordingError(path_ + ": records: cannot be flushed: " + std::strerror(errno));
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

void SessionRecorder::close(bool ran_to_end) {
  const std::vector<uint8_t> end = encode_end(written_.load(), ran_to_end);
  int error = 0;
  if (std::fwrite(end.data(), 1, end.size(), file_) != end.size() || std::fflush(file_) != 0) error = errno;
  if (error == 0 && ::fsync(::fileno(file_)) != 0) error = errno;
  if (std::fclose(file_) != 0 && error == 0) error = errno;
  file_ = nullptr;
  if (error != 0) throw RecordingError(path_ + ": end: cannot be written: " + std::strerror(error));
}

void SessionRecorder::stop(bool ran_to_end) {
  if (thread_.joinable()) {
    stop_ = true;
    thread_.join();
  }
  if (file_ == nullptr) return;
  try {
    if (!failed_) drain();
  } catch (const std::exception& e) {
    error_ = e.what();
    failed_ = true;
  }
  try {
    if (failed_) {
      std::fclose(file_);  // no end mark: the file reads as cut after its last whole block
      file_ = nullptr;
    } else {
      close(ran_to_end);
    }
  } catch (const std::exception& e) {
    error_ = e.what();
    failed_ = true;
  }
}

std::string SessionRecorder::error() const { return failed_.load() ? error_ : std::string(); }

}  // namespace needle::haptics
