#include "engine/measure/trade_images.h"

#include "engine/render/render_output.h"
#include "engine/report/image_compare.h"

namespace globe {

Result<std::vector<ImageRgba>> renderExactReferences(vk::Device& device, HeadlessRenderer& renderer,
                                                     const ElevationModel& model, TerrainSettings exact,
                                                     const std::vector<Camera>& cameras,
                                                     const std::function<void(double)>& progress) {
  std::vector<ImageRgba> references;
  for (const Camera& camera : cameras) {
    exact.style.sunDirection = defaultSunDirection(camera.position_m);
    auto terrain = Terrain::create(device, model, exact);  // fresh per camera, as each measurement
    if (!terrain) return terrain.error();
    renderer.renderFrame(**terrain, camera, true);
    references.push_back(toImage(renderer.readback(), camera));
    if (progress) progress(double(references.size()) / double(cameras.size()));
  }
  return references;
}

void compareWithReference(TradeRow& row, const ImageRgba& image, const ImageRgba& reference) {
  const ImageView a{image.width, image.height, image.rgba};
  const ImageView b{reference.width, reference.height, reference.rgba};
  row.imageSsim = ssimLuminance(a, b);
  row.imageColourDe = meanColourDifference(a, b);
}

}  // namespace globe
