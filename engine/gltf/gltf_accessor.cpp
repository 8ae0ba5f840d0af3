#include "engine/gltf/gltf_accessor.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

#include "engine/gltf/gltf_errors.hpp"

namespace needle::engine {
namespace {

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT2:
      return "MAT2";
    case TINYGLTF_TYPE_MAT3:
      return "MAT3";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "unknown type";
  }
}

const char* component_type_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    default:
      return "unknown component type";
  }
}

template <typename List, typename Name>
std::string list_names(const List& list, Name name) {
  std::string text;
  for (int v : list) text += (text.empty() ? "" : " or ") + std::string(name(v));
  return text;
}

bool contains(std::initializer_list<int> list, int value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

template <typename T>
T load(const uint8_t* p) {
  T v;  // memcpy: glTF data need not be aligned for T
  std::memcpy(&v, p, sizeof v);
  return v;
}

}  // namespace

ByteSpan view_buffer_view(const tinygltf::Model& gltf, int index, const std::string& file, const std::string& usage) {
  if (index < 0 || static_cast<size_t>(index) >= gltf.bufferViews.size())
    asset_fail(file, usage,
               "bufferView " + std::to_string(index) + " does not exist (" + std::to_string(gltf.bufferViews.size()) +
                   " bufferViews)");
  const tinygltf::BufferView& view = gltf.bufferViews[static_cast<size_t>(index)];
  const std::string name = element_name("bufferViews", static_cast<size_t>(index)) + " of " + usage;
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= gltf.buffers.size())
    asset_fail(file, name, "buffer " + std::to_string(view.buffer) + " does not exist");
  const std::vector<unsigned char>& data = gltf.buffers[static_cast<size_t>(view.buffer)].data;
  // Written as subtractions so that huge values cannot overflow.
  if (view.byteLength > data.size() || view.byteOffset > data.size() - view.byteLength)
    asset_fail(file, name,
               "byteOffset " + std::to_string(view.byteOffset) + " + byteLength " + std::to_string(view.byteLength) +
                   " exceeds the " + std::to_string(data.size()) + " bytes of buffers[" + std::to_string(view.buffer) +
                   "]");
  return {data.data() + view.byteOffset, view.byteLength};
}

AccessorView view_accessor(const tinygltf::Model& gltf, int index, const std::string& file, const std::string& usage,
                           const AccessorRule& rule) {
  if (index < 0 || static_cast<size_t>(index) >= gltf.accessors.size())
    asset_fail(file, usage,
               "accessor " + std::to_string(index) + " does not exist (" + std::to_string(gltf.accessors.size()) +
                   " accessors)");
  const tinygltf::Accessor& acc = gltf.accessors[static_cast<size_t>(index)];
  const std::string name = element_name("accessors", static_cast<size_t>(index)) + " (" + usage + ")";

  if (acc.sparse.isSparse) asset_fail(file, name, "sparse accessors are not supported");
  if (!contains(rule.types, acc.type))
    asset_fail(file, name,
               std::string("type is ") + type_name(acc.type) + ", expected " + list_names(rule.types, type_name));
  if (!contains(rule.component_types, acc.componentType))
    asset_fail(file, name,
               std::string("componentType is ") + component_type_name(acc.componentType) + ", expected " +
                   list_names(rule.component_types, component_type_name));
  if (rule.integers_normalized && acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !acc.normalized)
    asset_fail(file, name, "integer components must be normalized");
  if (acc.count == 0) asset_fail(file, name, "count is 0");
  if (acc.bufferView < 0) asset_fail(file, name, "has no bufferView (all-zero accessors are not supported)");

  const ByteSpan span = view_buffer_view(gltf, acc.bufferView, file, name);
  const tinygltf::BufferView& bv = gltf.bufferViews[static_cast<size_t>(acc.bufferView)];
  const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(acc.type));
  const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(acc.componentType));
  const size_t element_size = static_cast<size_t>(components * component_size);
  const size_t stride = bv.byteStride ? bv.byteStride : element_size;
  if (stride < element_size)
    asset_fail(file, name,
               "bufferViews[" + std::to_string(acc.bufferView) + "].byteStride " + std::to_string(stride) +
                   " is smaller than the element size " + std::to_string(element_size));
  if (acc.byteOffset % static_cast<size_t>(component_size) != 0 || stride % static_cast<size_t>(component_size) != 0)
    asset_fail(file, name,
               "byteOffset " + std::to_string(acc.byteOffset) + " or stride " + std::to_string(stride) +
                   " is not a multiple of the component size " + std::to_string(component_size));
  // span.size is a real in-memory size, so once count <= span.size the products below fit.
  if (acc.count > span.size || acc.byteOffset > span.size ||
      stride * (acc.count - 1) + element_size > span.size - acc.byteOffset)
    asset_fail(file, name,
               "byteOffset " + std::to_string(acc.byteOffset) + " + stride " + std::to_string(stride) + " x " +
                   std::to_string(acc.count) + " elements exceeds bufferViews[" + std::to_string(acc.bufferView) +
                   "] length " + std::to_string(span.size));

  AccessorView view;
  view.base_ = span.data + acc.byteOffset;
  view.stride_ = stride;
  view.count_ = acc.count;
  view.component_type_ = acc.componentType;
  view.components_ = components;
  view.component_size_ = component_size;
  return view;
}

float AccessorView::component(size_t i, int c) const {
  const uint8_t* p = base_ + i * stride_ + static_cast<size_t>(c * component_size_);
  switch (component_type_) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return static_cast<float>(*p) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return static_cast<float>(load<uint16_t>(p)) / 65535.0f;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return std::max(static_cast<float>(load<int8_t>(p)) / 127.0f, -1.0f);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return std::max(static_cast<float>(load<int16_t>(p)) / 32767.0f, -1.0f);
    default:
      return static_cast<float>(load<uint32_t>(p));
  }
}

uint32_t AccessorView::index(size_t i) const {
  const uint8_t* p = base_ + i * stride_;
  switch (component_type_) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<uint16_t>(p);
    default:
      return load<uint32_t>(p);
  }
}

}  // namespace needle::engine
