#pragma once
#include <stdexcept>

namespace tp::app {

// A command line that cannot be carried out as written (a bad value, a
// missing ####, an unknown scene key): main answers it with exit code 2, as
// it answers what the parser refuses, where other failures exit 1.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs `check`, a check of what the command line gave, its
// std::runtime_error rethrown as a UsageError.
template <typename Check>
void asUsageError(Check&& check) {
  try {
    check();
  } catch (const UsageError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());
  }
}

}  // namespace tp::app
