// Helpers for the glTF loader tests: hand-made models, files in a temporary folder, JSON edits.
#pragma once

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/glm.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "asset-gen/gltf_builder.hpp"
#include "engine/model.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::engine::testing {

// A fresh folder under the test output directory, removed afterwards.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(test::output_dir() / ("tmp_" + name + "_" + std::to_string(std::random_device{}()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }

 private:
  std::filesystem::path path_;
};

// Appends `values` (little-endian, as in memory) as a new accessor; returns its index.
template <typename T>
int add_accessor(tinygltf::Model& model, const std::vector<T>& values, int type, int component_type,
                 bool normalized = false) {
  const size_t components = static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type)));
  const int index = asset_gen::append_accessor(model, values.data(), values.size() * sizeof(T),
                                               values.size() / components, type, component_type);
  model.accessors[static_cast<size_t>(index)].normalized = normalized;
  return index;
}

// A model whose only mesh has one primitive with the given POSITION data (xyz triples)
// and optional indices; one root node in the default scene.
inline tinygltf::Model single_primitive_model(const std::vector<float>& positions, int mode = TINYGLTF_MODE_TRIANGLES) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  tinygltf::Primitive primitive;
  primitive.mode = mode;
  primitive.attributes["POSITION"] = add_accessor(model, positions, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT);
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  model.scenes.emplace_back();
  model.scenes[0].nodes = {0};
  model.defaultScene = 0;
  return model;
}

enum class Container { ExternalBin, DataUri, Glb };

// Writes `model` as `name` into `dir` (buffer 0 external as name.bin, embedded, or a GLB).
inline std::filesystem::path write_model(tinygltf::Model model, const std::filesystem::path& dir,
                                         const std::string& name, Container container = Container::ExternalBin) {
  const std::string stem = std::filesystem::path(name).stem().string();
  model.buffers[0].uri = container == Container::ExternalBin ? stem + ".bin" : "";
  tinygltf::TinyGLTF writer;
  const std::filesystem::path path = dir / name;
  EXPECT_TRUE(writer.WriteGltfSceneToFile(&model, path.string(), false, container == Container::DataUri, true,
                                          container == Container::Glb));
  return path;
}

inline nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// Rewrites a .gltf file's JSON through `edit`.
inline void edit_json(const std::filesystem::path& file, const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json json = read_json(file);
  edit(json);
  write_text(file, json.dump(2));
}

// Runs `load` and checks it throws AssetError whose text starts with the file and contains
// every fragment (the element, what is wrong).
template <typename Load>
void expect_asset_error(Load load, const std::string& file, std::initializer_list<std::string> fragments) {
  try {
    load();
    ADD_FAILURE() << "no AssetError; expected one about " << *fragments.begin();
  } catch (const AssetError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(file + ": ", 0), 0u) << what;
    for (const std::string& fragment : fragments)
      EXPECT_NE(what.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << what;
  }
}

}  // namespace needle::engine::testing
