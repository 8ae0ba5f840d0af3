// Scenario and parameter set files a test writes: a shipped file read as JSON, and a file name
// of the running test's own (CTest runs the tests of one file in parallel processes).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace needle::haptics::test {

inline nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

inline std::string own_file(const std::string& what) {
  return (std::filesystem::weakly_canonical(::testing::TempDir()) /
          (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" + what))
      .string();
}

}  // namespace needle::haptics::test
