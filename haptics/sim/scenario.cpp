#include "haptics/sim/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "haptics/model/urdf_loader.hpp"

namespace needle::haptics {
namespace {

using nlohmann::json;

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& expected) const {
    throw ScenarioError(source_ + ": key '" + key + "': expected " + expected);
  }
  const json& at(const json& j, const std::string& key, const std::string& path) const {
    if (!j.is_object() || !j.contains(key)) fail(path + key, "to be present");
    return j.at(key);
  }
  double number(const json& j, const std::string& key, const std::string& path) const {
    const json& v = at(j, key, path);
    if (!v.is_number()) fail(path + key, "a number");
    return v.get<double>();
  }
  double number_or(const json& j, const std::string& key, double fallback, const std::string& path) const {
    return j.contains(key) ? number(j, key, path) : fallback;
  }
  double positive(const json& j, const std::string& key, const std::string& path) const {
    const double v = number(j, key, path);
    if (!(v > 0.0)) fail(path + key, "a positive number");
    return v;
  }
  Eigen::VectorXd numbers(const json& j, const std::string& key, int size, const std::string& path) const {
    const json& v = at(j, key, path);
    if (!v.is_array() || (size >= 0 && static_cast<int>(v.size()) != size))
      fail(path + key, size >= 0 ? "an array of " + std::to_string(size) + " numbers" : "an array of numbers");
    Eigen::VectorXd out(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
      if (!v[i].is_number()) fail(path + key, "numbers only");
      out[static_cast<Eigen::Index>(i)] = v[i].get<double>();
    }
    return out;
  }
  int count(const json& j, const std::string& key, const std::string& path) const {
    const double v = number(j, key, path);
    if (!(v >= 1.0) || v != std::floor(v) || v > 1e6) fail(path + key, "a whole number from 1 to 1000000");
    return static_cast<int>(v);
  }
  Eigen::Vector3d vec3(const json& j, const std::string& key, const std::string& path) const { return numbers(j, key, 3, path); }

 private:
  std::string source_;
};

ImplicitSurface read_surface(const Reader& r, const json& j, const std::string& path, const Eigen::Vector3d& base) {
  const std::string combine = j.value("combine", "union");
  if (combine != "union" && combine != "intersection") r.fail(path + "combine", "\"union\" or \"intersection\"");
  const json& list = r.at(j, "primitives", path);
  if (!list.is_array() || list.empty() || list.size() > static_cast<size_t>(ImplicitSurface::kMaxPrimitives))
    r.fail(path + "primitives", "an array of 1 to " + std::to_string(ImplicitSurface::kMaxPrimitives) + " primitives");
  std::vector<SurfacePrimitive> prims;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string p = path + "primitives[" + std::to_string(i) + "].";
    const json& e = list[i];
    if (e.contains("sphere")) {
      prims.push_back(SurfacePrimitive::sphere(r.vec3(e["sphere"], "centre", p + "sphere.") - base, r.positive(e["sphere"], "radius", p + "sphere.")));
    } else if (e.contains("plane")) {
      prims.push_back(SurfacePrimitive::plane(r.vec3(e["plane"], "point", p + "plane.") - base, r.vec3(e["plane"], "normal", p + "plane.")));
    } else if (e.contains("capsule")) {
      const json& c = e["capsule"];
      prims.push_back(SurfacePrimitive::capsule(r.vec3(c, "a", p + "capsule.") - base, r.vec3(c, "b", p + "capsule."), r.positive(c, "radius", p + "capsule.")));
      prims.back().b -= base;
    } else {
      r.fail(p.substr(0, p.size() - 1), "one of \"sphere\", \"plane\", \"capsule\"");
    }
  }
  const auto mode = combine == "union" ? ImplicitSurface::Combine::Union : ImplicitSurface::Combine::Intersection;
  return ImplicitSurface(prims, mode);
}

}  // namespace

