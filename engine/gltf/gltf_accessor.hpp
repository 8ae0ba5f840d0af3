// Bounds-checked access to glTF accessor data. Every check happens when the view is made,
// so reading elements afterwards cannot leave the buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>

namespace tinygltf {
class Model;
}

namespace needle::engine {

// What a use of an accessor allows (e.g. POSITION: VEC3 of FLOAT).
struct AccessorRule {
  std::initializer_list<int> types;            // TINYGLTF_TYPE_*
  std::initializer_list<int> component_types;  // TINYGLTF_COMPONENT_TYPE_*
  bool integers_normalized = false;            // integer components must be `normalized`
};

class AccessorView {
 public:
  size_t count() const { return count_; }
  int components() const { return components_; }
  // Component c of element i as float: floats as stored, normalized integers in [0, 1].
  float component(size_t i, int c) const;
  // Element i of a SCALAR integer accessor (indices).
  uint32_t index(size_t i) const;

 private:
  friend AccessorView view_accessor(const tinygltf::Model&, int, const std::string&, const std::string&,
                                    const AccessorRule&);
  const uint8_t* base_ = nullptr;
  size_t stride_ = 0;
  size_t count_ = 0;
  int component_type_ = 0;
  int components_ = 0;
  int component_size_ = 0;
};

// A validated byte range of a buffer.
struct ByteSpan {
  const uint8_t* data = nullptr;
  size_t size = 0;
};

// Validates bufferView `index` (used as `usage`) against its buffer and returns its bytes.
ByteSpan view_buffer_view(const tinygltf::Model& gltf, int index, const std::string& file, const std::string& usage);

// Validates accessor `index` (used as `usage`, e.g. "POSITION of meshes[0].primitives[1]")
// against its bufferView and buffer, then returns a view on it. Throws AssetError.
AccessorView view_accessor(const tinygltf::Model& gltf, int index, const std::string& file, const std::string& usage,
                           const AccessorRule& rule);

}  // namespace needle::engine
