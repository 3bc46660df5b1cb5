// The surfaces' specialization constants, for GLSL and C++:
// render/surfaces.cpp sets them per pipeline from the scene, so that a
// shader holds no code for what its scene lacks. On lavapipe code costs
// where it never runs: llvmpipe runs both sides of every `if` for every
// pixel, and lavapipe folds these constants and drops the code they guard
// when it compiles the pipeline (docs/frame-skipping.md). Shaders made
// without them, and C++, hold all the code.
#ifndef TP_SHARED_SPECIALIZATION_H
#define TP_SHARED_SPECIALIZATION_H
#include "shared/interop.h"

#define TP_SPEC_SPHERE_SHADOWS 100  // opaque spheres cast the sun's shadow (shared/sun_shadow.h)
#define TP_SPEC_BOX_SHADOWS 101     // boxes cast it
#define TP_SPEC_GLOSSY 102          // a surface has a glossy lobe (lib/glossy_lookup.glsl)
#define TP_SPEC_BRICK_WALLS 103     // the pool's walls are brick (shared/pool.h)
#define TP_SPEC_TILES 104           // a plane is tiled or paved (shared/surface_pattern.h)
#define TP_SPEC_GLASS_SHADOWS 105   // glass spheres shade and focus the sun (shared/sun_shadow.h)
// The resolve pass's (resolve.comp, render/frame_resolve.cpp).
#define TP_SPEC_HAZE 110       // the scene has haze (shared/haze.h)
#define TP_SPEC_STORE_HDR 111  // the frame's HDR colour is read back: store what the pass made of it
#define TP_SPEC_WRITE_LDR 112  // the frame's 8-bit image is shown or read back: tonemap into it

#ifdef __cplusplus
TP_BEGIN
const bool kSphereShadows = true;
const bool kBoxShadows = true;
const bool kGlossySurfaces = true;
const bool kBrickWalls = true;
const bool kTiledSurfaces = true;
const bool kGlassShadows = true;
TP_END
#else
layout(constant_id = TP_SPEC_SPHERE_SHADOWS) const bool kSphereShadows = true;
layout(constant_id = TP_SPEC_BOX_SHADOWS) const bool kBoxShadows = true;
layout(constant_id = TP_SPEC_GLOSSY) const bool kGlossySurfaces = true;
layout(constant_id = TP_SPEC_BRICK_WALLS) const bool kBrickWalls = true;
layout(constant_id = TP_SPEC_TILES) const bool kTiledSurfaces = true;
layout(constant_id = TP_SPEC_GLASS_SHADOWS) const bool kGlassShadows = true;
#endif

#endif
