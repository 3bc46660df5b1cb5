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
        << args << "\n"
        << line;
  }
  const std::string line =
      expectCleanFailure("render --out " + dir.file("x.exr"), dir, {}, "TIDEPOOL_INJECT_FAULT=melt");
  EXPECT_NE(line.find("TIDEPOOL_INJECT_FAULT=melt: expected device-lost, out-of-memory or leak"), std::string::npos)
      << line;
}

// With no Vulkan driver the loader can load (VK_ICD_FILENAMES naming a file
// that is not there), the one line says where the loader looked and how to
// point it at a driver; a --device that matches none lists the devices found.
TEST(DeviceTrouble, NoDriverOrNoMatchingDeviceSaysWhatWasFound) {
  ScratchDir dir;
  const std::string missing = dir.file("nosuch_icd.json");
  for (const std::string& args :
       {"render --size 16x16 --out " + dir.file("x.exr"), "sim --grid 16 --steps 1 --out " + dir.file("s.exr"),
        "export --out " + dir.file("m.obj")}) {
    const ProcessResult r = cleanFailure(args, dir, {}, "env -u VK_DRIVER_FILES VK_ICD_FILENAMES=" + missing);
    EXPECT_EQ(r.exitCode, 1) << args;
    for (const std::string& says : {"no Vulkan driver: the loader found none it could load in VK_ICD_FILENAMES=" +
                                        missing + "; set it to an installed driver's .json (",
                                    std::string("lvp_icd."),
                                    std::string("or unset it, and choose among its "
                                                "devices with --device NAME")}) {
      EXPECT_NE(r.err.find(says), std::string::npos) << args << "\n" << r.err;
    }
  }
  const ProcessResult r = cleanFailure("render --size 16x16 --device no-such-gpu --out " + dir.file("x.exr"), dir, {});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("no usable Vulkan 1.3 device matches 'no-such-gpu' (devices: llvmpipe"), std::string::npos)
      << r.err;
}

// Every Vulkan object is destroyed before the device and instance: the
// validation layer, which reports what is left when the device goes, prints
// nothing after its count, for each command that makes GPU objects. The
// check can fail: with buffers leaked on purpose, the layer's report of them
// reaches stderr.
TEST(DeviceTrouble, NoVulkanObjectIsLeftAtExit) {
  ScratchDir dir;
  const std::string runs[] = {
      "render --validate --width 48 --height 27 --aov Z,N,P,ao --out " + dir.file("r.exr") + " --png " +
          dir.file("r.png"),
      "render --validate --width 48 --height 27 --frames 0-2 --checkpoint-every 1 --checkpoint-dir " +
          dir.path().string() + " --out " + dir.file("f.####.exr"),
      "sim --validate --grid 32 --steps 5 --out " + dir.file("s.exr"),
      "export --validate --frame 2 --out " + dir.file("e.obj"),
      "bench frame --validate --frames 2 --resolution 32x18 --plot \"\" --csv " + dir.file("b.csv"),
  };
  for (const std::string& args : runs) {
    const ProcessResult r = runTidepool(args, dir);
    EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.err;
    // The count is the last line: nothing was reported when the device went (bench prints progress before it).
    EXPECT_TRUE(r.err.ends_with("validation: 0 warnings, 0 errors\n")) << args << "\n" << r.err;
  }
  const ProcessResult leaky = runTidepool(runs[0], dir, "TIDEPOOL_INJECT_FAULT=leak");
  EXPECT_NE(leaky.err.find("has not been destroyed"), std::string::npos) << leaky.err.substr(0, 2000);
}

}  // namespace tp::test
