#pragma once
#include <cstdint>
#include <vector>

#include "gpu/context.hpp"
#include "viewer/swapchain.hpp"

struct GLFWwindow;

namespace tp::app {

// Dear ImGui over the viewer's frame: Debian's libimgui with its GLFW and
// Vulkan backends. The backend (1.86) draws inside a VkRenderPass, so the
// overlay owns one: the swapchain image, already holding the blitted frame,
// is loaded and drawn over. One overlay at a time (ImGui's context and
// backends are global).
class UiOverlay {
 public:
  // Installs ImGui's GLFW callbacks, which pass every event on to the ones
  // the window installed before; uploads the font. `swapchain` gives the
  // format the render pass is made for.
  UiOverlay(const gpu::Context& ctx, GLFWwindow* window, const Swapchain& swapchain);
  // Waits for the queue to be idle: a frame in flight may still read the
  // backend's buffers.
  ~UiOverlay();
  UiOverlay(const UiOverlay&) = delete;
  UiOverlay& operator=(const UiOverlay&) = delete;

  // Starts a frame of widgets (ImGui::NewFrame); then build them, then end it.
  void beginFrame();
  // Closes the widgets into the draw data record() draws (ImGui::Render).
  void endFrame();
  // Whether the last frame's widgets take the mouse (the cursor is over the
  // panel or dragging in it) or the keyboard (a text field has focus): the
  // viewer's own controls then leave those events alone.
  bool wantsMouse() const;
  bool wantsKeyboard() const;

  // Draws the last endFrame()'s widgets over swapchain image `index`, which
  // this command buffer wrote with a blit (layout TransferDstOptimal); leaves
  // it in ColorAttachmentOptimal, written at the colour attachment output.
  void record(const vk::raii::CommandBuffer& cmd, const Swapchain& swapchain, uint32_t index);

 private:
  void makeFramebuffers(const Swapchain& swapchain);

  const gpu::Context& ctx_;
  vk::Format format_;
  vk::raii::DescriptorPool pool_ = nullptr;
  vk::raii::RenderPass renderPass_ = nullptr;
  std::vector<vk::raii::Framebuffer> framebuffers_;
  uint64_t framebuffersFor_ = 0;  // the swapchain generation they were made for
  bool backendsReady_ = false;
};

}  // namespace tp::app
