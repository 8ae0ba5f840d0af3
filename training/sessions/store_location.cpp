#include "training/sessions/store_location.hpp"

namespace needle::training {

bool is_postgres_uri(const std::string& location) {
  return location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0;
}

std::string shown_location(const std::string& location) {
  if (!is_postgres_uri(location)) return location;
  std::string shown = location;
  // user:password@host: the authority ends at the first '/', '?' or '#' after "://".
  const size_t start = shown.find("://") + 3;
  const size_t end = shown.find_first_of("/?#", start);
  const size_t at = shown.rfind('@', end == std::string::npos ? shown.size() : end);
  if (at != std::string::npos && at >= start) {
    const size_t colon = shown.find(':', start);
    if (colon != std::string::npos && colon < at) shown.replace(colon + 1, at - colon - 1, "***");
  }
  // ?...&password=...&...
  for (size_t p = shown.find("password=", start); p != std::string::npos; p = shown.find("password=", p + 1)) {
    if (p == 0 || (shown[p - 1] != '?' && shown[p - 1] != '&')) continue;
    const size_t value = p + 9;
    const size_t stop = shown.find_first_of("&#", value);
    shown.replace(value, (stop == std::string::npos ? shown.size() : stop) - value, "***");
  }
  return shown;
}

}  // namespace needle::training