Scenario load_scenario(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ScenarioError(path + ": cannot open");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw ScenarioError(path + ": not valid JSON (" + e.what() + ")");
  }
  const Reader r(path);
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  Scenario s;
  s.source = path;
  if (!r.at(j, "name", "").is_string()) r.fail("name", "a string");
  s.name = j["name"].get<std::string>();
  auto urdf = [&](const std::string& key) {
    const json& v = r.at(j, key, "");
    if (!v.is_string()) r.fail(key, "a path (relative to the scenario file)");
    return (dir / v.get<std::string>()).string();
  };
  s.master = load_robot_urdf(urdf("master_urdf"));
  s.virt = load_robot_urdf(urdf("virtual_urdf"), s.master.dof());
  const int n = s.master.dof();
  s.base_in_world = r.vec3(j, "robot_base_in_world_m", "");
  s.period_s = r.positive(j, "period_s", "");
  s.duration_s = r.positive(j, "duration_s", "");
  s.master_substeps = r.count(j, "master_substeps", "");
  s.virtual_substeps = r.count(j, "virtual_substeps", "");
  s.q0 = r.numbers(j, "q0_rad", n, "");

  const json& g = r.at(j, "gains", "");
  if (!r.at(g, "preset", "gains.").is_string()) r.fail("gains.preset", "a string");
  const std::string preset = g["preset"].get<std::string>();
  if (preset == "thesis_holonomic") s.gains = thesis_holonomic_gains(n);
  else if (preset == "thesis_nonholonomic") s.gains = thesis_nonholonomic_gains(n);
  else r.fail("gains.preset", "\"thesis_holonomic\" or \"thesis_nonholonomic\"");
  if (g.contains("gpm")) {
    s.gains.gpm = {r.positive(g["gpm"], "alpha", "gains.gpm."), r.positive(g["gpm"], "xi", "gains.gpm."), r.positive(g["gpm"], "omega", "gains.gpm.")};
  }
  if (g.contains("nonholonomic")) {
    s.gains.nonholonomic = {r.positive(g["nonholonomic"], "alpha", "gains.nonholonomic."), r.positive(g["nonholonomic"], "beta", "gains.nonholonomic.")};
  }
  s.gains.switch_time_s = r.number_or(g, "switch_time_s", s.gains.switch_time_s, "gains.");

  if (j.contains("rigid")) s.scene.rigid = read_surface(r, j["rigid"], "rigid.", s.base_in_world);
  if (j.contains("tissue")) s.scene.tissue = read_surface(r, j["tissue"], "tissue.", s.base_in_world);

  const json& hand = r.at(j, "hand", "");
  s.hand.mass_kg = r.number_or(hand, "mass_kg", s.hand.mass_kg, "hand.");
  s.hand.damping_Ns_per_m = r.number_or(hand, "damping_Ns_per_m", s.hand.damping_Ns_per_m, "hand.");
  s.hand.stiffness_N_per_m = r.number_or(hand, "stiffness_N_per_m", s.hand.stiffness_N_per_m, "hand.");
  s.hand.grip_length_m = r.number_or(hand, "grip_length_m", s.hand.grip_length_m, "hand.");
  const json& wps = r.at(hand, "waypoints", "hand.");
  if (!wps.is_array() || wps.empty()) r.fail("hand.waypoints", "a non-empty array");
  std::vector<HandWaypoint> waypoints;
  for (size_t i = 0; i < wps.size(); ++i) {
    const std::string p = "hand.waypoints[" + std::to_string(i) + "].";
    waypoints.push_back({r.number(wps[i], "t", p), r.vec3(wps[i], "p", p) - s.base_in_world, r.vec3(wps[i], "dir", p)});
  }
  try {
    s.trajectory = HandTrajectory(std::move(waypoints));
  } catch (const std::invalid_argument& e) {
    r.fail("hand.waypoints", std::string("valid waypoints: ") + e.what());
  }
  if (j.contains("sensor")) {
    const json& sj = j["sensor"];
    s.sensor.force_noise_N = r.number_or(sj, "force_noise_N", s.sensor.force_noise_N, "sensor.");
    s.sensor.bandwidth_Hz = r.number_or(sj, "bandwidth_Hz", s.sensor.bandwidth_Hz, "sensor.");
    s.sensor.seed = static_cast<unsigned>(r.number_or(sj, "seed", s.sensor.seed, "sensor."));
    if (sj.contains("bias_N")) s.sensor.bias.head<3>() = r.vec3(sj, "bias_N", "sensor.");
  }
  if (j.contains("device")) s.device.force_limit_N = r.number_or(j["device"], "force_limit_N", s.device.force_limit_N, "device.");
  s.energy_bound_J = r.number_or(j, "energy_bound_J", s.energy_bound_J, "");
  return s;
}

}  // namespace needle::haptics
