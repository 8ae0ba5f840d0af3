// Full disks for tests of the writes: a small tmpfs filled to the last byte (needs the right to
// mount, i.e. root as in CI; a test without it is skipped and says why), and a child process
// whose files may not grow past a limit (RLIMIT_FSIZE with SIGXFSZ ignored: a write past it fails
// with EFBIG, "File too large"), which needs no privilege. And a folder this process cannot
// write, for the readers that must need no write access.
#pragma once

#include <sys/mount.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace needle::test {

class FullTmpfs {
 public:
  // Mounts a tmpfs of `bytes` on `dir` (created) and fills it; check mounted() first.
  FullTmpfs(std::filesystem::path dir, size_t bytes) : dir_(std::move(dir)) {
    std::filesystem::create_directories(dir_);
    const std::string options = "size=" + std::to_string(bytes);
    if (::mount("tmpfs", dir_.c_str(), "tmpfs", 0, options.c_str()) != 0) {
      why_ = std::string("cannot mount a tmpfs on ") + dir_.string() + ": " + std::strerror(errno);
      return;
    }
    mounted_ = true;
    std::ofstream filler(dir_ / "filler", std::ios::binary);
    const std::string block(4096, 'x');
    while (filler.write(block.data(), std::streamsize(block.size())) && filler.flush()) {
    }
  }
  ~FullTmpfs() {
    if (mounted_) ::umount2(dir_.c_str(), MNT_DETACH);
  }
  FullTmpfs(const FullTmpfs&) = delete;
  FullTmpfs& operator=(const FullTmpfs&) = delete;

  // Frees about `bytes` (whole 4 KiB pages) for the next writes, the rest still full.
  void leave_free(size_t bytes) {
    std::filesystem::resize_file(dir_ / "filler",
                                 std::filesystem::file_size(dir_ / "filler") - (bytes + 4095) / 4096 * 4096);
  }

  bool mounted() const { return mounted_; }
  const std::string& why_not() const { return why_; }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  bool mounted_ = false;
  std::string why_;
};

// A folder this process cannot write: a tmpfs mounted on `dir` (made empty first) and remounted
// read-only when the process may mount (root, as in CI), else the folder's permissions (which root
// would ignore). Put its files in, then make_read_only(); undone however the test ends.
class ReadOnlyFolder {
 public:
  explicit ReadOnlyFolder(std::filesystem::path dir) : dir_(std::move(dir)) {
    ::umount2(dir_.c_str(), MNT_DETACH);  // left by a run that was killed
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    mounted_ = ::mount("tmpfs", dir_.c_str(), "tmpfs", 0, "size=8m") == 0;
  }
  ~ReadOnlyFolder() {
    if (mounted_) ::umount2(dir_.c_str(), MNT_DETACH);
    std::error_code ignored;
    std::filesystem::permissions(dir_, std::filesystem::perms::owner_all, ignored);
  }
  ReadOnlyFolder(const ReadOnlyFolder&) = delete;
  ReadOnlyFolder& operator=(const ReadOnlyFolder&) = delete;

  // Returns an error, or "" when the folder is now read-only.
  std::string make_read_only() const {
    if (!mounted_) {
      std::filesystem::permissions(dir_, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
      return "";
    }
    if (::mount(nullptr, dir_.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr) == 0) return "";
    return "remounting " + dir_.string() + " read-only: " + std::strerror(errno);
  }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  bool mounted_ = false;
};

// A shell prefix that runs a command with its files limited to `bytes`.
inline std::string with_file_size_limit(size_t bytes) {
  // ulimit -f counts 1024-byte blocks; trap '' XFSZ makes a write past it fail instead of killing.
  return "trap '' XFSZ; ulimit -f " + std::to_string((bytes + 1023) / 1024) + "; ";
}

}  // namespace needle::test
