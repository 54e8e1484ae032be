// Payload surface textures (docs/rendering.md, "Surface textures"): GPU texels against the CPU double
// reference, agreement across node edges and face seams, and the pool's budget per slot.
#include "engine/generation/payload_generator.h"
#include "planet/geometry/node_id.h"
#include "planet/streaming/normal_map_reference.h"
#include "planet/streaming/payload_pool.h"
#include "planet/streaming/payload_reference.h"
#include "tests/engine/source_payload_check.h"
#include "tests/support/fake_payload_generator.h"
#include "tests/support/gpu_test.h"

#include "engine/vk/resources.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;

// One texel of the surface textures as stored (payload_layout.h): RGBA16_SNORM normal and coast
// field, RGBA8_UNORM square root of the albedo.
struct StoredTexel {
  std::array<int16_t, 4> normal{};
  std::array<uint8_t, 4> albedo{};
  bool operator==(const StoredTexel&) const = default;
};

double snorm(int16_t v) { return std::max(double(v) / 32767.0, -1.0); }
glm::dvec3 storedNormal(const StoredTexel& t) { return {snorm(t.normal[0]), snorm(t.normal[1]), snorm(t.normal[2])}; }
double storedCoast(const StoredTexel& t) { return snorm(t.normal[3]); }

// The surface textures' texels of `nodes` generated into slots 0..n-1 at map scale `scale`, per node
// in the reference's order (level 0, then level 1: normalMapReference).
std::vector<std::vector<StoredTexel>> generateMaps(vk::Device& device, const ElevationModel& model,
                                                   const std::vector<NodeId>& nodes, uint32_t scale) {
  GpuPayloadGenerator gen(device, model, kCells, GLOBE_PAYLOAD_MAX_BATCH, 1, GenerationPrecision::kDouble, false,
                          scale);
  gen.reserveSlots(uint32_t(nodes.size()));
  EXPECT_EQ(generateIntoSlots(gen, nodes).size(), nodes.size());
  const SurfaceTextures& textures = gen.surfaceTextures();
  EXPECT_EQ(textures.pageCount(), 1u);
  const uint32_t w = textures.width(), h = textures.height(), m = kCells * scale;
  const VkDeviceSize layerTexels = VkDeviceSize(w) * h, layers = nodes.size();
  vk::Buffer normals(device, layerTexels * layers * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::HostVisible,
                     "surface normals readback");
  vk::Buffer albedo(device, layerTexels * layers * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::HostVisible,
                    "surface albedo readback");
  device.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, uint32_t(layers)};
    copy.imageExtent = {w, h, 1};
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS};
    for (const auto& [image, buffer] : {std::pair{textures.normalsImage(0), normals.handle()},
                                        std::pair{textures.albedoImage(0), albedo.handle()}}) {
      vk::transitionImage(cmd, image, all, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
      vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &copy);
      vk::transitionImage(cmd, image, all, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
    }
    vk::hostReadBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  });
  const auto* n = static_cast<const std::array<int16_t, 4>*>(normals.mapped());
  const auto* a = static_cast<const std::array<uint8_t, 4>*>(albedo.mapped());
  std::vector<std::vector<StoredTexel>> maps(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) {
    for (uint32_t level = 0; level < 2; ++level) {
      const uint32_t side = (m >> level) + 1, first = level == 0 ? 0 : m + 1;
      for (uint32_t t = 0; t < side * side; ++t) {
        const size_t at = k * layerTexels + size_t(t / side) * w + first + t % side;
        maps[k].push_back({n[at], a[at]});
      }
    }
  }
  return maps;
}

uint8_t rootByte(float linear) { return uint8_t(std::lround(std::sqrt(std::clamp(linear, 0.0f, 1.0f)) * 255.0f)); }

int albedoStep(const StoredTexel& t, const glm::vec3& linear) {
  int worst = 0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(t.albedo[size_t(c)]) - int(rootByte(linear[c]))));
  return worst;
}

int albedoStep(const StoredTexel& a, const StoredTexel& b) {
  int worst = 0;
  for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.albedo[c]) - int(b.albedo[c])));
  return worst;
}

// One step of RGBA16_SNORM: the stored normal is the double one rounded once per component.
constexpr double kSnormStep = 1.0 / 32767.0;

