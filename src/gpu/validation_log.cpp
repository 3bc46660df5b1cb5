#include "gpu/validation_log.hpp"

#include <cstdio>

namespace tp::gpu {

void ValidationLog::record(vk::DebugUtilsMessageSeverityFlagBitsEXT severity, const char* idName, const char* message) {
  std::string text = std::string(idName ? idName : "") + ": " + (message ? message : "");
  std::lock_guard lock(mutex_);
  if (severity == vk::DebugUtilsMessageSeverityFlagBitsEXT::eError) {
    ++errors_;
  } else {
    ++warnings_;
  }
  if (echo_) std::fprintf(stderr, "validation: %s\n", text.c_str());
  messages_.push_back(std::move(text));
}

int ValidationLog::warnings() const {
  std::lock_guard lock(mutex_);
  return warnings_;
}

int ValidationLog::errors() const {
  std::lock_guard lock(mutex_);
  return errors_;
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

bool ValidationLog::contains(const std::string& needle) const {
  std::lock_guard lock(mutex_);
  for (const auto& m : messages_) {
    if (m.find(needle) != std::string::npos) return true;
  }
  return false;
}

void ValidationLog::clear() {
  std::lock_guard lock(mutex_);
  warnings_ = errors_ = 0;
  messages_.clear();
}

VKAPI_ATTR VkBool32 VKAPI_CALL validationCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
  auto* log = static_cast<ValidationLog*>(userData);
  log->record(static_cast<vk::DebugUtilsMessageSeverityFlagBitsEXT>(severity), data->pMessageIdName, data->pMessage);
  return VK_FALSE;
}

}  // namespace tp::gpu
