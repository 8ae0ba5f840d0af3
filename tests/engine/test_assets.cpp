// The asset generator: committed files match a fresh run byte for byte, and the generated
// geometry matches its closed forms (thesis sphere eq. 3.29-3.31, needle, tissue block).
#include <fstream>
#include <iterator>
#include <numbers>

#include "asset-gen/assets.hpp"
#include "engine/gltf_loader.hpp"
#include "test_gltf_fixtures.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::engine {
namespace {
using namespace testing;
namespace fs = std::filesystem;

const fs::path kAssets = test::source_dir() / "assets";

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(Assets, CommittedFilesAreExactlyWhatTheGeneratorWrites) {
  TempDir dir("assets");
  for (const asset_gen::GeneratedAsset& asset : asset_gen::committed_assets())
    asset_gen::write_asset(asset, dir.path());
  size_t files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir.path())) {
    const fs::path committed = kAssets / entry.path().filename();
    ASSERT_TRUE(fs::exists(committed)) << committed << " is generated but not committed (run needle-asset-gen)";
    EXPECT_TRUE(bytes_of(entry.path()) == bytes_of(committed))
        << committed << " differs from the generator's output: rerun needle-asset-gen and commit";
    ++files;
  }
  EXPECT_GE(files, 9u);  // 4 glTF + 4 bin + the skin PNG
}

TEST(Assets, EveryCommittedAssetLoads) {
  for (const asset_gen::GeneratedAsset& asset : asset_gen::committed_assets()) {
    const Model model = load_gltf(kAssets / asset.file);
    EXPECT_FALSE(model.instances.empty()) << asset.file;
    EXPECT_FALSE(model.world_bounds.empty()) << asset.file;
  }
}

// Every triangle of these convex parts must face away from its part's vertex centroid
// (counter-clockwise seen from outside).
void expect_outward(const Model& model) {
  for (const MeshInstance& instance : model.instances) {
    const Primitive& p = model.primitives[instance.primitive];
    glm::vec3 inside(0.0f);
    for (const MeshVertex& v : p.vertices) inside += glm::vec3(instance.world * glm::vec4(v.position, 1));
    inside /= static_cast<float>(p.vertices.size());
    for (size_t t = 0; t < p.indices.size(); t += 3) {
      const glm::vec3 a = instance.world * glm::vec4(p.vertices[p.indices[t]].position, 1);
      const glm::vec3 b = instance.world * glm::vec4(p.vertices[p.indices[t + 1]].position, 1);
      const glm::vec3 c = instance.world * glm::vec4(p.vertices[p.indices[t + 2]].position, 1);
      const glm::vec3 n = glm::cross(b - a, c - a);
      const glm::vec3 out = (a + b + c) / 3.0f - inside;
      ASSERT_GT(glm::dot(n, out), 0.0f) << instance.node_name << " triangle " << t / 3;
    }
  }
}

TEST(Assets, ThesisSphereFollowsEquations329To331) {
  for (int p : {100, 37}) {
    const int m = p == 100 ? 100 : 50;
    const Model model = convert_gltf(asset_gen::make_sphere(p, m), "sphere");
    ASSERT_EQ(model.instances.size(), 1u);
    const Primitive& prim = model.primitives[0];
    // (p + 1) parallels of (m + 1) vertices; p m quads, the 2 m at the poles one triangle each.
    EXPECT_EQ(prim.vertices.size(), size_t(p + 1) * size_t(m + 1));
    EXPECT_EQ(prim.indices.size(), 3 * (2 * size_t(p) * size_t(m) - 2 * size_t(m)));
    const double pi = std::numbers::pi;
    for (int i = 0; i <= p; i += 7)
      for (int j = 0; j <= m; j += 5) {
        const double alpha = -pi / 2 + pi * i / p, beta = 2 * pi * j / m;
        const MeshVertex& v = prim.vertices[size_t(i) * size_t(m + 1) + size_t(j)];
        EXPECT_NEAR(v.position.x, 0.1 * std::cos(alpha) * std::cos(beta), 1e-7);
        EXPECT_NEAR(v.position.y, 0.1 * std::cos(alpha) * std::sin(beta), 1e-7);
        EXPECT_NEAR(v.position.z, 0.1 * std::sin(alpha), 1e-7);
        EXPECT_NEAR(glm::dot(v.normal, v.position / 0.1f), 1.0f, 1e-6);  // radial
      }
    // Widest parallel: the equator when p is even, else the two next to it at +-90/p degrees.
    const double widest = 0.1 * std::cos(p % 2 == 0 ? 0.0 : pi / 2 / p);
    EXPECT_NEAR(model.world_bounds.min.x, 0.4 - widest, 1e-6);
    EXPECT_NEAR(model.world_bounds.max.x, 0.4 + widest, 1e-6);
    EXPECT_NEAR(model.world_bounds.max.z, 0.1f, 1e-6);
    expect_outward(model);
  }
}