class NormalMapTest : public GpuTest {};
class NormalMapShapeTest : public GpuTest, public ::testing::WithParamInterface<PlanetShapeCase> {};
INSTANTIATE_TEST_SUITE_P(Shapes, NormalMapShapeTest, ::testing::Values(kPlanetShapes[0], kPlanetShapes[1]),
                         planetShapeName);

// Stored GPU normals within the 16-bit rounding of the CPU's double normals, albedo within one 8-bit
// step, the coast field within two 16-bit steps, at depths 0..26, at face corners and seams, at every
// map scale.
TEST_P(NormalMapShapeTest, MatchesCpuDoubleReference) {
  const ElevationModel& model = earthlikeModel(GetParam());
  std::vector<NodeId> nodes;
  for (int level : {0, 4, 9, 14, 18, 22, 26}) {
    const uint32_t last = (1u << level) - 1;
    nodes.push_back({uint8_t((level * 7) % 30), uint8_t(level), last / 3, last / 2});
  }
  nodes.push_back({0, 12, 0, 0});                // a polyhedron vertex
  nodes.push_back({13, 20, (1u << 20) - 1, 0});  // a seam
  for (uint32_t scale : {1u, 2u, 4u}) {
    const auto maps = generateMaps(device(), model, nodes, scale);
    double worstNormal = 0.0;
    int worstAlbedo = 0;
    for (size_t k = 0; k < nodes.size(); ++k) {
      SCOPED_TRACE(::testing::Message() << "scale " << scale << " face " << int(nodes[k].face) << " level "
                                        << int(nodes[k].level));
      const auto reference = normalMapReference(model, makePayloadJob(nodes[k], 0, model), kCells, scale);
      ASSERT_EQ(reference.size(), maps[k].size());
      for (size_t t = 0; t < reference.size(); ++t) {
        const double error = glm::length(storedNormal(maps[k][t]) - reference[t].normal);
        worstNormal = std::max(worstNormal, error);
        ASSERT_LE(error, kSnormStep) << "texel " << t;
        const int step = albedoStep(maps[k][t], reference[t].albedo);
        worstAlbedo = std::max(worstAlbedo, step);
        ASSERT_LE(step, 1) << "texel " << t;
        ASSERT_NEAR(storedCoast(maps[k][t]), reference[t].coast, 2.0 * kSnormStep) << "texel " << t;
      }
    }
    RecordProperty("worst_normal_scale" + std::to_string(scale), std::to_string(worstNormal));
    RecordProperty("worst_albedo_steps_scale" + std::to_string(scale), worstAlbedo);
  }
}

