#include "haptics/sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>

#include "haptics/anatomy/patient_cache.hpp"
#include "haptics/model/urdf_loader.hpp"
#include "haptics/sim/scenario_limits.hpp"
#include "haptics/sim/syringe_reader.hpp"
#include "io/input_limits.hpp"
#include "io/strict_json.hpp"

namespace needle::haptics {
namespace {

using nlohmann::json;

// The keys of a layer's parameters (every mechanical number, "rigid", "ultrasound" and "injection")
// after `first`.
std::vector<const char*> with_mechanics_keys(std::vector<const char*> first) {
  for (const auto& f : kMechanicsFields) first.push_back(f.key);
  first.push_back("rigid");
  first.push_back("ultrasound");
  first.push_back("injection");
  return first;
}

// A layer's parameters: its mechanics and, when given, what it is to ultrasound and to injection.
struct LayerParameters {
  LayerMechanics mechanics;
  std::optional<LayerAcoustics> acoustics;
  std::optional<LayerInjection> injection;
};

// A layer's mechanical parameters: inline in a scenario (each a number, or {value, source}) or a
// parameter set file (assets/tissues/*.json), where every parameter is {value, source} and the
// source cites one of the file's `references` ("key: where in it") or reads "design value: why".
class MechanicsReader : io::StrictJsonReader<ScenarioError> {
 public:
  using StrictJsonReader::StrictJsonReader;

  // `references` is the file's references object, or nullptr inline (sources optional there).
  LayerMechanics mechanics(const json& j, const std::string& at, const json* references) {
    LayerMechanics m;
    for (const auto& f : kMechanicsFields)
      if (j.contains(f.key))
        m.*f.member = non_negative(value(j[f.key], at + "/" + f.key, references), pointer_to(at, f.key, j[f.key]));
    if (j.contains("rigid")) {
      const json& rigid = value(j["rigid"], at + "/rigid", references);
      if (!rigid.is_boolean()) fail(pointer_to(at, "rigid", j["rigid"]), "expected true or false");
      m.rigid = rigid.get<bool>();
    }
    if (const auto problem = mechanics_problem(m))
      fail(pointer_to(at, problem->key, j.value(problem->key, json())), problem->what);
    return m;
  }

  // The `ultrasound` block, when there is one: every key of kAcousticsFields, numbers as above.
  std::optional<LayerAcoustics> acoustics(const json& j, const std::string& at, const json* references) {
    return field_block(j, at, references, "ultrasound", kAcousticsFields, acoustics_problem);
  }

  // The `injection` block, when there is one: every key of kInjectionFields, numbers as above.
  std::optional<LayerInjection> injection(const json& j, const std::string& at, const json* references) {
    return field_block(j, at, references, "injection", kInjectionFields, injection_problem);
  }

  LayerParameters parameter_set(const json& j) {
    object(j, "", with_mechanics_keys({"tissue", "description", "references"}));
    string(member(j, "", "tissue"), "/tissue");
    string(member(j, "", "description"), "/description");
    const json& references = member(j, "", "references");
    if (!references.is_object()) fail("/references", "expected an object of citations");
    const bool rigid = j.contains("rigid");
    const std::vector<const char*> required =
        rigid ? std::vector<const char*>{"rigid"}
              : std::vector<const char*>{"stiffness_N_per_m", "puncture_force_N", "cutting_force_N", "friction_N_per_m",
                                         "static_friction_N_per_m"};
    for (const char* key : required) member(j, "", key);
    const LayerParameters p{mechanics(j, "", &references), acoustics(j, "", &references),
                            injection(j, "", &references)};
    for (const auto& item : references.items()) {
      const std::string& key = item.key();  // not a structured binding: clang before 16 cannot capture one
      string(item.value(), "/references/" + key);
      if (std::none_of(sources_.begin(), sources_.end(),
                       [&](const std::string& s) { return s.find(key) != std::string::npos; }))
        fail("/references/" + key, "not cited by any parameter's source");
    }
    return p;
  }