TEST(Assets, SphereUsesThirtyTwoBitIndicesPast65536Vertices) {
  for (int n : {100, 400, 800}) {
    const tinygltf::Model gltf = asset_gen::make_sphere(n, n);
    const int index_type = gltf.accessors[static_cast<size_t>(gltf.meshes[0].primitives[0].indices)].componentType;
    EXPECT_EQ(index_type, n == 100 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    const Model model = convert_gltf(gltf, "sphere");
    const Primitive& prim = model.primitives[0];
    EXPECT_EQ(prim.vertices.size(), size_t(n + 1) * size_t(n + 1));
    // The last vertex (north pole, seam copy) is referenced, so indices above 65535 survived.
    EXPECT_EQ(*std::max_element(prim.indices.begin(), prim.indices.end()), prim.vertices.size() - 1);
  }
}

// Largest angle (rad) between generated and exact radial normals away from the poles and seam.
double generated_normal_error(int n) {
  tinygltf::Model gltf = asset_gen::make_sphere(n, n);
  gltf.meshes[0].primitives[0].attributes.erase("NORMAL");
  const Primitive prim = convert_gltf(gltf, "sphere").primitives[0];
  double worst = 0;
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) {
      const MeshVertex& v = prim.vertices[size_t(i) * size_t(n + 1) + size_t(j)];
      const double c = glm::dot(glm::dvec3(v.normal), glm::normalize(glm::dvec3(v.position)));
      worst = std::max(worst, std::acos(std::min(c, 1.0)));
    }
  return worst;
}

TEST(Assets, GeneratedSphereNormalsConvergeToTheRadialClosedForm) {
  const double coarse = generated_normal_error(40), fine = generated_normal_error(80);
  // Area weighting on quads split along one diagonal is first-order accurate: the error is a
  // fraction of the grid spacing (4.5 degrees = 0.079 rad at n = 40) and halves with it.
  EXPECT_LT(coarse, 0.079 / 4);
  EXPECT_GT(fine, coarse * 0.4);
  EXPECT_LT(fine, coarse * 0.6);
}

TEST(Assets, NeedleTipIsAtTheOriginPointingAlongPlusX) {
  const Model model = convert_gltf(asset_gen::make_needle(), "needle");
  EXPECT_EQ(model.instances.size(), 3u);
  EXPECT_NEAR(model.world_bounds.max.x, 0.0f, 1e-9);
  EXPECT_NEAR(model.world_bounds.min.x, -0.095f, 1e-6);
  EXPECT_NEAR(model.world_bounds.max.y, 0.003f, 1e-6);  // hub radius
  size_t at_tip = 0;
  for (const Primitive& p : model.primitives)
    for (const MeshVertex& v : p.vertices)
      if (v.position.x > -1e-9f) {
        EXPECT_NEAR(glm::length(v.position), 0.0f, 1e-9);  // only the apex reaches x = 0
        ++at_tip;
      }
  EXPECT_GT(at_tip, 0u);
  // Shaft vertices sit at the visible radius 0.8 mm.
  for (const MeshVertex& v : model.primitives[1].vertices)
    EXPECT_NEAR(std::hypot(v.position.y, v.position.z), 0.0008f, 1e-7);
  expect_outward(model);
}

TEST(Assets, TissueBlockLayersStackDownFromTheSkinAtZZero) {
  const tinygltf::Model gltf = asset_gen::make_tissue_block();
  const Model model = load_gltf(kAssets / "tissue_block.gltf");
  ASSERT_EQ(model.primitives.size(), 4u);
  EXPECT_NEAR(model.world_bounds.max.z, 0.0f, 1e-9);
  EXPECT_NEAR(model.world_bounds.min.z, -0.05f, 1e-7);
  float previous_bottom = 0.0f;
  for (const Primitive& p : model.primitives) {  // skin, fat, muscle, bone: each starts where the last ended
    float top = -1, bottom = 1;
    for (const MeshVertex& v : p.vertices) top = std::max(top, v.position.z), bottom = std::min(bottom, v.position.z);
    EXPECT_NEAR(top, previous_bottom, 1e-7);
    previous_bottom = bottom;
  }
  // The skin's texture decodes back to exactly the generator's texels (PNG is lossless).
  ASSERT_EQ(model.textures.size(), 1u);
  EXPECT_EQ(model.materials[0].base_color_texture, 0);
  EXPECT_EQ(model.textures[0].width, 64u);
  EXPECT_TRUE(model.textures[0].rgba8 == gltf.images[0].image);
  expect_outward(model);
}

}  // namespace
}  // namespace needle::engine
