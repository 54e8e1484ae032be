// No pops: moving the camera by 1 mm changes the rendered depth by about 1 mm and the colour
// (shaded from the normal maps, blended with the parent's by the morph factor) by next to nothing,
// everywhere but at a few occlusion edges — no node switches level or snaps without morphing.
#include "engine/io/image_io.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "planet/model/planet_file.h"
#include "tests/support/gpu_test.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace globe::testing {
namespace {

constexpr uint32_t kWidth = 128, kHeight = 96;

struct PopCase {
  const char* name;
  GeodeticPose pose;
};
constexpr PopCase kPopCases[] = {{"2 m", {22.1, -98.3, 2.0, 60, -10, 0}},
                                 {"1 km", {22.05, -98.4, 1000.0, 60, -10, 0}},
                                 {"100 km", {22.0, -99.0, 1.0e5, 60, -30, 0}}};

// Renders `c` and the same camera 1 mm forward; the depth and colour change within bounds.
void expectNoPop(vk::Device& device, const ElevationModel& model, const TerrainSettings& settings, const PopCase& c,
                 const std::string& label) {
  auto terrain = Terrain::create(device, model, settings);
  ASSERT_TRUE(terrain.ok()) << terrain.error().format();
  HeadlessRenderer renderer(device, {kWidth, kHeight});
  glm::dvec3 down = directionFromLatLon(c.pose.latitude_deg, c.pose.longitude_deg);
  Camera a =
      cameraFromPose(c.pose, model.radius_m() + model.elevation_m(down), model.shape(), double(kWidth) / kHeight);
  Camera b = a;
  b.position_m += a.forward * 1e-3;  // 1 mm forward
  renderer.renderFrame(**terrain, a, true);
  ImageRgba ia = toImage(renderer.readback(), a);
  renderer.renderFrame(**terrain, b, true);
  ImageRgba ib = toImage(renderer.readback(), b);
  std::vector<double> diffs;
  int jumps = 0, hits = 0, colourJumps = 0;
  for (size_t i = 0; i < ia.z.size(); ++i) {
    bool ha = std::isfinite(ia.z[i]), hb = std::isfinite(ib.z[i]);
    if (ha != hb) ++jumps;  // silhouette pixels may flip
    if (!ha || !hb) continue;
    ++hits;
    double d = std::abs(double(ia.z[i]) - double(ib.z[i]));
    diffs.push_back(d);
    float colour = 0.0f;
    for (size_t ch = 0; ch < 3; ++ch)
      colour = std::max(
          colour, std::abs(float(linearToSrgb8(ia.rgba[4 * i + ch])) - float(linearToSrgb8(ib.rgba[4 * i + ch]))));
    if (colour > 12.0f) ++colourJumps;  // 12 sRGB steps: a pop, or an occlusion edge
    // More than 1 cm + 0.1 % of the distance: an occlusion edge moved under this pixel, or a pop.
    if (d > 0.01 + 1e-3 * double(ia.z[i])) ++jumps;
  }
  ASSERT_GT(hits, int(kWidth * kHeight / 4)) << label;
  std::sort(diffs.begin(), diffs.end());
  double p99 = diffs[diffs.size() * 99 / 100];
  std::printf(
      "[ info ] %s: depth change for a 1 mm step: p50 %.3g m, p99 %.3g m; %d edge pixels of %d, %d changed "
      "colour by > 12 steps\n",
      label.c_str(), diffs[diffs.size() / 2], p99, jumps, hits, colourJumps);
  EXPECT_LT(p99, 0.01 + 1e-4 * double(ia.z[ia.z.size() / 2])) << label;
  EXPECT_LT(jumps, int(kWidth * kHeight / 100)) << label << ": more than 1 % of the pixels jumped";
  EXPECT_LT(colourJumps, int(kWidth * kHeight / 100)) << label << ": more than 1 % of the pixels changed colour";
}

// On earthlike's sphere, on WGS84 and on flattening 0.1 (issue #18).
class NoPopsTest : public GpuTest, public ::testing::WithParamInterface<PlanetShapeCase> {};
INSTANTIATE_TEST_SUITE_P(Shapes, NoPopsTest, ::testing::ValuesIn(kPlanetShapes), planetShapeName);

TEST_P(NoPopsTest, OneMillimetreStepChangesDepthSmoothly) {
  const ElevationModel& model = earthlikeModel(GetParam());
  TerrainSettings settings;
  settings.gridCells = 16;
  settings.style.sky = false;
  settings.viewHeight_px = kHeight;
  // Distance ranges, then tolerance-driven ranges from the generated payloads' errors, per depth and
  // following the relief's roughness (docs/lod.md).
  for (const auto& [tolerance, roughness] : {std::pair{0.0, false}, {2.0, false}, {2.0, true}})
    for (const PopCase& c : kPopCases) {
      settings.ranges.tolerance_px = tolerance;
      settings.ranges.roughness = roughness;
      expectNoPop(device(), model, settings, c,
                  std::string(GetParam().name) + " " + c.name + " tolerance " + std::to_string(tolerance) +
                      (roughness ? " with roughness" : ""));
    }
}

// The default preset as shipped: grid 8, 32 texels a node (surface textures blended with the
// parent's as the mesh morphs), the 8 px tolerance and the texel rule.
class NoPopsPresetTest : public GpuTest {};

TEST_F(NoPopsPresetTest, BalancedOneMillimetreStepChangesDepthAndColourSmoothly) {
  TerrainSettings settings = terrainSettingsFor(QualityPreset::kBalanced);
  settings.style.sky = false;
  settings.viewHeight_px = kHeight;
  for (const PopCase& c : kPopCases)
    expectNoPop(device(), earthlikeModel(), settings, c, std::string("balanced ") + c.name);
}

}  // namespace
}  // namespace globe::testing