 private:
  // The block `name` of `j`, when there is one: every key of `fields`, each a number as above, the
  // whole checked by `problem`.
  template <class Set, size_t N>
  std::optional<Set> field_block(const json& j, const std::string& at, const json* references, const char* name,
                                 const ParameterField<Set> (&fields)[N],
                                 std::optional<MechanicsProblem> (*problem)(const Set&)) {
    if (!j.contains(name)) return std::nullopt;
    const json& block = j[name];
    const std::string where = at + "/" + name;
    std::vector<const char*> keys;
    for (const auto& f : fields) keys.push_back(f.key);
    object(block, where, keys);
    Set set;
    for (const auto& f : fields)
      set.*f.member = number(value(member(block, where, f.key), where + "/" + f.key, references),
                             pointer_to(where, f.key, block[f.key]));
    if (const auto p = problem(set)) fail(pointer_to(where, p->key, block[p->key]), p->what);
    return set;
  }

  // Where a parameter's number sits: the key itself, or its "value" when given with a source.
  static std::string pointer_to(const std::string& at, const std::string& key, const json& given) {
    return at + "/" + key + (given.is_object() ? "/value" : "");
  }

  // A parameter's value: a bare value (inline only) or {value, source}.
  const json& value(const json& given, const std::string& at, const json* references) {
    if (!given.is_object()) {
      if (references)
        fail(at, "expected {\"value\": ..., \"source\": \"...\"}: every number in a parameter set carries its source");
      return given;
    }
    object(given, at, {"value", "source"});
    const std::string source = string(member(given, at, "source"), at + "/source");
    const std::string cited = source.substr(0, source.find(':'));
    const bool design = cited == "design value";
    if (source.find(':') == std::string::npos || source.find_first_not_of(' ', cited.size() + 1) == std::string::npos)
      fail(at + "/source", "expected \"design value: why\" or \"<reference>: where in it\"");
    if (!design && references && !references->contains(cited))
      fail(at + "/source", "cites \"" + cited + "\", which is not in /references");
    sources_.push_back(source);
    return member(given, at, "value");
  }

  std::vector<std::string> sources_;  // every source read, for the references' check
};

// Scenario files through the project's one strict reader: "FILE: /json/pointer: what is wrong".
class ScenarioReader : io::StrictJsonReader<ScenarioError> {
 public:
  ScenarioReader(std::string file, std::filesystem::path folder, bool generate_patient)
      : StrictJsonReader(std::move(file)), folder_(std::move(folder)), generate_patient_(generate_patient) {}

  Scenario scenario(const json& j) {
    object(j, "",
           {"name", "description", "master_urdf", "virtual_urdf", "robot_base_in_world_m", "period_s", "duration_s",
            "master_substeps", "virtual_substeps", "q0_rad", "gains", "tool", "rigid", "tissue", "hand", "sensor",
            "device", "energy_bound_J", "syringe"});
    Scenario s;
    s.source = file_;
    s.name = string(member(j, "", "name"), "/name");
    if (j.contains("description")) string(j["description"], "/description");
    s.master = load_robot_urdf(existing_file(member(j, "", "master_urdf"), "/master_urdf", folder_).string());
    s.virt = load_robot_urdf(existing_file(member(j, "", "virtual_urdf"), "/virtual_urdf", folder_).string(),
                             s.master.dof());
    const int n = s.master.dof();
    s.base_in_world = point(member(j, "", "robot_base_in_world_m"), "/robot_base_in_world_m");
    s.period_s = in_range(member(j, "", "period_s"), "/period_s", limits::kPeriod);
    s.duration_s = in_range(member(j, "", "duration_s"), "/duration_s", io::kSessionDurationRange);
    s.master_substeps = int(whole(member(j, "", "master_substeps"), "/master_substeps", 1, limits::kMaxSubsteps));
    s.virtual_substeps = int(whole(member(j, "", "virtual_substeps"), "/virtual_substeps", 1, limits::kMaxSubsteps));
    s.q0 = vector(member(j, "", "q0_rad"), "/q0_rad", n, limits::kJointAngle);
    gains(member(j, "", "gains"), "/gains", n, s.gains);
    if (j.contains("tool")) tool(j["tool"], "/tool", s.gains.tool);
    if (j.contains("rigid")) {
      const Primitives rigid = surface(j["rigid"], "/rigid", s.base_in_world);
      s.scene.rigid = ImplicitSurface(rigid.list, rigid.combine);
    }
    if (j.contains("tissue")) tissue(j["tissue"], "/tissue", s);
    if (j.contains("syringe")) s.syringe = read_syringe(j["syringe"], file_, "/syringe", s.scene.tissue);
    hand(member(j, "", "hand"), "/hand", s);
    if (j.contains("sensor")) sensor(j["sensor"], "/sensor", s.sensor);
    if (j.contains("device")) {
      object(j["device"], "/device", {"force_limit_N"});
      if (j["device"].contains("force_limit_N"))
        s.device.force_limit_N =
            in_range(j["device"]["force_limit_N"], "/device/force_limit_N", limits::kDeviceForceLimit);
    }
    if (j.contains("energy_bound_J"))
      s.energy_bound_J = in_range(j["energy_bound_J"], "/energy_bound_J", limits::kEnergyBound);
    return s;
  }

