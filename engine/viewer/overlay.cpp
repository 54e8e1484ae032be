#include "engine/viewer/overlay.h"

#include "engine/viewer/window.h"
#include "engine/vk/vk_check.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <cmath>
#include <stdexcept>

namespace globe {

namespace {

void checkImguiResult(VkResult result) {
  if (result < 0) vk::throwVulkanError("imgui_impl_vulkan", result);
}

// Metres with a unit that keeps 3-4 significant digits readable from 1 cm to 10^11 m.
std::string formatDistance(double m) {
  char text[64];
  double a = std::abs(m);
  if (a < 1.0)
    std::snprintf(text, sizeof text, "%.1f cm", m * 100.0);
  else if (a < 1e4)
    std::snprintf(text, sizeof text, "%.2f m", m);
  else
    std::snprintf(text, sizeof text, "%.3f km", m / 1000.0);
  return text;
}

// Loads the blitted scene, draws on top, hands the image to presentation.
vk::UniqueRenderPass createOverlayRenderPass(VkDevice dev, VkFormat format) {
  VkAttachmentDescription colour{};
  colour.format = format;
  colour.samples = VK_SAMPLE_COUNT_1_BIT;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colour.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependency.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  passInfo.attachmentCount = 1;
  passInfo.pAttachments = &colour;
  passInfo.subpassCount = 1;
  passInfo.pSubpasses = &subpass;
  passInfo.dependencyCount = 1;
  passInfo.pDependencies = &dependency;
  VkRenderPass pass;
  GLOBE_VK_CHECK(vkCreateRenderPass(dev, &passInfo, nullptr, &pass));
  return vk::UniqueRenderPass(dev, pass);
}

// ImGui 1.86 allocates one combined image sampler (the font atlas) and frees it at shutdown.
vk::UniqueDescriptorPool createOverlayDescriptorPool(VkDevice dev) {
  VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 4;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &poolSize;
  VkDescriptorPool pool;
  GLOBE_VK_CHECK(vkCreateDescriptorPool(dev, &poolInfo, nullptr, &pool));
  return vk::UniqueDescriptorPool(dev, pool);
}

// The keys, for the help panel (F2/I); docs/viewer.md has the same table.
constexpr const char* kKeyHelp[][2] = {
    {"W / S", "forward / back along the view"},
    {"A / D", "left / right"},
    {"Q / E", "down (stops at eye height, 2 m) / up"},
    {"Shift", "10x faster"},
    {"Ctrl", "10x slower; Ctrl+Q goes below eye height"},
    {"left drag", "turn and pitch"},
    {"G", "go to LAT,LON[,HEIGHT] (type, Enter; Esc cancels)"},
    {"M", "bookmark the view"},
    {"1 - 9", "go to bookmark N"},
    {"H / K", "sun azimuth -/+ 15 degrees"},
    {"U / J", "sun up / down 5 degrees"},
    {"F1 / L", "debug view"},
    {"F12 / P", "screenshot"},
    {"R", "record a camera path"},
    {"B", "drop a body"},
    {"F2 / I", "this help"},
    {"Esc", "quit"},
};

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                         ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;

// Top right: the keys, then the bookmarks.
void buildHelp(const OverlayView& v) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkSize.x - 8, 8), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.65f);
  if (ImGui::Begin("keys", nullptr, kPanelFlags)) {
    for (const auto& [key, action] : kKeyHelp) {
      ImGui::TextUnformatted(key);
      ImGui::SameLine(90);
      ImGui::TextUnformatted(action);
    }
    ImGui::Separator();
    ImGui::TextDisabled("bookmarks (%s):", v.bookmarksPath.c_str());
    if (v.bookmarks.empty()) ImGui::TextDisabled("none yet: M saves the view");
    for (const std::string& b : v.bookmarks) ImGui::TextUnformatted(b.c_str());
  }
  ImGui::End();
}

}  // namespace

