// Where the viewer's panel first stands (panelPlacement): it covers at most
// a third of a window wide enough, and starts collapsed in a small one, so
// the scene is what a small window shows first.
#include <gtest/gtest.h>

#include "viewer/view_panel.hpp"

namespace tp::test {

TEST(ViewPanel, CoversAThirdOfTheWindowAtMostAndStartsCollapsedInASmallOne) {
  // 640x360: a panel of its own legible width would cover nearly half: collapsed.
  const app::PanelPlacement small = app::panelPlacement(640.0f, 360.0f);
  EXPECT_TRUE(small.collapsed);
  EXPECT_EQ(small.width, app::kPanelMinWidth);
  // 1024x576: a third of the width, open.
  const app::PanelPlacement middle = app::panelPlacement(1024.0f, 576.0f);
  EXPECT_FALSE(middle.collapsed);
  EXPECT_FLOAT_EQ(middle.width, 1024.0f / 3.0f);
  // 1920x1080: no wider than it needs.
  const app::PanelPlacement large = app::panelPlacement(1920.0f, 1080.0f);
  EXPECT_FALSE(large.collapsed);
  EXPECT_EQ(large.width, app::kPanelMaxWidth);
  for (const app::PanelPlacement& p : {small, middle, large}) {
    EXPECT_GT(p.x, 0.0f);
    EXPECT_GT(p.y, 0.0f);
  }
  // The height is the window's, less the margins above and below.
  EXPECT_FLOAT_EQ(large.height, 1080.0f - 2.0f * large.y);
  // From the narrowest window that opens it, it covers a third at most.
  for (float width = 3.0f * app::kPanelMinWidth; width <= 4096.0f; width += 7.0f) {
    const app::PanelPlacement p = app::panelPlacement(width, 720.0f);
    EXPECT_FALSE(p.collapsed) << width;
    EXPECT_LE(p.width, width / 3.0f) << width;
  }
}

}  // namespace tp::test
