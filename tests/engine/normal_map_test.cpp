// Payload surface textures (docs/rendering.md, "Surface textures"): GPU texels against the CPU double
// reference, agreement across node edges and face seams, and the pool's budget per slot.
#include "engine/generation/gpu_payload_generator.h"
#include "planet/geometry/node_id.h"
#include "planet/streaming/normal_map_reference.h"
#include "planet/streaming/payload_pool.h"
#include "planet/streaming/payload_reference.h"
#include "tests/engine/source_payload_check.h"
#include "tests/support/fake_payload_generator.h"
#include "tests/support/gpu_test.h"
#include "tests/support/imagery_fixture.h"
#include "tests/support/temp_dir.h"

#include "engine/vk/resources.h"
#include "planet/camera/camera.h"
#include "planet/geometry/face_mapping.h"
#include "planet/model/planet_file.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <utility>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;
// The grids and map scales tested against the reference: scales 1 to 4 at grid 16, and the balanced
// preset's grid 8 at its scale 4 and at scale 8 (quality.cpp).
constexpr std::array<std::pair<uint32_t, uint32_t>, 5> kGridsAndScales{{{16, 1}, {16, 2}, {16, 4}, {8, 4}, {8, 8}}};

// One texel of the surface texture as stored (payload_layout.h): RGBA8, the normal octahedral in the
// face frame, the luma of the albedo's square root, the coast field.
using StoredTexel = std::array<uint8_t, 4>;

int unitByte(double v) { return int(std::lround(v * 255.0)); }  // a value in [0, 1]

// Copies mip `mip` of layers [0, layers) of `image` (side x side texels of 4 bytes) into `out`.
void readMip(vk::Device& device, VkImage image, uint32_t mip, uint32_t side, uint32_t layers, vk::Buffer& out) {
  device.submitAndWait([&](VkCommandBuffer cmd) {
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, mip, 1, 0, VK_REMAINING_ARRAY_LAYERS};
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, layers};
    copy.imageExtent = {side, side, 1};
    vk::transitionImage(cmd, image, range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, out.handle(), 1, &copy);
    vk::transitionImage(cmd, image, range, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
    vk::hostReadBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  });
}

// The surface texture's texels of `nodes` generated into slots 0..n-1 at map scale `scale` (grid
// `cells`, default kCells; with the sea surface drawn where `waterSurface`), per node in the
// reference's order (mip 0 row by row, then mip 1: normalMapReference); on a planet with an overlay
// each slot's colour layer goes to `colours`, likewise.
std::vector<std::vector<StoredTexel>> generateMaps(vk::Device& device, const ElevationModel& model,
                                                   const std::vector<NodeId>& nodes, uint32_t scale,
                                                   std::vector<std::vector<StoredTexel>>* colours = nullptr,
                                                   uint32_t cells = kCells, bool waterSurface = false) {
  GpuPayloadGenerator gen(device, model, cells, GLOBE_PAYLOAD_MAX_BATCH, 1, GenerationPrecision::kDouble, waterSurface,
                          scale);
  gen.reserveSlots(uint32_t(nodes.size()));
  EXPECT_EQ(generateIntoSlots(gen, nodes).size(), nodes.size());
  const SurfaceTextures& textures = gen.surfaceTextures();
  EXPECT_EQ(textures.pageCount(), 1u);
  const uint32_t perSlot = textures.layersPerSlot(), layers = uint32_t(nodes.size()) * perSlot;
  std::vector<std::vector<StoredTexel>> maps(nodes.size());
  if (colours != nullptr) colours->assign(perSlot == 2 ? nodes.size() : 0, {});
  for (uint32_t mip = 0; mip < 2; ++mip) {
    const uint32_t side = textures.side() >> mip;
    vk::Buffer texels(device, VkDeviceSize(side) * side * layers * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      vk::MemoryUse::HostVisible, "surface readback");
    readMip(device, textures.image(0), mip, side, layers, texels);
    const auto* t = static_cast<const StoredTexel*>(texels.mapped());
    for (size_t k = 0; k < nodes.size(); ++k) {
      const StoredTexel* layer = t + k * perSlot * side * side;
      maps[k].insert(maps[k].end(), layer, layer + side * side);
      if (colours != nullptr && perSlot == 2)
        (*colours)[k].insert((*colours)[k].end(), layer + side * side, layer + 2 * side * side);
    }
  }
  return maps;
}

