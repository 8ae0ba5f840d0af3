// What the store's tests read of a refusal: the message a call threw ("" when it did not), whether
// it is a permission error (PostgreSQL's "permission denied", a row-level security violation, or
// the schema's triggers' "permission denied: ..."), and the roles script as the docs tell a centre
// to run it.
#pragma once

#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "tests/support/test_paths.hpp"

namespace needle::training {

inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

inline bool permission_error(const std::string& m) {
  return m.find("permission denied") != std::string::npos || m.find("row-level security") != std::string::npos;
}

inline std::string roles_sql() {
  std::ifstream in(test::source_dir() / "tools" / "postgres-roles.sql");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace needle::training
