#include "haptics/sim/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "haptics/model/urdf_loader.hpp"
#include "io/strict_json.hpp"

namespace needle::haptics {
namespace {

using nlohmann::json;

// Scenario files through the project's one strict reader: "FILE: /json/pointer: what is wrong".
class ScenarioReader : io::StrictJsonReader<ScenarioError> {
 public:
  ScenarioReader(std::string file, std::filesystem::path folder)
      : StrictJsonReader(std::move(file)), folder_(std::move(folder)) {}

  Scenario scenario(const json& j) {
    object(j, "", {"name", "description", "master_urdf", "virtual_urdf", "robot_base_in_world_m", "period_s",
                   "duration_s", "master_substeps", "virtual_substeps", "q0_rad", "gains", "rigid", "tissue", "hand",
                   "sensor", "device", "energy_bound_J"});
    Scenario s;
    s.source = file_;
    s.name = string(member(j, "", "name"), "/name");
    if (j.contains("description")) string(j["description"], "/description");
    s.master = load_robot_urdf(existing_file(member(j, "", "master_urdf"), "/master_urdf", folder_).string());
    s.virt = load_robot_urdf(existing_file(member(j, "", "virtual_urdf"), "/virtual_urdf", folder_).string(), s.master.dof());
    const int n = s.master.dof();
    s.base_in_world = vec3(member(j, "", "robot_base_in_world_m"), "/robot_base_in_world_m");
    s.period_s = positive(member(j, "", "period_s"), "/period_s");
    s.duration_s = positive(member(j, "", "duration_s"), "/duration_s");
    s.master_substeps = int(whole(member(j, "", "master_substeps"), "/master_substeps", 1, 1000000));
    s.virtual_substeps = int(whole(member(j, "", "virtual_substeps"), "/virtual_substeps", 1, 1000000));
    s.q0 = vector(member(j, "", "q0_rad"), "/q0_rad", n);
    gains(member(j, "", "gains"), "/gains", n, s.gains);
    if (j.contains("rigid")) s.scene.rigid = surface(j["rigid"], "/rigid", s.base_in_world);
    if (j.contains("tissue")) s.scene.tissue = surface(j["tissue"], "/tissue", s.base_in_world);
    hand(member(j, "", "hand"), "/hand", s);
    if (j.contains("sensor")) sensor(j["sensor"], "/sensor", s.sensor);
    if (j.contains("device")) {
      object(j["device"], "/device", {"force_limit_N"});
      if (j["device"].contains("force_limit_N"))
        s.device.force_limit_N = positive(j["device"]["force_limit_N"], "/device/force_limit_N");
    }
    if (j.contains("energy_bound_J")) s.energy_bound_J = positive(j["energy_bound_J"], "/energy_bound_J");
    return s;
  }

 private:
  Eigen::Vector3d vec3(const json& v, const std::string& at) const {
    const auto a = numbers<3>(v, at);
    return {a[0], a[1], a[2]};
  }

  Eigen::VectorXd vector(const json& v, const std::string& at, int size) const {
    if (!v.is_array() || static_cast<int>(v.size()) != size)
      fail(at, "expected an array of " + std::to_string(size) + " numbers");
    Eigen::VectorXd out(size);
    for (int i = 0; i < size; ++i) out[i] = number(v[size_t(i)], at + "/" + std::to_string(i));
    return out;
  }

  void gains(const json& g, const std::string& at, int n, TeleoperationGains& out) const {
    object(g, at, {"preset", "gpm", "nonholonomic", "switch_time_s"});
    const std::string preset = string(member(g, at, "preset"), at + "/preset");
    if (preset == "thesis_holonomic") out = thesis_holonomic_gains(n);
    else if (preset == "thesis_nonholonomic") out = thesis_nonholonomic_gains(n);
    else fail(at + "/preset", "expected \"thesis_holonomic\" or \"thesis_nonholonomic\", got \"" + preset + "\"");
    if (g.contains("gpm")) {
      const json& p = g["gpm"];
      const std::string where = at + "/gpm";
      object(p, where, {"alpha", "xi", "omega"});
      out.gpm = {positive(member(p, where, "alpha"), where + "/alpha"), positive(member(p, where, "xi"), where + "/xi"),
                 positive(member(p, where, "omega"), where + "/omega")};
    }
    if (g.contains("nonholonomic")) {
      const json& p = g["nonholonomic"];
      const std::string where = at + "/nonholonomic";
      object(p, where, {"alpha", "beta"});
      out.nonholonomic = {positive(member(p, where, "alpha"), where + "/alpha"),
                          positive(member(p, where, "beta"), where + "/beta")};
    }
    if (g.contains("switch_time_s")) out.switch_time_s = positive(g["switch_time_s"], at + "/switch_time_s");
  }

