#pragma once
#include <functional>

#include "gpu/context.hpp"

namespace tp::gpu {

// A primary command buffer submitted in one piece or several, each waited
// for. A lost device or a timeout throws with a message that says what was
// running.
class Submission {
 public:
  Submission(const Context& ctx, const char* what);
  const vk::raii::CommandBuffer& cmd() const { return buffers_.front(); }
  // Submits what was recorded since the last flush, waits for it, and
  // begins the command buffer again (a profile of each pass by wall clock).
  void flush();
  // Submits the rest and waits.
  void finish();

 private:
  void submitAndWaitPiece();
  const Context& ctx_;
  const char* what_;
  vk::raii::CommandBuffers buffers_;
  vk::raii::Fence fence_;
};

// Records a primary command buffer with `record`, submits it and waits.
void submitAndWait(const Context& ctx, const std::function<void(const vk::raii::CommandBuffer&)>& record,
                   const char* what = "GPU work");

}  // namespace tp::gpu
