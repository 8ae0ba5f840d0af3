// needle-asset-gen [--out DIR]: writes every committed asset (assets.hpp) into DIR,
// by default the repository's assets/ folder.
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>

#include "asset-gen/assets.hpp"

int main(int argc, char** argv) {
  std::filesystem::path out = NEEDLE_ASSETS_DIR;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out = argv[++i];
    } else {
      std::cerr << "usage: needle-asset-gen [--out DIR]   (default " << NEEDLE_ASSETS_DIR << ")\n";
      return std::strcmp(argv[i], "--help") == 0 ? 0 : 2;
    }
  }
  try {
    std::filesystem::create_directories(out);
    for (const auto& asset : needle::asset_gen::committed_assets()) {
      needle::asset_gen::write_asset(asset, out);
      std::cout << (out / asset.file).string() << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "needle-asset-gen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
