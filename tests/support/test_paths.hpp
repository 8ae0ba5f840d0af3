// Where a test finds the checkout and writes its output. The paths are compiled into one small
// generated file per test program (tests/CMakeLists.txt, needle_test_paths), not into every test:
// a fresh clone in another folder then recompiles that file alone and ccache serves the rest.
#pragma once

#include <filesystem>

namespace needle::test {

std::filesystem::path source_dir();      // the checkout (assets/, tests/golden/)
std::filesystem::path output_dir();      // this test program's output folder in the build
std::filesystem::path needle_sim_exe();  // the built needle-sim (command-line tests only)

}  // namespace needle::test
