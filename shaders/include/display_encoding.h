// How the scene's colour target stores colour, shared by C++ (engine/render/offscreen_target.cpp decodes
// it) and GLSL (display_encoding.glsl encodes it). The target is 8-bit UNORM: lavapipe writes that
// format ~17 % cheaper per frame than sRGB or half float (docs/rendering.md, "Scene colour format").
// A fragment shader stores e = A·√c − (A − 1)·c of its linear colour c clamped to [0, 1]: one square
// root instead of sRGB's power, within 0.022 of the sRGB curve over [0, 1] (A chosen for the least
// largest difference), so the viewer shows the target as it is through a UNORM swapchain. Readback
// inverts it exactly: √c = (A − √(A² − 4(A − 1)e)) / (2(A − 1)).
#ifndef GLOBE_DISPLAY_ENCODING_H
#define GLOBE_DISPLAY_ENCODING_H

#define GLOBE_DISPLAY_ENCODING_A 1.063
// Where the display transform leaves the linear (display_encoding.glsl, displayTone).
#define GLOBE_DISPLAY_TONE_KNEE 0.6

#endif
