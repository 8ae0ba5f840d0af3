// A simulated B-mode ultrasound image of a probe's plane through the tissue's layers, made by a
// Vulkan compute pass: per scan line, the layers along the beam (deformed as the tissue deforms),
// reflection at their interfaces, attenuation, shadow behind bone, the needle as a strong
// reflector with its reverberation tail, then speckle from a fixed scatterer field convolved
// with the point spread function, and log compression to 8 bits. The scan-line model also runs
// on the CPU in double precision (trace_scan_lines), the reference the pass is tested against.
// The model, its parameters and its limits: docs/RENDERING.md, "Ultrasound".
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/extent.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/tissue.hpp"

namespace needle::engine {

class GpuDevice;
class UltrasoundDisplay;
class UltrasoundPass;

// A rectangle of a frame, in pixels from its top left corner.
struct ScreenRect {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
};

// What a layer is to sound. The defaults are a generic soft tissue (the docs say why), used for
// a layer whose tissue file gives no ultrasound parameters.
struct EchoMaterial {
  double impedance_MRayl = 1.62;           // Z: the interfaces' reflection, ((Z₂ − Z₁)/(Z₂ + Z₁))
  double attenuation_dB_per_cm_MHz = 0.5;  // α, one way, proportional to the frequency
  double echogenicity = 0.5;               // mean backscatter amplitude, 0 (anechoic) to 1
  double scatterer_density = 1.0;          // share of scatterer cells that hold one, (0, 1]
};

// A layer's region, as the haptic tissue model has it: signed distances (φ < 0 inside) of
// spheres, half-spaces (behind `b`, the outward normal) and capsules, combined by union (min) or
// intersection (max). World frame, metres.
struct EchoPrimitive {
  enum class Kind { Sphere, Plane, Capsule };
  Kind kind = Kind::Sphere;
  glm::dvec3 a{0.0};  // sphere centre, point on the plane, capsule end
  glm::dvec3 b{0.0};  // plane's unit outward normal, capsule's other end
  double radius = 0.0;
};

// A layer's region sampled on a grid, as a generated anatomy's layers are (haptics' SdfGrid in plain
// types): φ at the nodes origin + (i, j, k)·spacing in whole quanta (x fastest, then y, then z),
// trilinear between them, its gradient the normal; outside the grid's box φ is the distance to the
// box plus the nearest box point's φ where that is positive (the region is clipped to the box).
// World frame, metres. Several layers may share one grid at different offsets.
struct EchoGrid {
  glm::dvec3 origin{0.0};
  double spacing_m = 1e-3;
  double quantum_m = 1e-6;
  glm::uvec3 nodes{2u};
  std::shared_ptr<const std::vector<int16_t>> values;  // nodes.x · nodes.y · nodes.z
};

struct EchoLayer {
  static constexpr size_t kMaxPrimitives = 8;
  std::string name;
  std::vector<EchoPrimitive> primitives;  // 1 to kMaxPrimitives; none with a grid
  bool intersection = false;              // combined by max; else by min
  EchoMaterial material;
  // Or the region {φ_grid + grid_offset_m ≤ 0} of a grid (no primitives then).
  std::shared_ptr<const EchoGrid> grid;
  double grid_offset_m = 0.0;
};

// The needle as a reflector: a steel cylinder from the tip back along the axis.
struct EchoNeedle {
  double radius_m = 0.0008;  // the needle asset's shaft (tools/asset-gen)
  double length_m = 0.08;    // tip and shaft, without the hub
};

// What the probe images. Layers are listed outside in: a point belongs to the last layer whose
// region holds it (as in haptics' TissueModel); outside every layer is coupling gel (no echo, no
// attenuation). With `deformation`, the layers move with the tissue's displacement field of the
// needle's state (the same field the scene's tissue mesh is deformed by).
struct EchoScene {
  static constexpr size_t kMaxLayers = 16;
  static constexpr size_t kMaxGrids = 16;                    // distinct grids the layers use
  static constexpr size_t kMaxGridValues = size_t(1) << 26;  // their nodes in all (128 MiB)
  std::vector<EchoLayer> layers;
  std::optional<TissueParams> deformation;
  EchoNeedle needle;
};

// A linear array: parallel scan lines across `width_m`, from the face down to `depth_m`.
struct UltrasoundProbe {
  glm::dvec3 position{0.0};              // centre of the transducer face, world
  glm::dvec3 direction{0.0, 0.0, -1.0};  // the beams', unit: the image's top to bottom
  glm::dvec3 lateral{1.0, 0.0, 0.0};     // along the array, unit, ⊥ direction: the image's left to right
  double depth_m = 0.05;
  double width_m = 0.04;
  double frequency_MHz = 7.5;
  double slice_thickness_m = 0.0015;  // elevation beam width (full width at half maximum)