Overlay::Overlay(vk::Device& device, Window& window, const vk::Swapchain& swapchain) : device_(device) {
  VkDevice dev = device.device();
  format_ = swapchain.format();

  renderPass_ = createOverlayRenderPass(dev, format_);
  descriptorPool_ = createOverlayDescriptorPool(dev);
  attach(swapchain);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in the user's directory
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  // Chains to the Window's callbacks, which were installed first.
  if (!ImGui_ImplGlfw_InitForVulkan(window.handle(), true)) throw std::runtime_error("ImGui GLFW backend failed");
  glfwBackend_ = true;
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = device.instance();
  info.PhysicalDevice = device.physical();
  info.Device = dev;
  info.QueueFamily = device.queueFamily();
  info.Queue = device.queue();
  info.DescriptorPool = descriptorPool_;
  info.Subpass = 0;
  info.MinImageCount = swapchain.minImageCount();
  info.ImageCount = std::max(swapchain.imageCount(), swapchain.minImageCount());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = &checkImguiResult;
  if (!ImGui_ImplVulkan_Init(&info, renderPass_)) throw std::runtime_error("ImGui Vulkan backend failed");
  vulkanBackend_ = true;
  device.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Overlay::~Overlay() {
  // The backend destroys buffers the last frames may still read. A destructor cannot report a
  // failure, and a lost device leaves nothing to wait for.
  (void)vkDeviceWaitIdle(device_.device());
  if (vulkanBackend_) ImGui_ImplVulkan_Shutdown();
  if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
  if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
}

void Overlay::attach(const vk::Swapchain& swapchain) {
  if (swapchain.format() != format_)
    throw std::runtime_error("the window's surface format changed; the overlay cannot follow");
  extent_ = swapchain.extent();
  framebuffers_.clear();
  for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
    VkImageView view = swapchain.view(i);
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent_.width;
    info.height = extent_.height;
    info.layers = 1;
    VkFramebuffer framebuffer;
    GLOBE_VK_CHECK(vkCreateFramebuffer(device_.device(), &info, nullptr, &framebuffer));
    framebuffers_.emplace_back(device_.device(), framebuffer);
  }
  if (ImGui::GetCurrentContext()) ImGui_ImplVulkan_SetMinImageCount(swapchain.minImageCount());
}

void Overlay::retireFramebuffers(vk::DeferredReleaseQueue& releases, uint64_t lastUseFrame) {
  releases.retire(lastUseFrame, std::move(framebuffers_));
  framebuffers_.clear();  // moved-from: make the state explicit
}

void Overlay::build(const OverlayView& v) {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImU32 kBodyColours[3] = {IM_COL32(230, 30, 30, 255), IM_COL32(240, 215, 30, 255), IM_COL32(30, 215, 230, 255)};
  for (const OverlayDisc& d : v.bodies)
    ImGui::GetBackgroundDrawList()->AddCircleFilled(ImVec2(d.x_px, d.y_px), d.radius_px, kBodyColours[d.shape % 3]);
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.55f);
  if (ImGui::Begin("globe", nullptr, kPanelFlags)) {
    const FrameStats& s = v.stats;
    double fps = s.frame_ms > 0 ? 1000.0 / s.frame_ms : 0.0;
    if (s.gpu_ms > 0)
      ImGui::Text("frame %.2f ms (%.0f fps)  select %.2f ms  gpu %.2f ms", s.frame_ms, fps, s.select_ms, s.gpu_ms);
    else  // not measured
      ImGui::Text("frame %.2f ms (%.0f fps)  select %.2f ms", s.frame_ms, fps, s.select_ms);
    ImGui::Text("altitude %s  lat %.5f  lon %.5f", formatDistance(v.altitude_m).c_str(), v.latitude_deg,
                v.longitude_deg);
    ImGui::Text("heading %.1f  pitch %.1f  speed %s/s", v.heading_deg, v.pitch_deg,
                formatDistance(v.speed_mps).c_str());
    ImGui::Text("nodes %u (%u partial)  triangles %llu  draws %u", s.nodes_selected, s.nodes_partial,
                static_cast<unsigned long long>(s.triangles), s.draw_calls);
    ImGui::Text("generation: queue %u  dispatched %u  in flight %u  done %u", s.queue_length, s.gen_dispatched,
                s.gen_in_flight, s.gen_completed);
    ImGui::Text("memory %.1f MiB resident  evicted %u", s.resident_mib, s.evicted);
    ImGui::TextDisabled("%s | %s", v.planet.c_str(), v.deviceName.c_str());
    ImGui::TextDisabled("view: %s | F2/I keys | G go to | M bookmark | Esc quit", v.debugView.c_str());
    if (v.typing)
      ImGui::TextColored(ImVec4(1.0f, 0.9f, 0.4f, 1.0f), "go to: %s_  (LAT,LON[,HEIGHT]; Enter, Esc)", v.typed.c_str());
    if (!v.hint.empty()) ImGui::TextColored(ImVec4(0.5f, 0.85f, 1.0f, 1.0f), "%s", v.hint.c_str());
    if (!v.recording.empty()) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", v.recording.c_str());
    if (!v.message.empty()) ImGui::TextUnformatted(v.message.c_str());
    if (!v.errors.empty()) {
      // Live reload kept the last good planet: say so, then every error as the loader wrote it.
      const ImVec4 red(1.0f, 0.45f, 0.4f, 1.0f);
      ImGui::TextColored(red, "planet file has %zu error(s); showing the last good planet:", v.errors.size());
      for (const std::string& e : v.errors) ImGui::TextColored(red, "%s", e.c_str());
    }
  }
  ImGui::End();
  if (v.help) buildHelp(v);
  ImGui::Render();
}

void Overlay::record(VkCommandBuffer cmd, uint32_t image) const {
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffers_[image];
  begin.renderArea = {{0, 0}, extent_};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
}

bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

}  // namespace globe
