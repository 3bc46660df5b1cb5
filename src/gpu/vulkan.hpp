#pragma once
// The one place that includes Vulkan-Hpp, so every file sees the same configuration.
#include <vulkan/vulkan_raii.hpp>
