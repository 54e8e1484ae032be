#pragma once
// The viewer's on-screen text (Dear ImGui): frame time, camera, nodes, generation queue and
// memory. Drawn last, straight into the swapchain image through ImGui 1.86's Vulkan backend,
// which needs a classic VkRenderPass (it predates dynamic rendering): one pass that loads the
// blitted scene, draws the overlay and leaves the image ready to present.
#include "engine/viewer/swapchain.h"
#include "engine/vk/deferred_release_queue.h"
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"
#include "planet/analysis/frame_stats.h"

#include <string>
#include <vector>

namespace globe {

class Window;

namespace vk {
using UniqueRenderPass = DeviceHandle<VkRenderPass, vkDestroyRenderPass>;
using UniqueFramebuffer = DeviceHandle<VkFramebuffer, vkDestroyFramebuffer>;
}  // namespace vk

// Everything the overlay prints for one frame.
// A dropped body on screen (engine/viewer/viewer_bodies.h): spheres red, boxes yellow, capsules cyan.
struct OverlayDisc {
  float x_px = 0, y_px = 0, radius_px = 0;
  uint8_t shape = 0;  // BodyShape
};

struct OverlayView {
  FrameStats stats;
  double altitude_m = 0;  // camera height above the ground below it
  double latitude_deg = 0;
  double longitude_deg = 0;
  double heading_deg = 0;              // clockwise from north
  double pitch_deg = 0;                // above the horizontal
  double speed_mps = 0;                // fly speed at this altitude (metres per second)
  std::string hint;                    // what to do now (e.g. over open sea near the surface), or empty
  bool help = false;                   // F2/I: the key help panel
  bool typing = false;                 // G: the go-to line is open
  std::string typed;                   // its text
  std::vector<std::string> bookmarks;  // "N  LAT, LON, HEIGHT  NAME", for the help panel
  std::string bookmarksPath;
  std::string debugView;  // F1/L state: "shaded", "LOD colours", "wireframe" (sphere: "grid"/"sphere")
  std::string deviceName;
  std::string planet;               // planet name and file
  std::string recording;            // path recording state; empty when not recording
  std::string message;              // e.g. the last screenshot or path written
  std::vector<std::string> errors;  // the planet file's errors (live reload), one per line
  std::vector<OverlayDisc> bodies;  // dropped bodies (B), drawn behind the text
};

class Overlay {
 public:
  // One per process (ImGui's backends keep global state).
  Overlay(vk::Device& device, Window& window, const vk::Swapchain& swapchain);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // Swapchain recreation: retire the framebuffers (until `lastUseFrame` is done) before the
  // swapchain retires the image views they use, then attach to the new swapchain.
  void retireFramebuffers(vk::DeferredReleaseQueue& releases, uint64_t lastUseFrame);
  void attach(const vk::Swapchain& swapchain);
  // Lays out this frame's overlay (ImGui NewFrame ... Render).
  void build(const OverlayView& view);
  // Records the overlay pass into swapchain image `image`, which must be in
  // COLOR_ATTACHMENT_OPTIMAL; leaves it in PRESENT_SRC_KHR.
  void record(VkCommandBuffer cmd, uint32_t image) const;
  // True while the pointer is over the overlay (mouse input then belongs to it, not the camera).
  bool wantsMouse() const;

 private:
  vk::Device& device_;
  vk::UniqueRenderPass renderPass_;
  vk::UniqueDescriptorPool descriptorPool_;
  std::vector<vk::UniqueFramebuffer> framebuffers_;  // one per swapchain image
  VkExtent2D extent_{};
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  bool glfwBackend_ = false;
  bool vulkanBackend_ = false;
};

}  // namespace globe
