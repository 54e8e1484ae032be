#include "trade_images.h"

#include "engine/render/render_output.h"
#include "engine/report/image_compare.h"
#include "options.h"
#include "progress_bar.h"

namespace globe::cli {

Result<std::vector<ImageRgba>> renderExactReferences(vk::Device& device, HeadlessRenderer& renderer,
                                                     const ElevationModel& model, const PlanetDescription& planet,
                                                     const std::vector<Camera>& cameras, double viewHeight_px) {
  QualityOptions exact;
  exact.quality = "exact";
  auto settings = terrainSettingsFromOptions(exact, planet, viewHeight_px);
  if (!settings) return settings.error();
  std::vector<ImageRgba> references;
  ProgressBar progress("trade: exact images");
  for (const Camera& camera : cameras) {
    settings->style.sunDirection = defaultSunDirection(camera.position_m);
    auto terrain = Terrain::create(device, model, *settings);  // fresh per camera, as each measurement
    if (!terrain) return terrain.error();
    renderer.renderFrame(**terrain, camera, true);
    references.push_back(toImage(renderer.readback(), camera));
    progress.update(double(references.size()) / double(cameras.size()));
  }
  return references;
}

void compareWithReference(TradeRow& row, const ImageRgba& image, const ImageRgba& reference) {
  const ImageView a{image.width, image.height, image.rgba};
  const ImageView b{reference.width, reference.height, reference.rgba};
  row.imageSsim = ssimLuminance(a, b);
  row.imageColourDe = meanColourDifference(a, b);
}

}  // namespace globe::cli
