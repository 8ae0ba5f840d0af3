#include "bench_table.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "io/file_write.hpp"

namespace needle::cli {
namespace {

std::string cell_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char buf[32];
    double d = v.get<double>();
    // Significant digits, not fixed decimals: errors span 1e-12 .. 1e3.
    std::snprintf(buf, sizeof buf, "%.4g", d);
    return buf;
  }
  return v.dump();
}

}  // namespace

BenchTable::BenchTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void BenchTable::add_row(std::vector<nlohmann::json> values) {
  if (values.size() != columns_.size()) throw std::logic_error("BenchTable row has the wrong number of values");
  nlohmann::json row = nlohmann::json::object();
  for (size_t i = 0; i < columns_.size(); ++i) row[columns_[i]] = std::move(values[i]);
  rows_.push_back(std::move(row));
}

void BenchTable::print(const std::string& title) const {
  std::vector<size_t> width(columns_.size());
  for (size_t c = 0; c < columns_.size(); ++c) {
    width[c] = columns_[c].size();
    for (const auto& row : rows_) width[c] = std::max(width[c], cell_text(row[columns_[c]]).size());
  }
  std::printf("%s\n", title.c_str());
  auto print_line = [&](auto cell) {
    for (size_t c = 0; c < columns_.size(); ++c) std::printf("%s%*s", c ? "  " : "", int(width[c]), cell(c).c_str());
    std::printf("\n");
  };
  print_line([&](size_t c) { return columns_[c]; });
  print_line([&](size_t c) { return std::string(width[c], '-'); });
  for (const auto& row : rows_) print_line([&](size_t c) { return cell_text(row[columns_[c]]); });
  std::fflush(stdout);
}

void BenchTable::write_json(const std::string& path) const { io::write_file(path, rows_.dump(2) + "\n"); }

void BenchTable::emit(const std::string& title, const std::optional<std::string>& json_path) const {
  print(title);
  if (json_path) write_json(*json_path);
}

}  // namespace needle::cli
