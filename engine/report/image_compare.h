#pragma once
// What a rendered image looks like against a reference: the same camera's reference render (SSIM
// of luminance [Wang et al. 2004], the difference of the mean colours), or the Earth itself, an
// equirectangular map such as NASA's Blue Marble (the mean colour of land and of ocean pixels and
// the spread of the land colours, each pixel classed by its colour). Colour differences are
// CIEDE2000 [Sharma et al. 2005] in CIELAB (D65), the unit of the figures in docs/rendering.md.
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>

namespace globe {

// Pixels as engine/io reads them: linear sRGB floats, 4 per pixel, row 0 at the top.
struct ImageView {
  uint32_t width = 0;
  uint32_t height = 0;
  std::span<const float> rgba;
};

// Linear sRGB -> CIELAB (D65 white, L in [0, 100]).
glm::dvec3 linearSrgbToLab(glm::dvec3 linear);
// CIEDE2000 colour difference of two CIELAB colours.
double deltaE2000(glm::dvec3 lab1, glm::dvec3 lab2);

// Mean SSIM of the display-encoded (sRGB) luma Y' of two images of one size: 11 x 11 Gaussian
// windows (sigma 1.5 px), K1 = 0.01, K2 = 0.03, windows within the image.
double ssimLuminance(const ImageView& image, const ImageView& reference);
// CIEDE2000 between the two images' mean CIELAB colours.
double meanColourDifference(const ImageView& image, const ImageView& reference);

// A pixel of a planet seen from afar, by its colour: space (black), sea (blue), snow, ice or cloud
// (bright and grey), land (everything else).
enum class EarthClass : uint8_t { kSpace, kSea, kBright, kLand };
EarthClass classifyEarthPixel(glm::dvec3 lab);

struct EarthColours {
  glm::dvec3 landLab{0.0};  // mean CIELAB of the land pixels
  glm::dvec3 seaLab{0.0};
  double landSpread = 0.0;  // RMS CIELAB distance of land pixels from their mean
  double landShare = 0.0;   // land's share of the land and sea pixels (weighted)
  bool valid() const { return landShare > 0.0 && landShare < 1.0; }
};
// A map (`equirectangular`: rows from 90 N to 90 S) weights each pixel by cos(latitude), the area it
// covers. A render shows the whole planet's disc against space: its pixels count equally within
// 0.8 of the disc's radius (seen at up to ~53 degrees from the vertical), like the map's views
// from above; the limb's long paths through the air and grazing sea reflections are left out.
EarthColours earthColours(const ImageView& image, bool equirectangular);

struct EarthComparison {
  double landDeltaE = 0.0;
  double seaDeltaE = 0.0;
  double spreadRatio = 0.0;  // the image's land spread / the reference's
};
EarthComparison compareEarthColours(const EarthColours& image, const EarthColours& reference);

}  // namespace globe
