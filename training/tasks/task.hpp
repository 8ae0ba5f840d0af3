// A guided needle task (assets/tasks/*.json, docs/TASKS.md): a scene, named markers and an
// ordered list of steps, each with an instruction, a success condition on the haptic state, an
// optional time limit and the guidance drawn for it; plus how the task is scored.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "training/tasks/task_syringe.hpp"
#include "training/tasks/ultrasound_probe.hpp"
#include "training/tasks/vec3.hpp"

namespace needle::training {

// "FILE: /json/pointer: what is wrong".
struct TaskError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class MarkerKind {
  kPoint,          // a position (entry point, target)
  kAxis,           // a planned needle axis: an origin and a unit direction
  kSurfaceNormal,  // the inward normal of a sphere at the point nearest the tip (thesis 4.3)
};

// A layer an axis enters and the depth (m, from the axis origin along its direction) it enters at;
// layer −1 (an index in Task::layers) is the axis leaving the tissue.
struct LayerStart {
  int layer = -1;
  double depth_m = 0.0;
};

struct Marker {
  std::string name;
  MarkerKind kind = MarkerKind::kPoint;
  Vec3 position{};      // point; axis origin; sphere centre
  Vec3 direction{};     // axis: unit direction the needle should point along
  double radius_m = 0;  // surface normal: the sphere's radius
};

enum class ConditionType {
  kTipNear,            // tip within `within_m` of a point marker
  kAxisAligned,        // needle axis within `within_rad` of an axis or surface-normal marker
  kDepthInBand,        // depth of the tip along an axis marker (from its origin) in [min, max] m
  kForceHeld,          // |environment force| in [min, max] N, held for hold_s
  kTargetReached,      // tip within `within_m` of a point marker while inside tissue
  kWithdrawn,          // no contact and the tip farther than `within_m` from a point marker
  kTipInLayer,         // the layered tissue's layer `layer` holds the tip (ToolSnapshot::tissue.tip_layer)
  kPunctured,          // the needle's track has passed into layer `layer` (ToolSnapshot::tissue.punctured_layers)
  kInterspaceEntered,  // the needle is in tissue and entered the skin over the patient's interspace `interspace`
};

enum class ContactRequirement { kAny, kFree, kRigidSurface, kTissue };

struct Condition {
  ConditionType type = ConditionType::kTipNear;
  int marker = -1;              // index in Task::markers (every type but force_held)
  double within_m = 0.0;        // tip_near, target_reached, withdrawn
  double within_rad = 0.0;      // axis_aligned
  double min = 0.0, max = 0.0;  // depth (m) or force (N) band
  double hold_s = 0.0;          // the condition must hold this long without a break
  ContactRequirement contact = ContactRequirement::kAny;
  int layer = -1;       // tip_in_layer, punctured: index in Task::layers
  int interspace = -1;  // interspace_entered: 0 = L1-L2 ... 4 = L5-S1
};

// What the panels draw during a step; marker indices, -1 when absent.
struct Guidance {
  int entry = -1;
  int axis = -1;
  int target = -1;
  int depth_gauge = -1;     // axis marker the gauge measures along (band from the condition)
  int normal_markers = -1;  // surface-normal marker: the thesis's three spheres at the contact
  bool landmarks = false;   // a patient's Tuffier's line and spinous processes (Task::landmarks)
};

struct Step {
  std::string id;
  std::string instruction;
  Condition condition;
  double time_limit_s = 0.0;        // 0: none
  double tip_fixed_within_m = 0.0;  // 0: the tip may move; else the step fails if it drifts further
  // 0: no rule; else the step fails when the tip, in tissue, stays out of the ultrasound probe's
  // imaged slice this long (the in-plane technique keeps it in view).
  double tip_out_of_plane_max_s = 0.0;
  // Faults that end the step at once, a bit per index in Task::layers: the track passing
  // into one of `forbidden_punctures` (the dura), the tip meeting one of `forbidden_touches` (bone).
  uint32_t forbidden_punctures = 0;
  uint32_t forbidden_touches = 0;
  // 0: no rule; else the step is where the loss of resistance is sought with the task's syringe: it
  // completes only once the plunger has given way in the syringe's space, and fails when the tip
  // advances further than this along the needle after it (docs/TASKS.md, "Syringe").
  double stop_at_loss_within_m = 0.0;
  Guidance guidance;
};

// A layer of the scenario's tissue as the task sees it: its name and whether it is rigid (bone).
struct TaskLayer {
  std::string name;
  bool rigid = false;
  double puncture_force_N = 0.0;  // > 0: a membrane, whose puncture is a pop (scene newtons)
};

// Component weights of the overall score (docs/SCORING.md); normalized to 100 on load.
// needle_visibility counts only in tasks with an ultrasound probe: 10 by default there, before
// the weights are normalized; 0 without one.
// overshoot, bone_contacts and redirections count only in tasks on a layered tissue (Task::layers):
// 10, 10 and 5 by default there, before the weights are normalized; 0 without layers.
struct ScoreWeights {
  double completion = 30, tip_error = 15, axis_deviation = 10, lateral_load = 10, peak_force = 10, force_steadiness = 5,
         path_efficiency = 5, smoothness = 5, time = 5, retries = 5, needle_visibility = 0, overshoot = 0,
         bone_contacts = 0, redirections = 0, loss_of_resistance = 0;
  static constexpr double kDefaultNeedleVisibility = 10;
  static constexpr double kDefaultLossOfResistance = 10;  // in a task with a syringe
  static constexpr double kDefaultOvershoot = 10, kDefaultBoneContacts = 10, kDefaultRedirections = 5;
};

// References at which a component's score reaches 0 (or, for time, starts to drop).
struct ScoreReferences {
  double tip_error_m = 0.01;
  double axis_deviation_deg = 20.0;
  double lateral_load_Ns = 1.0;
  double force_sd_N = 0.5;
  double normalized_jerk = 1e6;  // log scale, from sqrt(360)
  double time_s = 60.0;
  double overshoot_m = 0.01;  // design value: twice the epidural space's 5 mm depth
  // Design value: 8 mm past the loss of resistance is through the 5 mm epidural space and the
  // dura's 4 mm tent short of a millimetre: the advance after the loss that scores nothing.
  double loss_advance_m = 0.008;
};

// Which of the components that depend on the task's design it measures (docs/SCORING.md, "Score"):
// a component the task does not measure is not applicable, and the others share its weight. Set on
// load from the steps and the tissue (training::score_measures).
struct ScoreMeasures {
  bool tip_error = true;         // a step with a target (target_reached, or a guidance target)
  bool axis_deviation = true;    // a step with a planned axis (axis_aligned, or a guidance axis)
  bool force_steadiness = true;  // a force_held step
  bool lateral_load = true;      // penetrable tissue (a layer that is not rigid)
};

struct ScoringSpec {
  double safe_force_N = 3.0;
  double pass_score = 70.0;
  ScoreWeights weights;
  ScoreReferences references;
  ScoreMeasures measures;
};

// A task's name: 1 to kMaxNameBytes letters, digits, '_' or '-' (it becomes part of file names);
// its title at most kMaxTitleBytes.
inline constexpr size_t kMaxNameBytes = 64;
inline constexpr size_t kMaxTitleBytes = 200;
inline constexpr int kMaxTaskOrder = 1000000;

// The section view's plane a task fixes (docs/TASKS.md, "Section"), instead of the default one
// through the needle: through `point`, `normal` unit, pointing to the side cut away (the viewer's).
// Where a generated patient's landmarks lie, world frame (docs/PATIENTS.md): what the guidance
// draws when asked and what the patient's conditions and metrics measure against. Set by
// apply_patient from the scenario a session runs (a random patient is drawn for each attempt).
struct PatientLandmarks {
  static constexpr int kInterspaces = 5;        // L1-L2 ... L5-S1
  std::array<Vec3, kInterspaces> entries{};     // the skin on the midline between the spinous processes
  std::array<Vec3, kInterspaces> directions{};  // the midline approach, towards the interlaminar window's centre
  std::array<double, kInterspaces>
      skin_to_epidural_m{};  // along that approach, the patient's own (NaN where bone is in the way)
  std::array<Vec3, kInterspaces + 1> spinous_tips{};  // L1 ... L5, then the sacrum's crest at S1
  std::array<Vec3, 2> crest_tops{};                   // the iliac crests' highest points: Tuffier's line between them
  std::string patient;                                // the patient's parameters as JSON (what the session ran)
};

// The interspace whose spinous processes' tips bracket `point` along the spine (y), −1 beyond them.
int interspace_at(const PatientLandmarks& landmarks, const Vec3& point);
// Design value: the tip within 15 mm of the midline, between the laminae, is in the interspace.
inline constexpr double kInterspaceHalfWidth_m = 0.015;

// "L1-L2" ... "L5-S1" => 0 ... 4, -1 for anything else.
int interspace_index(const std::string& name);
const char* interspace_name(int index);

struct SectionPlaneSpec {
  Vec3 point{};
  Vec3 normal{0.0, -1.0, 0.0};
};

struct Task {
  std::string text;  // the file's text as it was read (a recording keeps it for the replay)
  std::string name;
  std::string title;
  std::string description;  // one line for the start screen; may be empty
  // The task's place in the start screen's list (docs/TASKS.md, "Top level"): tasks with an order
  // come first, lowest first; those without follow in file-name order.
  std::optional<int> order;
  std::string source;              // the file it came from
  std::filesystem::path scene;     // scene file (docs/SCENE_FORMAT.md), resolved
  std::filesystem::path scenario;  // haptics scenario (assets/scenarios), resolved; may be empty
  double normal_marker_spacing_m = 0.02;
  std::vector<Marker> markers;
  std::vector<Step> steps;
  ScoringSpec scoring;
  std::optional<UltrasoundProbeSpec> ultrasound_probe;  // the task's probe, when it has one
  // The scenario's tissue layers in its order (the indices of ToolSnapshot::tissue); empty without
  // a scenario. The thesis's single-surface tissue is one layer, "tissue".
  std::vector<TaskLayer> layers;
  // The scenario's gains.force_scale: newtons at the hand per newton on the needle in the scene
  // (1 without a scenario). The scored peak force and the trainee's gauge are at the hand.
  double force_scale = 1.0;
  // Hide the layer names from the trainee's panel (assessment runs): it shows "layer 3" instead.
  bool hide_layer_names = false;
  // Per marker (as `markers`): for an axis on a layered tissue, where along it each layer begins,
  // from the scenario's geometry at rest (training/tasks/layer_starts.hpp), computed once on load
  // for the depth gauge; empty otherwise.
  std::vector<std::vector<LayerStart>> layer_starts;
  std::optional<SectionPlaneSpec> section_plane;  // the section view's plane, when the task fixes it
  // The patient a task on a generated patient runs on: "" the scenario's own, a patient file
  // (resolved), or "random" (one drawn from the generator's ranges for each attempt).
  std::string patient;
  // The landmarks of the patient a session runs on (apply_patient); none before one runs, and for
  // a task on no patient.
  std::optional<PatientLandmarks> landmarks;
  std::optional<TaskSyringe> syringe;  // the loss-of-resistance syringe on the needle, when it has one
  // An untimed practice run of the task (docs/TASKS.md, "Practice"): no step has a time limit.
  bool practice = false;

