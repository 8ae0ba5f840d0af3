#include "app/recording_upload.hpp"

#include <fstream>

namespace needle::app {

RecordingUpload::RecordingUpload(const std::string& location, int64_t session, std::filesystem::path file)
    : store_(std::make_unique<training::SessionStore>(location)), session_(session), file_(std::move(file)) {
  offset_ = store_->recording_bytes(session_);
}

RecordingUpload::~RecordingUpload() { stop(); }

bool RecordingUpload::send_new() {
  const std::lock_guard lock(mutex_);
  if (!error_.empty()) return false;
  try {
    std::ifstream in(file_, std::ios::binary);
    in.seekg(offset_.load());
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) return true;
    store_->append_recording(session_, offset_.load(), bytes);
    offset_ += int64_t(bytes.size());
    return true;
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
}

void RecordingUpload::start() {
  stop_ = false;
  thread_ = std::thread([this] {
    while (!stop_.load()) {
      if (!send_new()) return;
      std::this_thread::sleep_for(kPeriod);
    }
  });
}

void RecordingUpload::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::string RecordingUpload::error() const {
  const std::lock_guard lock(mutex_);
  return error_;
}

}  // namespace needle::app
