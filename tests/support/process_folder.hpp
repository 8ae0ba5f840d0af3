// A fresh folder under `parent` for one test process: ctest runs each test of a suite as a
// process of its own, in parallel, so the files a suite fixture makes must not be shared.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace needle::test {

inline std::filesystem::path process_folder(const std::filesystem::path& parent) {
  const std::filesystem::path dir = parent / std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace needle::test
