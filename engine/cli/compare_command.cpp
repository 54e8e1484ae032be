// globe compare: how a rendered image looks against a reference (docs/rendering.md, "Colour").
#include "commands.h"
#include "engine/io/image_io.h"
#include "engine/report/image_compare.h"
#include "options.h"

#include <cstdio>
#include <memory>

namespace globe::cli {

namespace {

struct CompareFiles {
  std::string image;
  std::string reference;
  std::string earth;
};

ImageView view(const ImageRgba& image) { return {image.width, image.height, image.rgba}; }

// The same camera rendered twice: SSIM of luminance and the mean colours' difference.
int compareRenders(const ImageRgba& image, const CompareFiles& f) {
  auto reference = readImage8(f.reference);
  if (!reference) return usageError(reference.error());
  if (reference->width != image.width || reference->height != image.height)
    return usageError(Error::inFile(f.reference, "is " + std::to_string(reference->width) + "x" +
                                                     std::to_string(reference->height) + ", the image " +
                                                     std::to_string(image.width) + "x" + std::to_string(image.height)));
  std::printf("ssim %.4f  mean colour dE2000 %.2f\n", ssimLuminance(view(image), view(*reference)),
              meanColourDifference(view(image), view(*reference)));
  return kExitOk;
}

// A view of the planet against an equirectangular map of the Earth, class by class.
int compareEarth(const ImageRgba& image, const CompareFiles& f) {
  auto map = readImage8(f.earth);
  if (!map) return usageError(map.error());
  EarthColours ours = earthColours(view(image), false), earth = earthColours(view(*map), true);
  if (!ours.valid())
    return usageError(Error::inFile(f.image, "shows no land and sea pixels to compare (classed by colour)"));
  if (!earth.valid()) return usageError(Error::inFile(f.earth, "holds no land and sea pixels (classed by colour)"));
  EarthComparison c = compareEarthColours(ours, earth);
  std::printf(
      "land dE2000 %.2f  sea dE2000 %.2f  land spread %.1f of %.1f (%.0f %%)  land share %.0f %% (map %.0f %%)\n",
      c.landDeltaE, c.seaDeltaE, ours.landSpread, earth.landSpread, 100.0 * c.spreadRatio, 100.0 * ours.landShare,
      100.0 * earth.landShare);
  std::printf("land Lab %.1f %.1f %.1f (map %.1f %.1f %.1f)  sea Lab %.1f %.1f %.1f (map %.1f %.1f %.1f)\n",
              ours.landLab.x, ours.landLab.y, ours.landLab.z, earth.landLab.x, earth.landLab.y, earth.landLab.z,
              ours.seaLab.x, ours.seaLab.y, ours.seaLab.z, earth.seaLab.x, earth.seaLab.y, earth.seaLab.z);
  return kExitOk;
}

int runCompare(const CompareFiles& f) {
  if (f.reference.empty() == f.earth.empty())
    return usageError({"", 0, 0, "--reference", "give exactly one of --reference and --earth"});
  auto image = readImage8(f.image);
  if (!image) return usageError(image.error());
  return f.earth.empty() ? compareRenders(*image, f) : compareEarth(*image, f);
}

}  // namespace

void addCompareCommand(CLI::App& app, Runner& run) {
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare a rendered image with a reference render (SSIM, colour) or with a map of the Earth");
  auto f = std::make_shared<CompareFiles>();
  cmd->add_option("IMAGE", f->image, "The rendered image (PNG or JPEG)")->required();
  cmd->add_option("--reference", f->reference,
                  "The same camera's reference render (e.g. --quality exact): prints the SSIM of luminance and the "
                  "CIEDE2000 difference of the mean colours");
  cmd->add_option("--earth", f->earth,
                  "An equirectangular map of the Earth (e.g. /usr/share/xplanet/images/earth.jpg, NASA Blue Marble): "
                  "prints the CIEDE2000 differences of the mean land and sea colours and the land colours' spread");
  cmd->callback([f, &run] { run = [f] { return runCompare(*f); }; });
}

}  // namespace globe::cli
