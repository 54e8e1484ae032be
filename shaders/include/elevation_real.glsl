// Precision-generic body of the elevation function, included by elevation.glsl once per precision
// with GLOBE_REAL (double or float), GLOBE_REAL3 (its vec3) and GLOBE_FN(name) (the function's name
// in that precision) defined. Literals are written GLOBE_REAL(small integer), exact in both. No
// include guard on purpose.

// = globe::gradientDot: Perlin's 16 gradients (12 cube edges), index = top 4 bits of the hash.
GLOBE_REAL GLOBE_FN(globeGradientDot)(uint hash, GLOBE_REAL x, GLOBE_REAL y, GLOBE_REAL z) {
  uint h = hash >> 28;
  GLOBE_REAL u = h < 8u ? x : y;
  GLOBE_REAL v = h < 4u ? y : ((h == 12u || h == 14u) ? x : z);
  precise GLOBE_REAL a = (h & 1u) == 0u ? u : -u;
  precise GLOBE_REAL b = (h & 2u) == 0u ? v : -v;
  precise GLOBE_REAL r = a + b;
  return r;
}

GLOBE_REAL GLOBE_FN(globeNoiseFade)(GLOBE_REAL t) {
  precise GLOBE_REAL r = t * t * t * (t * (t * GLOBE_REAL(6.0) - GLOBE_REAL(15.0)) + GLOBE_REAL(10.0));
  return r;
}

GLOBE_REAL GLOBE_FN(globeNoiseLerp)(GLOBE_REAL a, GLOBE_REAL b, GLOBE_REAL t) {
  precise GLOBE_REAL r = a + t * (b - a);
  return r;
}

// = globe::gradientNoise<Real>.
GLOBE_REAL GLOBE_FN(globeGradientNoise)(GLOBE_REAL x, GLOBE_REAL y, GLOBE_REAL z, uint seed) {
  precise GLOBE_REAL fx = floor(x);
  precise GLOBE_REAL fy = floor(y);
  precise GLOBE_REAL fz = floor(z);
  int64_t ix = int64_t(fx);
  int64_t iy = int64_t(fy);
  int64_t iz = int64_t(fz);
  precise GLOBE_REAL x0 = x - fx;
  precise GLOBE_REAL y0 = y - fy;
  precise GLOBE_REAL z0 = z - fz;
  precise GLOBE_REAL x1 = x0 - GLOBE_REAL(1.0);
  precise GLOBE_REAL y1 = y0 - GLOBE_REAL(1.0);
  precise GLOBE_REAL z1 = z0 - GLOBE_REAL(1.0);

  // = globe::latticeWordX/Y/Z, then one globe::latticeCornerHash per corner.
  uint wx0 = globeLatticeKey(ix) * 0x9e3779b1u;
  uint wx1 = globeLatticeKey(ix + 1L) * 0x9e3779b1u;
  uint wy0 = globeLatticeKey(iy) * 0x85ebca77u;
  uint wy1 = globeLatticeKey(iy + 1L) * 0x85ebca77u;
  uint wz0 = globeLatticeKey(iz) * 0xc2b2ae3du;
  uint wz1 = globeLatticeKey(iz + 1L) * 0xc2b2ae3du;
  precise GLOBE_REAL g000 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx0, wy0, wz0, seed), x0, y0, z0);
  precise GLOBE_REAL g100 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx1, wy0, wz0, seed), x1, y0, z0);
  precise GLOBE_REAL g010 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx0, wy1, wz0, seed), x0, y1, z0);
  precise GLOBE_REAL g110 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx1, wy1, wz0, seed), x1, y1, z0);
  precise GLOBE_REAL g001 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx0, wy0, wz1, seed), x0, y0, z1);
  precise GLOBE_REAL g101 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx1, wy0, wz1, seed), x1, y0, z1);
  precise GLOBE_REAL g011 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx0, wy1, wz1, seed), x0, y1, z1);
  precise GLOBE_REAL g111 = GLOBE_FN(globeGradientDot)(globeLatticeCornerHash(wx1, wy1, wz1, seed), x1, y1, z1);

  precise GLOBE_REAL u = GLOBE_FN(globeNoiseFade)(x0);
  precise GLOBE_REAL v = GLOBE_FN(globeNoiseFade)(y0);
  precise GLOBE_REAL w = GLOBE_FN(globeNoiseFade)(z0);
  precise GLOBE_REAL a00 = GLOBE_FN(globeNoiseLerp)(g000, g100, u);
  precise GLOBE_REAL a10 = GLOBE_FN(globeNoiseLerp)(g010, g110, u);
  precise GLOBE_REAL a01 = GLOBE_FN(globeNoiseLerp)(g001, g101, u);
  precise GLOBE_REAL a11 = GLOBE_FN(globeNoiseLerp)(g011, g111, u);
  precise GLOBE_REAL b0 = GLOBE_FN(globeNoiseLerp)(a00, a10, v);
  precise GLOBE_REAL b1 = GLOBE_FN(globeNoiseLerp)(a01, a11, v);
  precise GLOBE_REAL r = GLOBE_FN(globeNoiseLerp)(b0, b1, w);
  return r;
}

