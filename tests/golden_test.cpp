// The golden images: `tidepool render` of the default scene and the example
// scene files against PNGs committed under tests/golden/ (tools/update-golden.sh
// writes them; each was looked at before it was committed). They guard
// against any change to what a frame shows that no other test describes; the
// reference tests say whether the images are right.
#include <gtest/gtest.h>

#include "picture_cases.hpp"

namespace tp::test {

TEST(GoldenImage, ScenesMatchTheirGoldenImages) {
  expectPicturesRenderedAgain("tests/golden/cases.txt", "tests/golden", "--width 160 --height 90",
                              "tools/update-golden.sh rewrites the goldens when the change is meant");
}

}  // namespace tp::test
