// libFuzzer target: the water-state reader of `sim --init PATH.exr` and of
// the checkpoints (sim::readStateExr, through OpenImageIO) on arbitrary
// bytes in a file. It must return a square state of at least 2x2 cells with
// as many values as cells, or throw std::runtime_error.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "io/water_state_file.hpp"
#include "sim/water_state.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/tidepool-fuzz-state-" + std::to_string(getpid()) + ".exr";
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) std::abort();
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  try {
    const tp::sim::WaterState state = tp::io::readStateExr(path);
    const size_t cells = size_t(state.n) * state.n;
    if (state.n < 2 || state.u.size() != cells || state.v.size() != cells) std::abort();
  } catch (const std::runtime_error&) {
  }
  return 0;
}
