// Golden images, rendered on lavapipe, of every committed asset (framed automatically, as
// `render --gltf` does) and every committed scene. The lists come from the assets/ folder, so a
// new asset or scene without a golden fails until one is made (tests/README.md).
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/gltf_loader.hpp"
#include "engine/offscreen.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;
constexpr engine::Extent kGoldenSize{320, 240};
const fs::path kAssets = test::source_dir() / "assets";

std::vector<fs::path> files_in(const fs::path& dir, std::initializer_list<const char*> extensions) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    for (const char* ext : extensions) {
      if (entry.is_regular_file() && entry.path().extension() == ext) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string test_name(const ::testing::TestParamInfo<fs::path>& info) {
  std::string s = info.param.stem().string();
  std::replace_if(
      s.begin(), s.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return s;
}

class AssetGolden : public VulkanTest, public ::testing::WithParamInterface<fs::path> {};
class SceneGolden : public VulkanTest, public ::testing::WithParamInterface<fs::path> {};

TEST_P(AssetGolden, MatchesGolden) {
  engine::Model model = engine::load_gltf(GetParam());
  engine::RgbaImage image =
      engine::render_model_offscreen(device(), model, kGoldenSize, engine::framing_view(model, kGoldenSize));
  EXPECT_TRUE(matches_golden(image, "asset_" + GetParam().stem().string()));
}

TEST_P(SceneGolden, MatchesGolden) {
  engine::RgbaImage image = engine::render_scene_offscreen(device(), engine::load_scene(GetParam()), kGoldenSize);
  EXPECT_TRUE(matches_golden(image, "scene_" + GetParam().stem().string()));
}

INSTANTIATE_TEST_SUITE_P(Committed, AssetGolden, ::testing::ValuesIn(files_in(kAssets, {".gltf", ".glb"})), test_name);
INSTANTIATE_TEST_SUITE_P(Committed, SceneGolden, ::testing::ValuesIn(files_in(kAssets / "scenes", {".json"})),
                         test_name);

// The suites above take their cases from the folders; an empty folder (assets moved, a path
// changed) would make them run nothing and pass.
TEST(GoldenList, AssetAndSceneFoldersAreNotEmpty) {
  EXPECT_FALSE(files_in(kAssets, {".gltf", ".glb"}).empty());
  EXPECT_FALSE(files_in(kAssets / "scenes", {".json"}).empty());
}

}  // namespace
}  // namespace needle::test