// The octahedral code [Cigolle 2014] of a unit normal in `face`'s frame, in [0, 1]^2.
glm::dvec2 octahedralCode(const glm::dvec3& normal, int face) {
  const auto frame = RhombusFaceMapping::get().faceFrame(face);
  const glm::dvec3 n(glm::dot(frame[0], normal), glm::dot(frame[1], normal), glm::dot(frame[2], normal));
  glm::dvec2 o = glm::dvec2(n.x, n.y) / (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
  if (n.z < 0.0)
    o = glm::dvec2((1.0 - std::abs(o.y)) * (o.x >= 0.0 ? 1.0 : -1.0),
                   (1.0 - std::abs(o.x)) * (o.y >= 0.0 ? 1.0 : -1.0));
  return o * 0.5 + 0.5;
}

// The planet-fixed unit normal a stored texel of a node on `face` decodes to (surface_textures.glsl).
glm::dvec3 storedNormal(const StoredTexel& t, int face) {
  const glm::dvec2 o = glm::dvec2(t[0], t[1]) / 255.0 * 2.0 - 1.0;
  glm::dvec3 f(o, 1.0 - std::abs(o.x) - std::abs(o.y));
  const double fold = std::max(-f.z, 0.0);
  f.x += f.x >= 0.0 ? -fold : fold;
  f.y += f.y >= 0.0 ? -fold : fold;
  const auto frame = RhombusFaceMapping::get().faceFrame(face);
  return glm::normalize(f.x * frame[0] + f.y * frame[1] + f.z * frame[2]);
}

// The texel the GPU should store for a reference texel of a node on `face`.
StoredTexel expectedTexel(const NormalMapTexel& r, int face) {
  const glm::dvec2 code = octahedralCode(r.normal, face);
  const glm::dvec3 root = glm::sqrt(glm::clamp(glm::dvec3(r.albedo), 0.0, 1.0));
  const double luma = 0.25 * root.x + 0.5 * root.y + 0.25 * root.z;
  return {uint8_t(unitByte(code.x)), uint8_t(unitByte(code.y)), uint8_t(unitByte(luma)),
          uint8_t(unitByte(r.coast * 0.5 + 0.5))};
}

// Largest difference in stored bytes between two texels, over channels [first, last).
int byteStep(const StoredTexel& a, const StoredTexel& b, size_t first = 0, size_t last = 4) {
  int worst = 0;
  for (size_t c = first; c < last; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(b[c])));
  return worst;
}

// Where texel `t` (the generateMaps order) of a map of `m` cells lies: its half-cell lattice point
// (payload_layout.h) and its mip.
struct TexelPlace {
  glm::ivec2 lattice;
  uint32_t mip;
  glm::ivec2 at;  // texel coordinates within the mip
};
TexelPlace texelPlace(uint32_t t, uint32_t m) {
  const uint32_t side0 = m + 4, side1 = m / 2 + 2;
  if (t < side0 * side0) {
    const glm::ivec2 at(int(t % side0), int(t / side0));
    return {at * 2 - 3, 0, at};
  }
  t -= side0 * side0;
  const glm::ivec2 at(int(t % side1), int(t / side1));
  return {at * 4 - 2, 1, at};
}

// maps[base] is a parent's, maps[base + 1 + q] its quadrant q child's: each child's mip 1 must hold
// the parent's mip 0 texels over its quadrant bit for bit.
void expectChildrenShowParent(const std::vector<std::vector<StoredTexel>>& maps, size_t base, uint32_t m) {
  const uint32_t half = m / 2, side0 = m + 4, side1 = half + 2;
  for (uint32_t q = 0; q < 4; ++q) {
    const std::vector<StoredTexel>& child = maps[base + 1 + q];
    for (uint32_t d = 0; d < side1; ++d)
      for (uint32_t c = 0; c < side1; ++c) {
        const StoredTexel mine = child[side0 * side0 + d * side1 + c];
        // Child mip-1 texel c lies at parent mip-0 texel c + 1 (+ half in the upper quadrants).
        const uint32_t px = c + 1 + (q & 1u) * half, py = d + 1 + (q >> 1) * half;
        const StoredTexel parents = maps[base][py * side0 + px];
        ASSERT_TRUE(mine == parents) << "parent " << base << " quadrant " << q << " texel " << c << ", " << d;
      }
  }
}