 private:
  // A position in the world (io::kWorldCoordinateRange).
  Eigen::Vector3d point(const json& v, const std::string& at) const {
    const auto a = position(v, at);
    return {a[0], a[1], a[2]};
  }

  // A direction as given, not the zero vector (io::kDirectionComponentRange).
  Eigen::Vector3d way(const json& v, const std::string& at) const {
    const auto a = direction(v, at);
    return {a[0], a[1], a[2]};
  }

  Eigen::VectorXd vector(const json& v, const std::string& at, int size, const io::Range& range) const {
    if (!v.is_array() || static_cast<int>(v.size()) != size)
      fail(at, "expected an array of " + std::to_string(size) + " numbers");
    Eigen::VectorXd out(size);
    for (int i = 0; i < size; ++i) out[i] = in_range(v[size_t(i)], at + "/" + std::to_string(i), range);
    return out;
  }

  void gains(const json& g, const std::string& at, int n, TeleoperationGains& out) const {
    object(g, at,
           {"preset", "law", "gpm", "nonholonomic", "switch_time_s", "force_scale", "lateral_damping_Ns_per_m",
            "lateral_stiffness_N_per_m", "axial_damping_Ns_per_m", "axial_stiffness_N_per_m",
            "passivity_max_damping_per_tick"});
    const std::string preset = string(member(g, at, "preset"), at + "/preset");
    if (preset == "thesis_holonomic")
      out = thesis_holonomic_gains(n);
    else if (preset == "thesis_nonholonomic")
      out = thesis_nonholonomic_gains(n);
    else
      fail(at + "/preset", "expected \"thesis_holonomic\" or \"thesis_nonholonomic\", got \"" + preset + "\"");
    if (g.contains("gpm")) {
      const json& p = g["gpm"];
      const std::string where = at + "/gpm";
      object(p, where, {"alpha", "xi", "omega"});
      out.gpm = {in_range(member(p, where, "alpha"), where + "/alpha", limits::kGpmAlpha),
                 in_range(member(p, where, "xi"), where + "/xi", limits::kGpmXi),
                 in_range(member(p, where, "omega"), where + "/omega", limits::kGpmOmega)};
    }
    if (g.contains("nonholonomic")) {
      const json& p = g["nonholonomic"];
      const std::string where = at + "/nonholonomic";
      object(p, where, {"alpha", "beta"});
      out.nonholonomic = {in_range(member(p, where, "alpha"), where + "/alpha", limits::kNonholonomicAlpha),
                          in_range(member(p, where, "beta"), where + "/beta", limits::kNonholonomicBeta)};
    }
    if (g.contains("switch_time_s"))
      out.switch_time_s = in_range(g["switch_time_s"], at + "/switch_time_s", limits::kSwitchTime);
    if (g.contains("law")) {
      const std::string law = string(g["law"], at + "/law");
      const auto named = control_law_named(law);
      if (!named) fail(at + "/law", "expected \"tool\" or \"thesis\", got \"" + law + "\"");
      out.law = *named;
    }
    if (g.contains("force_scale"))
      out.force_scale = in_range(g["force_scale"], at + "/force_scale", limits::kForceScale);
    const std::tuple<const char*, double*, const io::Range&> springs[] = {
        {"axial_damping_Ns_per_m", &out.axial_damping_Ns_per_m, limits::kToolDamping},
        {"lateral_damping_Ns_per_m", &out.lateral_damping_Ns_per_m, limits::kToolDamping},
        {"lateral_stiffness_N_per_m", &out.lateral_stiffness_N_per_m, limits::kToolStiffness},
        {"axial_stiffness_N_per_m", &out.axial_stiffness_N_per_m, limits::kToolStiffness}};
    for (const auto& [key, field, range] : springs)
      if (g.contains(key)) *field = in_range(g[key], at + "/" + key, range);
    if (g.contains("passivity_max_damping_per_tick"))
      out.passivity.max_damping_per_tick =
          in_range(g["passivity_max_damping_per_tick"], at + "/passivity_max_damping_per_tick",
                   limits::kPassivityDampingPerTick);
  }

