// Where the shipped assets live: $NEEDLE_ASSETS, else the source tree's assets/ folder.
#pragma once

#include <filesystem>

namespace needle::cli {

std::filesystem::path asset_dir();

}  // namespace needle::cli