  int marker_index(const std::string& name) const;  // -1 when absent
  int layer_index(const std::string& name) const;   // -1 when absent
};

Task load_task(const std::filesystem::path& file);
// A task from the text of its file as it was at `source` (a recording keeps it): paths in it are
// relative to `source`'s folder, errors read "SOURCE (as recorded): /json/pointer: what is wrong".
Task parse_task(const std::string& text, const std::filesystem::path& source);

// `task` as a practice run: every step's time limit lifted (the session may then last as long as
// io::kMaxSessionSeconds), `practice` set; the rest, its score included, as the task says.
Task practice_task(Task task);

// What the task's steps and tissue give its score to measure (ScoreMeasures).
ScoreMeasures score_measures(const Task& task);

// How long a session of `task` may last (docs/TASKS.md, "Limits"): when every step has a time
// limit, their sum (by then every step has ended) plus kTaskEndMargin_s; never more than
// io::kMaxSessionSeconds, the bound for a task with a step that has no limit.
inline constexpr double kTaskEndMargin_s = 4.0;
double session_time_bound_s(const Task& task);

// The thesis's three normal markers (section 4.3): points along the outward normal of the
// surface-normal marker's sphere, at the surface point nearest the tip, 1, 2 and 3 spacings out.
std::array<Vec3, 3> normal_marker_positions(const Task& task, const Marker& surface, const Vec3& tip);

// The direction the needle should point along for an axis or surface-normal marker, given the tip.
Vec3 planned_direction(const Marker& marker, const Vec3& tip);

}  // namespace needle::training