  ImplicitSurface surface(const json& j, const std::string& at, const Eigen::Vector3d& base) const {
    object(j, at, {"combine", "primitives"});
    const std::string combine = j.contains("combine") ? string(j["combine"], at + "/combine") : "union";
    if (combine != "union" && combine != "intersection") fail(at + "/combine", "expected \"union\" or \"intersection\"");
    const json& list = member(j, at, "primitives");
    if (!list.is_array() || list.empty() || list.size() > static_cast<size_t>(ImplicitSurface::kMaxPrimitives))
      fail(at + "/primitives", "expected an array of 1 to " + std::to_string(ImplicitSurface::kMaxPrimitives) + " primitives");
    std::vector<SurfacePrimitive> prims;
    for (size_t i = 0; i < list.size(); ++i) prims.push_back(primitive(list[i], at + "/primitives/" + std::to_string(i), base));
    const auto mode = combine == "union" ? ImplicitSurface::Combine::Union : ImplicitSurface::Combine::Intersection;
    return ImplicitSurface(prims, mode);
  }

  SurfacePrimitive primitive(const json& e, const std::string& at, const Eigen::Vector3d& base) const {
    object(e, at, {"sphere", "plane", "capsule"});
    if (e.size() != 1) fail(at, "expected exactly one of \"sphere\", \"plane\", \"capsule\"");
    if (e.contains("sphere")) {
      const json& p = e["sphere"];
      const std::string where = at + "/sphere";
      object(p, where, {"centre", "radius"});
      return SurfacePrimitive::sphere(vec3(member(p, where, "centre"), where + "/centre") - base,
                                      positive(member(p, where, "radius"), where + "/radius"));
    }
    if (e.contains("plane")) {
      const json& p = e["plane"];
      const std::string where = at + "/plane";
      object(p, where, {"point", "normal"});
      const Eigen::Vector3d normal = vec3(member(p, where, "normal"), where + "/normal");
      if (normal.norm() < 1e-9) fail(where + "/normal", "must not be the zero vector");
      return SurfacePrimitive::plane(vec3(member(p, where, "point"), where + "/point") - base, normal);
    }
    const json& p = e["capsule"];
    const std::string where = at + "/capsule";
    object(p, where, {"a", "b", "radius"});
    return SurfacePrimitive::capsule(vec3(member(p, where, "a"), where + "/a") - base,
                                     vec3(member(p, where, "b"), where + "/b") - base,
                                     positive(member(p, where, "radius"), where + "/radius"));
  }

  void hand(const json& h, const std::string& at, Scenario& s) const {
    object(h, at, {"mass_kg", "damping_Ns_per_m", "stiffness_N_per_m", "grip_length_m", "waypoints"});
    if (h.contains("mass_kg")) s.hand.mass_kg = positive(h["mass_kg"], at + "/mass_kg");
    if (h.contains("damping_Ns_per_m")) s.hand.damping_Ns_per_m = non_negative(h["damping_Ns_per_m"], at + "/damping_Ns_per_m");
    if (h.contains("stiffness_N_per_m")) s.hand.stiffness_N_per_m = non_negative(h["stiffness_N_per_m"], at + "/stiffness_N_per_m");
    if (h.contains("grip_length_m")) s.hand.grip_length_m = positive(h["grip_length_m"], at + "/grip_length_m");
    const json& wps = member(h, at, "waypoints");
    if (!wps.is_array() || wps.empty()) fail(at + "/waypoints", "expected a non-empty array of waypoints");
    std::vector<HandWaypoint> waypoints;
    for (size_t i = 0; i < wps.size(); ++i) {
      const std::string where = at + "/waypoints/" + std::to_string(i);
      object(wps[i], where, {"t", "p", "dir"});
      waypoints.push_back({number(member(wps[i], where, "t"), where + "/t"),
                           vec3(member(wps[i], where, "p"), where + "/p") - s.base_in_world,
                           vec3(member(wps[i], where, "dir"), where + "/dir")});
    }
    try {
      s.trajectory = HandTrajectory(std::move(waypoints));
    } catch (const std::invalid_argument& e) {
      fail(at + "/waypoints", std::string("expected valid waypoints: ") + e.what());
    }
  }

  void sensor(const json& j, const std::string& at, ForceSensorParams& out) const {
    object(j, at, {"bias_N", "force_noise_N", "bandwidth_Hz", "seed"});
    if (j.contains("force_noise_N")) out.force_noise_N = non_negative(j["force_noise_N"], at + "/force_noise_N");
    if (j.contains("bandwidth_Hz")) out.bandwidth_Hz = positive(j["bandwidth_Hz"], at + "/bandwidth_Hz");
    if (j.contains("seed")) out.seed = static_cast<unsigned>(whole(j["seed"], at + "/seed", 0, 4294967295LL));
    if (j.contains("bias_N")) out.bias.head<3>() = vec3(j["bias_N"], at + "/bias_N");
  }

  std::filesystem::path folder_;
};

}  // namespace

Scenario load_scenario(const std::string& path) {
  return ScenarioReader(path, std::filesystem::path(path).parent_path())
      .scenario(io::read_json_file<ScenarioError>(path));
}

}  // namespace needle::haptics
