// Payload surface words (albedo and hole mask in normal.w): packing and the reference's albedo.
#include "planet/model/planet_file.h"
#include "planet/streaming/payload_reference.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <bit>
#include <cmath>
#include <vector>

namespace globe {
namespace {

TEST(PayloadSurface, PackedColoursComeBackWithinOneStepOfTheirSquareRoot) {
  for (float c : {0.0f, 0.0005f, 0.005f, 0.02f, 0.2f, 0.5f, 0.9f, 1.0f}) {
    for (float hole : {0.0f, 0.3f, 0.5f, 1.0f}) {
      const PayloadSurface s = unpackPayloadSurface(packPayloadSurface(glm::vec3(c, 1.0f - c, c * 0.5f), hole));
      EXPECT_NEAR(std::sqrt(s.albedo.x), std::sqrt(c), 0.5 / 255.0 + 1e-6) << c;
      EXPECT_NEAR(std::sqrt(s.albedo.y), std::sqrt(1.0f - c), 0.5 / 255.0 + 1e-6) << c;
      EXPECT_NEAR(s.hole, hole, 0.5 / 255.0 + 1e-6) << hole;
      EXPECT_EQ(s.hole >= 0.5f, hole >= 0.5f) << hole;  // the kept-hole threshold survives
    }
  }
  // A dark sea colour keeps distinct steps (a linear byte would make 0.002 and 0.005 one value).
  EXPECT_NE(std::bit_cast<uint32_t>(packPayloadSurface(glm::vec3(0.002f), 0.0)),
            std::bit_cast<uint32_t>(packPayloadSurface(glm::vec3(0.005f), 0.0)));
  // Out-of-range inputs clamp instead of wrapping into the next byte.
  const PayloadSurface s = unpackPayloadSurface(packPayloadSurface(glm::vec3(2.0f, -1.0f, 0.5f), 3.0));
  EXPECT_EQ(s.albedo.x, 1.0f);
  EXPECT_EQ(s.albedo.y, 0.0f);
  EXPECT_EQ(s.hole, 1.0f);
}

TEST(PayloadSurface, ReferenceSamplesCarryTheRampAtTheirElevationAndSlope) {
  auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  planet->land_cover = {};  // the ramp colours only a planet without land cover
  const ElevationModel model(*planet);
  constexpr uint32_t kCells = 16;
  const NodeId node{7, 9, 300, 200};
  const gpu::PayloadJob job = makePayloadJob(node, 0, model);
  std::vector<glm::vec4> slot(GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells));
  fillPayloadReference(model, job, kCells, slot);
  const size_t samples = slot.size() / 2, side = kCells + 3;
  for (size_t j = 1; j + 1 < side; ++j) {
    for (size_t i = 1; i + 1 < side; ++i) {
      const size_t at = j * side + i;
      const glm::dvec3 position =
          glm::dvec3(job.centre.x, job.centre.y, job.centre.z) + glm::dvec3(glm::vec3(slot[at]));
      const double cosSlope = glm::dot(glm::dvec3(glm::vec3(slot[samples + at])), glm::normalize(position));
      const glm::vec3 expected = rampColour(model.colourRamp(), slot[at].w, cosSlope);
      const PayloadSurface s = unpackPayloadSurface(slot[samples + at].w);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(std::sqrt(s.albedo[c]), std::sqrt(expected[c]), 1.5 / 255.0) << i << ' ' << j;
      EXPECT_EQ(s.hole, 0.0f);
    }
  }
}

}  // namespace
}  // namespace globe
