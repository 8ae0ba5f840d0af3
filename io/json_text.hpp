// A JSON document's text read into a value, refused before it is built when it is nested deeper
// than kMaxNestingDepth (io/input_limits.hpp) or gives a key twice in one object: nlohmann's parser
// keeps the last of two equal keys, and a file that sets a value twice would silently lose one
// (RFC 8259 leaves what a reader does with them open).
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>

namespace needle::io {

// A JSON document that cannot be read: what() says why ("not valid JSON: ...", "nested deeper
// than 64 levels", "the key is given twice in its object"), `pointer` where (a JSON pointer; "/"
// for the whole document).
struct JsonTextError : std::runtime_error {
  JsonTextError(std::string at, const std::string& what) : std::runtime_error(what), pointer(std::move(at)) {}
  std::string pointer;
  // "POINTER: what", or what alone where it is the whole document.
  std::string located() const { return pointer == "/" ? what() : pointer + ": " + what(); }
};

// The document in `text`. Throws JsonTextError.
nlohmann::json parse_json_text(const std::string& text);

}  // namespace needle::io
