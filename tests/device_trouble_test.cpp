// How a run ends when the device fails it (faults injected through
// TIDEPOOL_INJECT_FAULT, gpu/fault_injection.hpp): a lost device and memory
// running out each end the run with one line naming them, exit 1, and no
// file written.
#include <gtest/gtest.h>

#include "process.hpp"

namespace tp::test {

TEST(DeviceTrouble, LostDeviceEndsTheRunWithOneLine) {
  ScratchDir dir;
  for (const std::string& args : {"render --width 64 --height 36 --out " + dir.file("x.exr"),
                                  "render --width 64 --height 36 --frames 0-3 --out " + dir.file("f.####.exr"),
                                  "sim --grid 64 --steps 10 --out " + dir.file("s.exr")}) {
    const std::string line = expectCleanFailure(args, dir, {}, "TIDEPOOL_INJECT_FAULT=device-lost");
    EXPECT_NE(line.find("the GPU device was lost (VK_ERROR_DEVICE_LOST)"), std::string::npos) << args << "\n" << line;
  }
}

TEST(DeviceTrouble, OutOfDeviceMemoryEndsTheRunWithOneLine) {
  ScratchDir dir;
  for (const std::string& args : {"render --width 640 --height 360 --out " + dir.file("x.exr"),
                                  "sim --grid 512 --steps 10 --out " + dir.file("s.exr")}) {
    const std::string line = expectCleanFailure(args, dir, {}, "TIDEPOOL_INJECT_FAULT=out-of-memory");
    EXPECT_NE(line.find("out of device memory (VK_ERROR_OUT_OF_DEVICE_MEMORY) allocating"), std::string::npos)
        << args << "\n" << line;
  }
  const std::string line = expectCleanFailure("render --out " + dir.file("x.exr"), dir, {}, "TIDEPOOL_INJECT_FAULT=melt");
  EXPECT_NE(line.find("TIDEPOOL_INJECT_FAULT=melt: expected device-lost or out-of-memory"), std::string::npos) << line;
}

}  // namespace tp::test
