#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/validation_log.hpp"
#include "gpu/vulkan.hpp"

namespace tp::gpu {

struct ContextOptions {
  // VK_LAYER_KHRONOS_validation with synchronization validation, counted by log().
  bool validation = false;
  // Substring of the device name; empty means $TIDEPOOL_DEVICE, then the best
  // device by type (discrete, integrated, virtual, CPU).
  std::string deviceName = {};
  // For a window: the instance extensions its surface needs (the window
  // system names them, e.g. glfwGetRequiredInstanceExtensions) and
  // VK_KHR_swapchain on the device. Empty and false: headless, as before.
  std::vector<std::string> surfaceExtensions = {};
  bool swapchain = false;
};

// Instance, device and the one queue tidepool uses. Members are declared in
// creation order so that vk::raii destroys them in reverse.
class Context {
 public:
  explicit Context(const ContextOptions& options);
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const vk::raii::Instance& instance() const { return instance_; }
  const vk::raii::Device& device() const { return device_; }
  const vk::raii::PhysicalDevice& physicalDevice() const { return physical_; }
  const vk::raii::Queue& queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const vk::raii::CommandPool& commandPool() const { return commandPool_; }
  const vk::PhysicalDeviceProperties& properties() const { return properties_; }
  const vk::PhysicalDeviceLimits& limits() const { return properties_.limits; }
  const vk::PhysicalDeviceMemoryProperties& memoryProperties() const { return memoryProperties_; }
  std::string deviceName() const { return properties_.deviceName.data(); }
  bool timestampsSupported() const { return timestampValidBits_ > 0; }
  bool validationEnabled() const { return messenger_.has_value(); }
  ValidationLog& validationLog() { return *log_; }

 private:
  std::unique_ptr<ValidationLog> log_;  // outlives the messenger that points at it
  vk::raii::Context context_;
  vk::raii::Instance instance_;
  std::optional<vk::raii::DebugUtilsMessengerEXT> messenger_;
  vk::raii::PhysicalDevice physical_;
  vk::PhysicalDeviceProperties properties_;
  vk::PhysicalDeviceMemoryProperties memoryProperties_;
  uint32_t queueFamily_ = 0;
  uint32_t timestampValidBits_ = 0;
  vk::raii::Device device_;
  vk::raii::Queue queue_;
  vk::raii::CommandPool commandPool_;
};

}  // namespace tp::gpu