class NormalMapTest : public GpuTest {};
class NormalMapShapeTest : public GpuTest, public ::testing::WithParamInterface<PlanetShapeCase> {};
INSTANTIATE_TEST_SUITE_P(Shapes, NormalMapShapeTest, ::testing::Values(kPlanetShapes[0], kPlanetShapes[1]),
                         planetShapeName);

// Stored GPU texels within one 8-bit step of the CPU's double reference (the normal's octahedral
// code, the albedo's luma, the coast field), at depths 0..26, at face corners and seams, at every map
// scale and at the balanced preset's grid.
TEST_P(NormalMapShapeTest, MatchesCpuDoubleReference) {
  const ElevationModel& model = earthlikeModel(GetParam());
  std::vector<NodeId> nodes;
  for (int level : {0, 4, 9, 14, 18, 22, 26}) {
    const uint32_t last = (1u << level) - 1;
    nodes.push_back({uint8_t((level * 7) % 30), uint8_t(level), last / 3, last / 2});
  }
  nodes.push_back({0, 12, 0, 0});                // a polyhedron vertex
  nodes.push_back({13, 20, (1u << 20) - 1, 0});  // a seam
  for (const auto& [cells, scale] : kGridsAndScales) {
    const auto maps = generateMaps(device(), model, nodes, scale, nullptr, cells);
    int worstNormal = 0, worstAlbedo = 0;
    for (size_t k = 0; k < nodes.size(); ++k) {
      SCOPED_TRACE(::testing::Message() << "grid " << cells << " scale " << scale << " face " << int(nodes[k].face)
                                        << " level " << int(nodes[k].level));
      const auto reference = normalMapReference(model, makePayloadJob(nodes[k], 0, model), cells, scale);
      ASSERT_EQ(reference.size(), maps[k].size());
      for (size_t t = 0; t < reference.size(); ++t) {
        const StoredTexel expected = expectedTexel(reference[t], nodes[k].face);
        const int normal = byteStep(maps[k][t], expected, 0, 2), albedo = byteStep(maps[k][t], expected, 2, 4);
        worstNormal = std::max(worstNormal, normal);
        worstAlbedo = std::max(worstAlbedo, albedo);
        ASSERT_LE(normal, 1) << "texel " << t;
        ASSERT_LE(albedo, 1) << "texel " << t;
      }
    }
    const std::string config = "_grid" + std::to_string(cells) + "_scale" + std::to_string(scale);
    RecordProperty("worst_normal_steps" + config, worstNormal);
    RecordProperty("worst_albedo_steps" + config, worstAlbedo);
  }
}

