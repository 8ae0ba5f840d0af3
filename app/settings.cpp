#include "app/settings.hpp"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "haptics/devices/device_spec.hpp"
#include "io/file_write.hpp"
#include "io/strict_json.hpp"

namespace needle::app {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kRadPerDeg = 0.017453292519943295;

const char* section_name(const std::optional<engine::Section::Mode>& mode) {
  return !mode ? "off" : *mode == engine::Section::Mode::Cut ? "cut" : "translucent";
}

struct SettingsError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr const char* kTraineeDevices = "expected mouse, keyboard, gamepad[:N] or falcon[:N]";

class SettingsReader : io::StrictJsonReader<SettingsError> {
 public:
  using StrictJsonReader::StrictJsonReader;

  Settings settings(const json& root) const {
    object(root, "", {"version", "trainee", "device", "window", "views", "render_scale"});
    Settings s;
    if (root.contains("trainee")) s.trainee = string(root["trainee"], "/trainee");
    if (root.contains("device")) {
      const std::string text = string(root["device"], "/device");
      try {
        s.device = haptics::DeviceSpec::parse(text);
      } catch (const haptics::DeviceSpecError&) {
        fail("/device", "unknown device \"" + text + "\" (" + kTraineeDevices + ")");
      }
      if (!s.device.live()) fail("/device", "device \"" + text + "\" is no trainee's device (" + kTraineeDevices + ")");
    }
    if (root.contains("window")) {
      const json& w = root["window"];
      object(w, "/window", {"width", "height"});
      s.window.width = uint32_t(whole(member(w, "/window", "width"), "/window/width", 320, 16384));
      s.window.height = uint32_t(whole(member(w, "/window", "height"), "/window/height", 240, 16384));
    }
    if (root.contains("views")) s.views = views(root["views"]);
    if (root.contains("render_scale")) s.render_scale = render_scale(root["render_scale"]);
    return s;
  }

  std::optional<float> render_scale(const json& v) const {
    if (v.is_string() && v == "auto") return std::nullopt;
    const io::Range range{engine::kMinRenderScale, engine::kMaxRenderScale, false, ""};
    if (!v.is_number()) fail("/render_scale", "expected \"auto\" or a number in " + range.text());
    return float(in_range(v, "/render_scale", range));
  }

  ViewSettings views(const json& v) const {
    object(v, "/views", {"section", "ultrasound", "probe"});
    ViewSettings out;
    if (v.contains("section")) {
      const std::string mode = string(v["section"], "/views/section");
      if (mode == "cut")
        out.section = engine::Section::Mode::Cut;
      else if (mode == "translucent")
        out.section = engine::Section::Mode::Translucent;
      else if (mode != "off")
        fail("/views/section", "\"" + mode + "\": expected off, cut or translucent");
    }
    if (v.contains("ultrasound")) {
      if (!v["ultrasound"].is_boolean()) fail("/views/ultrasound", "expected true or false");
      out.ultrasound = v["ultrasound"].get<bool>();
    }
    if (v.contains("probe")) {
      const json& p = v["probe"];
      object(p, "/views/probe", {"along_m", "across_m", "turn_deg"});
      // A probe stays on its task's skin: a metre either way is past any task's tissue.
      if (p.contains("along_m"))
        out.probe.along_m = in_range(p["along_m"], "/views/probe/along_m", {-1.0, 1.0, false, "m"});
      if (p.contains("across_m"))
        out.probe.across_m = in_range(p["across_m"], "/views/probe/across_m", {-1.0, 1.0, false, "m"});
      if (p.contains("turn_deg"))
        out.probe.turn_rad =
            in_range(p["turn_deg"], "/views/probe/turn_deg", {-360.0, 360.0, false, "degrees"}) * kRadPerDeg;
    }
    return out;
  }

  int version(const json& root) const {
    if (!root.is_object()) fail("", "expected an object, got " + std::string(root.type_name()));
    return int(whole(member(root, "", "version"), "/version", 1, 1000000));
  }
};

std::string utc_stamp() {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", std::gmtime(&now));
  return stamp;
}

}  // namespace

fs::path default_settings_file() {
  const char* config = std::getenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  const fs::path base = config && *config ? fs::path(config)
                        : home && *home   ? fs::path(home) / ".config"
                                          : fs::path(".");
  return base / "needle-sim" / "settings.json";
}

LoadedSettings load_settings(const fs::path& file) {
  LoadedSettings loaded;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec))) return loaded;
  try {
    const SettingsReader reader(file.string());
    const json root = io::read_json_file<SettingsError>(file);
    const int version = reader.version(root);
    if (version > kSettingsVersion) {
      loaded.writable = false;
      loaded.notice = file.string() + " was written by a newer needle-sim (settings version " +
                      std::to_string(version) +
                      "): left as it is; this run starts from the defaults and does not save them";
      return loaded;
    }
    loaded.settings = reader.settings(root);
  } catch (const SettingsError& e) {
    const std::string stem = file.string() + ".damaged-" + utc_stamp();
    fs::path aside = stem;
    for (int n = 2; fs::exists(fs::symlink_status(aside, ec)); ++n) aside = stem + "_" + std::to_string(n);
    fs::rename(file, aside, ec);
    loaded.settings = Settings{};
    loaded.notice =
        ec ? std::string(e.what()) + "; it could not be set aside (" + ec.message() + "): the defaults are used"
           : std::string(e.what()) + "; the file was set aside as " + aside.string() + " and the defaults are used";
  }
  return loaded;
}

void save_settings(const fs::path& file, const Settings& settings) {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  if (ec) throw std::runtime_error(file.string() + ": cannot write: making its folder: " + ec.message());
  json j = {{"version", kSettingsVersion},
            {"device", settings.device.text()},
            {"window", {{"width", settings.window.width}, {"height", settings.window.height}}},
            {"views",
             {{"section", section_name(settings.views.section)},
              {"ultrasound", settings.views.ultrasound},
              {"probe",
               {{"along_m", settings.views.probe.along_m},
                {"across_m", settings.views.probe.across_m},
                {"turn_deg", settings.views.probe.turn_rad / kRadPerDeg}}}}}};
  if (!settings.trainee.empty()) j["trainee"] = settings.trainee;
  j["render_scale"] = settings.render_scale ? json(*settings.render_scale) : json("auto");
  io::write_file(file, j.dump(2) + "\n");
}

}  // namespace needle::app
