// load_gltf: reads a .gltf/.glb file, checks everything tinygltf would read blindly (GLB chunk
// layout, external URIs, buffer sizes), lets tinygltf parse it through guarded file callbacks,
// then converts it with convert_gltf.
#include "engine/gltf_loader.hpp"

#include <tiny_gltf.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "engine/gltf/gltf_errors.hpp"
#include "engine/gltf/gltf_uri.hpp"
#include "engine/gltf/image_decode.hpp"
#include "io/strict_json.hpp"

namespace needle::engine {
namespace fs = std::filesystem;
namespace {

bool read_bytes(const fs::path& path, std::vector<unsigned char>& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

uint32_t le32(const std::vector<unsigned char>& b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}

// The GLB container (header, JSON chunk, optional BIN chunk) checked in full: tinygltf 2.7
// forgets the BIN chunk's 8-byte header when it compares the chunk length with the file length.
std::string glb_json(const std::vector<unsigned char>& bytes, const std::string& file) {
  const uint64_t size = bytes.size();
  if (size < 20)
    asset_fail(file, "GLB header", "file has " + std::to_string(size) + " bytes, less than the 20-byte header");
  if (le32(bytes, 4) != 2) asset_fail(file, "GLB header", "version " + std::to_string(le32(bytes, 4)) + ", expected 2");
  const uint64_t length = le32(bytes, 8);
  if (length > size)
    asset_fail(file, "GLB header",
               "length " + std::to_string(length) + " exceeds the file's " + std::to_string(size) + " bytes");
  const uint64_t json_length = le32(bytes, 12);
  if (le32(bytes, 16) != 0x4E4F534Au || json_length == 0 || 20 + json_length > length)
    asset_fail(file, "GLB JSON chunk",
               "missing, empty or longer than the file (" + std::to_string(json_length) + " bytes)");
  const uint64_t bin_at = 20 + json_length;
  if (bin_at < length) {
    if (bin_at + 8 > length) asset_fail(file, "GLB BIN chunk", "truncated chunk header");
    const uint64_t bin_length = le32(bytes, bin_at);
    if (le32(bytes, bin_at + 4) != 0x004E4942u) asset_fail(file, "GLB BIN chunk", "chunk type is not BIN");
    if (bin_at + 8 + bin_length > length)
      asset_fail(file, "GLB BIN chunk", "length " + std::to_string(bin_length) + " runs past the end of the file");
  }
  return std::string(bytes.begin() + 20, bytes.begin() + static_cast<std::ptrdiff_t>(bin_at));
}

// Bytes held by a base64 data URI, from its length and padding.
uint64_t data_uri_bytes(const std::string& uri) {
  const size_t comma = uri.find(',');
  const size_t n = comma == std::string::npos ? 0 : uri.size() - comma - 1;
  const size_t padding = n >= 2 && uri[uri.size() - 2] == '=' ? 2 : n >= 1 && uri.back() == '=' ? 1 : 0;
  return n % 4 == 0 ? n / 4 * 3 - padding : n * 3 / 4;  // the latter: unpadded base64
}

// The document's nesting depth and every buffer and image URI checked before tinygltf touches any
// file: confined to the asset's folder, existing, and for buffers exactly byteLength bytes long.
void check_uris(const std::string& json_text, const fs::path& folder, const std::string& file) {
  nlohmann::json root;
  try {
    root = io::parse_json_text(json_text);  // nested at most io::kMaxNestingDepth: tinygltf recurses once a level
  } catch (const io::JsonTextError& e) {
    asset_fail(file, "JSON", e.located());
  }
  if (!root.is_object()) asset_fail(file, "JSON", "the top level is not an object");
  for (const char* array : {"buffers", "images"}) {
    const auto it = root.find(array);
    if (it == root.end() || !it->is_array()) continue;
    for (size_t i = 0; i < it->size(); ++i) {
      const nlohmann::json& element = (*it)[i];
      if (!element.is_object() || !element.contains("uri") || !element["uri"].is_string()) continue;
      const std::string uri = element["uri"];
      const std::string name = element_name(array, i);
      const bool is_buffer = array == std::string("buffers");
      const nlohmann::json length = element.value("byteLength", nlohmann::json());
      uint64_t actual = 0;
      if (uri.rfind("data:", 0) == 0) {
        actual = data_uri_bytes(uri);
      } else {
        std::string why;
        const fs::path path = resolve_inside(folder, decode_uri(uri), why);
        if (path.empty()) asset_fail(file, name, "uri \"" + uri + "\" " + why);
        actual = fs::file_size(path);
      }
      if (is_buffer && length.is_number_unsigned() && length.get<uint64_t>() != actual)
        asset_fail(file, name,
                   "byteLength " + std::to_string(length.get<uint64_t>()) + " but uri \"" + uri.substr(0, 64) +
                       "\" holds " + std::to_string(actual) + " bytes");
    }
  }
}

// tinygltf's file access, confined to the asset's folder whatever the file asks for.
struct FolderGuard {
  std::string base_dir;  // as passed to tinygltf, which joins it with each decoded URI
  fs::path folder;       // canonical
};

fs::path guarded_path(const std::string& path, void* user) {
  const auto* guard = static_cast<const FolderGuard*>(user);
  const std::string prefix = guard->base_dir + "/";
  // Anything not below base_dir (tinygltf also tries the working directory) is refused.
  if (path.rfind(prefix, 0) != 0) return {};
  std::string why;
  return resolve_inside(guard->folder, path.substr(prefix.size()), why);
}

bool guarded_exists(const std::string& path, void* user) { return !guarded_path(path, user).empty(); }

// No ~ or $VAR expansion (tinygltf's default runs wordexp on the URI).
std::string no_expansion(const std::string& path, void*) { return path; }

bool guarded_read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const fs::path resolved = guarded_path(path, user);
  if (!resolved.empty() && read_bytes(resolved, *out)) return true;
  if (err) *err = "refused or unreadable: " + path;
  return false;
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err = "the loader never writes files";
  return false;
}

// Images in a bufferView are decoded by convert_gltf once the bufferView is bounds-checked:
// tinygltf 2.7 hands them over without checking the bufferView against its buffer.
bool decode_or_defer(tinygltf::Image* image, int index, std::string* err, std::string* warn, int, int,
                     const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0) return true;
  return decode_image(image, index, err, warn, bytes, size);
}

std::string first_line(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return line.size() > 300 ? line.substr(0, 300) + "..." : line;
}

}  // namespace

Model load_gltf(const fs::path& file) {
  const std::string name = file.string();
  std::vector<unsigned char> bytes;
  if (!fs::is_regular_file(file) || !read_bytes(file, bytes)) asset_fail(name, "file", "not found or not readable");
  if (bytes.size() > UINT32_MAX) asset_fail(name, "file", "larger than the 4 GiB glTF limit");
  const bool binary = bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
  const fs::path folder = fs::canonical(fs::absolute(file).parent_path());
  check_uris(binary ? glb_json(bytes, name) : std::string(bytes.begin(), bytes.end()), folder, name);

  FolderGuard guard{folder.string(), folder};
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&guarded_exists, &no_expansion, &guarded_read, &refuse_write, &guard});
  loader.SetImageLoader(&decode_or_defer, nullptr);
  tinygltf::Model gltf;
  std::string err, warn;
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()),
                                              guard.base_dir)
                : loader.LoadASCIIFromString(&gltf, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                             static_cast<unsigned>(bytes.size()), guard.base_dir);
  } catch (const std::exception& e) {
    asset_fail(name, "glTF", e.what());
  }
  if (!ok) asset_fail(name, "glTF", first_line(err.empty() ? warn : err));
  return convert_gltf(gltf, name);
}

}  // namespace needle::engine
