#include "io/file_read.hpp"

#include <fstream>

#include "io/input_limits.hpp"

namespace needle::io {

std::string read_text(const std::filesystem::path& file, std::string& problem) {
  const std::string too_large = "larger than " + std::to_string(kMaxTextFileBytes >> 20) + " MiB";
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  problem.clear();
  if (!std::filesystem::exists(status)) problem = "file not found";
  else if (std::filesystem::is_directory(status)) problem = "is a folder, not a file";
  else if (!std::filesystem::is_regular_file(status)) problem = "not a regular file (a device or a pipe)";
  else if (const auto size = std::filesystem::file_size(file, ec); !ec && size > kMaxTextFileBytes)
    problem = too_large + " (" + std::to_string(size) + " bytes)";
  if (!problem.empty()) return {};
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    problem = "cannot open the file for reading";
    return {};
  }
  // One byte more than the limit: a file that grew since its size was read is refused, not cut.
  std::string text(size_t(kMaxTextFileBytes) + 1, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(size_t(in.gcount()));
  if (in.bad()) problem = "cannot be read";
  else if (text.size() > kMaxTextFileBytes) problem = too_large;
  return problem.empty() ? text : std::string();
}

}  // namespace needle::io