// A node's gutter texels (the two cells beyond its edges, payload_layout.h) and its edge neighbour's
// texels at the same directions hold the same texel, so bilinear filtering at the shared edge reads
// the same values from both sides: bit-identical within a face; across a face seam (the neighbour's
// axes are turned, so its differences are taken in another order, and its normals are coded in its
// own face's frame) decoded normals within two 8-bit octahedral roundings (0.025), luma and coast
// within one 8-bit step. Both mips.
// Across seams the texels within two texels of a node's corner are skipped: their differences reach
// beyond the corner, where at a polyhedron vertex the rings of 3 or 5 faces meet and no
// neighbourhood is shared.
TEST_P(NormalMapShapeTest, BorderTexelsAgreeAcrossNodeEdgesAndFaceSeams) {
  const ElevationModel& model = earthlikeModel(GetParam());
  const uint32_t scale = 2, m = kCells * scale;
  std::vector<NodeId> nodes;
  for (const NodeId& a : {NodeId{3, 10, 517, 222}, NodeId{13, 14, (1u << 14) - 1, 0}, NodeId{0, 6, 0, 17}}) {
    nodes.push_back(a);
    for (int e = 0; e < 4; ++e) nodes.push_back(edgeNeighbour(a, e));
  }
  const auto maps = generateMaps(device(), model, nodes, scale);
  const uint32_t texels = uint32_t(normalMapTexelCount(m));
  auto direction = [&](const gpu::PayloadJob& job, uint32_t t) {
    const glm::ivec2 l = texelPlace(t, m).lattice;
    return payloadSampleDirection(job, 2 * m, l.x, l.y);
  };
  int compared = 0, acrossSeams = 0;
  for (size_t base = 0; base < nodes.size(); base += 5) {
    const gpu::PayloadJob a = makePayloadJob(nodes[base], 0, model);
    for (size_t e = 0; e < 4; ++e) {
      const NodeId& other = nodes[base + 1 + e];
      const gpu::PayloadJob b = makePayloadJob(other, 0, model);
      const bool seam = other.face != nodes[base].face;
      std::map<std::array<int64_t, 3>, uint32_t> neighbourTexels;  // direction (1e-12 grid) -> texel
      auto key = [](const glm::dvec3& d) {
        return std::array<int64_t, 3>{std::llround(d.x * 1e12), std::llround(d.y * 1e12), std::llround(d.z * 1e12)};
      };
      for (uint32_t tb = 0; tb < texels; ++tb) neighbourTexels[key(direction(b, tb))] = tb;
      for (uint32_t ta = 0; ta < texels; ++ta) {
        const TexelPlace place = texelPlace(ta, m);
        const int gutter = 2 - int(place.mip), last = int((m >> place.mip) + 2 * (2 - place.mip)) - 1;
        const auto nearCorner = [&](int c) { return c < gutter + 2 || c > last - gutter - 2; };
        const auto found = neighbourTexels.find(key(direction(a, ta)));
        if (found == neighbourTexels.end() || texelPlace(found->second, m).mip != place.mip) continue;
        if (seam && nearCorner(place.at.x) && nearCorner(place.at.y)) continue;
        const StoredTexel va = maps[base][ta], vb = maps[base + 1 + e][found->second];
        ++compared;
        if (!seam) {
          EXPECT_TRUE(va == vb) << "node " << base / 5 << " edge " << e << " texel " << ta;
          continue;
        }
        ++acrossSeams;
        EXPECT_LE(glm::length(storedNormal(va, nodes[base].face) - storedNormal(vb, other.face)), 0.025)
            << "node " << base / 5 << " edge " << e << " texel " << ta;
        EXPECT_LE(byteStep(va, vb, 2, 4), 1) << "node " << base / 5 << " edge " << e << " texel " << ta;
      }
    }
  }
  // Per edge: four columns of mip 0 and two of mip 1 are shared.
  EXPECT_GT(compared, 3 * 4 * (4 * int(m) + 2 * int(m / 2)));
  EXPECT_GT(acrossSeams, 2 * 4 * int(m));
}

// No pop at the end of a morph: a child's mip 1 (what it shows at k = 1) holds exactly the parent's
// own mip 0 texels over its quadrant, bit for bit, so the switch to the parent changes nothing.
TEST_F(NormalMapTest, ChildParentLevelEqualsParentMap) {
  const ElevationModel& model = earthlikeModel();
  const uint32_t scale = 2, m = kCells * scale;
  std::vector<NodeId> nodes;
  for (const NodeId& parent : {NodeId{5, 9, 100, 301}, NodeId{22, 21, 77777, (1u << 21) - 1}}) {
    nodes.push_back(parent);
    for (uint32_t q = 0; q < 4; ++q)
      nodes.push_back({parent.face, uint8_t(parent.level + 1), parent.x * 2 + (q & 1u), parent.y * 2 + (q >> 1)});
  }
  const auto maps = generateMaps(device(), model, nodes, scale);
  for (size_t base = 0; base < nodes.size(); base += 5) expectChildrenShowParent(maps, base, m);
  // The balanced preset's grid 8 at scale 4 (32 texels a node) and at scale 8 (64).
  for (uint32_t grid8Scale : {4u, 8u}) {
    const auto grid8 = generateMaps(device(), model, nodes, grid8Scale, nullptr, 8);
    for (size_t base = 0; base < nodes.size(); base += 5) expectChildrenShowParent(grid8, base, 8 * grid8Scale);
  }
}

