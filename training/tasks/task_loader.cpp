// Task files (docs/TASKS.md): strict JSON reading (io/strict_json.hpp, shared with scene,
// scenario and tissue files); every error names the file and the JSON pointer of the culprit.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <tuple>

#include "haptics/sim/scenario.hpp"
#include "io/input_limits.hpp"
#include "io/strict_json.hpp"
#include "training/tasks/layer_starts.hpp"
#include "training/tasks/task.hpp"
#include "training/tasks/task_limits.hpp"

namespace needle::training {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

class TaskReader : io::StrictJsonReader<TaskError> {
 public:
  TaskReader(std::string file, fs::path folder) : StrictJsonReader(std::move(file)), folder_(std::move(folder)) {}

  Task task(const json& root) {
    object(root, "",
           {"name", "title", "description", "scene", "scenario", "normal_marker_spacing_m", "markers", "steps",
            "scoring", "ultrasound", "section", "hide_layer_names", "order", "patient", "syringe"});
    Task t;
    ScenarioTissue tissue;
    t.name = name(member(root, "", "name"), "/name");
    t.title = root.contains("title") ? string(root["title"], "/title") : t.name;
    if (t.title.size() > kMaxTitleBytes) fail("/title", "longer than " + std::to_string(kMaxTitleBytes) + " bytes");
    if (root.contains("description")) {
      t.description = string(root["description"], "/description");
      if (t.description.find('\n') != std::string::npos) fail("/description", "must be one line");
    }
    t.scene = existing_file(member(root, "", "scene"), "/scene", folder_);
    if (root.contains("scenario")) {
      t.scenario = existing_file(root["scenario"], "/scenario", folder_);
      tissue = scenario_tissue(t.scenario);
      t.force_scale = tissue.force_scale;
      for (const haptics::TissueLayer& l : tissue.tissue.layers())
        t.layers.push_back({l.name, l.mechanics.rigid, l.mechanics.puncture_force_N});
      for (const auto& l : tissue.patient_layers)
        t.layers.push_back({l.name, l.mechanics.rigid, l.mechanics.puncture_force_N});
      on_patient_ = !tissue.patient_layers.empty();
    }
    if (root.contains("patient")) t.patient = patient(root["patient"], "/patient");
    if (root.contains("syringe")) {
      std::vector<haptics::Scenario::NamedMechanics> layers = tissue.patient_layers;
      for (const haptics::TissueLayer& l : tissue.tissue.layers()) layers.push_back({l.name, l.mechanics, l.injection});
      t.syringe = read_task_syringe(root["syringe"], file_, "/syringe", layers);
    }
    if (root.contains("order")) t.order = static_cast<int>(whole(root["order"], "/order", 0, kMaxTaskOrder));
    if (root.contains("hide_layer_names")) t.hide_layer_names = boolean(root["hide_layer_names"], "/hide_layer_names");
    if (root.contains("normal_marker_spacing_m"))
      t.normal_marker_spacing_m =
          in_range(root["normal_marker_spacing_m"], "/normal_marker_spacing_m", limits::kMarkerSpacing);
    const json& markers = member(root, "", "markers");
    if (!markers.is_array() || markers.size() > limits::kMaxMarkers)
      fail("/markers", "expected an array of at most " + std::to_string(limits::kMaxMarkers) + " markers");
    std::set<std::string> marker_names;
    for (size_t i = 0; i < markers.size(); ++i) {
      const std::string at = "/markers/" + std::to_string(i);
      t.markers.push_back(marker(markers[i], at));
      if (!marker_names.insert(t.markers.back().name).second)
        fail(at + "/name", "\"" + t.markers.back().name + "\" is used twice");
      const Marker& m = t.markers.back();
      t.layer_starts.push_back(m.kind == MarkerKind::kAxis && t.layers.size() > 1 && !tissue.tissue.empty()
                                   ? layer_starts_along(tissue.tissue, tissue.frame_in_world, m.position, m.direction)
                                   : std::vector<LayerStart>{});
    }
    if (root.contains("ultrasound")) t.ultrasound_probe = ultrasound(root["ultrasound"], "/ultrasound");
    if (root.contains("section")) t.section_plane = section(root["section"], "/section");
    const json& steps = member(root, "", "steps");
    if (!steps.is_array() || steps.empty() || steps.size() > limits::kMaxSteps)
      fail("/steps", "expected a non-empty array of at most " + std::to_string(limits::kMaxSteps) + " steps");
    std::set<std::string> ids;
    for (size_t i = 0; i < steps.size(); ++i) {
      const std::string at = "/steps/" + std::to_string(i);
      t.steps.push_back(step(t, steps[i], at));
      if (!ids.insert(t.steps.back().id).second) fail(at + "/id", "\"" + t.steps.back().id + "\" is used twice");
    }
    t.scoring =
        scoring(root.contains("scoring") ? root["scoring"] : json::object(), "/scoring", t.ultrasound_probe.has_value(),
                !t.layers.empty() && t.layers.size() > 1, t.syringe.has_value());
    t.scoring.measures = score_measures(t);
    return t;
  }