  void tool(const json& t, const std::string& at, Tool& out) const {
    object(t, at, {"name", "mass_kg"});
    if (t.contains("name")) out.name = string(t["name"], at + "/name");
    if (t.contains("mass_kg")) out.mass_kg = in_range(t["mass_kg"], at + "/mass_kg", limits::kToolMass);
  }

  struct Primitives {
    std::vector<SurfacePrimitive> list;
    ImplicitSurface::Combine combine;
  };

  Primitives surface(const json& j, const std::string& at, const Eigen::Vector3d& base) const {
    object(j, at, {"combine", "primitives"});
    const std::string combine = j.contains("combine") ? string(j["combine"], at + "/combine") : "union";
    if (combine != "union" && combine != "intersection")
      fail(at + "/combine", "expected \"union\" or \"intersection\"");
    const json& list = member(j, at, "primitives");
    if (!list.is_array() || list.empty() || list.size() > static_cast<size_t>(ImplicitSurface::kMaxPrimitives))
      fail(at + "/primitives",
           "expected an array of 1 to " + std::to_string(ImplicitSurface::kMaxPrimitives) + " primitives");
    Primitives out{{}, combine == "union" ? ImplicitSurface::Combine::Union : ImplicitSurface::Combine::Intersection};
    for (size_t i = 0; i < list.size(); ++i)
      out.list.push_back(primitive(list[i], at + "/primitives/" + std::to_string(i), base));
    return out;
  }

  // The scenario's tissue: {layers: [...], stick}, {patient, entry, tissues, stick} or the
  // single-surface form {combine, primitives}.
  void tissue(const json& j, const std::string& at, Scenario& s) const {
    if (j.is_object() && j.contains("patient")) return patient_tissue(j, at, s);
    if (!j.is_object() || !j.contains("layers")) {
      const Primitives single = surface(j, at, s.base_in_world);
      s.scene.tissue = TissueModel::single_surface(LayerShape::of_surface(single.list, single.combine));
      return;
    }
    object(j, at, {"layers", "stick"});
    const StickParams stick = stick_params(j, at);
    const json& list = member(j, at, "layers");
    const std::string where = at + "/layers";
    if (!list.is_array() || list.empty() || list.size() > size_t(TissueModel::kMaxLayers))
      fail(where, "expected an array of 1 to " + std::to_string(TissueModel::kMaxLayers) + " layers");
    std::vector<TissueLayer> layers;
    for (size_t i = 0; i < list.size(); ++i)
      layers.push_back(layer(list[i], where + "/" + std::to_string(i), s.base_in_world));
    try {
      s.scene.tissue = TissueModel(std::move(layers), stick);
    } catch (const TissueLayerError& e) {
      fail(where + "/" + std::to_string(e.layer) + "/" + e.key, e.what());
    }
  }

