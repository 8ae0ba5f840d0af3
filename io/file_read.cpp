#include "io/file_read.hpp"

#include <algorithm>
#include <fstream>

#include "io/input_limits.hpp"

namespace needle::io {

std::string read_text(const std::filesystem::path& file, std::string& problem) {
  return read_bytes(file, kMaxTextFileBytes, problem);
}

std::string read_bytes(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string& problem) {
  const std::string too_large = "larger than " + std::to_string(max_bytes >> 20) + " MiB";
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  problem.clear();
  if (!std::filesystem::exists(status))
    problem = "file not found";
  else if (std::filesystem::is_directory(status))
    problem = "is a folder, not a file";
  else if (!std::filesystem::is_regular_file(status))
    problem = "not a regular file (a device or a pipe)";
  else if (const auto size = std::filesystem::file_size(file, ec); !ec && size > max_bytes)
    problem = too_large + " (" + std::to_string(size) + " bytes)";
  if (!problem.empty()) return {};
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    problem = "cannot open the file for reading";
    return {};
  }
  // Up to one byte more than the limit: a file that grew since its size was read is refused, not cut.
  std::string text;
  text.reserve(size_t(std::min<std::uintmax_t>(max_bytes, std::filesystem::file_size(file, ec))) + 1);
  char chunk[1 << 16];
  while (in && text.size() <= max_bytes) {
    in.read(chunk, std::streamsize(std::min<std::uintmax_t>(sizeof chunk, max_bytes + 1 - text.size())));
    text.append(chunk, size_t(in.gcount()));
  }
  if (in.bad())
    problem = "cannot be read";
  else if (text.size() > max_bytes)
    problem = too_large;
  return problem.empty() ? text : std::string();
}

}  // namespace needle::io
