// glTF loader on valid input: containers, node transforms, index types, topology,
// attribute formats and generated normals, each against a hand-derived expectation.
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>

#include "asset-gen/assets.hpp"
#include "engine/gltf_loader.hpp"
#include "test_gltf_fixtures.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::engine {
namespace {
using namespace testing;
namespace fs = std::filesystem;

// Flat quad in the tilted plane spanned by e1 = (1, 0, 1) and e2 = (0, 2, 0): corners 0, e1,
// e1 + e2, e2. Its unit normal is e1 x e2 / |e1 x e2| = (-2, 0, 2) / sqrt(8).
const std::vector<float> kQuad = {0, 0, 0, 1, 0, 1, 1, 2, 1, 0, 2, 0};

tinygltf::Model quad_with_indices(const std::vector<uint32_t>& indices, int component_type) {
  tinygltf::Model model = single_primitive_model(kQuad);
  int accessor = -1;
  if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
    accessor =
        add_accessor(model, std::vector<uint8_t>(indices.begin(), indices.end()), TINYGLTF_TYPE_SCALAR, component_type);
  else if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
    accessor = add_accessor(model, std::vector<uint16_t>(indices.begin(), indices.end()), TINYGLTF_TYPE_SCALAR,
                            component_type);
  else
    accessor = add_accessor(model, indices, TINYGLTF_TYPE_SCALAR, component_type);
  model.meshes[0].primitives[0].indices = accessor;
  return model;
}

tinygltf::Model indexed_quad() { return quad_with_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT); }

TEST(GltfLoader, EveryIndexComponentTypeGivesTheSameTriangles) {
  const std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
  for (int type : {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}) {
    TempDir dir("index_types");
    const auto file = write_model(quad_with_indices(indices, type), dir.path(), "quad.gltf");
    const Model model = load_gltf(file);
    ASSERT_EQ(model.primitives.size(), 1u);
    EXPECT_EQ(model.primitives[0].indices, indices) << "component type " << type;
  }
}

