#pragma once
// Anti-aliasing of the raster: a frame as the average of jittered frames of
// the same moment (docs/rendering.md, "Anti-aliasing").
#include <cstdint>

#include "render/renderer.hpp"

namespace tp::app {

// Frame request.frame rendered `samples` times, each pixel sampling the
// image at pixelSamplePoint(s, samples) (the reference tracer's points), and
// averaged with equal weights: a box filter over the pixel. The water is
// stepped once, by the first render: the others draw the same moment. One
// sample is renderer.render(request), bit for bit.
//
// With several samples: the AOVs and the AO (request.aovs, request.ao) are
// those of a further render at the pixel centres, as the reference takes
// them; the sRGB preview (request.ldr) is the average tonemapped on the CPU;
// with `foreground`, RenderedFrame::foreground holds RGBA premultiplied by
// the share of samples that hit something (each sample's positions say).
// The passes and counts returned are the first sample's.
render::RenderedFrame renderSamples(render::Renderer& renderer, const render::FrameRequest& request, uint32_t samples,
                                    bool foreground = false);

}  // namespace tp::app
