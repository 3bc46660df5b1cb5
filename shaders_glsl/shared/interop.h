// Lets one header declare a struct (and small functions) for both C++ and GLSL,
// so the std140/std430 layout is written once. C++ side: glm types in tp::shader.
#ifndef TP_SHARED_INTEROP_H
#define TP_SHARED_INTEROP_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define TP_BEGIN        \
  namespace tp::shader { \
  using namespace glm;  \
  using uint = std::uint32_t;
#define TP_END }
#define TP_INLINE inline
#define TP_PRECISE
#define TP_DONT_UNROLL
#else
#extension GL_EXT_control_flow_attributes : enable
#define TP_BEGIN
#define TP_END
#define TP_INLINE
// Keeps the GPU from fusing or reordering, so shared functions give the same
// bits as C++ (compiled as ISO C++: no contraction there either).
#define TP_PRECISE precise
// A loop the shader compiler keeps a loop: unrolled, its body would be
// compiled once per iteration at every call site (lavapipe compiles each
// pipeline when first drawn).
#define TP_DONT_UNROLL [[dont_unroll]]
#endif

#endif
