#include "engine/ui_pass.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "engine/passes/scene_pass.hpp"
#include "engine/passes/srgb.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "engine/window.hpp"

namespace needle::engine {
namespace {

bool g_ui_pass_alive = false;

// The text size for a target: ImGui's own font (ProggyClean) at the 13 px it is drawn for up to
// 900 px, then at sizes that keep it about as tall against the window: 20 px to 1300 px
// (1920x1080), 26 px above; the size measured is the height, or for a target narrower than 16:9
// the height a 16:9 one of its width would have (a tall narrow picture keeps 13 px). Everything
// ImGui sizes from the style scales with it.
constexpr float kFontSizes_px[] = {13.0f, 20.0f, 26.0f};
constexpr uint32_t kFontUpTo_px[] = {900, 1300};

size_t font_for(Extent extent) {
  const uint32_t size = std::min(extent.height, extent.width * 9 / 16);
  size_t i = 0;
  while (i < std::size(kFontUpTo_px) && size > kFontUpTo_px[i]) ++i;
  return i;
}

void check_imgui_vk(VkResult result) { vk_check(result, "ImGui Vulkan backend"); }

// Panel colours are meant in linear light (ImGui's style colours, sRGB values, are decoded once
// here; the panels' own colours are written as linear); the target holds sRGB-encoded values, so
// every vertex colour is encoded after ImGui::Render (encode_vertex_colors).
void linearise_style_colors() {
  for (ImVec4& c : ImGui::GetStyle().Colors) {
    for (float* channel : {&c.x, &c.y, &c.z}) *channel = srgb_decode(*channel);
  }
}

// Byte => encoded byte, for the vertex colours' red, green and blue (alpha stays linear coverage).
std::array<uint8_t, 256> encoding_table() {
  std::array<uint8_t, 256> table{};
  for (size_t i = 0; i < table.size(); ++i) table[i] = uint8_t(std::lround(255.0f * srgb_encode(float(i) / 255.0f)));
  return table;
}

// (the frame's draw lists, colours linear) => (the same, colours encoded). A few thousand vertices
// a frame: the panels' CPU time (`ui_build_cpu`, docs/BENCHMARKS.md, "UNORM targets") did not move.
void encode_vertex_colors(ImDrawData& data, const std::array<uint8_t, 256>& table) {
  constexpr ImU32 kRgb = (0xFFu << IM_COL32_R_SHIFT) | (0xFFu << IM_COL32_G_SHIFT) | (0xFFu << IM_COL32_B_SHIFT);
  for (int l = 0; l < data.CmdListsCount; ++l) {
    for (ImDrawVert& v : data.CmdLists[l]->VtxBuffer) {
      const ImU32 c = v.col;
      v.col = (c & ~kRgb) | (ImU32(table[(c >> IM_COL32_R_SHIFT) & 0xFF]) << IM_COL32_R_SHIFT) |
              (ImU32(table[(c >> IM_COL32_G_SHIFT) & 0xFF]) << IM_COL32_G_SHIFT) |
              (ImU32(table[(c >> IM_COL32_B_SHIFT) & 0xFF]) << IM_COL32_B_SHIFT);
    }
  }
}

}  // namespace

struct UiPass::Backend {
  VkDevice device = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  bool with_window = false;
  ImFont* fonts[std::size(kFontSizes_px)] = {};
  ImGuiStyle base_style;  // at 13 px
  size_t font = 0;        // the one in use
  std::array<uint8_t, 256> encode = encoding_table();
};

UiPass::UiPass(const SceneRenderer& renderer, Window* window) : backend_(std::make_unique<Backend>()) {
  if (g_ui_pass_alive) throw std::logic_error("only one UiPass may exist at a time (ImGui's backend is global)");
  const ScenePass& pass = renderer.pass();
  const VulkanContext& context = pass.context();
  backend_->device = context.device();
  backend_->with_window = window != nullptr;
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;  // the backend frees its font set
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  VK_CHECK(vkCreateDescriptorPool(backend_->device, &pool_info, nullptr, &backend_->pool));

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini written next to wherever the user runs us
  ImGui::StyleColorsDark();
  linearise_style_colors();
  backend_->base_style = ImGui::GetStyle();
  for (size_t i = 0; i < std::size(kFontSizes_px); ++i) {
    ImFontConfig font;  // as AddFontDefault() sets up its pixel font
    font.OversampleH = font.OversampleV = 1;
    font.PixelSnapH = true;
    font.SizePixels = kFontSizes_px[i];
    backend_->fonts[i] = io.Fonts->AddFontDefault(&font);
  }
  if (window) ImGui_ImplGlfw_InitForVulkan(window->handle(), true);

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context.instance();
  info.PhysicalDevice = context.physical_device();
  info.Device = backend_->device;
  info.QueueFamily = context.queue_family();
  info.Queue = context.queue();
  info.DescriptorPool = backend_->pool;
  info.MinImageCount = 2;
  info.ImageCount = 3;  // vertex-buffer sets the backend cycles through: more than our frames in flight
  info.MSAASamples = pass.samples();
  info.CheckVkResultFn = check_imgui_vk;
  ImGui_ImplVulkan_Init(&info, pass.render_pass());
  context.submit_and_wait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  g_ui_pass_alive = true;
}

UiPass::~UiPass() {
  vkDeviceWaitIdle(backend_->device);
  ImGui_ImplVulkan_Shutdown();
  if (backend_->with_window) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  vkDestroyDescriptorPool(backend_->device, backend_->pool, nullptr);
  g_ui_pass_alive = false;
}

void UiPass::begin_frame(Extent extent, float delta_s) {
  const size_t font = font_for(extent);
  if (font != backend_->font) {
    backend_->font = font;
    ImGuiStyle& style = ImGui::GetStyle();
    style = backend_->base_style;
    style.ScaleAllSizes(kFontSizes_px[font] / kFontSizes_px[0]);
  }
  ImGui::GetIO().FontDefault = backend_->fonts[font];
  ImGui_ImplVulkan_NewFrame();
  if (backend_->with_window) {
    ImGui_ImplGlfw_NewFrame();
  } else {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(extent.width), float(extent.height));
    io.DeltaTime = delta_s > 0.0f ? delta_s : 1.0f / 60.0f;
  }
  ImGui::NewFrame();
}

CommandRecorder UiPass::end_frame() {
  ImGui::Render();
  encode_vertex_colors(*ImGui::GetDrawData(), backend_->encode);
  return [](const CommandBuffer& cmd) { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd.handle); };
}

}  // namespace needle::engine