  StickParams stick_params(const json& j, const std::string& at) const {
    StickParams stick;
    if (j.contains("stick")) {
      const json& p = j["stick"];
      const std::string where = at + "/stick";
      object(p, where, {"stiffness_N_per_m", "band_mps"});
      if (p.contains("stiffness_N_per_m"))
        stick.stiffness_N_per_m =
            in_range(p["stiffness_N_per_m"], where + "/stiffness_N_per_m", limits::kStickStiffness);
      if (p.contains("band_mps")) stick.band_mps = in_range(p["band_mps"], where + "/band_mps", limits::kStickBand);
    }
    return stick;
  }

  // A generated patient (docs/PATIENTS.md): `patient` a patient file or its object inline, `entry`
  // where the skin over L3–L4 on the midline lies (world), `tissues` the folder of the layers'
  // parameter sets (default: the `tissues` folder beside the scenario's folder), `stick` optional.
  void patient_tissue(const json& j, const std::string& at, Scenario& s) const {
    object(j, at, {"patient", "entry", "tissues", "stick"});
    const json& given = j["patient"];
    anatomy::PatientParams params;
    try {
      params = given.is_object() ? anatomy::read_patient(given, file_, at + "/patient")
                                 : anatomy::load_patient(existing_file(given, at + "/patient", folder_).string());
    } catch (const anatomy::PatientError& e) {
      throw ScenarioError(e.what());
    }
    const std::array<double, 3> entry = position(member(j, at, "entry"), at + "/entry");
    const std::filesystem::path tissues =
        j.contains("tissues") ? folder_ / string(j["tissues"], at + "/tissues") : folder_ / ".." / "tissues";
    if (!std::filesystem::is_directory(tissues)) fail(at + "/tissues", "folder not found: " + tissues.string());
    const StickParams stick = stick_params(j, at);
    std::map<std::string, LayerParameters> sets;
    for (const anatomy::PatientLayerSpec& l : anatomy::kPatientLayers) {
      if (!sets.count(l.parameters)) {
        const std::string set = (tissues / (std::string(l.parameters) + ".json")).string();
        if (!std::filesystem::is_regular_file(set))
          fail(at + "/tissues", "no parameter set " + set + " for the layer \"" + l.name + "\"");
        sets.emplace(l.parameters, MechanicsReader(set).parameter_set(io::read_json_file<ScenarioError>(set)));
      }
      s.patient_layers.push_back({l.name, sets.at(l.parameters).mechanics, sets.at(l.parameters).injection});
    }
    if (!generate_patient_) return;
    s.patient = anatomy::shared_patient(params, Eigen::Vector3d(entry[0], entry[1], entry[2]) - s.base_in_world);
    std::vector<TissueLayer> layers;
    for (const anatomy::PatientLayer& l : s.patient->layers) {
      const LayerParameters& set = sets.at(l.parameters);
      layers.push_back({l.name, l.shape, set.mechanics, set.acoustics, set.injection});
    }
    try {
      s.scene.tissue = TissueModel(std::move(layers), stick);
    } catch (const TissueLayerError& e) {
      fail(at + "/patient",
           std::string("the generated layer ") + std::to_string(e.layer) + " (" + e.key + "): " + e.what());
    }
  }

  TissueLayer layer(const json& l, const std::string& at, const Eigen::Vector3d& base) const {
    object(l, at, with_mechanics_keys({"name", "shape", "parameters"}));
    TissueLayer layer{
        string(member(l, at, "name"), at + "/name"), layer_shape(member(l, at, "shape"), at + "/shape", base), {}};
    if (!l.contains("parameters")) {
      MechanicsReader inline_reader(file_);
      layer.mechanics = inline_reader.mechanics(l, at, nullptr);
      layer.acoustics = inline_reader.acoustics(l, at, nullptr);
      layer.injection = inline_reader.injection(l, at, nullptr);
      return layer;
    }
    for (const char* key : with_mechanics_keys({}))
      if (l.contains(key))
        fail(at + "/" + key,
             "given beside \"parameters\": a layer's parameters come from the file or inline, not both");
    const std::string set = existing_file(l["parameters"], at + "/parameters", folder_).string();
    const LayerParameters p = MechanicsReader(set).parameter_set(io::read_json_file<ScenarioError>(set));
    layer.mechanics = p.mechanics;
    layer.acoustics = p.acoustics;
    layer.injection = p.injection;
    return layer;
  }

