#version 450
// FXAA 3.11 "quality" [Lottes 2011] on the display-encoded scene colour (perceptual, as FXAA wants
// its luma): finds the local edge, walks along it to both ends (up to 8 steps) and re-samples the
// image across the edge by the pixel's estimated coverage; sub-pixel aliasing is blended by the
// 3x3 neighbourhood's contrast. Branches depend on the image, never on push constants alone.
layout(location = 0) in vec2 inNdc;
layout(location = 0) out vec4 outColour;

layout(binding = 0) uniform sampler2D scene;
layout(push_constant) uniform Push {
  vec2 texel;  // 1 / image size
} push;

const float kEdgeThreshold = 0.166;      // local contrast (of the brightest luma) below which nothing is done
const float kEdgeThresholdMin = 0.0833;  // ... and an absolute floor (dark areas)
const float kSubpix = 0.75;              // amount of sub-pixel blending
const int kSteps = 8;
const float kStep[kSteps] = float[](1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);

float luma(vec4 c) { return dot(c.rgb, vec3(0.299, 0.587, 0.114)); }
float lumaAt(vec2 uv) { return luma(textureLod(scene, uv, 0.0)); }
float lumaAt(vec2 uv, vec2 offsetPixels) { return lumaAt(uv + offsetPixels * push.texel); }

void main() {
  vec2 uv = gl_FragCoord.xy * push.texel;
  vec4 colourM = textureLod(scene, uv, 0.0);
  float lumaM = luma(colourM);
  float lumaN = lumaAt(uv, vec2(0, -1)), lumaS = lumaAt(uv, vec2(0, 1));
  float lumaW = lumaAt(uv, vec2(-1, 0)), lumaE = lumaAt(uv, vec2(1, 0));
  float lumaMax = max(max(max(lumaN, lumaS), max(lumaW, lumaE)), lumaM);
  float lumaMin = min(min(min(lumaN, lumaS), min(lumaW, lumaE)), lumaM);
  float range = lumaMax - lumaMin;
  if (range < max(kEdgeThresholdMin, lumaMax * kEdgeThreshold)) {
    outColour = colourM;
    return;
  }
  float lumaNW = lumaAt(uv, vec2(-1, -1)), lumaNE = lumaAt(uv, vec2(1, -1));
  float lumaSW = lumaAt(uv, vec2(-1, 1)), lumaSE = lumaAt(uv, vec2(1, 1));

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

  // The side of the edge with the larger gradient; the search runs half a pixel towards it.
  float luma1 = horizontal ? lumaN : lumaW, luma2 = horizontal ? lumaS : lumaE;
  float gradient1 = luma1 - lumaM, gradient2 = luma2 - lumaM;
  bool side1 = abs(gradient1) >= abs(gradient2);
  float gradientScaled = 0.25 * max(abs(gradient1), abs(gradient2));
  float stepLength = horizontal ? push.texel.y : push.texel.x;
  stepLength = side1 ? -stepLength : stepLength;
  float lumaLocal = 0.5 * ((side1 ? luma1 : luma2) + lumaM);
  vec2 edgeUv = uv + (horizontal ? vec2(0.0, 0.5 * stepLength) : vec2(0.5 * stepLength, 0.0));
  vec2 along = horizontal ? vec2(push.texel.x, 0.0) : vec2(0.0, push.texel.y);

  // Walk both ways until the luma along the edge leaves the edge's average.
  vec2 uvN = edgeUv - along * kStep[0], uvP = edgeUv + along * kStep[0];
  float endN = lumaAt(uvN) - lumaLocal, endP = lumaAt(uvP) - lumaLocal;
  bool doneN = abs(endN) >= gradientScaled, doneP = abs(endP) >= gradientScaled;
  for (int i = 1; i < kSteps && !(doneN && doneP); ++i) {
    if (!doneN) {
      uvN -= along * kStep[i];
      endN = lumaAt(uvN) - lumaLocal;
      doneN = abs(endN) >= gradientScaled;
    }
    if (!doneP) {
      uvP += along * kStep[i];
      endP = lumaAt(uvP) - lumaLocal;
      doneP = abs(endP) >= gradientScaled;
    }
  }

  // The nearer end decides: blend only when the edge's luma there crosses the way the centre's does.
  float distanceN = horizontal ? uv.x - uvN.x : uv.y - uvN.y;
  float distanceP = horizontal ? uvP.x - uv.x : uvP.y - uv.y;
  bool nearN = distanceN < distanceP;
  bool centreBelow = lumaM - lumaLocal < 0.0;
  bool goodSpan = ((nearN ? endN : endP) < 0.0) != centreBelow;
  float offset = goodSpan ? 0.5 - min(distanceN, distanceP) / (distanceN + distanceP) : 0.0;
  offset = max(offset, subpix);
  vec2 finalUv = uv + (horizontal ? vec2(0.0, offset * stepLength) : vec2(offset * stepLength, 0.0));
  outColour = textureLod(scene, finalUv, 0.0);
}
