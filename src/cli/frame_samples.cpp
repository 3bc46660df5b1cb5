#include "cli/frame_samples.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "reference/image_error.hpp"
#include "shading/hammersley.hpp"

namespace tp::app {

render::RenderedFrame renderSamples(render::Renderer& renderer, const render::FrameRequest& request, uint32_t samples,
                                    bool foreground) {
  if (samples == 0) throw std::invalid_argument("a frame needs at least one sample");
  if (samples == 1) return renderer.render(request);
  const uint32_t width = renderer.width(), height = renderer.height();
  const size_t values = size_t(width) * height * 4;
  // Sums in double: 65536 samples of a bright pixel keep their last bits.
  std::vector<double> sum(values, 0.0), covered(foreground ? values : 0, 0.0);
  render::RenderedFrame first;
  for (uint32_t s = 0; s < samples; ++s) {
    render::FrameRequest sample{.frame = request.frame, .hdr = true, .aovs = foreground};
    sample.pixelOffset = render::pixelSamplePoint(s, samples) - glm::vec2(0.5f);
    sample.filterWidth = 1.0f / std::sqrt(float(samples));
    render::RenderedFrame frame = renderer.render(sample);
    for (size_t i = 0; i < values; ++i) sum[i] += frame.rgba[i];
    if (foreground) {
      for (size_t p = 0; p < values / 4; ++p) {
        if (!std::isfinite(frame.position[p * 4 + 3])) continue;  // nothing hit
        for (int c = 0; c < 3; ++c) covered[p * 4 + c] += frame.rgba[p * 4 + c];
        covered[p * 4 + 3] += 1.0;
      }
    }
    if (s == 0) first = std::move(frame);
  }
  render::RenderedFrame out;
  if (request.aovs || request.ao) {
    render::FrameRequest centre = request;
    centre.hdr = centre.ldr = centre.present = centre.passWallTimes = false;
    out = renderer.render(centre);
  } else {
    out.width = width;
    out.height = height;
    out.worldToCamera = first.worldToCamera;  // the centre's: a sample's jitter is not in them
    out.worldToNDC = first.worldToNDC;
    out.inverseProjection = first.inverseProjection;
  }
  out.passes = std::move(first.passes);
  out.counts = first.counts;
  out.waterAsleep = first.waterAsleep;
  out.waterEnergy = first.waterEnergy;
  out.rgba.resize(values);
  for (size_t i = 0; i < values; ++i) out.rgba[i] = float(sum[i] / samples);
  if (foreground) {
    out.foreground.resize(values);
    for (size_t i = 0; i < values; ++i) out.foreground[i] = float(covered[i] / samples);
  }
  if (request.ldr) out.srgb = render::tonemapToSrgb8(out.rgba, renderer.scene().render.exposure);
  return out;
}

}  // namespace tp::app
