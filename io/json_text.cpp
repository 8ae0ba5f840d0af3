#include "io/json_text.hpp"

#include <unordered_set>
#include <vector>

#include "io/input_limits.hpp"

namespace needle::io {
namespace {

using json = nlohmann::json;

// Follows nlohmann's SAX events through the document in one linear pass, keeping the open
// containers (at most kMaxNestingDepth of them) and the keys each open object has given, and
// stops at the first container past that depth or the first key given twice. nlohmann's parse
// callback cannot do this: its parser looks through a container's members each time one of them
// ends, which is quadratic in a long array of objects (a glTF of 100,000 nodes took seconds, a
// few MiB of `{}` hours). Syntax errors are left to the parse that builds the document, which
// says where.
class DocumentCheck : public nlohmann::json_sax<json> {
 public:
  // What is wrong ("" when nothing) and where.
  std::string problem;
  std::string pointer = "/";

  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool null() override { return element(); }
  bool boolean(bool) override { return element(); }
  bool number_integer(number_integer_t) override { return element(); }
  bool number_unsigned(number_unsigned_t) override { return element(); }
  bool number_float(number_float_t, const string_t&) override { return element(); }
  bool string(string_t&) override { return element(); }
  bool binary(binary_t&) override { return element(); }
  bool key(string_t& k) override {
    Container& c = open_[size_t(depth_ - 1)];
    c.key = k;
    if (c.keys.insert(k).second) return true;
    problem = "the key is given twice in its object";
    pointer = where();
    return false;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  struct Container {
    bool object = false;
    std::unordered_set<std::string> keys;  // an object's, so far
    std::string key;                       // an object's member being read
    size_t elements = 0;                   // an array's, so far
  };

  // A value begins: an array counts it as its next element.
  bool element() {
    if (depth_ > 0 && !open_[size_t(depth_ - 1)].object) ++open_[size_t(depth_ - 1)].elements;
    return true;
  }
  bool open(bool object) {
    element();
    if (depth_ == kMaxNestingDepth) {
      problem = "nested deeper than " + std::to_string(kMaxNestingDepth) + " levels";
      return false;
    }
    if (open_.size() <= size_t(depth_)) open_.emplace_back();
    Container& c = open_[size_t(depth_++)];  // reused: its set keeps its buckets
    c.object = object;
    c.keys.clear();
    c.elements = 0;
    return true;
  }
  bool close() {
    --depth_;
    return true;
  }
  // The pointer of the member or element being read in the innermost container.
  std::string where() const {
    json::json_pointer p;
    for (int d = 0; d < depth_; ++d) {
      const Container& c = open_[size_t(d)];
      p = c.object ? p / c.key : p / (c.elements - 1);
    }
    return p.to_string();
  }

  std::vector<Container> open_;
  int depth_ = 0;
};

}  // namespace

json parse_json_text(const std::string& text) {
  DocumentCheck check;
  json::sax_parse(text, &check);
  if (!check.problem.empty()) throw JsonTextError(check.pointer, check.problem);
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    throw JsonTextError("/", std::string("not valid JSON: ") + e.what());
  }
}

}  // namespace needle::io
