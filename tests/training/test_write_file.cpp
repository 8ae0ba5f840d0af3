// io::write_file, through which every whole file is written: the bytes land, an old file is
// replaced whole, and a write that cannot happen throws naming the file and leaves neither a
// temporary file nor a changed old one.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/write_file.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ostringstream s;
  s << std::ifstream(file, std::ios::binary).rdbuf();
  return s.str();
}

size_t entries(const fs::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(WriteFile, WritesAndReplacesWhole) {
  const fs::path dir = process_folder(output_dir() / "write_file");
  const fs::path file = dir / "a.json";
  io::write_file(file, "{\"a\": 1}\n");
  EXPECT_EQ(read(file), "{\"a\": 1}\n");
  const std::string big(1 << 20, 'x');
  io::write_file(file, big);
  EXPECT_EQ(read(file), big);
  io::write_file(file, "");
  EXPECT_EQ(read(file), "");
  EXPECT_EQ(entries(dir), 1u) << "no temporary file left beside it";
}

TEST(WriteFile, AWriteThatCannotHappenThrowsNamingTheFileAndLeavesNothing) {
  const fs::path dir = process_folder(output_dir() / "write_file_fails");
  const fs::path missing = dir / "no_such_folder" / "a.json";
  try {
    io::write_file(missing, "x");
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string() + ": cannot write"), std::string::npos) << e.what();
  }
  // The name is taken by a folder: the rename fails, the temporary file goes, the folder stays.
  const fs::path taken = dir / "taken";
  fs::create_directories(taken / "inside");
  try {
    io::write_file(taken, "x");
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(taken.string() + ": cannot write: "), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(taken / "inside"));
  EXPECT_EQ(entries(dir), 1u) << "no temporary file left";
}

}  // namespace
}  // namespace needle::test