 private:
  // A task's name is its key in the session store and part of its recordings' file names.
  std::string name(const json& value, const std::string& at) const {
    const std::string n = string(value, at);
    const bool safe = std::all_of(
        n.begin(), n.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; });
    if (!safe || n.size() > kMaxNameBytes)
      fail(at, "\"" + (n.size() > 80 ? n.substr(0, 80) + "..." : n) + "\": a task name is 1 to " +
                   std::to_string(kMaxNameBytes) + " letters, digits, '_' or '-'");
    return n;
  }

  // The scenario's tissue (the scenario read as a run reads it) and the frame it is in.
  // A generated patient is read and checked but not generated (its layers are known without it):
  // listing tasks stays quick; the session generates it.
  struct ScenarioTissue {
    haptics::TissueModel tissue;
    Vec3 frame_in_world{};
    double force_scale = 1.0;
    std::vector<haptics::Scenario::NamedMechanics> patient_layers;
  };
  ScenarioTissue scenario_tissue(const fs::path& scenario) const {
    try {
      const haptics::Scenario s = haptics::load_scenario(scenario.string(), false);
      return {s.scene.tissue,
              {s.base_in_world.x(), s.base_in_world.y(), s.base_in_world.z()},
              s.gains.force_scale,
              s.patient_layers};
    } catch (const haptics::ScenarioError& e) {
      fail("/scenario", e.what());
    }
  }

  // "random", or a patient file (resolved) checked by the patient reader.
  std::string patient(const json& value, const std::string& at) const {
    if (!on_patient_) fail(at, "the task's /scenario has no generated patient (tissue.patient) to replace");
    if (value.is_string() && value.get<std::string>() == "random") return "random";
    const fs::path file = existing_file(value, at, folder_);
    try {
      haptics::anatomy::load_patient(file.string());
    } catch (const haptics::anatomy::PatientError& e) {
      fail(at, e.what());
    }
    return file.string();
  }

  bool boolean(const json& value, const std::string& at) const {
    if (!value.is_boolean()) fail(at, "expected true or false, got " + std::string(value.type_name()));
    return value.get<bool>();
  }

  // A layer of the scenario's tissue by its name; `rigid` says whether it must be rigid (bone) or not.
  int layer_ref(const Task& t, const json& value, const std::string& at, bool rigid) const {
    const std::string name = string(value, at);
    if (t.layers.empty()) fail(at, "the task has no layered tissue (its /scenario has no tissue layers)");
    const int index = t.layer_index(name);
    if (index < 0) {
      std::string names;
      for (const TaskLayer& l : t.layers) names += (names.empty() ? "\"" : ", \"") + l.name + "\"";
      fail(at, "no layer named \"" + name + "\" in the scenario's tissue (its layers: " + names + ")");
    }
    if (t.layers[size_t(index)].rigid != rigid)
      fail(at, "layer \"" + name + "\" is " +
                   (rigid ? "not rigid (expected a rigid layer, bone)"
                          : "rigid (bone is never punctured nor holds the tip)"));
    return index;
  }

  // {"punctured": [layer, ...], "touched": [rigid layer, ...]}: a bit per layer.
  void forbidden(const Task& t, Step& s, const json& value, const std::string& at) const {
    object(value, at, {"punctured", "touched"});
    const std::pair<const char*, uint32_t*> lists[] = {{"punctured", &s.forbidden_punctures},
                                                       {"touched", &s.forbidden_touches}};
    for (const auto& [key, mask] : lists) {
      if (!value.contains(key)) continue;
      const json& list = value[key];
      const std::string where = at + "/" + key;
      if (!list.is_array() || list.empty()) fail(where, "expected a non-empty array of layer names");
      for (size_t i = 0; i < list.size(); ++i)
        *mask |= 1u << layer_ref(t, list[i], where + "/" + std::to_string(i), std::string(key) == "touched");
    }
  }

