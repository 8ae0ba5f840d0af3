// Every file the product writes whole (settings, score.json, scenarios, exports, benchmark JSON)
// goes through write_file: a temporary file in the same folder, written, flushed to the disk
// (fsync) and renamed over the old one, so a crash or a full disk leaves the old file or the new
// one, never half of either; any failure throws naming the file and the reason.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace needle::io {

// Throws std::runtime_error "FILE: cannot write: WHAT: reason".
inline void write_file(const std::filesystem::path& file, const std::string& bytes) {
  auto failed = [&file](const std::string& what, int error) {
    std::string message = file.string() + ": cannot write";
    if (!what.empty()) message += ": " + what;
    if (error) message += std::string(": ") + std::strerror(error);
    return std::runtime_error(message);
  };
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  const std::filesystem::path temporary = folder / ("." + file.filename().string() + ".tmp-" + std::to_string(::getpid()));
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw failed("creating " + temporary.string(), errno);
  int error = 0;
  for (size_t done = 0; done < bytes.size() && error == 0;) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno != EINTR) error = errno;
    if (n > 0) done += size_t(n);
  }
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(temporary.c_str(), file.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    throw failed("", error);
  }
}

}  // namespace needle::io
