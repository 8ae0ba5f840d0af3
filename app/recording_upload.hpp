// A session's recording sent to the server as it is written (PostgreSQL): the bytes the recording
// file has gained since the last send, as one chunk with its CRC (training::SessionStore::
// append_recording). In a window a thread of its own sends every kPeriod; headless the run sends
// every kPeriod of session time. A station that dies loses at most the period and the recorder's
// pass, under 100 ms; the stored stream is always a prefix of the file, read back like a file cut
// there. On its own connection, so the haptic loop, the recorder and the UI never wait on it.
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "training/sessions/session_store.hpp"

namespace needle::app {

class RecordingUpload {
 public:
  static constexpr std::chrono::milliseconds kPeriod{50};

  // Opens its connection to `location`; throws SessionStoreError when it cannot.
  RecordingUpload(const std::string& location, int64_t session, std::filesystem::path file);
  ~RecordingUpload();
  RecordingUpload(const RecordingUpload&) = delete;
  RecordingUpload& operator=(const RecordingUpload&) = delete;

  // Sends what the file gained since the last send. False once the server was lost: then it
  // sends nothing more and error() says why.
  bool send_new();
  void start();  // sends every kPeriod on its own thread until stop()
  void stop();
  std::string error() const;
  int64_t sent_bytes() const { return offset_.load(); }

 private:
  std::unique_ptr<training::SessionStore> store_;
  int64_t session_;
  std::filesystem::path file_;
  std::atomic<int64_t> offset_{0};
  mutable std::mutex mutex_;  // error_, and one send at a time
  std::string error_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace needle::app
