#pragma once
#include <functional>

#include "gpu/context.hpp"

namespace tp::gpu {

// Records a primary command buffer with `record`, submits it and waits.
// A lost device or a timeout throws with a message that says what was running.
void submitAndWait(const Context& ctx, const std::function<void(const vk::raii::CommandBuffer&)>& record,
                   const char* what = "GPU work");

}  // namespace tp::gpu
