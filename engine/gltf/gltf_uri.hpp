// External glTF URIs: decoding and confinement to the asset's folder.
#pragma once

#include <filesystem>
#include <string>

namespace needle::engine {

// Percent-decodes a URI the way tinygltf does before it opens a file ('+' becomes a space),
// so that our checks see the same path tinygltf will ask for.
std::string decode_uri(const std::string& uri);

// Resolves a decoded relative path inside `folder` (canonical). Returns the canonical file
// path, or an empty path with `why` set when it is absolute, escapes the folder (after
// resolving "..", symlinks) or does not name an existing regular file.
std::filesystem::path resolve_inside(const std::filesystem::path& folder, const std::string& relative,
                                     std::string& why);

}  // namespace needle::engine