  // A layer's region: one of the surface primitives, a slab, a box, or a combined surface.
  LayerShape layer_shape(const json& j, const std::string& at, const Eigen::Vector3d& base) const {
    object(j, at, {"sphere", "plane", "capsule", "slab", "box", "surface"});
    if (j.size() != 1)
      fail(at, "expected exactly one of \"sphere\", \"plane\", \"capsule\", \"slab\", \"box\", \"surface\"");
    if (j.contains("slab")) {
      const json& p = j["slab"];
      const std::string where = at + "/slab";
      object(p, where, {"point", "normal", "thickness_m"});
      return LayerShape::slab(point(member(p, where, "point"), where + "/point") - base,
                              way(member(p, where, "normal"), where + "/normal"),
                              in_range(member(p, where, "thickness_m"), where + "/thickness_m", limits::kShapeSize));
    }
    if (j.contains("box")) {
      const json& p = j["box"];
      const std::string where = at + "/box";
      object(p, where, {"min", "max"});
      const Eigen::Vector3d lo = point(member(p, where, "min"), where + "/min"),
                            hi = point(member(p, where, "max"), where + "/max");
      if (!(lo.array() < hi.array()).all()) fail(where + "/max", "must exceed min on every axis");
      return LayerShape::box(lo - base, hi - base);
    }
    if (j.contains("surface")) {
      const Primitives combined = surface(j["surface"], at + "/surface", base);
      return LayerShape::of_surface(combined.list, combined.combine);
    }
    const SurfacePrimitive single = primitive(j, at, base);
    return LayerShape::of_surface(std::span<const SurfacePrimitive>(&single, 1), ImplicitSurface::Combine::Union);
  }

  SurfacePrimitive primitive(const json& e, const std::string& at, const Eigen::Vector3d& base) const {
    object(e, at, {"sphere", "plane", "capsule"});
    if (e.size() != 1) fail(at, "expected exactly one of \"sphere\", \"plane\", \"capsule\"");
    if (e.contains("sphere")) {
      const json& p = e["sphere"];
      const std::string where = at + "/sphere";
      object(p, where, {"centre", "radius"});
      return SurfacePrimitive::sphere(point(member(p, where, "centre"), where + "/centre") - base,
                                      in_range(member(p, where, "radius"), where + "/radius", limits::kShapeSize));
    }
    if (e.contains("plane")) {
      const json& p = e["plane"];
      const std::string where = at + "/plane";
      object(p, where, {"point", "normal"});
      return SurfacePrimitive::plane(point(member(p, where, "point"), where + "/point") - base,
                                     way(member(p, where, "normal"), where + "/normal"));
    }
    const json& p = e["capsule"];
    const std::string where = at + "/capsule";
    object(p, where, {"a", "b", "radius"});
    return SurfacePrimitive::capsule(point(member(p, where, "a"), where + "/a") - base,
                                     point(member(p, where, "b"), where + "/b") - base,
                                     in_range(member(p, where, "radius"), where + "/radius", limits::kShapeSize));
  }

  void hand(const json& h, const std::string& at, Scenario& s) const {
    OperatorHand read = read_hand(h, file_, at, s.base_in_world);
    s.hand = read.impedance;
    s.trajectory = std::move(read.trajectory);
    s.thumb = std::move(read.thumb);
    if (s.thumb && !s.syringe) fail(at + "/thumb", "the scenario has no syringe for the thumb to press (/syringe)");
  }

