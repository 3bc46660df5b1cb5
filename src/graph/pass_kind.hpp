#pragma once
#include <string_view>

namespace tp::render {

// What a pass is: a named constant, found by its address. A frame's passes
// are looked up by the constant (findPass(passes, passes::kResolve)), so a misspelt
// pass is a compile error, not a search that finds nothing. Define each as
// `inline constexpr PassKind kName{"name"};` (one address in every unit).
struct PassKind {
  std::string_view name;
};

}  // namespace tp::render
