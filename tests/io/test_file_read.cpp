// The bounded text reader and the JSON parse every format goes through (io/file_read.hpp,
// io/strict_json.hpp): what is not a regular file is refused before it is opened (a FIFO would
// block, /dev/zero never end), a file past 16 MiB before it is read, a document nested past 64
// levels before it is built; a number past its range names the range and the value.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/file_read.hpp"
#include "io/strict_json.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::io {
namespace {
namespace fs = std::filesystem;

struct TestError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

fs::path own_folder() {
  const fs::path dir =
      test::output_dir() / "file_read" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string problem_of(const fs::path& file) {
  std::string problem;
  const std::string text = read_text(file, problem);
  EXPECT_TRUE(problem.empty() || text.empty());
  return problem;
}

TEST(FileRead, WhatIsNotARegularFileIsRefusedBeforeItIsOpened) {
  const fs::path dir = own_folder();
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(problem_of(fifo), "not a regular file (a device or a pipe)");  // returns: nothing writes to it
  EXPECT_EQ(problem_of("/dev/zero"), "not a regular file (a device or a pipe)");
  EXPECT_EQ(problem_of(dir), "is a folder, not a file");
  EXPECT_EQ(problem_of(dir / "absent.json"), "file not found");
  EXPECT_THROW(read_json_file<TestError>(fifo), TestError);
}

TEST(FileRead, AFileLargerThanSixteenMebibytesIsRefusedBeforeItIsRead) {
  const fs::path file = own_folder() / "large.json";
  std::ofstream(file) << "{}";
  fs::resize_file(file, (16u << 20) + 1);  // sparse: nothing is written
  EXPECT_EQ(problem_of(file), "larger than 16 MiB (16777217 bytes)");
  fs::resize_file(file, 16u << 20);
  EXPECT_EQ(problem_of(file), "");
}

// `depth` arrays nested around a number.
std::string nested(size_t depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

TEST(FileRead, JsonNestedPastSixtyFourLevelsIsRefusedBeforeItIsBuilt) {
  EXPECT_NO_THROW(parse_json_text(nested(64)));
  try {
    parse_json_text(nested(65));
    ADD_FAILURE() << "65 levels parsed";
  } catch (const JsonTextError& e) {
    EXPECT_STREQ(e.what(), "nested deeper than 64 levels");
  }
  EXPECT_THROW(parse_json_text(nested(1000000)), JsonTextError);  // would overflow a recursive copy
  try {
    parse_json<TestError>("{\"a\": NaN}", "f.json");
    ADD_FAILURE() << "NaN parsed";
  } catch (const TestError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("f.json: /: not valid JSON: ", 0), 0u) << e.what();
  }
}

// nlohmann's parser keeps the last of two equal keys; a reader refuses the document and names the
// second, by its JSON pointer (RFC 6901: "~" and "/" in a key escaped as "~0" and "~1").
TEST(FileRead, AKeyGivenTwiceInAnObjectIsRefusedByItsPointer) {
  const auto error_of = [](const std::string& text) {
    try {
      parse_json<TestError>(text, "f.json");
    } catch (const TestError& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_EQ(error_of(R"({"seed": 1, "height_m": 1.7, "seed": 2})"),
            "f.json: /seed: the key is given twice in its object");
  EXPECT_EQ(error_of(R"({"a": {"b": 1}, "c": [0, {"d": 1, "d": 1}]})"),
            "f.json: /c/1/d: the key is given twice in its object");
  EXPECT_EQ(error_of(R"([[], [{"x": [1, 2]}, {"a/b~": 0, "a/b~": 0}]])"),
            "f.json: /1/1/a~1b~0: the key is given twice in its object");
  EXPECT_EQ(error_of(R"({"": 1, "": 2})"), "f.json: /: the key is given twice in its object");
  // The same key in different objects, or as a value, is no repetition.
  EXPECT_EQ(error_of(R"({"a": {"k": 1}, "b": {"k": 1}, "k": "k", "l": [{"k": 1}, {"k": 2}]})"), "read");
  EXPECT_EQ(error_of(R"({"a": 1, "A": 2, "a ": 3})"), "read");
}

// A long array of objects is read in one linear pass: a check of the depth that looked through
// an array's members at the end of each of them would take hours over these 3 MB (ctest's timeout
// would fail this test), and the glTF node chain of 100,000 seconds.
TEST(FileRead, AMillionObjectsInOneArrayAreReadWhole) {
  std::string text = "[";
  for (int i = 0; i < 1000000; ++i) text += i ? ",{}" : "{}";
  text += "]";
  EXPECT_EQ(parse_json_text(text).size(), 1000000u);
  EXPECT_THROW(parse_json_text("[" + text + ","), JsonTextError);  // unfinished: the parse says where
}

TEST(FileRead, ANumberPastItsRangeNamesThePointerTheRangeAndTheValue) {
  const StrictJsonReader<TestError> reader("f.json");
  const Range period{1e-4, 4e-3, false, "s"};
  EXPECT_EQ(reader.in_range(nlohmann::json(0.002), "/period_s", period), 0.002);
  try {
    reader.in_range(nlohmann::json(1e300), "/period_s", period);
    ADD_FAILURE();
  } catch (const TestError& e) {
    EXPECT_STREQ(e.what(), "f.json: /period_s: must be in [0.0001, 0.004] s, got 1e+300");
  }
  const Range open{0.0, 1.0, true, "m"};
  EXPECT_FALSE(open.contains(0.0));
  EXPECT_TRUE(open.contains(1.0));
  EXPECT_EQ(open.text(), "(0, 1] m");
  try {
    reader.position(nlohmann::json::parse("[0, -1e300, 0]"), "/p");
    ADD_FAILURE();
  } catch (const TestError& e) {
    EXPECT_STREQ(e.what(), "f.json: /p/1: must be in [-10, 10] m, got -1e+300");
  }
  try {
    reader.direction(nlohmann::json::parse("[0, 0, 1e-12]"), "/d");
    ADD_FAILURE();
  } catch (const TestError& e) {
    EXPECT_STREQ(e.what(), "f.json: /d: must not be the zero vector");
  }
}

}  // namespace
}  // namespace needle::io
