#include "asset_path.hpp"

#include <cstdlib>

namespace needle::cli {

std::filesystem::path asset_dir() {
  const char* env = std::getenv("NEEDLE_ASSETS");
  return env && *env ? std::filesystem::path(env) : std::filesystem::path(NEEDLE_ASSET_DIR);
}

}  // namespace needle::cli