  // A position in the world (io::kWorldCoordinateRange).
  Vec3 point(const json& value, const std::string& at) const {
    const auto a = position(value, at);
    return {a[0], a[1], a[2]};
  }

  Marker marker(const json& value, const std::string& at) const {
    object(value, at, {"name", "point", "axis", "surface_normal"});
    Marker m;
    m.name = string(member(value, at, "name"), at + "/name");
    const int kinds =
        int(value.contains("point")) + int(value.contains("axis")) + int(value.contains("surface_normal"));
    if (kinds != 1) fail(at, "expected exactly one of point, axis or surface_normal");
    if (value.contains("point")) {
      m.kind = MarkerKind::kPoint;
      m.position = point(value["point"], at + "/point");
    } else if (value.contains("axis")) {
      const json& axis = value["axis"];
      object(axis, at + "/axis", {"origin", "direction"});
      m.kind = MarkerKind::kAxis;
      m.position = point(member(axis, at + "/axis", "origin"), at + "/axis/origin");
      m.direction = unit(member(axis, at + "/axis", "direction"), at + "/axis/direction");
    } else {
      const json& sphere = value["surface_normal"];
      object(sphere, at + "/surface_normal", {"centre", "radius"});
      m.kind = MarkerKind::kSurfaceNormal;
      m.position = point(member(sphere, at + "/surface_normal", "centre"), at + "/surface_normal/centre");
      m.radius_m =
          in_range(member(sphere, at + "/surface_normal", "radius"), at + "/surface_normal/radius", limits::kTolerance);
    }
    return m;
  }

  // A marker reference: must exist and be of one of the accepted kinds.
  int marker_ref(const Task& t, const json& value, const std::string& at, std::initializer_list<MarkerKind> kinds,
                 const char* expected) const {
    const std::string name = string(value, at);
    const int index = t.marker_index(name);
    if (index < 0) fail(at, "no marker named \"" + name + "\"");
    if (std::find(kinds.begin(), kinds.end(), t.markers[index].kind) == kinds.end())
      fail(at, "marker \"" + name + "\" is not " + expected);
    return index;
  }

  int point_ref(const Task& t, const json& value, const std::string& at) const {
    return marker_ref(t, value, at, {MarkerKind::kPoint}, "a point");
  }

  int axis_ref(const Task& t, const json& value, const std::string& at) const {
    return marker_ref(t, value, at, {MarkerKind::kAxis, MarkerKind::kSurfaceNormal}, "an axis or a surface normal");
  }

  // [min, max] within `range`, min < max.
  void band(Condition& c, const json& value, const std::string& at, const io::Range& range) const {
    c.min = in_range(member(value, at, "min"), at + "/min", range);
    c.max = in_range(member(value, at, "max"), at + "/max", range);
    if (c.max <= c.min) fail(at + "/max", "must be greater than min");
  }