// Border texels of a node and its edge neighbour at the same level lie at the same directions and
// hold the same texel: bit-identical within a face; across a face seam (the neighbour's axes are
// turned, so its differences are taken in another order) within one 16-bit step of the normal and
// the coast field and one albedo step. Both levels of the map. Across seams the edge's end texels are
// skipped: they may be polyhedron vertices, where 3 or 5 faces meet and no neighbourhood is shared.
TEST_P(NormalMapShapeTest, BorderTexelsAgreeAcrossNodeEdgesAndFaceSeams) {
  const ElevationModel& model = earthlikeModel(GetParam());
  const uint32_t scale = 2, m = kCells * scale;
  std::vector<NodeId> nodes;
  for (const NodeId& a : {NodeId{3, 10, 517, 222}, NodeId{13, 14, (1u << 14) - 1, 0}, NodeId{0, 6, 0, 17}}) {
    nodes.push_back(a);
    for (int e = 0; e < 4; ++e) nodes.push_back(edgeNeighbour(a, e));
  }
  const auto maps = generateMaps(device(), model, nodes, scale);
  int compared = 0, acrossSeams = 0;
  for (size_t base = 0; base < nodes.size(); base += 5) {
    const gpu::PayloadJob a = makePayloadJob(nodes[base], 0, model);
    for (size_t e = 0; e < 4; ++e) {
      const NodeId& other = nodes[base + 1 + e];
      const gpu::PayloadJob b = makePayloadJob(other, 0, model);
      const bool seam = other.face != nodes[base].face;
      for (uint32_t level = 0; level < 2; ++level) {
        const uint32_t side = (m >> level) + 1, first = level == 0 ? 0 : (m + 1) * (m + 1);
        auto direction = [&](const gpu::PayloadJob& job, uint32_t t) {
          return payloadSampleDirection(job, m, int((t % side) << level), int((t / side) << level));
        };
        for (uint32_t ta = 0; ta < side * side; ++ta) {
          const uint32_t ia = ta % side, ja = ta / side;
          if (ia != 0 && ja != 0 && ia != side - 1 && ja != side - 1) continue;
          const glm::dvec3 da = direction(a, ta);
          for (uint32_t tb = 0; tb < side * side; ++tb) {
            if (glm::length(direction(b, tb) - da) > 1e-13) continue;
            const bool corner = (ia == 0 || ia == side - 1) && (ja == 0 || ja == side - 1);
            if (seam && corner) continue;  // an end of a seam edge: maybe a polyhedron vertex
            const StoredTexel va = maps[base][first + ta], vb = maps[base + 1 + e][first + tb];
            ++compared;
            if (!seam) {
              EXPECT_TRUE(va == vb) << "node " << base / 5 << " edge " << e << " level " << level << " texel " << ta;
              continue;
            }
            ++acrossSeams;
            for (size_t c = 0; c < 4; ++c)
              EXPECT_LE(std::abs(int(va.normal[c]) - int(vb.normal[c])), 1)
                  << "node " << base / 5 << " edge " << e << " level " << level << " texel " << ta << " channel " << c;
            EXPECT_LE(albedoStep(va, vb), 1);
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 3 * 4 * 2 * 17);
  EXPECT_GT(acrossSeams, 2 * 17);
}

// No pop at the end of a morph: a child's parent level (what it shows at k = 1) holds exactly the
// parent's own texels over its quadrant, bit for bit, so the switch to the parent changes nothing.
TEST_F(NormalMapTest, ChildParentLevelEqualsParentMap) {
  const ElevationModel& model = earthlikeModel();
  const uint32_t scale = 2, m = kCells * scale, half = m / 2;
  std::vector<NodeId> nodes;
  for (const NodeId& parent : {NodeId{5, 9, 100, 301}, NodeId{22, 21, 77777, (1u << 21) - 1}}) {
    nodes.push_back(parent);
    for (uint32_t q = 0; q < 4; ++q)
      nodes.push_back({parent.face, uint8_t(parent.level + 1), parent.x * 2 + (q & 1u), parent.y * 2 + (q >> 1)});
  }
  const auto maps = generateMaps(device(), model, nodes, scale);
  for (size_t base = 0; base < nodes.size(); base += 5) {
    for (uint32_t q = 0; q < 4; ++q) {
      const std::vector<StoredTexel>& child = maps[base + 1 + q];
      for (uint32_t b = 0; b <= half; ++b)
        for (uint32_t a = 0; a <= half; ++a) {
          const StoredTexel mine = child[(m + 1) * (m + 1) + b * (half + 1) + a];
          const StoredTexel parents = maps[base][((q >> 1) * half + b) * (m + 1) + (q & 1u) * half + a];
          ASSERT_TRUE(mine == parents) << "parent " << base / 5 << " quadrant " << q << " texel " << a << ", " << b;
        }
    }
  }
}

// The pool's slot count comes from the whole slot: mesh, land cover masks and surface texture layers.
TEST(NormalMapBudgetTest, PoolBudgetCountsTheNormalMap) {
  const size_t mesh = 2 * 19 * 19 * 16;         // 16 cells: 19 x 19 samples, position + normal vec4
  const size_t cover = (19 * 19 + 1) / 2 * 16;  // 8 mask bytes a sample
  EXPECT_EQ(GpuPayloadGenerator::slotBytesFor(kCells, 0), mesh + cover);
  for (uint32_t scale : {1u, 2u, 4u}) {
    const size_t m = kCells * scale, texels = (m + 1 + m / 2 + 1) * (m + 1);
    const size_t slot = GpuPayloadGenerator::slotBytesFor(kCells, scale);
    EXPECT_EQ(slot, mesh + cover + texels * (8 + 4)) << scale;
    FakePayloadGenerator generator(slot, 6371000.0, {6.36e6, 6.38e6});
    StreamingConfig config;
    config.vramBudget_MiB = 64.0;
    auto pool = PayloadPool::create(config, generator, 6371000.0);
    ASSERT_TRUE(pool.ok()) << pool.error().format();
    EXPECT_EQ((*pool)->slotCapacity(), uint32_t(64.0 * 1024 * 1024 / double(slot))) << scale;
  }
}

}  // namespace
}  // namespace globe::testing
