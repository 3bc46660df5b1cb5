// Square tiles of the frame's pixels that a pass works on, listed by
// screen_tile_list.comp for an indirect dispatch of one workgroup a tile:
// the water's deferred shading (the tiles its G-buffer pass tagged) and the
// resolve (those whose pixels may differ from the last frame's).
#ifndef TP_SHARED_SCREEN_TILES_H
#define TP_SHARED_SCREEN_TILES_H
#include "shared/interop.h"

TP_BEGIN

// The tile's side in pixels: the workgroup's of the passes that read a list.
#define TP_SCREEN_TILE 8
// A list: the indirect dispatch's x, y, z and a pad, then the tiles.
#define TP_SCREEN_TILE_LIST_HEADER 4

// Tile t's column and row among the frame's tiles, `perRow` to a row.
TP_INLINE uvec2 screenTileAt(uint t, uint perRow) { return uvec2(t % perRow, t / perRow); }

// screen_tile_list.comp's push constants. A tile is listed when its tag is
// one of two frames' (a tile never tagged holds 0, no frame's tag) or it lies
// in the rectangle.
struct ScreenTileListParams {
  uvec4 tags;  // x, y: the frames' tags (the same twice for one frame); z: tiles in all; w: tiles per row
  uvec4 rect;  // tiles x0, y0 to x1, y1, the ends left out (x0 = x1 for none)
};

TP_END

#ifdef __cplusplus
static_assert(sizeof(tp::shader::ScreenTileListParams) == 32);
#endif

#endif
