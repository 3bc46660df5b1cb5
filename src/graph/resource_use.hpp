#pragma once
#include <cstdint>

namespace tp::render {

// How a pass touches a resource. Each use fixes the stage, access and image
// layout, so the barriers between passes follow from the declarations alone.
enum class Use {
  ComputeRead,           // storage buffer or storage image, read
  ComputeWrite,          // storage buffer or storage image, fully written
  ComputeReadWrite,      // storage buffer or storage image, updated in place
  FragmentSample,        // sampled image in the fragment stage
  ComputeSample,         // sampled image in the compute stage (a depth target read by SSAO)
  ComputeReadIndirect,   // storage buffer read in the compute stage that also holds an indirect dispatch's arguments
  FragmentStorageWrite,  // storage buffer written in the fragment stage (in part: what it leaves keeps its contents)
  ColorWrite,            // color attachment, cleared or fully covered
  ColorReadWrite,        // color attachment, loaded and drawn over
  DepthWrite,            // depth attachment, cleared, tested and written
  DepthReadWrite,        // depth attachment, loaded, tested and written
  VertexStorageRead,     // storage buffer read in the vertex stage
  FragmentStorageRead,   // storage buffer read in the fragment stage
  FragmentUniformRead,   // buffer read as a uniform buffer in the fragment stage
  ComputeUniformRead,    // buffer read as a uniform buffer in the compute stage
  TransferRead,          // source of a copy
  TransferWrite,         // destination of a copy
  TransferWritePart,     // destination of a copy that may leave part of it as it was
  HostData,              // a buffer the host fills, read as uniforms by any stage: no barrier (the submission
                         // makes host writes visible); declared so that cached passes see it change (touch())
};

struct ResourceRef {
  uint32_t index = ~0u;
};

}  // namespace tp::render
