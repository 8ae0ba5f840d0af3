#include "engine/gltf/gltf_uri.hpp"

#include <algorithm>

namespace needle::engine {
namespace fs = std::filesystem;

namespace {
int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

std::string decode_uri(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size() && hex_value(uri[i + 1]) >= 0 && hex_value(uri[i + 2]) >= 0) {
      out += static_cast<char>(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

fs::path resolve_inside(const fs::path& folder, const std::string& relative, std::string& why) {
  if (relative.empty()) return why = "empty path", fs::path();
  if (relative.find('\0') != std::string::npos) return why = "contains a NUL byte", fs::path();
  const fs::path rel(relative);
  if (rel.is_absolute() || rel.has_root_name() || relative.front() == '/' || relative.front() == '\\')
    return why = "is an absolute path; only paths inside the asset's folder are allowed", fs::path();
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(folder / rel, ec);
  if (ec) return why = "cannot be resolved: " + ec.message(), fs::path();
  // Inside means: the folder's components are a prefix of the resolved path's.
  const auto [f, r] = std::mismatch(folder.begin(), folder.end(), resolved.begin(), resolved.end());
  if (f != folder.end() || r == resolved.end())
    return why = "escapes the asset's folder " + folder.string() + " (resolves to " + resolved.string() + ")",
           fs::path();
  if (!fs::is_regular_file(resolved, ec)) return why = "file not found: " + resolved.string(), fs::path();
  return resolved;
}

}  // namespace needle::engine
