#pragma once

namespace tp::app {

// "tidepool 0.1 (commit 003c05a1b2c3)": the version and the git commit this
// binary was built from, "-dirty" when the tree had changes, or "commit
// unknown" for a build outside a git checkout. Written at build time
// (cmake/build_version.cmake).
const char* versionText();

}  // namespace tp::app
