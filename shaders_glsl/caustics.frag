#version 450
// The sun's irradiance on the floor through the waves relative to flat water:
// the area a patch of the surface sends its light to through flat water over
// the area it sends it to through the waves (areas from the screen-space
// derivatives of the two landing points). Added up where folds overlap, and
// the layers counted (green): no layer (0) reaches the lines past the water's
// edge at a wall it is drawn down at, which lib/caustics_lookup.glsl's read
// leaves out.
layout(location = 0) in vec2 flatLanding;
layout(location = 1) in vec2 landing;
layout(location = 0) out vec4 intensity;

float area(vec2 dx, vec2 dy) { return abs(dx.x * dy.y - dx.y * dy.x); }

void main() {
  const float ratio = area(dFdx(flatLanding), dFdy(flatLanding)) / area(dFdx(landing), dFdy(landing));
  intensity = vec4(ratio, 1.0, 0.0, 0.0);
}
