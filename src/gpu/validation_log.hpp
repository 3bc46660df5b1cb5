#pragma once
#include <mutex>
#include <string>
#include <vector>

#include "gpu/vulkan.hpp"

namespace tp::gpu {

// Collects what the validation layer says through the debug-utils messenger.
// Tests fail on any warning or error; the CLI reports the count at exit.
class ValidationLog {
 public:
  void record(vk::DebugUtilsMessageSeverityFlagBitsEXT severity, const char* idName, const char* message);

  int warnings() const;
  int errors() const;
  int total() const { return warnings() + errors(); }
  std::vector<std::string> messages() const;
  bool contains(const std::string& needle) const;
  void clear();
  // Print each message to stderr as it arrives (the CLI does; tests collect).
  void setEcho(bool echo) { echo_ = echo; }

 private:
  mutable std::mutex mutex_;
  int warnings_ = 0;
  int errors_ = 0;
  bool echo_ = false;
  std::vector<std::string> messages_;
};

VKAPI_ATTR VkBool32 VKAPI_CALL validationCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT types,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData);

}  // namespace tp::gpu
