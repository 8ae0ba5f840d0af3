#include "app/default_db.hpp"

#include <cstdlib>
#include <stdexcept>

namespace needle::app {

std::filesystem::path default_db() {
  namespace fs = std::filesystem;
  const char* data = std::getenv("XDG_DATA_HOME");
  const char* home = std::getenv("HOME");
  fs::path base = data && *data ? fs::path(data) : home && *home ? fs::path(home) / ".local/share" : fs::path(".");
  return base / "needle-sim" / "sessions.db";
}

std::unique_ptr<training::SessionStore> open_existing_db(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file))
    throw std::runtime_error(file.string() + ": no session database (needle-sim run makes one; --db names another)");
  return std::make_unique<training::SessionStore>(file, training::kReadOnly);
}

}  // namespace needle::app