  Condition condition(const Task& t, const json& value, const std::string& at) const {
    if (!value.is_object()) fail(at, "expected an object, got " + std::string(value.type_name()));
    const std::string type = string(member(value, at, "type"), at + "/type");
    Condition c;
    if (type == "tip_near" || type == "target_reached" || type == "withdrawn") {
      object(value, at, {"type", "marker", "within_m", "hold_s", "contact"});
      c.type = type == "tip_near"         ? ConditionType::kTipNear
               : type == "target_reached" ? ConditionType::kTargetReached
                                          : ConditionType::kWithdrawn;
      c.marker = point_ref(t, member(value, at, "marker"), at + "/marker");
      c.within_m = in_range(member(value, at, "within_m"), at + "/within_m", limits::kTolerance);
    } else if (type == "axis_aligned") {
      object(value, at, {"type", "marker", "within_deg", "hold_s", "contact"});
      c.type = ConditionType::kAxisAligned;
      c.marker = axis_ref(t, member(value, at, "marker"), at + "/marker");
      const double deg = positive(member(value, at, "within_deg"), at + "/within_deg");
      if (deg >= 180.0) fail(at + "/within_deg", "must be below 180 degrees");
      c.within_rad = deg * std::numbers::pi / 180.0;
    } else if (type == "depth_in_band") {
      object(value, at, {"type", "marker", "min", "max", "hold_s", "contact"});
      c.type = ConditionType::kDepthInBand;
      c.marker = marker_ref(t, member(value, at, "marker"), at + "/marker", {MarkerKind::kAxis}, "an axis");
      band(c, value, at, limits::kDepth);
    } else if (type == "force_held") {
      object(value, at, {"type", "min", "max", "hold_s", "contact"});
      c.type = ConditionType::kForceHeld;
      band(c, value, at, limits::kForce);
      if (!value.contains("hold_s")) fail(at + "/hold_s", "missing (a held force needs a time)");
    } else if (type == "tip_in_layer" || type == "punctured") {
      object(value, at, {"type", "layer", "hold_s", "contact"});
      c.type = type == "tip_in_layer" ? ConditionType::kTipInLayer : ConditionType::kPunctured;
      c.layer = layer_ref(t, member(value, at, "layer"), at + "/layer", false);
    } else if (type == "interspace_entered") {
      object(value, at, {"type", "interspace", "hold_s", "contact"});
      c.type = ConditionType::kInterspaceEntered;
      if (!on_patient_)
        fail(at + "/type", "interspace_entered needs a generated patient (the task's /scenario has none)");
      const std::string name = string(member(value, at, "interspace"), at + "/interspace");
      c.interspace = interspace_index(name);
      if (c.interspace < 0) fail(at + "/interspace", "\"" + name + "\", expected L1-L2, L2-L3, L3-L4, L4-L5 or L5-S1");
    } else {
      fail(at + "/type",
           "unknown step type \"" + type +
               "\" (expected tip_near, axis_aligned, depth_in_band, force_held, target_reached, withdrawn, "
               "tip_in_layer, punctured or interspace_entered)");
    }
    if (value.contains("hold_s")) c.hold_s = in_range(value["hold_s"], at + "/hold_s", io::kSessionTimeRange);
    if (c.type == ConditionType::kForceHeld && c.hold_s <= 0.0) fail(at + "/hold_s", "must be > 0 for force_held");
    if (value.contains("contact")) {
      const std::string contact = string(value["contact"], at + "/contact");
      if (contact == "any")
        c.contact = ContactRequirement::kAny;
      else if (contact == "free")
        c.contact = ContactRequirement::kFree;
      else if (contact == "rigid")
        c.contact = ContactRequirement::kRigidSurface;
      else if (contact == "tissue")
        c.contact = ContactRequirement::kTissue;
      else
        fail(at + "/contact", "\"" + contact + "\", expected any, free, rigid or tissue");
    }
    if (c.type == ConditionType::kTargetReached) c.contact = ContactRequirement::kTissue;
    if (c.type == ConditionType::kWithdrawn) c.contact = ContactRequirement::kFree;
    return c;
  }

  Guidance guidance(const Task& t, const Step& s, const json& value, const std::string& at) const {
    object(value, at, {"entry", "axis", "target", "depth_gauge", "normal_markers", "landmarks"});
    Guidance g;
    if (value.contains("landmarks")) {
      g.landmarks = boolean(value["landmarks"], at + "/landmarks");
      if (g.landmarks && !on_patient_)
        fail(at + "/landmarks", "landmarks need a generated patient (the task's /scenario has none)");
    }
    if (value.contains("entry")) g.entry = point_ref(t, value["entry"], at + "/entry");
    if (value.contains("axis")) g.axis = axis_ref(t, value["axis"], at + "/axis");
    if (value.contains("target")) g.target = point_ref(t, value["target"], at + "/target");
    if (value.contains("depth_gauge")) {
      g.depth_gauge = marker_ref(t, value["depth_gauge"], at + "/depth_gauge", {MarkerKind::kAxis}, "an axis");
      if (s.condition.type != ConditionType::kDepthInBand)
        fail(at + "/depth_gauge", "a depth gauge needs a depth_in_band condition (it shows its band)");
    }
    if (value.contains("normal_markers"))
      g.normal_markers = marker_ref(t, value["normal_markers"], at + "/normal_markers", {MarkerKind::kSurfaceNormal},
                                    "a surface normal");
    return g;
  }

