#include "gpu/fault_injection.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace tp::gpu {

Fault injectedFault() {
  static const Fault fault = [] {
    const char* name = std::getenv("TIDEPOOL_INJECT_FAULT");
    if (!name || !*name) return Fault::None;
    if (std::string(name) == "device-lost") return Fault::DeviceLost;
    if (std::string(name) == "out-of-memory") return Fault::OutOfDeviceMemory;
    if (std::string(name) == "leak") return Fault::Leak;
    throw std::runtime_error(std::string("TIDEPOOL_INJECT_FAULT=") + name +
                             ": expected device-lost, out-of-memory or leak");
  }();
  return fault;
}

}  // namespace tp::gpu
