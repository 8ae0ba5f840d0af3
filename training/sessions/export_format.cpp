#include "training/sessions/export_format.hpp"

#include <cmath>
#include <sstream>

namespace needle::training {

nlohmann::json json_number(double x) { return std::isnan(x) ? nlohmann::json(nullptr) : nlohmann::json(x); }

// Quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "";
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

}  // namespace needle::training
