#include "app/default_db.hpp"

#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <stdexcept>

#include "training/sessions/store_location.hpp"

namespace needle::app {

std::filesystem::path default_db() {
  namespace fs = std::filesystem;
  const char* data = std::getenv("XDG_DATA_HOME");
  const char* home = std::getenv("HOME");
  fs::path base = data && *data ? fs::path(data) : home && *home ? fs::path(home) / ".local/share" : fs::path(".");
  return base / "needle-sim" / "sessions.db";
}

std::string db_location(const std::optional<std::string>& flag) {
  if (flag) return *flag;
  const char* env = std::getenv("NEEDLE_DB");
  return env && *env ? std::string(env) : default_db().string();
}

std::string station_name(const std::optional<std::string>& flag) {
  if (flag) return *flag;
  char host[HOST_NAME_MAX + 1] = {};
  if (gethostname(host, sizeof host - 1) != 0 || !*host) return "station";
  return host;
}

void require_existing_db(const std::string& location) {
  if (!training::is_postgres_uri(location) && !std::filesystem::is_regular_file(location))
    throw std::runtime_error(location + ": no session database (needle-sim run makes one; --db names another)");
}

std::unique_ptr<training::SessionStore> open_existing_db(const std::string& location) {
  require_existing_db(location);
  return std::make_unique<training::SessionStore>(location, training::kReadOnly);
}

std::filesystem::path local_folder(const std::string& location) {
  const std::filesystem::path file =
      training::is_postgres_uri(location) ? default_db() : std::filesystem::path(location);
  return std::filesystem::absolute(file).parent_path();
}

}  // namespace needle::app
