// Running-bond brick, one text for C++ and GLSL (the pool walls' raster pass
// and the CPU reference shade with it). Positions are in brick units: the
// wall point (along the wall, down from the rim) divided by the brick size
// (joints included), so each course is one unit high and each brick one unit
// wide; odd courses are shifted half a brick. A joint of mortar is centred on
// every integer line; halfJoint is half its width in those units (x: the head
// joints between bricks, y: the bed joints between courses).
#ifndef TP_SHARED_BRICK_H
#define TP_SHARED_BRICK_H
#include "shared/interop.h"

TP_BEGIN

// Integral from 0 to x of the pulse that is 1 on the brick part of each unit
// period, [halfJoint, 1 - halfJoint), and 0 on the joint.
TP_INLINE float brickPulseIntegral(float x, float halfJoint) {
  float period = floor(x);
  TP_PRECISE float f = x - period;
  TP_PRECISE float brickWidth = 1.0f - 2.0f * halfJoint;
  TP_PRECISE float inside = clamp(f - halfJoint, 0.0f, brickWidth);
  TP_PRECISE float total = period * brickWidth + inside;
  return total;
}

// Fraction of [x - width/2, x + width/2] on brick; width 0 point-samples it.
TP_INLINE float brickPulse(float x, float width, float halfJoint) {
  if (width <= 0.0f) {
    TP_PRECISE float f = x - floor(x);
    return f >= halfJoint && f < 1.0f - halfJoint ? 1.0f : 0.0f;
  }
  return (brickPulseIntegral(x + 0.5f * width, halfJoint) - brickPulseIntegral(x - 0.5f * width, halfJoint)) / width;
}

// Half a brick on odd courses, none on even ones.
TP_INLINE float brickCourseShift(float course) {
  TP_PRECISE float shift = 0.5f * (course - 2.0f * floor(0.5f * course));
  return shift;
}

// The brick (column, course) that holds brick-unit point q.
TP_INLINE vec2 brickCell(vec2 q) {
  float course = floor(q.y);
  TP_PRECISE float along = q.x + brickCourseShift(course);
  return vec2(floor(along), course);
}

// Fraction of the footprint (brick units, centred on q) that is brick rather
// than mortar. The box filter is separable within one course; across courses
// the head joints move, and the course at the footprint's centre places them
// (exact for a footprint of whole bricks along, or within one course).
TP_INLINE float brickFraction(vec2 q, vec2 footprint, vec2 halfJoint) {
  TP_PRECISE float along = q.x + brickCourseShift(floor(q.y));
  TP_PRECISE float fraction = brickPulse(along, footprint.x, halfJoint.x) * brickPulse(q.y, footprint.y, halfJoint.y);
  return fraction;
}

TP_END

#endif
