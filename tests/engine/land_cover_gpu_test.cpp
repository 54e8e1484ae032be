// Land cover masks from the payload kernel: against the CPU reference (planet/surface/land_cover.cpp),
// summing to 255 at every sample, and identical on both sides of node and face seams.
#include "engine/generation/gpu_payload_generator.h"
#include "planet/model/planet_file.h"
#include "planet/streaming/payload_reference.h"
#include "tests/engine/source_payload_check.h"
#include "tests/support/gpu_test.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <random>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;
constexpr size_t kSide = kCells + 3;

// Earth-like relief with 6 classes whose rules use every criterion, written here so that the test
// does not depend on how assets/planets/earthlike.toml is tuned.
const ElevationModel& coveredModel() {
  static const ElevationModel model = [] {
    auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
    if (!planet) throw std::runtime_error(planet.error().format());
    LandCover cover;
    auto add = [&](const char* name, glm::vec3 colour) {
      LandCoverClass c;
      c.name = name;
      c.colour = colour;
      cover.classes.push_back(c);
      return &cover.classes.back();
    };
    add("shore", {0.45f, 0.4f, 0.28f})->elevation_max_m = 10.0;
    LandCoverClass* grass = add("grass", {0.1f, 0.2f, 0.05f});
    grass->elevation_min_m = 10.0;
    grass->moisture_min = 0.3;
    LandCoverClass* desert = add("desert", {0.5f, 0.4f, 0.25f});
    desert->elevation_min_m = 10.0;
    desert->moisture_max = 0.3;
    desert->temperature_min_c = 5.0;
    add("rock", {0.2f, 0.19f, 0.18f})->slope_min_deg = 35.0;
    add("ice", {0.8f, 0.85f, 0.9f})->temperature_max_c = -5.0;
    LandCoverClass* forest = add("forest", {0.03f, 0.09f, 0.02f});
    forest->moisture_min = 0.55;
    forest->temperature_min_c = 0.0;
    forest->elevation_min_m = 20.0;
    planet->land_cover = cover;
    return ElevationModel(*planet);
  }();
  return model;
}

using Masks = std::array<uint8_t, 8>;

Masks masksAt(const std::vector<glm::vec4>& slots, size_t slot, size_t sample) {
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells);
  const auto* bytes =
      reinterpret_cast<const unsigned char*>(slots.data() + slot * perSlot + GLOBE_PAYLOAD_COVER_OFFSET(kCells));
  Masks m;
  std::memcpy(m.data(), bytes + sample * 8, 8);
  return m;
}

class LandCoverGpuTest : public GpuTest {
 protected:
  std::vector<glm::vec4> generate(const std::vector<NodeId>& nodes) {
    GpuPayloadGenerator gen(device(), coveredModel(), kCells, GLOBE_PAYLOAD_MAX_BATCH, 4);
    gen.reserveSlots(uint32_t(nodes.size()));
    EXPECT_EQ(generateIntoSlots(gen, nodes).size(), nodes.size());
    return readPayloadBuffer(device(), gen);
  }
};

TEST_F(LandCoverGpuTest, MasksMatchTheCpuReferenceAndSumTo255) {
  std::vector<NodeId> nodes;
  std::mt19937_64 rng(17);
  for (int level = 2; level <= 22; ++level) {
    std::uniform_int_distribution<uint32_t> cell(0, (1u << level) - 1);
    for (int k = 0; k < 3; ++k) nodes.push_back({uint8_t(rng() % 30), uint8_t(level), cell(rng), cell(rng)});
  }
  const std::vector<glm::vec4> gpu = generate(nodes);
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells);
  std::vector<glm::vec4> cpu(perSlot);
  size_t compared = 0, differing = 0;
  int worst = 0;
  std::array<int, 8> seen{};
  for (size_t k = 0; k < nodes.size(); ++k) {
    fillPayloadReference(coveredModel(), makePayloadJob(nodes[k], 0, coveredModel()), kCells, cpu);
    for (size_t i = 0; i < kSide * kSide; ++i) {
      const Masks g = masksAt(gpu, k, i), c = masksAt(cpu, 0, i);
      int sum = 0, distance = 0;
      for (int b = 0; b < 8; ++b) {
        sum += g[size_t(b)];
        distance = std::max(distance, std::abs(int(g[size_t(b)]) - int(c[size_t(b)])));
        seen[size_t(b)] += g[size_t(b)] > 127;
      }
      ASSERT_EQ(sum, 255) << "node " << k << " sample " << i;
      ++compared;
      differing += distance > 0;
      worst = std::max(worst, distance);
    }
  }
  std::printf("[ info ] %zu samples, %zu differ from the CPU (worst %d / 255)\n", compared, differing, worst);
  // Float climate on both sides: the same operations, so only acos and the noise's roundings differ.
  EXPECT_LE(worst, 2);
  EXPECT_LE(double(differing), 0.01 * double(compared));
  for (int b = 0; b < 6; ++b) EXPECT_GT(seen[size_t(b)], 0) << "class " << b << " never dominates";
}

TEST_F(LandCoverGpuTest, NeighboursHoldTheSameMasksOnSharedEdges) {
  std::vector<NodeId> nodes;
  std::vector<std::pair<size_t, int>> pairs;
  for (int face = 0; face < 30; ++face) {
    for (int edge = 0; edge < 4; ++edge) {
      const int level = (face + edge) % 2 ? 9 : 15;
      const uint32_t last = (1u << level) - 1;
      NodeId a{uint8_t(face), uint8_t(level), edge == 1 ? last : last / 2, edge == 2 ? last : last / 2};
      if (edge == 3) a.x = 0;
      if (edge == 0) a.y = 0;
      pairs.push_back({nodes.size(), edge});
      nodes.push_back(a);
      nodes.push_back(edgeNeighbour(a, edge));
    }
  }
  const std::vector<glm::vec4> gpu = generate(nodes);
  const size_t perSlot = GLOBE_PAYLOAD_SLOT_VEC4(kCells);
  int compared = 0;
  for (auto [ia, edge] : pairs) {
    const glm::dvec3 ca = payloadCentre(nodes[ia], coveredModel()), cb = payloadCentre(nodes[ia + 1], coveredModel());
    auto position = [&](size_t slot, glm::dvec3 centre, size_t sample) {
      return centre + glm::dvec3(glm::vec3(gpu[slot * perSlot + sample]));
    };
    for (int t = 0; t <= int(kCells); ++t) {
      const int n = int(kCells);
      const int i = edge == 0 ? t : edge == 1 ? n : edge == 2 ? n - t : 0;
      const int j = edge == 0 ? 0 : edge == 1 ? t : edge == 2 ? n : n - t;
      const size_t sa = size_t(j + 1) * kSide + size_t(i + 1);
      const glm::dvec3 pa = position(ia, ca, sa);
      bool found = false;
      for (size_t sb = 0; sb < kSide * kSide && !found; ++sb) {
        const size_t bi = sb % kSide, bj = sb / kSide;
        if (bi < 1 || bj < 1 || bi > kCells + 1 || bj > kCells + 1) continue;  // vertices only
        if (position(ia + 1, cb, sb) != pa) continue;
        found = true;
        EXPECT_EQ(masksAt(gpu, ia, sa), masksAt(gpu, ia + 1, sb))
            << "face " << int(nodes[ia].face) << " edge " << edge << " t " << t;
      }
      EXPECT_TRUE(found) << "face " << int(nodes[ia].face) << " edge " << edge << " t " << t;
      ++compared;
    }
  }
  std::printf("[ info ] %d shared edge vertices compared\n", compared);
}

}  // namespace
}  // namespace globe::testing
