// The gallery (docs/gallery.md) against what the build renders: each picture
// of docs/images/gallery.txt rendered again as tools/gallery.sh renders it
// (1280x720, 8 samples a pixel) and compared with the committed one as the
// golden images are. A change that moves the look fails here until
// tools/gallery.sh renders the gallery again. Rendered at a quarter of the
// size and compared with the picture averaged down, the resolution alone
// moved the pictures by an RMSE of 0.9 to 2.6 of 255 (the ambient
// occlusion's screen-space reach, 8 samples at an edge against 128), as much
// as a default picture left stale by a change of lighting (2.5): too blunt.
#include <gtest/gtest.h>

#include "picture_cases.hpp"

namespace tp::test {

TEST(Gallery, PicturesMatchWhatTheBuildRenders) {
  expectPicturesRenderedAgain("docs/images/gallery.txt", "docs/images", "--width 1280 --height 720 --samples 8",
                              "tools/gallery.sh renders the gallery again when the change is meant");
}

}  // namespace tp::test
