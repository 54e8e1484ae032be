// The sea's colour per fragment (terrain_water.frag): body colour tinted by the depth of the ground
// below, lit by the sun on the flat sea surface, plus the sky reflected by Schlick's Fresnel term and
// a sun glint. Per fragment because the view angle changes within the large flat triangles of a
// sea near the camera (per vertex, a camera 10 cm above the water saw a sky-coloured sea at its
// feet). Reads the frame constants; no branch or loop depends on them alone (docs/rendering.md,
// "No shader compile per frame"). The includer declares the frame constants (TerrainFrameBlock).
// `sunShare`: the sun's share the relief lets through (terrain_shadows.glsl; 1 without shadows): a
// shaded sea loses its sunlit body and its glint, as the land does.

// Reflectance of water at normal incidence ((1.33 - 1) / (1.33 + 1))^2.
const float kWaterF0 = 0.02;
// Sharpness of the glint (a Phong-like lobe standing in for a wavy surface) and its strength.
const float kGlintExponent = 600.0;
const float kGlintStrength = 6.0;

vec3 waterColour(float depth_m, vec3 relative, float sunShare) {
  // The camera-to-fragment ray and the sea's normal (the local vertical): directions only, so
  // float is enough although the planet centre is far.
  vec3 up = normalize(relative - frame.centreFromCamera.xyz);
  vec3 view = normalize(relative);
  vec3 sun = frame.sun.xyz;
  float sunHeight = dot(up, sun);
  float light = frame.sun.w + (1.0 - frame.sun.w) * max(sunHeight, 0.0) * sunShare;
  float murk = 1.0 - exp(-depth_m * frame.waterDeep.w);
  vec3 body = mix(frame.waterShallow.rgb, frame.waterDeep.rgb, murk) * light;
  float cosView = clamp(-dot(view, up), 0.0, 1.0);
  float fresnel = kWaterF0 + (1.0 - kWaterF0) * pow(1.0 - cosView, 5.0);
  vec3 reflected = reflect(view, up);
  float skyUp = clamp(dot(reflected, up), 0.0, 1.0);
  // The sky's colours (the atmosphere's from the vertex stage, else the fixed gradient's), dimmed on
  // the night side.
#ifdef GLOBE_TERRAIN_ATMOSPHERE
  vec3 sky = mix(inSkyHorizon, inSkyZenith, sqrt(skyUp));
#else
  vec3 sky = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, sqrt(skyUp));
#endif
  sky *= clamp(sunHeight * 4.0 + 0.1, 0.0, 1.0);
  float glint = pow(max(dot(reflected, sun), 0.0), kGlintExponent) * kGlintStrength * step(0.0, sunHeight) * sunShare;
  vec3 c = mix(body, sky, fresnel) + vec3(glint);
  // Through the air to the camera as the land's vertices are (terrain_atmosphere.glsl, or the
  // analytic haze, terrain_haze.glsl).
  c = c * inAerialTransmittance + inAerialInscatter;
  return encodeScene(c, 1.0).rgb;
}
