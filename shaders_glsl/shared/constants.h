// Mathematical constants for the shared headers, GLSL and C++ alike.
#ifndef TP_SHARED_CONSTANTS_H
#define TP_SHARED_CONSTANTS_H
#include "shared/interop.h"

TP_BEGIN

const float kPi = 3.14159265358979323846f;

TP_END

#endif
