// The one output format of every `needle-sim bench ...`: a table printed to stdout and, with
// --json FILE, the same rows written as a JSON array of objects (column name -> value).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace needle::cli {

class BenchTable {
 public:
  // Column names are the JSON keys; the printed header uses them too.
  explicit BenchTable(std::vector<std::string> columns);

  // Values in column order: numbers, strings or booleans.
  void add_row(std::vector<nlohmann::json> values);

  void print(const std::string& title) const;
  // Writes the file whole (io::write_file); io::WriteError naming the file when it cannot.
  void write_json(const std::string& path) const;
  // print, then write_json when a path is given.
  void emit(const std::string& title, const std::optional<std::string>& json_path) const;

  const nlohmann::json& rows() const { return rows_; }

 private:
  std::vector<std::string> columns_;
  nlohmann::json rows_ = nlohmann::json::array();
};

}  // namespace needle::cli
