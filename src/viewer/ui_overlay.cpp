#include "viewer/ui_overlay.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <stdexcept>
#include <string>

#include "gpu/barriers.hpp"
#include "gpu/submit.hpp"

namespace tp::app {
namespace {

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
constexpr gpu::Access kBlitWrite{S::eBlit, A::eTransferWrite};
// The render pass loads the frame and blends the widgets over it.
constexpr gpu::Access kDrawOver{S::eColorAttachmentOutput, A::eColorAttachmentRead | A::eColorAttachmentWrite};

// The backend reports its own Vulkan errors through this; ours are exceptions.
void checkImGuiVk(VkResult result) {
  if (result < 0) throw std::runtime_error("the ImGui Vulkan backend failed: " + vk::to_string(vk::Result(result)));
}

}  // namespace

UiOverlay::UiOverlay(const gpu::Context& ctx, GLFWwindow* window, const Swapchain& swapchain)
    : ctx_(ctx), format_(swapchain.format()) {
  // The font's one combined image sampler is all the backend allocates.
  const vk::DescriptorPoolSize sampler{vk::DescriptorType::eCombinedImageSampler, 1};
  pool_ = vk::raii::DescriptorPool(
      ctx.device(), vk::DescriptorPoolCreateInfo{.flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                 .maxSets = 1,
                                                 .poolSizeCount = 1,
                                                 .pPoolSizes = &sampler});
  // The frame is already in the image (loaded, kept); the layout does not
  // change inside the pass: the barriers around it are recorded by hand.
  const vk::AttachmentDescription target{.format = format_,
                                         .samples = vk::SampleCountFlagBits::e1,
                                         .loadOp = vk::AttachmentLoadOp::eLoad,
                                         .storeOp = vk::AttachmentStoreOp::eStore,
                                         .stencilLoadOp = vk::AttachmentLoadOp::eDontCare,
                                         .stencilStoreOp = vk::AttachmentStoreOp::eDontCare,
                                         .initialLayout = vk::ImageLayout::eColorAttachmentOptimal,
                                         .finalLayout = vk::ImageLayout::eColorAttachmentOptimal};
  const vk::AttachmentReference color{0, vk::ImageLayout::eColorAttachmentOptimal};
  const vk::SubpassDescription subpass{
      .pipelineBindPoint = vk::PipelineBindPoint::eGraphics, .colorAttachmentCount = 1, .pColorAttachments = &color};
  renderPass_ = vk::raii::RenderPass(
      ctx.device(), vk::RenderPassCreateInfo{
                        .attachmentCount = 1, .pAttachments = &target, .subpassCount = 1, .pSubpasses = &subpass});
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  // No imgui.ini in the working directory: the panel's place is not kept.
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  if (!ImGui_ImplGlfw_InitForVulkan(window, true)) {
    ImGui::DestroyContext();
    throw std::runtime_error("the ImGui GLFW backend could not start");
  }
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = *ctx.instance();
  info.PhysicalDevice = *ctx.physicalDevice();
  info.Device = *ctx.device();
  info.QueueFamily = ctx.queueFamily();
  info.Queue = *ctx.queue();
  info.DescriptorPool = *pool_;
  info.Subpass = 0;
  // Each frame waits for the last before it is recorded: two sets of the
  // backend's vertex buffers are plenty.
  info.MinImageCount = 2;
  info.ImageCount = 2;
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkImGuiVk;
  if (!ImGui_ImplVulkan_Init(&info, *renderPass_)) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw std::runtime_error("the ImGui Vulkan backend could not start");
  }
  backendsReady_ = true;
  gpu::submitAndWait(
      ctx, [](const vk::raii::CommandBuffer& cmd) { ImGui_ImplVulkan_CreateFontsTexture(*cmd); }, "ImGui font upload");
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

UiOverlay::~UiOverlay() {
  try {
    ctx_.queue().waitIdle();
  } catch (const vk::SystemError&) {
    // A lost device: nothing is running any more.
  }
  if (backendsReady_) {
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
}

void UiOverlay::beginFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void UiOverlay::endFrame() { ImGui::Render(); }

bool UiOverlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool UiOverlay::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

void UiOverlay::makeFramebuffers(const Swapchain& swapchain) {
  if (swapchain.format() != format_) {
    throw std::logic_error("the swapchain changed format: the panel's render pass no longer fits it");
  }
  // The images of the swapchain these were made for are gone: a swapchain is
  // only recreated after the queue was idle.
  framebuffers_.clear();
  for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
    const vk::ImageView view = swapchain.view(i);
    framebuffers_.emplace_back(ctx_.device(), vk::FramebufferCreateInfo{.renderPass = *renderPass_,
                                                                        .attachmentCount = 1,
                                                                        .pAttachments = &view,
                                                                        .width = swapchain.extent().width,
                                                                        .height = swapchain.extent().height,
                                                                        .layers = 1});
  }
  framebuffersFor_ = swapchain.generation();
}

void UiOverlay::record(const vk::raii::CommandBuffer& cmd, const Swapchain& swapchain, uint32_t index) {
  if (framebuffersFor_ != swapchain.generation()) makeFramebuffers(swapchain);
  const auto color = vk::ImageAspectFlagBits::eColor;
  const vk::ImageMemoryBarrier2 toDraw[] = {gpu::imageBarrier(swapchain.image(index), color, kBlitWrite,
                                                              vk::ImageLayout::eTransferDstOptimal, kDrawOver,
                                                              vk::ImageLayout::eColorAttachmentOptimal)};
  gpu::pipelineBarrier(cmd, {}, toDraw);
  cmd.beginRenderPass(vk::RenderPassBeginInfo{.renderPass = *renderPass_,
                                              .framebuffer = *framebuffers_.at(index),
                                              .renderArea = {{0, 0}, swapchain.extent()}},
                      vk::SubpassContents::eInline);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), *cmd);
  cmd.endRenderPass();
}

}  // namespace tp::app
