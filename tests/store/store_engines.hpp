// The fixture of the session store's tests on both engines (test_store_engines.cpp instantiates it
// for every file of this folder): a fresh database per test, on an SQLite file or on the throwaway
// PostgreSQL cluster (with-postgres.sh), and a connection of its own for what another program writes.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"
#include "training/sessions/postgres_connection.hpp"
#include "training/sessions/sqlite_connection.hpp"

namespace needle::training {

inline std::string test_name() {
  std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '_';
  return name;
}

inline std::filesystem::path test_folder() {
  const std::filesystem::path dir = test::output_dir() / "store" / test_name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

class StoreEngines : public testing::TestWithParam<SqlEngine> {
 protected:
  // An empty database for this test: a new file, or a new database on the cluster.
  std::string fresh() {
    if (GetParam() == SqlEngine::kSqlite) return (test_folder() / "sessions.db").string();
    if (test::postgres_dir().empty())
      throw std::runtime_error("run through tests/support/with-postgres.sh (ctest does)");
    return test::fresh_postgres_database("t_" + test_name().substr(0, 50));
  }
  // A connection of its own, for what an older program or another process writes.
  static std::unique_ptr<SqlConnection> raw(const std::string& location) {
    if (location.rfind("postgresql://", 0) == 0) return std::make_unique<PostgresConnection>(location, false);
    return std::make_unique<SqliteConnection>(location, false);
  }
};

}  // namespace needle::training