// = globe::craterProfile<Real>: one crater's height at s = r^2 / R^2, in units of its depth.
GLOBE_REAL GLOBE_FN(globeCraterProfile)(GLOBE_REAL s) {
  if (s < GLOBE_REAL(1.0)) {
    precise GLOBE_REAL r = GLOBE_REAL(-1.0) + (GLOBE_REAL(1.0) + GLOBE_REAL(0.25)) * (s * s);
    return r;
  }
  if (s < GLOBE_REAL(1.5)) {
    precise GLOBE_REAL t = GLOBE_REAL(2.0) * (GLOBE_REAL(1.5) - s);
    precise GLOBE_REAL r = GLOBE_REAL(0.25) * (t * t * t);
    return r;
  }
  return GLOBE_REAL(0.0);
}

// = globe::craterCell<Real>: the crater of one lattice cell at offset (x, y, z) from its corner.
GLOBE_REAL GLOBE_FN(globeCraterCell)(uint hash, GLOBE_REAL x, GLOBE_REAL y, GLOBE_REAL z) {
  uint h = globeHashMix32(hash);
  if ((h & 1u) == 0u) return GLOBE_REAL(0.0);
  uint k = (h >> 1) & 3u;
  precise GLOBE_REAL cx = GLOBE_REAL((h >> 8) & 255u) * GLOBE_REAL(0.00390625);
  precise GLOBE_REAL cy = GLOBE_REAL((h >> 16) & 255u) * GLOBE_REAL(0.00390625);
  precise GLOBE_REAL cz = GLOBE_REAL(h >> 24) * GLOBE_REAL(0.00390625);
  precise GLOBE_REAL ox = x - cx;
  precise GLOBE_REAL oy = y - cy;
  precise GLOBE_REAL oz = z - cz;
  // kCraterInverseRadiusSquared = 8 * 2^k and kCraterDepthScale = {1, 0.75, 0.5, 0.375}, exact.
  GLOBE_REAL inverseRadiusSquared = k == 0u ? GLOBE_REAL(8.0) : k == 1u ? GLOBE_REAL(16.0)
                                  : k == 2u ? GLOBE_REAL(32.0) : GLOBE_REAL(64.0);
  GLOBE_REAL depthScale = k == 0u ? GLOBE_REAL(1.0) : k == 1u ? GLOBE_REAL(0.75)
                        : k == 2u ? GLOBE_REAL(0.5) : GLOBE_REAL(0.375);
  precise GLOBE_REAL s = (ox * ox + oy * oy + oz * oz) * inverseRadiusSquared;
  precise GLOBE_REAL r = depthScale * GLOBE_FN(globeCraterProfile)(s);
  return r;
}

// = globe::craterField<Real>: the 2x2x2 cells at floor(q - 1/2) hold every crater reaching q.
GLOBE_REAL GLOBE_FN(globeCraterField)(GLOBE_REAL x, GLOBE_REAL y, GLOBE_REAL z, uint seed) {
  precise GLOBE_REAL fx = floor(x - GLOBE_REAL(0.5));
  precise GLOBE_REAL fy = floor(y - GLOBE_REAL(0.5));
  precise GLOBE_REAL fz = floor(z - GLOBE_REAL(0.5));
  int64_t ix = int64_t(fx);
  int64_t iy = int64_t(fy);
  int64_t iz = int64_t(fz);
  precise GLOBE_REAL x0 = x - fx;
  precise GLOBE_REAL y0 = y - fy;
  precise GLOBE_REAL z0 = z - fz;
  precise GLOBE_REAL deepest = GLOBE_REAL(0.0);
  precise GLOBE_REAL raised = GLOBE_REAL(0.0);
  [[unroll]] for (int c = 0; c < 8; ++c) {
    int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
    uint hash = globeLatticeCornerHash(globeLatticeKey(ix + int64_t(dx)) * 0x9e3779b1u,
                                       globeLatticeKey(iy + int64_t(dy)) * 0x85ebca77u,
                                       globeLatticeKey(iz + int64_t(dz)) * 0xc2b2ae3du, seed);
    precise GLOBE_REAL crater = GLOBE_FN(globeCraterCell)(hash, x0 - GLOBE_REAL(dx), y0 - GLOBE_REAL(dy), z0 - GLOBE_REAL(dz));
    deepest = min(deepest, crater);
    raised = raised + max(crater, GLOBE_REAL(0.0));
  }
  precise GLOBE_REAL r = deepest + raised;
  return r;
}

