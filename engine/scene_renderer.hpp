// The renderer: the scene pass, and what is drawn inside and before it, into any RenderTarget.
// Lit, depth-tested, multisampled meshes (opaque and masked first, blended ones back to front),
// compute passes (tissue deformation) recorded before it and the UI pass inside it; frames in
// flight overlap recording with the device's work. docs/RENDERING.md.
#pragma once

#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene.hpp"
#include "engine/tissue.hpp"

namespace needle::engine {

class GpuDevice;
class GpuModel;
class RenderTarget;
class ScenePass;
struct CommandBuffer;

// Commands an engine pass adds to a frame (GpuScene's deformation, UiPass's panels), given the
// frame's command buffer. Made inside the engine; outside it they are only handed on.
using CommandRecorder = std::function<void(const CommandBuffer&)>;

struct DrawItem {
  const GpuModel* model = nullptr;
  glm::mat4 transform{1.0f};  // placed before each instance's own world transform
  // World-space spheres outside which the vertex buffers hold the uploaded mesh (a deformed
  // tissue's reach): chunks touching them are always drawn, the others are culled by rest bounds.
  std::vector<Sphere> moved;
  bool sectioned = false;  // cut by the frame's section (the tissue), not the tool
  // The item (index into FrameParams::items) whose closed opaque surface holds this one wholly.
  // Without a section view and with the camera outside that item's reach (its box and moved
  // spheres) nothing of this one can be seen, so it is not drawn (RendererSettings::cull_inside).
  std::optional<size_t> inside;
};

// The section view (docs/RENDERING.md, "Section view"): the sectioned items cut by a plane, the
// half on the side `normal` points to (towards the viewer) removed and the cut filled with each
// surface's own colour (Cut), or drawn see-through (Translucent).
struct Section {
  enum class Mode { Cut, Translucent };
  Mode mode = Mode::Cut;
  glm::vec3 point{0.0f};
  glm::vec3 normal{0.0f, -1.0f, 0.0f};  // unit
};
// The default plane: through the needle's axis, turned to face the camera as nearly as the axis
// allows; without a needle in or on the tissue (`needle` nullptr), through the camera's target,
// facing the camera.
Section section_through_needle(const Camera& camera, const NeedleLoad* needle, Section::Mode mode = Section::Mode::Cut);

// One frame, as GpuScene::frame_params makes it; the camera may be changed before drawing.
struct FrameParams {
  Camera camera;
  Lights lights;
  glm::vec3 background{0.0f};
  std::vector<DrawItem> items;
  // Recorded before the scene's render pass (compute passes such as tissue deformation), when set.
  CommandRecorder before_pass;
  // Recorded last inside the scene's render pass (the UI pass), when set.
  CommandRecorder overlay;
  std::optional<Section> section;  // the section view, when set
};

// How the section's Translucent mode draws the tissue (docs/RENDERING.md, "Section view").
enum class Translucency {
  Blended,     // weighted blended order-independent transparency: see-through tissue
  ScreenDoor,  // 5 of 16 fragments kept on a fixed dither: cheaper, coarse (docs/BENCHMARKS.md)
};

// The render scales the renderer draws at: a fraction of the target's width and height from
// kMinRenderScale to 1 (RendererSettings::render_scale). Below a quarter the view is too coarse to
// aim a needle in (a 1280x720 window's view under 320x180 pixels); a design value, the one range
// the renderer, the settings file and the command line use.
inline constexpr float kMinRenderScale = 0.25f;
inline constexpr float kMaxRenderScale = 1.0f;

struct RendererSettings {
  // MSAA samples (1, 2, 4, 8): the highest count up to this that the device supports for colour
  // and depth together is used.
  int msaa_samples = 4;
  // Draw an asset's coarser level of detail when its mesh is finer than its pixels, and leave out
  // runs of triangles that face away from the camera (the same picture). Off only to measure what
  // they save.
  bool level_of_detail = true;
  bool cull_chunks = true;
  // With cull_chunks, a sectioned item's chunks wholly on the section's cut-away side are left
  // out (the same picture). Off only to measure what it saves (`bench frame --variants`).
  bool cull_cut_away = true;
  // The scene's meshes drawn at this fraction of the target's width and height, in
  // [kMinRenderScale, kMaxRenderScale], then
  // upscaled over the target with linear filtering before the overlay, drawn at full resolution:
  // fewer pixels to shade where they cost the frame (a CPU device). Below 1 it needs MSAA 1 and a
  // colour format the device samples with linear filtering (std::invalid_argument naming what is
  // missing). docs/RENDERING.md, "Render scale".
  float render_scale = 1.0f;
  Translucency translucency = Translucency::Blended;
  // Items held inside another's closed surface (DrawItem::inside) left out where they cannot be
  // seen (the same picture). Off only to measure what it saves (`bench frame --variants`).
  bool cull_inside = true;
};

// What one pass of a frame cost, in milliseconds.
struct PassCost {
  double record_ms = 0.0;           // the CPU, recording its commands
  std::optional<double> device_ms;  // the device, running them (SceneRenderer::set_device_timings)
};

// What drawing a frame cost, in milliseconds (docs/BENCHMARKS.md, "The trainee's frame").
struct FrameCost {
  double slot_wait_ms = 0.0;  // waiting for the frame drawn frames-in-flight ago to finish
  double acquire_ms = 0.0;    // waiting for the target's next image (a window's swapchain)
  double submit_ms = 0.0;     // handing the commands to the device (on a CPU device, running its vertex work)
  double present_ms = 0.0;    // presenting (a CPU device's window copies the finished frame to the display)
  PassCost before_pass;       // FrameParams::before_pass: tissue deformation
  PassCost scene;             // the scene's meshes
  PassCost upscale;           // at a render scale below 1, the scene's upscale over the target (device only)
  PassCost overlay;           // FrameParams::overlay: the UI
};

class SceneRenderer {
 public:
  // The target fixes the colour format and what the frame is handed on to (presented or read back).
  SceneRenderer(const GpuDevice& device, const RenderTarget& target, const RendererSettings& settings = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Records and submits one frame. False when the target could not take one (minimised).
  // With `capture`, the frame is also copied out before it is presented (same command buffer)
  // and this call waits for it: headless output and window screenshots alike.
  bool draw(RenderTarget& target, const FrameParams& params, RgbaImage* capture = nullptr);
  // Waits until every submitted frame has finished on the device.
  void wait_idle() const;

  // The MSAA samples it draws with: the settings' count, capped at the device's.
  int msaa_samples() const;
  // Triangles the last recorded frame sent to the device, after chunk culling.
  size_t triangles_drawn() const;
  // The render scale from the next frame on (RendererSettings::render_scale), for frames drawn
  // into `target`; std::invalid_argument outside (0, 1] or, below 1, where the upscale cannot be done.
  void set_render_scale(const RenderTarget& target, float scale);
  float render_scale() const;
  // RendererSettings::cull_cut_away from the next frame on (for `bench frame --variants`).
  void set_cull_cut_away(bool on);
  // RendererSettings::cull_inside from the next frame on (for `bench frame --variants`).
  void set_cull_inside(bool on);
  // RendererSettings::translucency from the next frame on.
  void set_translucency(Translucency translucency);
  // Each draw uses the mesh shader specialized to what it needs (the default: no discards for
  // opaque unsectioned draws, no texture fetch for untextured materials); off, every draw uses
  // the general one, as before (for `bench frame --variants`). The same picture either way.
  void set_specialized_pipelines(bool on);
  // Why a render scale below 1 cannot be used with `target`, empty when it can.
  std::string render_scale_unsupported(const RenderTarget& target) const;
  // Timestamp queries around each pass from the next frame on (FrameCost's device times), where
  // the device has them (GpuDevice::timestamp_period_ns). A CPU device (lavapipe) then finishes
  // each pass before it starts the next, so this is for measuring (`needle-sim bench frame`).
  void set_device_timings(bool on);
  // What the last draw() cost on the CPU; the device times are those of the last frame whose
  // timestamps have come back, else nullopt.
  const FrameCost& frame_cost() const;

  // The engine's own access (engine/passes/scene_pass.hpp); an incomplete type outside it.
  const ScenePass& pass() const { return *pass_; }

 private:
  std::unique_ptr<ScenePass> pass_;
};

}  // namespace needle::engine