  // {"probe": {position, direction, lateral, depth_m, width_m, frequency_MHz, slice_thickness_m}}.
  UltrasoundProbeSpec ultrasound(const json& value, const std::string& at) const {
    object(value, at, {"probe"});
    const json& p = member(value, at, "probe");
    const std::string where = at + "/probe";
    object(p, where, {"position", "direction", "lateral", "depth_m", "width_m", "frequency_MHz", "slice_thickness_m"});
    UltrasoundProbeSpec probe;
    probe.position = point(member(p, where, "position"), where + "/position");
    probe.direction = unit(member(p, where, "direction"), where + "/direction");
    probe.lateral = unit(member(p, where, "lateral"), where + "/lateral");
    if (std::abs(dot(probe.direction, probe.lateral)) > 1e-6)
      fail(where + "/lateral", "must be perpendicular to direction");
    const std::tuple<const char*, double*, const io::Range&> sizes[] = {
        {"depth_m", &probe.depth_m, limits::kProbeDepth},
        {"width_m", &probe.width_m, limits::kProbeWidth},
        {"frequency_MHz", &probe.frequency_MHz, limits::kProbeFrequency},
        {"slice_thickness_m", &probe.slice_thickness_m, limits::kProbeSliceThickness}};
    for (const auto& [key, field, range] : sizes) *field = in_range(member(p, where, key), where + "/" + key, range);
    return probe;
  }

  SectionPlaneSpec section(const json& value, const std::string& at) const {
    object(value, at, {"point", "normal"});
    return {point(member(value, at, "point"), at + "/point"), unit(member(value, at, "normal"), at + "/normal")};
  }

  // A direction, normalized (io::kDirectionComponentRange, not the zero vector).
  Vec3 unit(const json& value, const std::string& at) const {
    const auto a = direction(value, at);
    const Vec3 v{a[0], a[1], a[2]};
    return (1.0 / norm(v)) * v;
  }

  Step step(const Task& t, const json& value, const std::string& at) const {
    object(value, at,
           {"id", "instruction", "condition", "time_limit_s", "tip_fixed_within_m", "tip_out_of_plane_max_s",
            "forbidden", "guidance", "stop_at_loss"});
    Step s;
    s.id = string(member(value, at, "id"), at + "/id");
    s.instruction = string(member(value, at, "instruction"), at + "/instruction");
    s.condition = condition(t, member(value, at, "condition"), at + "/condition");
    if (value.contains("time_limit_s"))
      s.time_limit_s = in_range(value["time_limit_s"], at + "/time_limit_s", io::kSessionDurationRange);
    if (value.contains("tip_fixed_within_m"))
      s.tip_fixed_within_m = in_range(value["tip_fixed_within_m"], at + "/tip_fixed_within_m", limits::kTolerance);
    if (value.contains("tip_out_of_plane_max_s")) {
      if (!t.ultrasound_probe) fail(at + "/tip_out_of_plane_max_s", "needs the task's ultrasound probe (/ultrasound)");
      s.tip_out_of_plane_max_s =
          in_range(value["tip_out_of_plane_max_s"], at + "/tip_out_of_plane_max_s", io::kSessionDurationRange);
    }
    if (value.contains("forbidden")) forbidden(t, s, value["forbidden"], at + "/forbidden");
    if (value.contains("stop_at_loss")) {
      if (!t.syringe) fail(at + "/stop_at_loss", "needs the task's syringe (/syringe)");
      object(value["stop_at_loss"], at + "/stop_at_loss", {"within_m"});
      s.stop_at_loss_within_m = in_range(member(value["stop_at_loss"], at + "/stop_at_loss", "within_m"),
                                         at + "/stop_at_loss/within_m", limits::kTolerance);
    }
    if (value.contains("guidance")) s.guidance = guidance(t, s, value["guidance"], at + "/guidance");
    return s;
  }

  ScoringSpec scoring(const json& value, const std::string& at, bool has_probe, bool layered, bool syringe) const {
    object(value, at, {"safe_force_N", "pass_score", "weights", "references"});
    ScoringSpec s;
    if (has_probe) s.weights.needle_visibility = ScoreWeights::kDefaultNeedleVisibility;
    if (layered) {
      s.weights.overshoot = ScoreWeights::kDefaultOvershoot;
      s.weights.bone_contacts = ScoreWeights::kDefaultBoneContacts;
      s.weights.redirections = ScoreWeights::kDefaultRedirections;
    }
    if (syringe) s.weights.loss_of_resistance = ScoreWeights::kDefaultLossOfResistance;
    if (value.contains("safe_force_N"))
      s.safe_force_N = in_range(value["safe_force_N"], at + "/safe_force_N", limits::kSafeForce);
    if (value.contains("pass_score"))
      s.pass_score = in_range(value["pass_score"], at + "/pass_score", limits::kPassScore);
    s.weights = weights(value.contains("weights") ? value["weights"] : json::object(), at + "/weights", s.weights);
    if (value.contains("references")) s.references = references(value["references"], at + "/references");
    return s;
  }