// Layer l of globe::ElevationModel::elevation_m. l is a literal at every call, so after inlining
// the octave count, kind and modulator are constants and the octave loop unrolls (lavapipe keeps no
// loop-carried value in registers across a loop's iterations).
void GLOBE_FN(globeElevationLayer)(uint l, GLOBE_REAL px, GLOBE_REAL py, GLOBE_REAL pz,
                                   inout GLOBE_REAL values[GLOBE_MAX_ELEVATION_LAYERS], inout GLOBE_REAL total) {
  precise GLOBE_REAL lacunarity = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].lacunarity);
  precise GLOBE_REAL gain = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].gain);
  precise GLOBE_REAL frequency = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].frequency);
  precise GLOBE_REAL amplitude = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].amplitude_m);
  uint seed = GLOBE_ELEVATION_PARAMS.layers[l].seed;
  uint octaves = globeLayerOctaves(l);
  uint kind = globeLayerKind(l);
  int modulator = globeLayerModulator(l);
  // Scale first, octaves skipped where it is exactly 0: bit-identical, see planet/elevation/layer_evaluation.h.
  precise GLOBE_REAL scale = GLOBE_REAL(1.0);
  if (modulator >= 0) {
    precise GLOBE_REAL low = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].modulation_low_m);
    precise GLOBE_REAL inv_range = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].modulation_inv_range);
    precise GLOBE_REAL floor_scale = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].modulation_floor);
    precise GLOBE_REAL m = (values[max(modulator, 0)] - low) * inv_range;
    m = min(max(m, GLOBE_REAL(0.0)), GLOBE_REAL(1.0));
    precise GLOBE_REAL s = m * m * (GLOBE_REAL(3.0) - GLOBE_REAL(2.0) * m);
    scale = floor_scale + (GLOBE_REAL(1.0) - floor_scale) * s;
  }
  precise GLOBE_REAL sum = GLOBE_REAL(0.0);
  if (scale != GLOBE_REAL(0.0)) {
    [[unroll]] for (uint o = 0u; o < octaves; ++o) {
      precise GLOBE_REAL t;
      if (kind == GLOBE_LAYER_CRATERS) {
        t = GLOBE_FN(globeCraterField)(px * frequency, py * frequency, pz * frequency, seed);
      } else {
        precise GLOBE_REAL n = GLOBE_FN(globeGradientNoise)(px * frequency, py * frequency, pz * frequency, seed);
        t = n;
        if (kind == GLOBE_LAYER_RIDGED) {
          precise GLOBE_REAL c = GLOBE_REAL(1.0) - abs(n);
          t = c * c;
        } else if (kind == GLOBE_LAYER_BILLOW) {
          t = abs(n);
        }
      }
      sum = sum + amplitude * t;
      frequency = frequency * lacunarity;
      amplitude = amplitude * gain;
      seed = seed + 0x9e3779b9u;
    }
  }
  if (modulator >= 0) sum = sum * scale;
  precise GLOBE_REAL value = sum + GLOBE_REAL(GLOBE_ELEVATION_PARAMS.layers[l].offset_m);
  values[l] = value;
  total = total + value;
}

// = globe::ElevationModel::elevation_m: elevation above radius_m at a unit direction, metres; and
// the first layer's value (= ElevationModel::firstLayer_m), which the land cover's climate reads.
GLOBE_REAL GLOBE_FN(globeElevationWithFirstLayer)(GLOBE_REAL3 unit_direction, out GLOBE_REAL firstLayer) {
  precise GLOBE_REAL radius = GLOBE_REAL(GLOBE_ELEVATION_PARAMS.radius_m);
  precise GLOBE_REAL px = unit_direction.x * radius;
  precise GLOBE_REAL py = unit_direction.y * radius;
  precise GLOBE_REAL pz = unit_direction.z * radius;
  GLOBE_REAL values[GLOBE_MAX_ELEVATION_LAYERS];
  precise GLOBE_REAL total = GLOBE_REAL(0.0);
  // Unrolled by hand: the compiler won't unroll a loop that holds another.
  GLOBE_FN(globeElevationLayer)(0u, px, py, pz, values, total);
  if (kGlobeLayerCount > 1u) GLOBE_FN(globeElevationLayer)(1u, px, py, pz, values, total);
  if (kGlobeLayerCount > 2u) GLOBE_FN(globeElevationLayer)(2u, px, py, pz, values, total);
  if (kGlobeLayerCount > 3u) GLOBE_FN(globeElevationLayer)(3u, px, py, pz, values, total);
  if (kGlobeLayerCount > 4u) GLOBE_FN(globeElevationLayer)(4u, px, py, pz, values, total);
  if (kGlobeLayerCount > 5u) GLOBE_FN(globeElevationLayer)(5u, px, py, pz, values, total);
  if (kGlobeLayerCount > 6u) GLOBE_FN(globeElevationLayer)(6u, px, py, pz, values, total);
  if (kGlobeLayerCount > 7u) GLOBE_FN(globeElevationLayer)(7u, px, py, pz, values, total);
  firstLayer = values[0];
  return total;
}

GLOBE_REAL GLOBE_FN(globeElevation)(GLOBE_REAL3 unit_direction) {
  GLOBE_REAL firstLayer;
  return GLOBE_FN(globeElevationWithFirstLayer)(unit_direction, firstLayer);
}