  glm::dvec3 elevation() const { return glm::cross(direction, lateral); }
};

// The probe moved in its face's plane to lie over the needle's tip, its array turned along the
// needle's projection on that plane: the needle in plane wherever it goes. The probe as given
// when the needle runs along the beam.
UltrasoundProbe probe_following(const UltrasoundProbe& probe, const NeedleLoad& needle);

// The probe moved along its beams so that its face lies where a beam from `above` first enters a
// layer (the skin), to 1 µm; as given when that beam meets none within a metre.
UltrasoundProbe probe_on_skin(const EchoScene& scene, const UltrasoundProbe& probe, const glm::dvec3& above);

struct UltrasoundSettings {
  uint32_t lines = 256;    // scan lines, the image's width in pixels
  uint32_t samples = 512;  // per line, its height
  bool speckle = true;     // off: the scan-line model alone, blurred by the point spread function
  double dynamic_range_dB = 60.0;
  double gain_dB = 0.0;
  // A deformed tissue's rest positions (where each sample's scatterer is) are found at nodes this
  // many samples apart down each line and interpolated between; 0 (the default): the spacing that
  // keeps them within 2 µm of the exact ones for this image's deformation (rest_node_spacing below),
  // 1: at every sample.
  uint32_t rest_node_spacing = 0;
  // The frames a window's image is swept over (UltrasoundView::record): its lines in this many
  // slices, one a frame, each made with that frame's probe and tissue, as a scanner fires its lines
  // across the array one after another; 1: the whole image every frame. render() always makes the
  // whole image.
  uint32_t sweep_frames = 1;
};

// An interface a scan line crosses: where, and between which layers (indices in
// EchoScene::layers; -1 outside every layer).
struct EchoInterface {
  double depth_m = 0.0;
  int from_layer = -1;
  int to_layer = -1;
};

// One scan line of the model: its interfaces in depth order (at most kMaxInterfaces), the depth
// where its shadow begins (the round-trip amplitude after time-gain compensation 40 dB below the
// start; infinity when it never does) and the depth of the needle's near wall (infinity when the
// line misses the needle).
struct ScanLine {
  static constexpr size_t kMaxInterfaces = 24;
  std::vector<EchoInterface> interfaces;
  double shadow_depth_m = std::numeric_limits<double>::infinity();
  double needle_depth_m = std::numeric_limits<double>::infinity();
};

// The CPU reference, double precision, of the scan-line model (not the speckle): every line of
// the image the GPU pass makes with the same scene, probe, needle (nullptr: none) and settings.
std::vector<ScanLine> trace_scan_lines(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad* needle,
                                       const UltrasoundSettings& settings);
// The rest nodes' spacing (samples) an image of this needle takes: the settings' own, or for 0 the
// one chosen for the tissue's deformation (UltrasoundSettings::rest_node_spacing).
uint32_t rest_node_spacing(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad& needle,
                           const UltrasoundSettings& settings);
// The largest distance, over every sample of that image, between the rest position interpolated
// between the nodes and the exact one, double precision (0 at rest): the nodes' error.
double rest_interpolation_error(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad& needle,
                                const UltrasoundSettings& settings);

class UltrasoundView {
 public:
  // std::invalid_argument for a scene beyond the pass's limits (layers, primitives, grids and their
  // nodes) or sizes of 0.
  UltrasoundView(const GpuDevice& device, EchoScene scene, const UltrasoundSettings& settings = {});
  ~UltrasoundView();
  UltrasoundView(const UltrasoundView&) = delete;
  UltrasoundView& operator=(const UltrasoundView&) = delete;

  const EchoScene& scene() const;
  const UltrasoundSettings& settings() const;

  // This frame's image, to record before the scene's render pass (FrameParams::before_pass,
  // after what is there); draw() then shows it. The first image whole, then with a sweep over
  // several frames (UltrasoundSettings::sweep_frames) the next slice of lines not yet made for this
  // probe and needle. Empty when every line shown is already this probe's and needle's (nothing
  // moved): the passes then cost nothing.
  CommandRecorder record(const UltrasoundProbe& probe, const NeedleLoad* needle);
  // Records drawing the last image recorded into `rect` of a frame of `renderer`'s (`frame` its
  // size), stretched to the rectangle: to run after the UI pass in FrameParams::overlay, so it
  // lies on top of its panel (an ImGui window keeps the room for it). Nothing before the first image.
  CommandRecorder draw(const SceneRenderer& renderer, ScreenRect rect, Extent frame);
  // Makes the image now and waits for it (headless pictures, tests, the bench).
  void render(const UltrasoundProbe& probe, const NeedleLoad* needle);
  // The last image made, read back: `lines` wide, `samples` high, grey (R = G = B).
  RgbaImage image() const;
  // The scan lines the GPU traced for the last image, read back (what trace_scan_lines computes).
  std::vector<ScanLine> scan_lines() const;

  // The sweep from the next frame on (UltrasoundSettings::sweep_frames, at least 1): when it
  // changes, every line is made again.
  void set_sweep_frames(uint32_t frames);

  // Device time per pass of the images made from now on (timestamp queries): the last image's,
  // pass name → ms, in order; empty with timings off or on a device without timestamps.
  void set_device_timings(bool on);
  std::vector<std::pair<std::string, double>> pass_ms() const;

  // The engine's own access (engine/ultrasound/ultrasound_pass.hpp); an incomplete type outside it.
  const UltrasoundPass& pass() const { return *pass_; }

 private:
  std::unique_ptr<UltrasoundPass> pass_;
  std::unique_ptr<UltrasoundDisplay> display_;  // made for the first renderer draw() is given
};

// The image stretched to the probe's proportions (width_m : depth_m) at its height, for a picture
// a person reads: linear interpolation between scan lines.
RgbaImage to_picture(const RgbaImage& image, const UltrasoundProbe& probe);

}  // namespace needle::engine
