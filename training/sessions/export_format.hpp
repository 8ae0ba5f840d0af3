// The exports' shared spelling of values: a metric that does not apply (NaN) is JSON null and an
// empty CSV field; CSV fields are quoted as RFC 4180 says; numbers keep all 17 digits.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace needle::training {

nlohmann::json json_number(double x);
std::string csv_field(const std::string& text);
std::string csv_number(double x);

}  // namespace needle::training
