// Linear colour -> what the scene's 8-bit UNORM target stores (display_encoding.h). Every fragment
// shader writing the scene target ends with outColour = encodeDisplay(...).
#include "display_encoding.h"

vec4 encodeDisplay(vec3 linear, float alpha) {
  const float a = float(GLOBE_DISPLAY_ENCODING_A);
  vec3 c = clamp(linear, 0.0, 1.0);
  return vec4(a * sqrt(c) - (a - 1.0) * c, alpha);
}