  // The file's weights over the defaults, normalized to add up to 100.
  ScoreWeights weights(const json& value, const std::string& at, ScoreWeights w) const {
    object(value, at,
           {"completion", "tip_error", "axis_deviation", "lateral_load", "peak_force", "force_steadiness",
            "path_efficiency", "smoothness", "time", "retries", "needle_visibility", "overshoot", "bone_contacts",
            "redirections", "loss_of_resistance"});
    if (value.contains("needle_visibility") && w.needle_visibility == 0.0)
      fail(at + "/needle_visibility", "needs the task's ultrasound probe (/ultrasound)");
    for (const char* key : {"overshoot", "bone_contacts", "redirections"})
      if (value.contains(key) && w.overshoot == 0.0)
        fail(at + "/" + key, "needs a layered tissue (the /scenario's tissue layers)");
    if (value.contains("loss_of_resistance") && w.loss_of_resistance == 0.0)
      fail(at + "/loss_of_resistance", "needs the task's syringe (/syringe)");
    const std::pair<const char*, double*> fields[] = {{"completion", &w.completion},
                                                      {"tip_error", &w.tip_error},
                                                      {"axis_deviation", &w.axis_deviation},
                                                      {"lateral_load", &w.lateral_load},
                                                      {"peak_force", &w.peak_force},
                                                      {"force_steadiness", &w.force_steadiness},
                                                      {"path_efficiency", &w.path_efficiency},
                                                      {"smoothness", &w.smoothness},
                                                      {"time", &w.time},
                                                      {"retries", &w.retries},
                                                      {"needle_visibility", &w.needle_visibility},
                                                      {"overshoot", &w.overshoot},
                                                      {"bone_contacts", &w.bone_contacts},
                                                      {"redirections", &w.redirections},
                                                      {"loss_of_resistance", &w.loss_of_resistance}};
    double total = 0.0;
    for (const auto& [key, field] : fields) {
      if (value.contains(key)) *field = non_negative(value[key], at + "/" + key);
      total += *field;
    }
    if (total <= 0.0) fail(at, "the weights add up to 0");
    if (!std::isfinite(total))
      fail(at, "the weights add up to more than a number can hold (give them as points, e.g. 30)");
    for (const auto& [key, field] : fields) *field *= 100.0 / total;
    return w;
  }

  ScoreReferences references(const json& value, const std::string& at) const {
    object(value, at,
           {"tip_error_m", "axis_deviation_deg", "lateral_load_Ns", "force_sd_N", "normalized_jerk", "time_s",
            "overshoot_m", "loss_advance_m"});
    ScoreReferences r;
    const std::tuple<const char*, double*, const io::Range&> fields[] = {
        {"tip_error_m", &r.tip_error_m, limits::kTipErrorReference},
        {"axis_deviation_deg", &r.axis_deviation_deg, limits::kAxisDeviationReference},
        {"lateral_load_Ns", &r.lateral_load_Ns, limits::kLateralLoadReference},
        {"force_sd_N", &r.force_sd_N, limits::kForceSdReference},
        {"normalized_jerk", &r.normalized_jerk, limits::kNormalizedJerkReference},
        {"time_s", &r.time_s, io::kSessionDurationRange},
        {"overshoot_m", &r.overshoot_m, limits::kOvershootReference},
        {"loss_advance_m", &r.loss_advance_m, limits::kOvershootReference}};
    for (const auto& [key, field, range] : fields)
      if (value.contains(key)) *field = in_range(value[key], at + "/" + key, range);
    if (r.normalized_jerk <= std::sqrt(360.0))
      fail(at + "/normalized_jerk", "must exceed sqrt(360), the minimum-jerk movement's value");
    return r;
  }

  fs::path folder_;
  bool on_patient_ = false;  // the scenario's tissue is a generated patient
};

}  // namespace

namespace {

Task task_from_text(const std::string& text, const std::string& label, const fs::path& source) {
  Task task = TaskReader(label, source.parent_path()).task(io::parse_json<TaskError>(text, label));
  task.source = source.string();
  task.text = text;
  return task;
}

}  // namespace

Task load_task(const fs::path& file) {
  return task_from_text(io::read_text_file<TaskError>(file), file.string(), file);
}

Task parse_task(const std::string& text, const fs::path& source) {
  return task_from_text(text, source.string() + " (as recorded)", source);
}

}  // namespace needle::training
