// io::write_file: the whole file or an error naming it, never a part, never a silent loss.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <sstream>

#include "io/file_write.hpp"
#include "tests/support/full_disk.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::io {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Only `names` are in `dir`: no temporary file was left behind.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string error_of(const fs::path& file, std::string_view bytes) {
  try {
    write_file(file, bytes);
  } catch (const WriteError& e) {
    return e.what();
  }
  return "";
}

TEST(FileWrite, WritesTheBytesAndReplacesAnOldFileWhole) {
  const fs::path dir = test::process_folder(test::output_dir() / "write");
  const fs::path file = dir / "score.json";
  write_file(file, "first version, longer than the second\n");
  write_file(file, std::string("second\0with a NUL", 17));
  EXPECT_EQ(read_all(file), std::string("second\0with a NUL", 17));
  EXPECT_EQ(entries(dir), std::vector<std::string>{"score.json"});
}

TEST(FileWrite, AFullDeviceIsAnErrorNamingTheFileAndTheReason) {
  EXPECT_EQ(error_of("/dev/full", "bytes"), "/dev/full: cannot write: No space left on device");
  EXPECT_EQ(error_of("/dev/null", "bytes"), "");  // a device that takes anything is written in place
}

TEST(FileWrite, AFullFileSystemKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path dir = test::process_folder(test::output_dir() / "full_tmpfs");
  const fs::path file = dir / "disk" / "picture.png";
  std::string old_content;
  {
    test::FullTmpfs disk(dir / "disk", 64 * 1024);
    if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
    // Room for a small file, made before the disk filled up: free it, write it, fill again.
    fs::remove(disk.dir() / "filler");
    write_file(file, "the old picture");
    std::ofstream(disk.dir() / "filler", std::ios::binary) << std::string(60 * 1024, 'x');
    const std::string error = error_of(file, std::string(256 * 1024, 'p'));
    EXPECT_EQ(error, file.string() + ": cannot write: No space left on device");
    old_content = read_all(file);
    EXPECT_EQ(entries(disk.dir()), (std::vector<std::string>{"filler", "picture.png"}));
  }
  EXPECT_EQ(old_content, "the old picture");
}

TEST(FileWrite, AFileSizeLimitIsAnError) {
  const fs::path dir = test::process_folder(test::output_dir() / "size_limit");
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // else the write past the limit kills
  rlimit limited = saved;
  limited.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  const std::string error = error_of(dir / "big.json", std::string(10000, 'x'));
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(error, (dir / "big.json").string() + ": cannot write: File too large");
  EXPECT_TRUE(entries(dir).empty());
}

TEST(FileWrite, AMissingFolderOrAFolderInPlaceOfTheFileIsAnError) {
  const fs::path dir = test::process_folder(test::output_dir() / "missing");
  EXPECT_EQ(error_of(dir / "nowhere" / "x.json", "{}"), (dir / "nowhere" / "x.json").string() +
                                                            ": cannot write: folder " + (dir / "nowhere").string() +
                                                            " does not exist");
  EXPECT_FALSE(fs::exists(dir / "nowhere"));
  EXPECT_EQ(error_of(dir, "{}"), dir.string() + ": cannot write: it is a folder");
}

TEST(FileWrite, ALinkIsWrittenThroughToItsTarget) {
  const fs::path dir = test::process_folder(test::output_dir() / "link");
  write_file(dir / "target.csv", "old");
  fs::create_symlink("target.csv", dir / "link.csv");
  write_file(dir / "link.csv", "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_EQ(read_all(dir / "target.csv"), "new");
}

TEST(FileWrite, MakeFolderMakesTheMissingFoldersAndNamesTheOneItCannotMake) {
  const fs::path dir = test::process_folder(test::output_dir() / "make_folder");
  make_folder(dir / "a" / "b");
  EXPECT_TRUE(fs::is_directory(dir / "a" / "b"));
  make_folder(dir / "a" / "b");  // one that exists is left as it is
  write_file(dir / "a" / "plain", "x");
  const fs::path under_a_file = dir / "a" / "plain" / "sub";
  try {
    make_folder(under_a_file);
    ADD_FAILURE() << "a folder under a plain file was made";
  } catch (const WriteError& e) {
    EXPECT_EQ(std::string(e.what()), under_a_file.string() + ": cannot create the folder: Not a directory");
  }
}

}  // namespace
}  // namespace needle::io
