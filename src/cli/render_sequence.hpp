#pragma once
#include "cli/render_command.hpp"

namespace tp::app {

// `render --frames A-B`: each frame of the range to the --out pattern (and
// --png's), with progress, checkpoints of the water every --checkpoint-every
// frames, a start from the latest checkpoint before the range, --resume
// leaving out frames already written whole, and SIGINT/SIGTERM ending the
// run after the frame being written (exit 130/143). Returns the exit code.
int runRenderSequence(const RenderOptions& o);

}  // namespace tp::app
