#version 450
// FXAA after the 3.11 "quality" algorithm [Lottes 2011] on the display-encoded scene colour
// (perceptual, as FXAA wants its luma): finds the local edge, walks along it to both ends (up to 5
// steps each way) and blends the pixel with its neighbour across the edge by its estimated coverage;
// sub-pixel aliasing is blended by the 3x3 neighbourhood's contrast. The scene arrives as packed
// B8G8R8A8 texels in a storage buffer (engine/render/fxaa_pass.h: lavapipe's texture reads are slow),
// so every read is a whole pixel: the search reads both rows beside the edge (their average is
// FXAA's half-pixel bilinear tap) and the final blend mixes two texels.
// Branches depend on the image, never on push constants alone.
layout(location = 0) out vec4 outColour;

layout(std430, binding = 0) readonly buffer Scene {
  uint texels[];  // B8G8R8A8, row-major, row 0 at the top
};
layout(push_constant) uniform Push {
  ivec2 size;  // pixels
} push;

const float kEdgeThreshold = 0.166;      // local contrast (of the brightest luma) below which nothing is done
const float kEdgeThresholdMin = 0.0833;  // ... and an absolute floor (dark areas)
const float kSubpix = 0.75;              // amount of sub-pixel blending
const int kSteps = 5;
const int kStep[kSteps] = int[](1, 1, 2, 4, 8);  // pixels per search step: reaches 16 pixels each way

vec4 texel(ivec2 p) {
  p = clamp(p, ivec2(0), push.size - 1);
  return unpackUnorm4x8(texels[p.y * push.size.x + p.x]).zyxw;  // BGRA in memory
}
float luma(vec4 c) { return dot(c.rgb, vec3(0.299, 0.587, 0.114)); }
float lumaAt(ivec2 p) { return luma(texel(p)); }

// How far to blend towards the neighbour across the edge (0 .. 0.5): walks both ways along the edge
// until the luma along it (both rows' average) leaves the edge's average; the nearer end decides, and
// blends only when the edge's luma there crosses the way the centre's does (`centreBelow`).
float edgeBlend(ivec2 p, ivec2 along, ivec2 across, bool horizontal, float lumaLocal, float gradientScaled,
                bool centreBelow) {
  ivec2 pN = p, pP = p;
  float endN = 0.0, endP = 0.0;
  bool doneN = false, doneP = false;
  for (int i = 0; i < kSteps && !(doneN && doneP); ++i) {
    if (!doneN) {
      pN -= along * kStep[i];
      endN = 0.5 * (lumaAt(pN) + lumaAt(pN + across)) - lumaLocal;
      doneN = abs(endN) >= gradientScaled;
    }
    if (!doneP) {
      pP += along * kStep[i];
      endP = 0.5 * (lumaAt(pP) + lumaAt(pP + across)) - lumaLocal;
      doneP = abs(endP) >= gradientScaled;
    }
  }
  float distanceN = float(horizontal ? p.x - pN.x : p.y - pN.y);
  float distanceP = float(horizontal ? pP.x - p.x : pP.y - p.y);
  bool nearN = distanceN < distanceP;
  bool goodSpan = ((nearN ? endN : endP) < 0.0) != centreBelow;
  return goodSpan ? 0.5 - min(distanceN, distanceP) / (distanceN + distanceP) : 0.0;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 colourM = texel(p), colourN = texel(p + ivec2(0, -1)), colourS = texel(p + ivec2(0, 1));
  vec4 colourW = texel(p + ivec2(-1, 0)), colourE = texel(p + ivec2(1, 0));
  float lumaM = luma(colourM), lumaN = luma(colourN), lumaS = luma(colourS), lumaW = luma(colourW),
        lumaE = luma(colourE);
  float lumaMax = max(max(max(lumaN, lumaS), max(lumaW, lumaE)), lumaM);
  float lumaMin = min(min(min(lumaN, lumaS), min(lumaW, lumaE)), lumaM);
  float range = lumaMax - lumaMin;
  if (range < max(kEdgeThresholdMin, lumaMax * kEdgeThreshold)) {
    outColour = colourM;
    return;
  }
  float lumaNW = lumaAt(p + ivec2(-1, -1)), lumaNE = lumaAt(p + ivec2(1, -1));
  float lumaSW = lumaAt(p + ivec2(-1, 1)), lumaSE = lumaAt(p + ivec2(1, 1));

  // Edge direction: horizontal (the edge runs along x) when the vertical second differences win.
  float edgeHorizontal = abs(lumaNW - 2.0 * lumaW + lumaSW) + 2.0 * abs(lumaN - 2.0 * lumaM + lumaS) +
                         abs(lumaNE - 2.0 * lumaE + lumaSE);
  float edgeVertical = abs(lumaNW - 2.0 * lumaN + lumaNE) + 2.0 * abs(lumaW - 2.0 * lumaM + lumaE) +
                       abs(lumaSW - 2.0 * lumaS + lumaSE);
  bool horizontal = edgeHorizontal >= edgeVertical;

  // Sub-pixel blend from the 3x3 low-pass against the centre.
  float average = (2.0 * (lumaN + lumaS + lumaW + lumaE) + lumaNW + lumaNE + lumaSW + lumaSE) / 12.0;
  float subpixC = clamp(abs(average - lumaM) / range, 0.0, 1.0);
  float subpix = (-2.0 * subpixC + 3.0) * subpixC * subpixC;
  subpix = subpix * subpix * kSubpix;

  // The side of the edge with the larger gradient: the neighbour across the edge.
  float luma1 = horizontal ? lumaN : lumaW, luma2 = horizontal ? lumaS : lumaE;
  bool side1 = abs(luma1 - lumaM) >= abs(luma2 - lumaM);
  float gradientScaled = 0.25 * max(abs(luma1 - lumaM), abs(luma2 - lumaM));
  ivec2 across = horizontal ? ivec2(0, side1 ? -1 : 1) : ivec2(side1 ? -1 : 1, 0);
  ivec2 along = horizontal ? ivec2(1, 0) : ivec2(0, 1);
  float lumaLocal = 0.5 * ((side1 ? luma1 : luma2) + lumaM);

  float offset = edgeBlend(p, along, across, horizontal, lumaLocal, gradientScaled, lumaM - lumaLocal < 0.0);
  offset = max(offset, subpix);
  vec4 colourAcross = horizontal ? (side1 ? colourN : colourS) : (side1 ? colourW : colourE);
  outColour = mix(colourM, colourAcross, offset);
}