// Under a drawn sea, the texels beside the coast take the colour of the land beside them (the mean
// ground of the land in their 3 x 3, colourElevation in payload_generate.glsl): the sea hides them,
// but bilinear filtering blends them into the land texels, and taken at the sea surface they were
// beach, drawn as a bright band of teeth along every coast seen from afar. At the flyover's coast
// (17N 107W), levels 5 to 11 (its views from 800 km down): the GPU's texels within one 8-bit step of
// the reference with the sea on, and the sea texels with land in their 3 x 3 within 12 luma steps of
// that land's mean on average (2.2 with 64 texels a node, 4.5 with 32; taken at the sea surface,
// with 32, 23 at levels 5 to 8 alone, where the land texels beside the sea are 25 steps from their
// land neighbours).
TEST_F(NormalMapTest, TexelsUnderTheSeaBesideTheCoastTakeTheLandsColour) {
  const ElevationModel& model = earthlikeModel();
  const uint32_t cells = 8, scale = 4, m = cells * scale, side = m + 4;  // the balanced preset's
  const FacePoint coast = RhombusFaceMapping::get().locate(directionFromLatLon(17.0, -106.97));
  std::vector<NodeId> nodes;
  for (int level : {5, 6, 7, 8, 11}) nodes.push_back(nodeAt(coast, level));
  const auto maps = generateMaps(device(), model, nodes, scale, nullptr, cells, /*waterSurface=*/true);
  int coastal = 0;
  double lumaSteps = 0.0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    SCOPED_TRACE(::testing::Message() << "level " << int(nodes[k].level));
    const auto reference = normalMapReference(model, makePayloadJob(nodes[k], 0, model), cells, scale, true);
    ASSERT_EQ(reference.size(), maps[k].size());
    for (size_t t = 0; t < reference.size(); ++t)
      ASSERT_LE(byteStep(maps[k][t], expectedTexel(reference[t], nodes[k].face)), 1) << "texel " << t;
    for (uint32_t y = 1; y + 1 < side; ++y)
      for (uint32_t x = 1; x + 1 < side; ++x) {
        const StoredTexel& sea = maps[k][y * side + x];
        if (sea[3] >= 128) continue;  // the coast field's byte: below 128 under the sea
        double landLuma = 0.0;
        int land = 0;
        for (uint32_t v = y - 1; v <= y + 1; ++v)
          for (uint32_t u = x - 1; u <= x + 1; ++u)
            if (maps[k][v * side + u][3] > 128) landLuma += maps[k][v * side + u][2], ++land;
        if (land == 0) continue;
        ++coastal;
        lumaSteps += std::abs(double(sea[2]) - landLuma / land);
      }
  }
  ASSERT_GT(coastal, 100);
  RecordProperty("mean_luma_steps_from_land", std::to_string(lumaSteps / coastal));
  EXPECT_LT(lumaSteps / coastal, 12.0);
}