  void sensor(const json& j, const std::string& at, ForceSensorParams& out) const {
    object(j, at, {"bias_N", "force_noise_N", "bandwidth_Hz", "seed"});
    if (j.contains("force_noise_N"))
      out.force_noise_N = in_range(j["force_noise_N"], at + "/force_noise_N", limits::kSensorNoise);
    if (j.contains("bandwidth_Hz"))
      out.bandwidth_Hz = in_range(j["bandwidth_Hz"], at + "/bandwidth_Hz", limits::kSensorBandwidth);
    if (j.contains("seed")) out.seed = static_cast<unsigned>(whole(j["seed"], at + "/seed", 0, 4294967295LL));
    if (j.contains("bias_N")) {
      const auto bias = numbers_in<3>(j["bias_N"], at + "/bias_N", limits::kSensorBias);
      out.bias.head<3>() = Eigen::Vector3d(bias[0], bias[1], bias[2]);
    }
  }

  std::filesystem::path folder_;
  bool generate_patient_ = true;
};

}  // namespace

OperatorHand read_hand(const json& h, const std::string& file, const std::string& at,
                       const Eigen::Vector3d& base_in_world) {
  const io::StrictJsonReader<ScenarioError> r(file);
  r.object(h, at, {"mass_kg", "damping_Ns_per_m", "stiffness_N_per_m", "grip_length_m", "waypoints", "thumb"});
  OperatorHand out;
  HandImpedance& i = out.impedance;
  const std::tuple<const char*, double*, const io::Range&> impedance[] = {
      {"mass_kg", &i.mass_kg, limits::kHandMass},
      {"damping_Ns_per_m", &i.damping_Ns_per_m, limits::kHandDamping},
      {"stiffness_N_per_m", &i.stiffness_N_per_m, limits::kHandStiffness},
      {"grip_length_m", &i.grip_length_m, limits::kGripLength}};
  for (const auto& [key, field, range] : impedance)
    if (h.contains(key)) *field = r.in_range(h[key], at + "/" + key, range);
  try {
    out.trajectory =
        HandTrajectory(read_waypoints(r.member(h, at, "waypoints"), file, at + "/waypoints", base_in_world));
  } catch (const std::invalid_argument& e) {
    r.fail(at + "/waypoints", std::string("expected valid waypoints: ") + e.what());
  }
  if (h.contains("thumb")) out.thumb = read_thumb(h["thumb"], file, at + "/thumb", base_in_world);
  return out;
}

std::vector<HandWaypoint> read_waypoints(const json& wps, const std::string& file, const std::string& at,
                                         const Eigen::Vector3d& base_in_world) {
  const io::StrictJsonReader<ScenarioError> r(file);
  auto vec3 = [](const std::array<double, 3>& a) { return Eigen::Vector3d(a[0], a[1], a[2]); };
  if (!wps.is_array() || wps.empty()) r.fail(at, "expected a non-empty array of waypoints");
  std::vector<HandWaypoint> waypoints;
  for (size_t k = 0; k < wps.size(); ++k) {
    const std::string where = at + "/" + std::to_string(k);
    r.object(wps[k], where, {"t", "p", "dir"});
    // A time past the longest session would make a run that never ends (docs/TASKS.md, "Limits").
    const double t = r.in_range(r.member(wps[k], where, "t"), where + "/t", io::kSessionTimeRange);
    if (!waypoints.empty() && !(t > waypoints.back().t))
      r.fail(where + "/t", "must be after the waypoint before it (" + std::to_string(waypoints.back().t) + " s)");
    waypoints.push_back({t, vec3(r.position(r.member(wps[k], where, "p"), where + "/p")) - base_in_world,
                         vec3(r.direction(r.member(wps[k], where, "dir"), where + "/dir"))});
  }
  return waypoints;
}

Scenario load_scenario(const std::string& path, bool generate_patient) {
  return ScenarioReader(path, std::filesystem::path(path).parent_path(), generate_patient)
      .scenario(io::read_json_file<ScenarioError>(path));
}

}  // namespace needle::haptics
