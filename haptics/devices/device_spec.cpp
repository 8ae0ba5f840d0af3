#include "haptics/devices/device_spec.hpp"

#include <array>

namespace needle::haptics {
namespace {

struct KindName {
  DeviceSpec::Kind kind;
  std::string_view name;
  bool takes_index;
};

constexpr std::array<KindName, 6> kKinds = {{{DeviceSpec::Kind::kSim, "sim", false},
                                             {DeviceSpec::Kind::kMouse, "mouse", false},
                                             {DeviceSpec::Kind::kKeyboard, "keyboard", false},
                                             {DeviceSpec::Kind::kGamepad, "gamepad", true},
                                             {DeviceSpec::Kind::kFalcon, "falcon", true},
                                             {DeviceSpec::Kind::kReplay, "replay", false}}};

DeviceSpecError error(std::string_view text, const std::string& what) {
  return DeviceSpecError("device '" + std::string(text) + "': " + what + " (expected " + kDeviceSpecForms + ")");
}

// "0" .. "15": digits only, no sign, no leading zero but "0".
int parse_index(std::string_view text, std::string_view digits) {
  const std::string range = "an index from 0 to " + std::to_string(kMaxDeviceIndex);
  if (digits.empty() || digits.size() > 2 || digits.find_first_not_of("0123456789") != std::string_view::npos ||
      (digits.size() > 1 && digits[0] == '0'))
    throw error(text, "expected " + range + " after ':'");
  const int index = std::stoi(std::string(digits));
  if (index > kMaxDeviceIndex) throw error(text, "expected " + range + " after ':'");
  return index;
}

}  // namespace

DeviceSpec DeviceSpec::parse(std::string_view text) {
  const size_t colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  const std::optional<std::string_view> rest =
      colon == std::string_view::npos ? std::nullopt : std::optional(text.substr(colon + 1));
  for (const KindName& k : kKinds) {
    if (name != k.name) continue;
    DeviceSpec spec;
    spec.kind = k.kind;
    if (k.kind == Kind::kReplay) {
      if (!rest || rest->empty()) throw error(text, "expected a recording file after replay:");
      spec.file = std::string(*rest);
    } else if (k.kind == Kind::kSim) {
      if (rest && rest->empty()) throw error(text, "expected a scenario file after sim:");
      if (rest) spec.file = std::string(*rest);
    } else if (rest) {
      if (!k.takes_index) throw error(text, std::string(k.name) + " takes nothing after ':'");
      spec.index = parse_index(text, *rest);
    }
    return spec;
  }
  throw error(text, text.empty() ? "empty" : "unknown device");
}

std::string DeviceSpec::text() const {
  for (const KindName& k : kKinds) {
    if (k.kind != kind) continue;
    std::string out(k.name);
    if (index) out += ":" + std::to_string(*index);
    if (!file.empty()) out += ":" + file;
    return out;
  }
  return "";
}

}  // namespace needle::haptics