// Imagery ([[imagery]], docs/imagery.md) and a vector line over it in the surface textures: the GPU's
// texels (the luma, the colour layer's albedo and its alpha, the vectors' coverage the sea shows them
// with) match the CPU reference (which blends the same overlay colours) within one 8-bit step, a
// child's mip 1 is still its parent's mip 0 bit for bit (both layers), and the texels away from the
// line show the checkerboard where its georeference puts it (a square's centre texel light or dark
// as the square is).
TEST_F(NormalMapTest, ImageryInTheSurfaceTexturesMatchesTheReference) {
  TempDir dir("normal_map_imagery");
  Checkerboard board;  // 64 x 64 pixels of 0.001 degrees (~111 m), squares of 8
  const double g[6] = {10.0, 0.001, 0.0, 20.0, 0.0, -0.001};
  std::copy(std::begin(g), std::end(g), board.geo);
  writeCheckerboard((dir / "board.tif").string(), board);
  PlanetDescription planet = *loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  ImagerySource source{(dir / "board.tif").string()};
  source.blend_m = 0.0;
  planet.imagery.push_back(source);
  std::ofstream((dir / "line.geojson").string())
      << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},)"
      << R"( "geometry": {"type": "LineString", "coordinates": [[10.01, 19.95], [10.05, 19.99]]}}]})";
  VectorLayer line{(dir / "line.geojson").string()};
  line.line = glm::vec3(1.0f, 0.0f, 0.0f);
  line.width_m = 120.0;
  line.width_px = 0.0;
  planet.vectors.push_back(line);
  const ElevationModel model(planet);
  ASSERT_NE(model.overlay(), nullptr);
  const uint32_t scale = 2, m = kCells * scale;
  const FacePoint centre = RhombusFaceMapping::get().locate(directionFromLatLon(19.968, 10.032));
  std::vector<NodeId> nodes;
  for (int level : {6, 9, 11}) nodes.push_back(nodeAt(centre, level));
  const NodeId parent = nodes.back();
  for (uint32_t q = 0; q < 4; ++q)
    nodes.push_back({parent.face, uint8_t(parent.level + 1), parent.x * 2 + (q & 1u), parent.y * 2 + (q >> 1)});
  std::vector<std::vector<StoredTexel>> colours;
  const auto maps = generateMaps(device(), model, nodes, scale, &colours);
  ASSERT_EQ(colours.size(), nodes.size());  // the colour layers of a planet with an overlay
  int underLine = 0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    const auto reference = normalMapReference(model, makePayloadJob(nodes[k], 0, model), kCells, scale);
    ASSERT_EQ(reference.size(), maps[k].size());
    for (size_t t = 0; t < reference.size(); ++t) {
      ASSERT_LE(byteStep(maps[k][t], expectedTexel(reference[t], nodes[k].face), 2, 3), 1)
          << "node " << k << " texel " << t;
      const glm::vec4 layer = reference[t].colourLayer;
      const glm::dvec3 root = glm::sqrt(glm::clamp(glm::dvec3(layer), 0.0, 1.0));
      const StoredTexel colour{uint8_t(unitByte(root.x)), uint8_t(unitByte(root.y)), uint8_t(unitByte(root.z)),
                               uint8_t(unitByte(layer.w))};
      ASSERT_LE(byteStep(colours[k][t], colour), 1) << "node " << k << " colour texel " << t;
      underLine += layer.w == 1.0f ? 1 : 0;
    }
  }
  EXPECT_GT(underLine, 100);  // the line is drawn: its texels carry its coverage for the sea
  // Level 11's texels are ~80 m: every square (888 m) spans ten of them; the texel nearest each
  // square's centre shows its colour (light luma ~1, dark red's ~0.35 after the sqrt encoding).
  int light = 0, dark = 0;
  const gpu::PayloadJob job = makePayloadJob(parent, 0, model);
  for (uint32_t t = 0; t < (m + 4) * (m + 4); ++t) {
    const TexelPlace place = texelPlace(t, m);
    const glm::dvec2 ll = latLonFromPosition(payloadSampleDirection(job, 2 * m, place.lattice.x, place.lattice.y));
    const double col = (ll.y - 10.0) / 0.008, row = (20.0 - ll.x) / 0.008;
    if (col < 0.0 || row < 0.0 || col >= 8.0 || row >= 8.0) continue;
    if (std::abs(col - std::floor(col) - 0.5) > 0.25 || std::abs(row - std::floor(row) - 0.5) > 0.25) continue;
    if (colours[nodes.size() - 5][t][3] != 0) continue;  // under the line
    const bool isLight = (int(col) + int(row)) % 2 == 0;
    const int luma = maps[nodes.size() - 5][t][2];
    (isLight ? light : dark)++;
    if (isLight)
      EXPECT_GT(luma, 240) << "texel " << t;
    else
      EXPECT_LT(luma, 110) << "texel " << t;
  }
  EXPECT_GT(light, 10);
  EXPECT_GT(dark, 10);
  expectChildrenShowParent(maps, nodes.size() - 5, m);
  expectChildrenShowParent(colours, nodes.size() - 5, m);
}

// The pool's slot count comes from the whole slot: mesh, land cover masks and surface texture layers
// (two with an overlay's colour layer).
TEST(NormalMapBudgetTest, PoolBudgetCountsTheNormalMap) {
  const size_t mesh = 2 * 19 * 19 * 16;         // 16 cells: 19 x 19 samples, position + normal vec4
  const size_t cover = (19 * 19 + 1) / 2 * 16;  // 8 mask bytes a sample
  EXPECT_EQ(GpuPayloadGenerator::slotBytesFor(kCells, 0), mesh + cover);
  for (uint32_t scale : {1u, 2u, 4u}) {
    const size_t m = kCells * scale, texels = (m + 4) * (m + 4) + (m / 2 + 2) * (m / 2 + 2);
    const size_t slot = GpuPayloadGenerator::slotBytesFor(kCells, scale);
    EXPECT_EQ(slot, mesh + cover + texels * 4) << scale;
    // With an overlay the colour layer doubles the texture part (docs/imagery.md).
    EXPECT_EQ(GpuPayloadGenerator::slotBytesFor(kCells, scale, 2), mesh + cover + texels * 8) << scale;
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
