#pragma once

namespace tp::gpu {

// Device trouble on demand, for the tests of how a run ends when it comes:
// TIDEPOOL_INJECT_FAULT=device-lost makes every wait for submitted work report
// VK_ERROR_DEVICE_LOST (after the work really finished), out-of-memory makes
// every device memory allocation of 1 MiB or more report
// VK_ERROR_OUT_OF_DEVICE_MEMORY, leak makes each buffer made leave a small
// buffer of its own undestroyed (for the test that the validation layer's
// report of objects left at exit reaches stderr). Unset (always, outside
// tests): nothing.
enum class Fault { None, DeviceLost, OutOfDeviceMemory, Leak };

// The fault asked for, read once; throws one line on an unknown name.
Fault injectedFault();

// Allocations at least this large fail under Fault::OutOfDeviceMemory: the
// frame's targets and the water, not the small uniform buffers made first.
inline constexpr unsigned long long kInjectedOutOfMemoryBytes = 1ull << 20;

}  // namespace tp::gpu
