#pragma once
// Every pass a frame can have, in the order a frame records them.
#include "graph/pass_kind.hpp"

namespace tp::render::passes {

inline constexpr PassKind kSimulate{"simulate"};
inline constexpr PassKind kCameraMedium{"camera medium"};
inline constexpr PassKind kCaustics{"caustics"};
inline constexpr PassKind kSky{"sky"};
inline constexpr PassKind kGlossyPrefilter{"glossy prefilter"};
inline constexpr PassKind kGlossyProbes{"glossy probes"};
inline constexpr PassKind kGlossyProbePrefilter{"glossy probe prefilter"};
inline constexpr PassKind kGround{"ground"};
inline constexpr PassKind kGroundCopy{"ground copy"};
inline constexpr PassKind kPool{"pool"};
inline constexpr PassKind kObjects{"objects"};
inline constexpr PassKind kSsao{"ssao"};
inline constexpr PassKind kAoBlurX{"ao blur x"};
inline constexpr PassKind kAoBlurY{"ao blur y"};
inline constexpr PassKind kAoUpsample{"ao upsample"};
inline constexpr PassKind kAoApply{"ao apply"};
inline constexpr PassKind kReadbackAo{"readback ao"};
inline constexpr PassKind kReadbackAoRaw{"readback ao raw"};
inline constexpr PassKind kReadbackDepth{"readback depth"};
inline constexpr PassKind kReadbackViewNormal{"readback view normal"};
inline constexpr PassKind kUnderwater{"underwater"};
inline constexpr PassKind kGlassBackFaces{"glass back faces"};
inline constexpr PassKind kGlass{"glass"};
inline constexpr PassKind kWaterGbuffer{"water g-buffer"};
inline constexpr PassKind kWaterTiles{"water tiles"};
inline constexpr PassKind kWater{"water"};
inline constexpr PassKind kWaterBelow{"water below"};
inline constexpr PassKind kAov{"aov"};
inline constexpr PassKind kReadbackNormal{"readback normal"};
inline constexpr PassKind kReadbackPosition{"readback position"};
inline constexpr PassKind kResolveTiles{"resolve tiles"};
inline constexpr PassKind kResolve{"resolve"};
inline constexpr PassKind kAntialias{"antialias"};
inline constexpr PassKind kReadbackHdr{"readback hdr"};
inline constexpr PassKind kReadbackLdr{"readback ldr"};

// The ambient occlusion's passes (bench ssao times them together).
inline bool isAo(const PassKind* kind) {
  for (const PassKind* ao : {&kSsao, &kAoBlurX, &kAoBlurY, &kAoUpsample, &kAoApply}) {
    if (kind == ao) return true;
  }
  return false;
}

// The water surface's passes: forward, its one pass; deferred, the G-buffer,
// the tiles, the shading and the side seen from below.
inline bool isWater(const PassKind* kind) {
  for (const PassKind* water : {&kWaterGbuffer, &kWaterTiles, &kWater, &kWaterBelow}) {
    if (kind == water) return true;
  }
  return false;
}

}  // namespace tp::render::passes
