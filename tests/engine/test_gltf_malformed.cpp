// glTF loader on malformed and hostile input: every case must throw AssetError naming the
// file and the element, never crash or read out of bounds (run under ASan: docs/ASSETS.md).
#include "engine/gltf_loader.hpp"
#include "test_gltf_fixtures.hpp"

namespace needle::engine {
namespace {
using namespace testing;

// A valid indexed triangle with a texture-free material: the base every case breaks.
tinygltf::Model triangle() {
  tinygltf::Model model = single_primitive_model({0, 0, 0, 1, 0, 0, 0, 1, 0});
  model.meshes[0].primitives[0].indices =
      add_accessor(model, std::vector<uint16_t>{0, 1, 2}, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  return model;
}

class GltfMalformed : public ::testing::Test {
 protected:
  TempDir dir{"malformed"};
  std::filesystem::path file = write_model(triangle(), dir.path(), "model.gltf");
  void expect_error(std::initializer_list<std::string> fragments) {
    expect_asset_error([&] { load_gltf(file); }, file.string(), fragments);
  }
};

TEST_F(GltfMalformed, TheUnbrokenBaseLoads) { EXPECT_EQ(load_gltf(file).primitives[0].indices.size(), 3u); }

TEST_F(GltfMalformed, MissingFile) {
  file = dir / "absent.gltf";
  expect_error({"file", "not found"});
}

TEST_F(GltfMalformed, BadJson) {
  write_text(file, "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [");
  expect_error({"JSON", "parse error"});
}

TEST_F(GltfMalformed, TruncatedExternalBuffer) {
  std::filesystem::resize_file(dir / "model.bin", 10);
  expect_error({"buffers[0]", "byteLength", "10 bytes"});
}

TEST_F(GltfMalformed, DataUriShorterThanByteLength) {
  file = write_model(triangle(), dir.path(), "embedded.gltf", Container::DataUri);
  edit_json(file, [](nlohmann::json& j) { j["buffers"][0]["byteLength"] = 4096; });
  expect_error({"buffers[0]", "byteLength 4096"});
}

TEST_F(GltfMalformed, MissingBufferFile) {
  std::filesystem::remove(dir / "model.bin");
  expect_error({"buffers[0]", "model.bin", "not found"});
}

TEST_F(GltfMalformed, BufferUriEscapingTheFolder) {
  std::filesystem::copy_file(dir / "model.bin", dir.path().parent_path() / "outside_g.bin",
                             std::filesystem::copy_options::overwrite_existing);
  for (const char* uri : {"../outside_g.bin", "%2E%2E/outside_g.bin", "sub/../../outside_g.bin"}) {
    edit_json(file, [&](nlohmann::json& j) { j["buffers"][0]["uri"] = uri; });
    expect_error({"buffers[0]", uri, "escapes the asset's folder"});
  }
  std::filesystem::remove(dir.path().parent_path() / "outside_g.bin");
}

TEST_F(GltfMalformed, AbsoluteBufferUri) {
  edit_json(file, [&](nlohmann::json& j) { j["buffers"][0]["uri"] = (dir / "model.bin").string(); });
  expect_error({"buffers[0]", "absolute path"});
}

TEST_F(GltfMalformed, SymlinkLeadingOutOfTheFolder) {
  const auto outside = dir.path().parent_path() / "outside_link_target_g.bin";
  std::filesystem::copy_file(dir / "model.bin", outside, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::create_symlink(outside, dir / "link.bin");
  edit_json(file, [](nlohmann::json& j) { j["buffers"][0]["uri"] = "link.bin"; });
  expect_error({"buffers[0]", "escapes the asset's folder"});
  std::filesystem::remove(outside);
}

TEST_F(GltfMalformed, ImageUriEscapingTheFolder) {
  write_text(dir.path().parent_path() / "outside_g.png", "not really a png");
  edit_json(file, [](nlohmann::json& j) {
    j["images"] = {{{"uri", "../outside_g.png"}}};
    j["textures"] = {{{"source", 0}}};
  });
  expect_error({"images[0]", "escapes the asset's folder"});
  std::filesystem::remove(dir.path().parent_path() / "outside_g.png");
}

TEST_F(GltfMalformed, IndexOutOfRange) {
  tinygltf::Model model = triangle();
  model.meshes[0].primitives[0].indices =
      add_accessor(model, std::vector<uint16_t>{0, 1, 3}, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  file = write_model(model, dir.path(), "index.gltf");
  expect_error({"indices of meshes[0].primitives[0]", "index 2 is 3", "3 vertices"});
}

TEST_F(GltfMalformed, CoarserIndicesOutOfRangeOrNotAList) {
  tinygltf::Model model = triangle();
  const int coarse =
      add_accessor(model, std::vector<uint16_t>{0, 1, 7}, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  model.meshes[0].primitives[0].extras = tinygltf::Value(tinygltf::Value::Object{
      {"needle_coarser_indices", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(coarse)})}});
  file = write_model(model, dir.path(), "coarse.gltf");
  expect_error({"meshes[0].primitives[0].extras.needle_coarser_indices[0]", "index 2 is 7", "3 vertices"});
  edit_json(file, [](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["extras"]["needle_coarser_indices"] = 3; });
  expect_error({"meshes[0].primitives[0].extras.needle_coarser_indices", "expected an array of accessor indices"});
  edit_json(file,
            [](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["extras"]["needle_coarser_indices"] = {"a"}; });
  expect_error({"needle_coarser_indices[0]", "expected an accessor index"});
}

TEST_F(GltfMalformed, StrideSmallerThanTheElement) {
  edit_json(file, [](nlohmann::json& j) { j["bufferViews"][0]["byteStride"] = 8; });
  expect_error({"accessors[0] (POSITION of meshes[0].primitives[0])", "byteStride 8", "element size 12"});
}

TEST_F(GltfMalformed, StrideRunningPastTheBufferView) {
  edit_json(file, [](nlohmann::json& j) { j["bufferViews"][0]["byteStride"] = 16; });
  expect_error({"accessors[0]", "exceeds bufferViews[0] length 36"});
}

TEST_F(GltfMalformed, AccessorOffsetPastTheBufferView) {
  edit_json(file, [](nlohmann::json& j) { j["accessors"][0]["byteOffset"] = 4; });
  expect_error({"accessors[0]", "byteOffset 4"});
}

TEST_F(GltfMalformed, HugeAccessorCounts) {
  // 2^62 and 2^64 - 1 elements: products with the stride would overflow 64 bits.
  for (uint64_t count : {uint64_t(1) << 62, ~uint64_t(0)}) {
    edit_json(file, [&](nlohmann::json& j) { j["accessors"][1]["count"] = count; });
    expect_error({"accessors[1]", "indices"});
  }
}

TEST_F(GltfMalformed, HugeBufferViewLength) {
  edit_json(file, [](nlohmann::json& j) { j["bufferViews"][0]["byteLength"] = uint64_t(1) << 63; });
  expect_error({"bufferViews[0]", "exceeds"});
}

TEST_F(GltfMalformed, WrongAccessorTypes) {
  edit_json(file, [](nlohmann::json& j) { j["accessors"][0]["type"] = "VEC2"; });
  expect_error({"POSITION", "type is VEC2, expected VEC3"});
  edit_json(file, [](nlohmann::json& j) {
    j["accessors"][0]["type"] = "VEC3";
    j["accessors"][1]["componentType"] = 5126;
  });
  expect_error({"indices", "componentType is FLOAT"});
}

TEST_F(GltfMalformed, WrongJsonTypes) {
  edit_json(file, [](nlohmann::json& j) { j["accessors"][0]["count"] = "three"; });
  expect_error({"glTF"});
}

TEST_F(GltfMalformed, SparseAccessor) {
  edit_json(file, [](nlohmann::json& j) {
    j["accessors"][0]["sparse"] = {
        {"count", 1}, {"indices", {{"bufferView", 1}, {"componentType", 5123}}}, {"values", {{"bufferView", 0}}}};
  });
  expect_error({"accessors[0]", "sparse"});
}

TEST_F(GltfMalformed, LinesAreRejected) {
  edit_json(file, [](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["mode"] = 1; });
  expect_error({"meshes[0].primitives[0]", "mode 1"});
}

TEST_F(GltfMalformed, NodeCycle) {
  edit_json(file, [](nlohmann::json& j) {
    j["nodes"].push_back({{"children", {0}}});
    j["nodes"][0]["children"] = {1};
  });
  expect_error({"nodes[0]", "reached twice"});
}

TEST_F(GltfMalformed, DanglingReferences) {
  edit_json(file, [](nlohmann::json& j) { j["nodes"][0]["mesh"] = 7; });
  expect_error({"nodes[0]", "mesh 7"});
  edit_json(file, [](nlohmann::json& j) {
    j["nodes"][0]["mesh"] = 0;
    j["meshes"][0]["primitives"][0]["material"] = 2;
  });
  expect_error({"meshes[0].primitives[0]", "material 2"});
}

// GLB whose BIN chunk claims to reach exactly the end of the file: with its 8-byte chunk
// header that is 8 bytes past it (the case tinygltf 2.7 itself misses).
TEST_F(GltfMalformed, GlbBinChunkPastTheEnd) {
  file = write_model(triangle(), dir.path(), "model.glb", Container::Glb);
  std::vector<char> bytes(std::filesystem::file_size(file));
  std::ifstream(file, std::ios::binary).read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  uint32_t json_length = 0, bin_length = 0;
  std::memcpy(&json_length, &bytes[12], 4);
  std::memcpy(&bin_length, &bytes[20 + json_length], 4);
  bin_length += 8;
  std::memcpy(&bytes[20 + json_length], &bin_length, 4);
  std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  expect_error({"GLB BIN chunk", "runs past the end"});
}

TEST_F(GltfMalformed, TruncatedGlb) {
  file = write_model(triangle(), dir.path(), "model.glb", Container::Glb);
  std::filesystem::resize_file(file, std::filesystem::file_size(file) - 12);
  expect_error({"GLB header", "exceeds the file"});
}

TEST_F(GltfMalformed, UndecodableImage) {
  write_text(dir / "noise.png", "this is not an image");
  edit_json(file, [](nlohmann::json& j) {
    j["images"] = {{{"uri", "noise.png"}}};
    j["textures"] = {{{"source", 0}}};
  });
  expect_error({"glTF", "image[0]"});
}

// A PNG whose header declares 16384 x 16384 grey pixels (1 GB as the RGBA texture) is refused from its header.
TEST_F(GltfMalformed, AnImageOverTheLargestTextureIsRefusedBeforeDecoding) {
  std::string png("\x89PNG\r\n\x1a\n", 8);
  const auto be32 = [&](uint32_t v) {
    for (int shift : {24, 16, 8, 0}) png += char((v >> shift) & 0xff);
  };
  be32(13);
  png += "IHDR";
  be32(16384);
  be32(16384);
  png += std::string("\x08\x00\x00\x00\x00", 5);  // 8 bits, grey, deflate, no filter, no interlace
  be32(0);                                        // the CRC, which stb_image does not check
  write_text(dir / "huge.png", png);
  edit_json(file, [](nlohmann::json& j) {
    j["images"] = {{{"uri", "huge.png"}}};
    j["textures"] = {{{"source", 0}}};
  });
  expect_error({"image[0]", "16384x16384", "8192 pixels a side"});
}

TEST_F(GltfMalformed, RequiredExtensionsAreRefused) {
  edit_json(file, [](nlohmann::json& j) {
    j["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  });
  expect_error({"extensionsRequired", "KHR_draco_mesh_compression"});
}

TEST(GltfMalformedInMemory, ImageBufferViewOutsideItsBuffer) {
  tinygltf::Model model = triangle();
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = model.buffers[0].data.size() - 4;
  view.byteLength = 64;
  model.bufferViews.push_back(view);
  tinygltf::Image image;
  image.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
  image.mimeType = "image/png";
  model.images.push_back(image);
  model.textures.emplace_back();
  model.textures[0].source = 0;
  expect_asset_error([&] { convert_gltf(model, "memory.glb"); }, "memory.glb",
                     {"images[0]", "bufferViews[" + std::to_string(image.bufferView) + "]", "exceeds"});
}

TEST(GltfMalformedInMemory, ImagePixelsShorterThanTheirSize) {
  tinygltf::Model model = triangle();
  tinygltf::Image image;
  image.width = image.height = 4;
  image.component = 4;
  image.bits = 8;
  image.image.resize(60);  // 4 x 4 x 4 = 64 needed
  model.images.push_back(image);
  model.textures.emplace_back();
  model.textures[0].source = 0;
  expect_asset_error([&] { convert_gltf(model, "memory"); }, "memory", {"images[0]", "60 bytes"});
}

TEST(GltfMalformedInMemory, AttributeCountsDisagree) {
  tinygltf::Model model = triangle();
  model.meshes[0].primitives[0].attributes["NORMAL"] =
      add_accessor(model, std::vector<float>{0, 0, 1, 0, 0, 1}, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT);
  expect_asset_error([&] { convert_gltf(model, "memory"); }, "memory",
                     {"meshes[0].primitives[0]", "NORMAL has 2 elements but POSITION has 3"});
}

// A chain of `length` nodes, each the only child of the one before, the last holding the mesh.
void make_chain(nlohmann::json& j, size_t length) {
  j["nodes"] = nlohmann::json::array();
  for (size_t i = 0; i + 1 < length; ++i) j["nodes"].push_back({{"children", {i + 1}}});
  j["nodes"].push_back({{"mesh", 0}});
  j["scenes"][0]["nodes"] = {0};
}

TEST_F(GltfMalformed, ANodeChainOfAHundredThousandIsRefusedAtTheStatedDepth) {
  edit_json(file, [](nlohmann::json& j) { make_chain(j, 100000); });
  expect_error({"nodes[256]", "nested deeper than 256 levels of the node hierarchy"});
  edit_json(file, [](nlohmann::json& j) { make_chain(j, 256); });
  const Model model = load_gltf(file);
  ASSERT_EQ(model.instances.size(), 1u);
  EXPECT_EQ(model.instances[0].world, glm::mat4(1.0f));
}

TEST_F(GltfMalformed, DeeplyNestedJsonIsRefusedBeforeTinygltfRecursesIntoIt) {
  std::string extras = "1";
  for (int k = 0; k < 100000; ++k) extras = "[" + extras;
  extras += std::string(100000, ']');
  std::string text = read_json(file).dump();
  text.insert(text.size() - 1, ",\"extras\":" + extras);
  write_text(file, text);
  expect_error({"JSON", "nested deeper than 64 levels"});
}

// tinygltf would keep one of the two values; the check before it names the second by its pointer.
TEST_F(GltfMalformed, AKeyGivenTwiceIsRefusedByItsPointer) {
  std::string text = read_json(file).dump();
  const size_t node = text.find("\"nodes\":[{");
  ASSERT_NE(node, std::string::npos) << text;
  text.insert(node + std::string("\"nodes\":[{").size(), "\"mesh\":0,");
  write_text(file, text);
  expect_error({"JSON: /nodes/0/mesh: the key is given twice in its object"});
}

TEST_F(GltfMalformed, AMeshWithoutPrimitivesIsRefusedAsSuch) {
  edit_json(file, [](nlohmann::json& j) { j["meshes"][0]["primitives"] = nlohmann::json::array(); });
  expect_error({"meshes[0]", "has no primitives"});
}

TEST_F(GltfMalformed, AModelWithNothingToDrawIsRefusedAsSuch) {
  edit_json(file, [](nlohmann::json& j) { j["nodes"][0].erase("mesh"); });
  expect_error({"scene", "no node with a mesh: nothing to draw"});
}

TEST_F(GltfMalformed, TransformsPastWhatFloatsHoldAreRefused) {
  edit_json(file, [](nlohmann::json& j) { j["nodes"][0]["translation"] = {1e39, 0, 0}; });
  expect_error({"nodes[0]", "beyond what 32-bit floats hold"});
  // A finite transform that carries the vertex (1, 0, 0) to 1e38 + 3e38, past a float's 3.4e38.
  edit_json(file, [](nlohmann::json& j) {
    j["nodes"][0]["translation"] = {3e38, 0, 0};
    j["nodes"][0]["scale"] = {1e38, 1, 1};
  });
  expect_error({"scene", "its vertices, placed by the nodes' transforms, lie beyond what 32-bit floats hold"});
}

}  // namespace
}  // namespace needle::engine
