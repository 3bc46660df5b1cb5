#pragma once

namespace tp::base {

// Keeps the memory the process frees for its next allocations rather than
// giving it back to the system at once. Lavapipe allocates and frees the
// same large blocks in every pass; returned each time, they come back as
// fresh pages, and the page faults took over a third of its command
// thread's time (docs/design-notes.md). Call once, first thing in main.
void keepFreedHeapMemory();

}  // namespace tp::base