TEST(GltfLoader, StripsAndFansBecomeTriangleListsWithTheSpecsWinding) {
  tinygltf::Model strip = quad_with_indices({0, 1, 3, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  strip.meshes[0].primitives[0].mode = TINYGLTF_MODE_TRIANGLE_STRIP;
  // glTF 2.0 spec, 3.7.2.1: strip triangle i = {v[i], v[i+1+i%2], v[i+2-i%2]}.
  EXPECT_EQ(convert_gltf(strip, "strip").primitives[0].indices, (std::vector<uint32_t>{0, 1, 3, 1, 2, 3}));
  tinygltf::Model fan = quad_with_indices({0, 1, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  fan.meshes[0].primitives[0].mode = TINYGLTF_MODE_TRIANGLE_FAN;
  // Fan triangle i = {v[i+1], v[i+2], v[0]}.
  EXPECT_EQ(convert_gltf(fan, "fan").primitives[0].indices, (std::vector<uint32_t>{1, 2, 0, 2, 3, 0}));
}

TEST(GltfLoader, NonIndexedPrimitivesGetSequentialIndices) {
  const Model model =
      convert_gltf(single_primitive_model({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 1, 2, 0}), "soup");
  EXPECT_EQ(model.primitives[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(GltfLoader, MissingNormalsOfAFlatQuadAreThePlaneNormal) {
  const Model model =
      convert_gltf(quad_with_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE), "quad");
  const glm::vec3 expected = glm::vec3(-2, 0, 2) / std::sqrt(8.0f);
  for (const MeshVertex& v : model.primitives[0].vertices) {
    EXPECT_NEAR(v.normal.x, expected.x, 1e-6);
    EXPECT_NEAR(v.normal.y, expected.y, 1e-6);
    EXPECT_NEAR(v.normal.z, expected.z, 1e-6);
  }
}

TEST(GltfLoader, GeneratedNormalsAreAreaWeighted) {
  // Vertex 0 is shared by a triangle in z = 0 (area 2) and one in x = 0 (area 0.5): the
  // area-weighted normal is (2 (0,0,1) + 0.5 (1,0,0)) normalized; an unweighted mean would be (1,0,1)/sqrt 2.
  tinygltf::Model gltf = single_primitive_model({0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 1, 0, 0, 0, 1});
  gltf.meshes[0].primitives[0].indices = add_accessor(gltf, std::vector<uint16_t>{0, 1, 2, 0, 3, 4},
                                                      TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  const glm::vec3 n = convert_gltf(gltf, "two_planes").primitives[0].vertices[0].normal;
  const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0.0f, 2.0f));
  EXPECT_NEAR(n.x, expected.x, 1e-6);
  EXPECT_NEAR(n.y, expected.y, 1e-6);
  EXPECT_NEAR(n.z, expected.z, 1e-6);
}

TEST(GltfLoader, NormalizedIntegerTexcoordsAndColoursAreScaledToUnitRange) {
  tinygltf::Model gltf = single_primitive_model({0, 0, 0, 1, 0, 0, 0, 1, 0});
  auto& attributes = gltf.meshes[0].primitives[0].attributes;
  attributes["TEXCOORD_0"] = add_accessor(gltf, std::vector<uint8_t>{0, 255, 51, 102, 255, 0}, TINYGLTF_TYPE_VEC2,
                                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, true);
  attributes["COLOR_0"] = add_accessor(gltf, std::vector<uint16_t>{65535, 0, 0, 0, 65535, 0, 13107, 13107, 65535},
                                       TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, true);
  const std::vector<MeshVertex> v = convert_gltf(gltf, "attributes").primitives[0].vertices;
  EXPECT_EQ(v[0].uv, glm::vec2(0.0f, 1.0f));
  EXPECT_NEAR(v[1].uv.x, 0.2f, 1e-6);            // 51 / 255
  EXPECT_NEAR(v[1].uv.y, 0.4f, 1e-6);            // 102 / 255
  EXPECT_EQ(v[0].color, glm::vec4(1, 0, 0, 1));  // VEC3 colours keep alpha 1
  EXPECT_NEAR(v[2].color.x, 0.2f, 1e-6);         // 13107 / 65535
  EXPECT_EQ(v[2].color.z, 1.0f);
}

// T R S with R = 90 degrees about z, written out by hand.
glm::mat4 hand_trs() {
  glm::mat4 m(0.0f);
  m[0] = {0, 2, 0, 0};   // column 0 = R x (2, 0, 0): x scaled by 2 then turned onto +y
  m[1] = {-3, 0, 0, 0};  // column 1 = R y (0, 3, 0)
  m[2] = {0, 0, 4, 0};
  m[3] = {1, 2, 3, 1};
  return m;
}

TEST(GltfLoader, TrsAndMatrixNodesGiveTheSameWorldTransformAndChildrenCompose) {
  tinygltf::Model gltf = indexed_quad();
  gltf.nodes[0].translation = {1, 2, 3};
  gltf.nodes[0].rotation = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};  // x y z w
  gltf.nodes[0].scale = {2, 3, 4};
  tinygltf::Node by_matrix;
  by_matrix.mesh = 0;
  const glm::mat4 m = hand_trs();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) by_matrix.matrix.push_back(m[c][r]);
  tinygltf::Node child;
  child.mesh = 0;
  child.translation = {0, 0, 1};
  by_matrix.children = {2};
  gltf.nodes.push_back(by_matrix);
  gltf.nodes.push_back(child);
  gltf.scenes[0].nodes = {0, 1};

  TempDir dir("trs");
  const Model model = load_gltf(write_model(gltf, dir.path(), "trs.gltf"));
  ASSERT_EQ(model.instances.size(), 3u);
  const glm::mat4 child_expected = m * glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(model.instances[0].world[c][r], m[c][r], 1e-6);
      EXPECT_NEAR(model.instances[1].world[c][r], m[c][r], 1e-6);
      EXPECT_NEAR(model.instances[2].world[c][r], child_expected[c][r], 1e-6);
    }
  // Bounds of the transformed quad: corner (1, 2, 1) maps to (1 - 6, 2 + 2, 3 + 4).
  EXPECT_NEAR(model.world_bounds.min.x, -5.0f, 1e-5);
  EXPECT_NEAR(model.world_bounds.max.z, 3.0f + 4.0f + 4.0f, 1e-5);  // the child is 1 up, scaled by 4
}

TEST(GltfLoader, WithoutADefaultSceneEveryRootNodeIsInstanced) {
  tinygltf::Model gltf = indexed_quad();
  gltf.defaultScene = -1;
  gltf.scenes.clear();
  tinygltf::Node parent;
  parent.children = {2};
  tinygltf::Node child;
  child.mesh = 0;
  gltf.nodes.push_back(parent);
  gltf.nodes.push_back(child);
  const Model model = convert_gltf(gltf, "roots");
  EXPECT_EQ(model.instances.size(), 2u);  // node 0 and node 2 through root node 1
}

TEST(GltfLoader, GlbAndDataUriContainersLoadTheSameModelAsExternalFiles) {
  tinygltf::Model gltf = quad_with_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  TempDir dir("containers");
  const Model external = load_gltf(write_model(gltf, dir.path(), "external.gltf"));
  for (auto [container, name] :
       {std::pair{Container::Glb, "binary.glb"}, std::pair{Container::DataUri, "embedded.gltf"}}) {
    const Model other = load_gltf(write_model(gltf, dir.path(), name, container));
    ASSERT_EQ(other.primitives.size(), 1u) << name;
    EXPECT_EQ(other.primitives[0].indices, external.primitives[0].indices) << name;
    for (size_t i = 0; i < 4; ++i)
      EXPECT_EQ(other.primitives[0].vertices[i].position, external.primitives[0].vertices[i].position) << name;
  }
}

TEST(GltfLoader, ExternalUrisArePercentDecoded) {
  TempDir dir("percent");
  const auto file = write_model(indexed_quad(), dir.path(), "quad.gltf");
  std::filesystem::rename(dir / "quad.bin", dir / "my quad.bin");
  edit_json(file, [](nlohmann::json& j) { j["buffers"][0]["uri"] = "my%20quad.bin"; });
  EXPECT_EQ(load_gltf(file).primitives[0].vertices.size(), 4u);
}

// The skin texture of the tissue block as the generator made it (RGBA8, 64 x 64).
const std::vector<unsigned char>& skin_texels() {
  static const std::vector<unsigned char> texels = asset_gen::make_tissue_block().images[0].image;
  return texels;
}

TEST(GltfLoader, ImagesInADataUriDecodeToTheOriginalTexels) {
  TempDir dir("data_uri_image");
  const tinygltf::Model gltf = asset_gen::make_tissue_block();
  tinygltf::TinyGLTF writer;
  const auto file = dir / "block.gltf";
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&gltf, file.string(), /*embedImages=*/true, true, true, false));
  const Model model = load_gltf(file);
  ASSERT_EQ(model.textures.size(), 1u);
  EXPECT_TRUE(model.textures[0].rgba8 == skin_texels());
}

