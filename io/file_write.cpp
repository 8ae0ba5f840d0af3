#include "io/file_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

namespace needle::io {
namespace fs = std::filesystem;

namespace {

// "FILE: cannot write: [what: ]the system's reason".
[[noreturn]] void fail(const fs::path& file, const std::string& what, int error) {
  std::string reason = what;
  if (error != 0) reason += (reason.empty() ? "" : ": ") + std::string(std::strerror(error));
  throw WriteError(file.string() + ": cannot write: " + reason);
}

// Writes all of `bytes` to `fd`; the errno of the failure, 0 when all went.
int write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    bytes.remove_prefix(static_cast<size_t>(n));
  }
  return 0;
}

// A device, a FIFO or a socket: written where it is, with the same checks.
void write_in_place(const fs::path& file, std::string_view bytes) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(file, "opening it", errno);
  int error = write_all(fd, bytes);
  // fsync of a character device or a pipe says EINVAL: there is nothing to sync.
  if (error == 0 && ::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) fail(file, "", error);
}

}  // namespace

void write_file(const fs::path& given, std::string_view bytes) {
  std::error_code ec;
  fs::path file = given;
  if (fs::is_symlink(fs::symlink_status(given, ec))) {
    file = fs::canonical(given, ec);
    if (ec) fail(given, "resolving the link", ec.value());
  }
  const fs::file_status status = fs::status(file, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    if (fs::is_directory(status)) fail(given, "it is a folder", 0);
    write_in_place(file, bytes);
    return;
  }
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  if (!fs::is_directory(folder, ec)) fail(given, "folder " + folder.string() + " does not exist", 0);

  static std::atomic<unsigned> serial{0};
  const fs::path temporary =
      folder / ("." + file.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(serial++));
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(given, "creating a temporary file in " + folder.string(), errno);
  int error = write_all(fd, bytes);
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(temporary.c_str(), file.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    fail(given, "", error);
  }
  // The rename is durable once the folder's entry is on the disk too.
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    const int synced = ::fsync(dir);
    const int sync_error = errno;
    ::close(dir);
    if (synced != 0 && sync_error != EINVAL) fail(given, "syncing folder " + folder.string(), sync_error);
  }
}

void make_folder(const fs::path& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw WriteError(folder.string() + ": cannot create the folder: " + ec.message());
}

}  // namespace needle::io
