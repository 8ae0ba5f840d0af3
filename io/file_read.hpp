// The one way the program reads a whole text input (task, scene, scenario, parameter set,
// operator script, URDF, settings): checked before it is opened, so that a FIFO cannot block the
// run and /dev/zero cannot fill the memory, and bounded in size while it is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace needle::io {

// The text of `file`, or "" with `problem` saying why it cannot be one: "file not found", "is a
// folder, not a file", "not a regular file (a device or a pipe)" (refused before it is opened:
// a FIFO would block the reader, a device never end), "larger than 16 MiB (N bytes)"
// (kMaxTextFileBytes, io/input_limits.hpp), "cannot open the file for reading", "cannot be read".
std::string read_text(const std::filesystem::path& file, std::string& problem);
// The same checks for a binary file of at most `max_bytes` ("larger than N MiB").
std::string read_bytes(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string& problem);

}  // namespace needle::io