TEST(GltfLoader, ImagesInABufferViewDecodeToTheOriginalTexels) {
  tinygltf::Model gltf = asset_gen::make_tissue_block();
  std::ifstream png(test::source_dir() / "assets" / "tissue_block_skin.png", std::ios::binary);
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(png), std::istreambuf_iterator<char>()};
  const int accessor = add_accessor(gltf, bytes, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
  tinygltf::Image& image = gltf.images[0];
  image = tinygltf::Image();
  image.bufferView = gltf.accessors[static_cast<size_t>(accessor)].bufferView;
  image.mimeType = "image/png";
  TempDir dir("buffer_view_image");
  const Model model = load_gltf(write_model(gltf, dir.path(), "block.glb", Container::Glb));
  ASSERT_EQ(model.textures.size(), 1u);
  EXPECT_EQ(model.textures[0].width, 64u);
  EXPECT_TRUE(model.textures[0].rgba8 == skin_texels());
}

TEST(GltfLoader, GreyAndSixteenBitImagesBecomeRgba8) {
  tinygltf::Model gltf = asset_gen::make_tissue_block();
  tinygltf::Image& image = gltf.images[0];
  image.width = 2;
  image.height = 1;
  image.component = 2;  // grey + alpha, 16 bits each, little-endian
  image.bits = 16;
  image.image = {0xff, 0xff, 0x00, 0x80, 0x00, 0x00, 0xff, 0xff};
  const Model model = convert_gltf(gltf, "grey16");
  // 0x8000 = 32768 -> round(32768 * 255 / 65535) = 128.
  EXPECT_EQ(model.textures[0].rgba8, (std::vector<uint8_t>{255, 255, 255, 128, 0, 0, 0, 255}));
}

}  // namespace
}  // namespace needle::engine
