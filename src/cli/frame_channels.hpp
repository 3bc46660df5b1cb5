#pragma once
// The channels of a rendered frame as `render` writes them to the EXR, named
// as compositors group them into layers (docs/rendering.md, "EXR layout").
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "render/renderer.hpp"

namespace tp::app {

// The EXR channel names of an --aov name: Z, N.X N.Y N.Z, P.X P.Y P.Z, AO.Y,
// AO_raw.Y, AO_ref.Y.
std::vector<std::string> aovChannelNames(const std::string& aov);

struct FrameChannelOptions {
  std::vector<std::string> aovs;  // the --aov names (written in the order Z N P ao ao_raw ao_ref)
  float farPlane = 0.0f;          // Z where nothing is hit, and P on the far plane there
  bool transparentSky = false;    // RGBA 0 where nothing is hit (frame.foreground, else from frame.position)
};

// RGBA, then each requested AOV's channels, interleaved. Where nothing is hit
// Z is farPlane and P the point of the pixel's ray at that depth, so that no
// channel holds an infinity. `aoRaw`, `aoRef`: one value per pixel, where
// requested.
io::FloatImage frameChannels(const render::RenderedFrame& frame, const FrameChannelOptions& options,
                             const std::vector<float>& aoRaw, const std::vector<float>& aoRef);

}  // namespace tp::app
