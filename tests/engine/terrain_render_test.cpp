// The terrain renderer on lavapipe: no cracks (background inside the planet's silhouette) at face
// seams, polyhedron vertices, poles and ±180° from 1 cm to orbit with morphing active; depth order at
// 1 m and 100 km; vertex jitter at 1 cm above an Earth-sized planet; the debug views and statistics.
// Payloads come from the CPU reference (planet/streaming/payload_reference.h), selections from LodSelector.
#include "engine/io/image_io.h"
#include "engine/render/offscreen_target.h"
#include "engine/render/render_output.h"
#include "engine/render/terrain_renderer.h"
#include "engine/vk/compute_pipeline.h"
#include "planet/camera/floating_origin.h"
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/triacontahedron.h"
#include "planet/lod/selection.h"
#include "planet/model/relief_roughness.h"
#include "planet/streaming/payload_reference.h"
#include "tests/support/gpu_test.h"
#include "tests/support/render_test_geometry.h"

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <unordered_map>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 8;  // the smallest grid (balanced's): partial nodes of 4 cells, fast CPU filling
constexpr uint32_t kWidth = 160, kHeight = 120;
constexpr double kRadius_m = 6371000.0;
// Clear colour the terrain never writes (alpha 0: every terrain fragment has alpha 1).
constexpr float kBackground[4] = {1.0f, 0.0f, 1.0f, 0.0f};

PlanetDescription testPlanet() {
  PlanetDescription p;
  p.name = "render-test";
  p.radius_m = kRadius_m;
  p.seed = 11;
  ElevationLayer continents;
  continents.name = "continents";
  continents.octaves = 4;
  continents.wavelength_m = 3.0e6;
  continents.amplitude_m = 3000.0;
  ElevationLayer hills;
  hills.name = "hills";
  hills.kind = LayerKind::kRidged;
  hills.octaves = 6;
  hills.wavelength_m = 40000.0;
  hills.amplitude_m = 600.0;
  hills.offset_m = -200.0;
  p.layers = {continents, hills};
  return p;
}

// Payloads filled on the CPU into a host-visible buffer, lazily for every node the selection asks
// about; every node is resident and reports its real (padded) radius range, like the pool does.
class CpuPayloads final : public NodeResidency {
 public:
  CpuPayloads(vk::Device& device, const ElevationModel& model, uint32_t capacity)
      : model_(model),
        capacity_(capacity),
        buffer_(device, VkDeviceSize(capacity) * GLOBE_PAYLOAD_SLOT_VEC4(kCells) * 16u,
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible, "test payloads") {}

  struct Entry {
    uint32_t slot = 0;
    glm::dvec3 centre_m{0.0};
    RadiusRange vertices;  // unpadded
    RadiusRange padded;
    double geometricError_m = 0.0;  // as the generator reports it (payloadGeometricError_m)
  };

  const Entry& entry(const NodeId& id) const {
    auto it = entries_.find(id);
    if (it != entries_.end()) return it->second;
    if (next_ >= capacity_) throw std::runtime_error("test payload buffer full");
    Entry e;
    e.slot = next_++;
    gpu::PayloadJob job = makePayloadJob(id, e.slot, model_);
    e.centre_m = {job.centre.x, job.centre.y, job.centre.z};
    auto all = buffer_.as<glm::vec4>();
    e.vertices = fillPayloadReference(
        model_, job, kCells,
        all.subspan(size_t(e.slot) * GLOBE_PAYLOAD_SLOT_VEC4(kCells), GLOBE_PAYLOAD_SLOT_VEC4(kCells)));
    e.padded = paddedRadiusRange(model_.params(), e.vertices, id.level, kCells);
    e.geometricError_m = payloadGeometricError_m(slot(e.slot), kCells);
    return entries_.emplace(id, e).first->second;
  }

  bool isResident(const NodeId&) const override { return true; }
  void request(const NodeId&, RequestPriority, double) override {}
  std::optional<RadiusRange> knownRadiusRange(const NodeId& node) const override { return entry(node).padded; }
  std::optional<double> knownGeometricError(const NodeId& node) const override { return entry(node).geometricError_m; }

  void clear() {
    entries_.clear();
    next_ = 0;
  }
  const vk::Buffer& buffer() const { return buffer_; }
  PayloadPages pages() const { return PayloadPages::single(buffer_.handle(), buffer_.size(), capacity_); }
  std::span<glm::vec4> slot(uint32_t s) const {
    return buffer_.as<glm::vec4>().subspan(size_t(s) * GLOBE_PAYLOAD_SLOT_VEC4(kCells),
                                           GLOBE_PAYLOAD_SLOT_VEC4(kCells));
  }

 private:
  const ElevationModel& model_;
  uint32_t capacity_;
  vk::Buffer buffer_;
  mutable std::unordered_map<NodeId, Entry, NodeIdHash> entries_;
  mutable uint32_t next_ = 0;
};

// First hit of the ray (o, unit d) with the sphere of radius r centred at 0, or -1 when it misses.
double raySphere(const glm::dvec3& o, const glm::dvec3& d, double r) {
  const double len = glm::length(o);
  const double b = glm::dot(o, d);
  const double c = (len - r) * (len + r);
  const double disc = b * b - c;
  if (disc < 0.0) return -1.0;
  const double t = -b - std::sqrt(disc);
  return t > 0.0 ? t : -1.0;
}

// No sky (background pixels stay the clear colour), optionally no skirts (geometry alone).
TerrainStyle terrainOnlyStyle(bool skirts) {
  TerrainStyle style;
  style.sky = false;
  if (!skirts) {
    style.skirtOutward = 0.0f;
    style.skirtDrop = 0.0f;
  }
  return style;
}

class TerrainRenderTest : public GpuTest {
 protected:
  explicit TerrainRenderTest(const PlanetShapeCase& shape = kPlanetShapes[0]) : model_(onShape(testPlanet(), shape)) {}

  struct Frame {
    ReadbackImage image;
    DrawStats stats;
    std::vector<DrawNode> nodes;
    double innerRadius_m = 0.0;  // no drawn triangle comes closer to the planet centre
    uint32_t morphing = 0;       // nodes whose morph band overlaps their distance range
  };

  Camera cameraAt(double lat, double lon, double height_m, double heading, double pitch) const {
    GeodeticPose pose{lat, lon, height_m, heading, pitch, 0.0};
    if (!model_.shape().isSphere()) {  // ground "radius" a + its ellipsoidal height (Ellipsoid::pointAbove)
      const double ground = model_.radius_m() + model_.elevation_m(directionFromLatLon(lat, lon));
      return cameraFromPose(pose, ground, model_.shape(), double(kWidth) / kHeight);
    }
    const double ground = glm::length(model_.surfacePosition(directionFromLatLon(lat, lon)));
    return cameraFromPose(pose, ground, kRadius_m, double(kWidth) / kHeight);
  }

  // tolerance_px > 0: tolerance-driven ranges from the payloads' geometric errors; roughness: also
  // following the planet's relief (reliefRoughnessMap), as Terrain does by default.
  LodSelector makeSelector(double tolerance_px = 0.0, bool roughness = false) const {
    LodConfig config;
    config.ranges.tolerance_px = tolerance_px;
    config.radius_m = model_.radius_m();
    config.flattening = model_.shape().flattening();
    ElevationRange range = model_.bounds();
    config.minElevation_m = range.min_m;
    config.maxElevation_m = range.max_m;
    auto selector = LodSelector::create(config);
    EXPECT_TRUE(selector.ok());
    if (roughness) selector->ranges().setRoughness(reliefRoughnessMap(model_, int(kCells), config.ranges.maxDepth));
    return std::move(selector.value());
  }

  // Selects, fills payloads and renders one frame of the terrain from `camera`.
  Frame render(TerrainRenderer& renderer, CpuPayloads& payloads, LodSelector& selector, const Camera& camera,
               double rebase_m = 0.0) {
    Frame f;
    auto frustum = Frustum::fromViewProjection(camera.projection() * camera.viewFromWorld(glm::dvec3(0.0)));
    EXPECT_TRUE(frustum.ok());
    Selection selection;
    EXPECT_TRUE(selector.select({camera.position_m, &frustum.value()}, payloads, selection).ok());
    double inner = std::numeric_limits<double>::infinity();
    const auto& mapping = RhombusFaceMapping::get();
    for (const SelectedNode& s : selection.nodes) {
      const CpuPayloads::Entry& e = payloads.entry(s.id);
      f.nodes.push_back({s.id, e.slot, s.morph, s.partial, e.centre_m});
      const MorphRange band = s.morph.at(0.5, 0.5);
      // Angular size of a drawn cell's diagonal, doubled for the morph to the parent's cells: every
      // drawn triangle lies within that angle of one of its vertices, so above r * cos(angle).
      const double diagonal =
          std::max(angleBetween_rad(nodeCornerDirection(mapping, s.id, 0), nodeCornerDirection(mapping, s.id, 2)),
                   angleBetween_rad(nodeCornerDirection(mapping, s.id, 1), nodeCornerDirection(mapping, s.id, 3)));
      const double angle = 2.0 * 1.25 * diagonal / double(s.partial ? kCells / 2 : kCells);
      inner = std::min(inner, e.vertices.min_m * std::cos(angle));
      // Morphing: the node's distance range (its bounding radius around the centre) meets its band.
      const double d = glm::length(e.centre_m - camera.position_m);
      const double reach = glm::length(e.centre_m) * diagonal;
      if (std::isfinite(band.start_m) && d - reach < band.end_m && d + reach > band.start_m) ++f.morphing;
    }
    f.innerRadius_m = inner;
    FloatingOrigin origin(rebase_m, payloadQuantum_m(0, model_.radius_m()));
    origin.update(camera.position_m);
    OffscreenTarget target(device(), {kWidth, kHeight});
    device().submitAndWait([&](VkCommandBuffer cmd) {
      target.begin(cmd, kBackground);
      f.stats = renderer.record(cmd, camera, origin.origin_m(), f.nodes, payloads.pages(), 0);
      target.end(cmd);
    });
    f.image = target.readback();
    return f;
  }

  // Pixels inside the silhouette of the sphere of radius `inner` (the whole pixel: centre and
  // corners hit it) that show the background.
  static int countHoles(const Frame& f, const Camera& camera, int* inside = nullptr) {
    int holes = 0, in = 0;
    for (uint32_t y = 0; y < kHeight; ++y) {
      for (uint32_t x = 0; x < kWidth; ++x) {
        bool hit = true;
        for (auto [dx, dy] : {std::pair{0.5, 0.5}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}}) {
          if (raySphere(camera.position_m, testing::pixelPositionRay(camera, x + dx, y + dy, kWidth, kHeight),
                        f.innerRadius_m) < 0.0)
            hit = false;
        }
        if (!hit) continue;
        ++in;
        if (f.image.pixel(x, y)[3] == 0.0f) ++holes;
      }
    }
    if (inside) *inside = in;
    return holes;
  }

  static void save(const Frame& f, const std::string& name) {
    auto dir = std::filesystem::path(GLOBE_BINARY_DIR) / "test_output";
    std::filesystem::create_directories(dir);
    ImageRgba image{f.image.width, f.image.height, f.image.rgba, {}};
    (void)writePng((dir / (name + ".png")).string(), image);
  }

  ElevationModel model_;
};

// The crack and jitter tests on the planet's sphere, on WGS84 and on flattening 0.1 (issue #18).
class TerrainRenderShapeTest : public TerrainRenderTest, public ::testing::WithParamInterface<PlanetShapeCase> {
 protected:
  TerrainRenderShapeTest() : TerrainRenderTest(GetParam()) {}
};
INSTANTIATE_TEST_SUITE_P(Shapes, TerrainRenderShapeTest, ::testing::ValuesIn(kPlanetShapes), planetShapeName);

struct CrackCase {
  const char* name;
  glm::dvec3 direction;  // where the camera is (unit, planet-fixed)
  double height_m;
  double heading_deg;
  double pitch_deg;
};

std::vector<CrackCase> crackCases() {
  const auto& m = RhombusFaceMapping::get();
  const auto& t = Triacontahedron::get();
  const glm::dvec3 seam = m.unitPoint(3, 0.5, 0.0);  // middle of a face edge (a seam)
  const glm::dvec3 fiveFold = t.vertexDirection(1);
  const glm::dvec3 threeFold = t.vertexDirection(17);
  const glm::dvec3 northPole = t.vertexDirection(0);
  const glm::dvec3 southPole = t.vertexDirection(11);
  const glm::dvec3 antimeridian = directionFromLatLon(5.0, 180.0);
  const glm::dvec3 vertex8 = t.vertexDirection(8);  // five-fold, on ±180°
  // Nudged off the exact point a little so the camera is not on a singular frame.
  return {
      {"seam_1cm", seam, 0.01, 30.0, -30.0},
      {"seam_1km", seam, 1000.0, 200.0, -20.0},
      {"fivefold_10m", fiveFold, 10.0, 45.0, -25.0},
      {"fivefold_100km", fiveFold, 1.0e5, 10.0, -40.0},
      {"threefold_1cm", threeFold, 0.01, 120.0, -35.0},
      {"threefold_10km", threeFold, 1.0e4, 300.0, -15.0},
      {"northpole_100m", northPole, 100.0, 0.0, -30.0},
      {"southpole_1m", southPole, 1.0, 90.0, -20.0},
      {"antimeridian_1cm", antimeridian, 0.01, 270.0, -25.0},
      {"vertex8_1km", vertex8, 1000.0, 90.0, -10.0},
      {"orbit", fiveFold, 1.2e7, 0.0, -90.0},
  };
}

TEST_P(TerrainRenderShapeTest, NoCracksAtSeamsVerticesPolesAndAntimeridian) {
  TerrainStyle style;
  style.sky = false;
  style.radius_m = model_.radius_m();
  TerrainRenderer renderer(device(), kCells, style);
  CpuPayloads payloads(device(), model_, 6000);
  // Distance ranges, then tolerance-driven ranges following the relief (docs/lod.md): both must
  // stay crack-free (per-depth tolerance ranges: WithoutSkirtsMorphedEdgesStillMeet).
  for (const double tolerance : {0.0, 2.0})
    for (const CrackCase& c : crackCases()) {
      payloads.clear();
      // Fresh ranges: observed for this camera only.
      LodSelector selector = makeSelector(tolerance, /*roughness=*/tolerance > 0.0);
      const glm::dvec2 ll = latLonFromPosition(c.direction);
      const Camera camera = cameraAt(ll.x, ll.y, c.height_m, c.heading_deg, c.pitch_deg);
      auto start = std::chrono::steady_clock::now();
      Frame f = render(renderer, payloads, selector, camera);
      double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      int inside = 0;
      int holes = countHoles(f, camera, &inside);
      std::printf(
          "[ info ] %s %-18s %4.1f px nodes %4u (partial %3u, morphing %3u) triangles %7llu, inside %5d px, holes %d "
          "(%.0f ms)\n",
          GetParam().name, c.name, tolerance, f.stats.nodes, f.stats.partialNodes, f.morphing,
          (unsigned long long)f.stats.triangles, inside, holes, ms);
      EXPECT_EQ(holes, 0) << c.name << " tolerance " << tolerance;
      EXPECT_GT(inside, int(kWidth * kHeight / 10))
          << c.name << " tolerance " << tolerance << ": the planet should fill part of the view";
      EXPECT_GT(f.stats.nodes, 0u);
      if (c.height_m < 1.0e6) {
        EXPECT_GT(f.morphing, 0u) << c.name << " tolerance " << tolerance << ": morphing should be active";
      }
      if (holes) save(f, std::string("terrain_cracks_") + GetParam().name + "_" + c.name);
      // CDLOD's guarantee (LodRanges::morph), checked on the ranges this selection used: where a
      // depth-d node meets a finer neighbour (at most R(d) + D(d) away) its band has not started.
      const LodRanges& ranges = selector.ranges();
      for (int d = 1; d < ranges.maxDepth(); ++d) {
        if (ranges.maxDiagonal(d) == 0.0) continue;  // depth not reached by this selection
        const double needed = ranges.refineRange(d) + ranges.maxDiagonal(d);
        EXPECT_GE(ranges.morph(d).start_m, needed) << c.name << " tolerance " << tolerance << " depth " << d;
        EXPECT_LE(ranges.morph(d).start_m, ranges.morph(d).end_m);
      }
    }
}

TEST_F(TerrainRenderTest, WithoutSkirtsMorphedEdgesStillMeet) {
  // Skirts only hide sub-pixel gaps; the geometry itself must be closed: without them a handful of
  // isolated pixels at most (rasteriser snapping of T-junctions), never a visible crack line.
  TerrainRenderer renderer(device(), kCells, terrainOnlyStyle(/*skirts=*/false));
  CpuPayloads payloads(device(), model_, 6000);
  int total = 0;
  const auto cases = crackCases();
  for (const auto& [tolerance, roughness] : {std::pair{0.0, false}, {2.0, false}, {2.0, true}})
    for (const CrackCase& c : std::span(cases).first(4)) {
      payloads.clear();
      LodSelector selector = makeSelector(tolerance, roughness);
      const glm::dvec2 ll = latLonFromPosition(c.direction);
      const Camera camera = cameraAt(ll.x, ll.y, c.height_m, c.heading_deg, c.pitch_deg);
      Frame f = render(renderer, payloads, selector, camera);
      int holes = countHoles(f, camera);
      total += holes;
      EXPECT_LE(holes, 3) << c.name << " tolerance " << tolerance;
    }
  std::printf("[ info ] without skirts: %d background pixel(s) inside silhouettes over 12 views\n", total);
}

// A flat square payload facing the camera: side_m wide, centred on the node centre.
void fillFacingSquare(std::span<glm::vec4> slot, const Camera& camera, double side_m) {
  const int n = int(kCells), s = n + 3;
  for (int j = -1; j <= n + 1; ++j) {
    for (int i = -1; i <= n + 1; ++i) {
      const glm::dvec3 p = (double(i) / n - 0.5) * side_m * camera.right + (double(j) / n - 0.5) * side_m * camera.up;
      const size_t index = size_t(j + 1) * size_t(s) + size_t(i + 1);
      slot[index] = glm::vec4(glm::vec3(p), 0.0f);
      slot[size_t(s * s) + index] = glm::vec4(glm::vec3(-camera.forward), 0.0f);
    }
  }
}

TEST_F(TerrainRenderTest, NearerSurfaceWinsAt1mAnd100km) {
  TerrainRenderer renderer(device(), kCells, terrainOnlyStyle(/*skirts=*/false));
  CpuPayloads payloads(device(), model_, 2);
  Camera camera = cameraAt(46.5, 7.5, 2.0, 30.0, -10.0);
  FloatingOrigin origin(0.0, payloadQuantum_m(0, kRadius_m));
  origin.update(camera.position_m);
  const double inf = std::numeric_limits<double>::infinity();
  // (near distance, gap): 1 cm apart at 1 m, 10 m apart at 100 km.
  for (auto [near_m, gap_m] : {std::pair{1.0, 0.01}, std::pair{100000.0, 10.0}}) {
    const double side = near_m * 0.5;
    fillFacingSquare(payloads.slot(0), camera, side);
    fillFacingSquare(payloads.slot(1), camera, side);
    DrawNode a{NodeId{0, 3, 0, 0}, 0, {inf, inf}, false, camera.position_m + near_m * camera.forward};
    DrawNode b{NodeId{0, 7, 0, 0}, 1, {inf, inf}, false, camera.position_m + (near_m + gap_m) * camera.forward};
    for (bool nearFirst : {true, false}) {
      std::vector<DrawNode> nodes = nearFirst ? std::vector<DrawNode>{a, b} : std::vector<DrawNode>{b, a};
      OffscreenTarget target(device(), {kWidth, kHeight});
      device().submitAndWait([&](VkCommandBuffer cmd) {
        target.begin(cmd, kBackground);
        renderer.record(cmd, camera, origin.origin_m(), nodes, payloads.pages(), 1);
        target.end(cmd);
      });
      ReadbackImage image = target.readback();
      int checked = 0;
      for (uint32_t y = kHeight / 2 - 10; y < kHeight / 2 + 10; ++y) {
        for (uint32_t x = kWidth / 2 - 10; x < kWidth / 2 + 10; ++x) {
          ASSERT_GT(image.depthAt(x, y), 0.0f) << "nothing drawn at " << x << "," << y;
          const double ray = rayDistanceFromDepth(camera, kWidth, kHeight, x, y, image.depthAt(x, y));
          const glm::dvec3 dir = testing::pixelPositionRay(camera, x + 0.5, y + 0.5, kWidth, kHeight);
          const double expected = near_m / glm::dot(dir, camera.forward);  // the near plane's distance
          EXPECT_NEAR(ray, expected, gap_m * 0.25) << near_m << " m, near drawn first: " << nearFirst;
          ++checked;
        }
      }
      EXPECT_EQ(checked, 400);
    }
  }
}

// Runs the vertex shader's computation (test_terrain_vertex.comp) for one full node and returns
// the clip positions of its grid vertices.
std::vector<glm::vec4> gpuClipPositions(vk::Device& device, TerrainRenderer& renderer, const Camera& camera,
                                        const glm::dvec3& origin_m, const DrawNode& node,
                                        const PayloadPages& payloads) {
  struct Push {
    uint32_t drawnCells, instance, vertexCount, pad0;
  };
  const uint32_t count = (kCells + 1) * (kCells + 1);
  vk::Buffer out(device, count * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible,
                 "terrain vertex readback");
  vk::ComputePipeline kernel(device, GLOBE_TEST_SHADER_DIR "/test_terrain_vertex.comp", 4, sizeof(Push),
                             /*uniformMask=*/1u << 2);
  OffscreenTarget target(device, {kWidth, kHeight});
  device.submitAndWait([&](VkCommandBuffer cmd) {
    target.begin(cmd, kBackground);
    renderer.record(cmd, camera, origin_m, std::span(&node, 1), payloads, 0);  // fills frame buffer 0
    target.end(cmd);
    Push push{kCells, 0, count, 0};
    kernel.bind(cmd,
                {renderer.instanceDescriptor(0), payloads.window(0), renderer.constantsDescriptor(0), out.descriptor()},
                &push, sizeof(push));
    vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
    vk::computeWriteBarrier(cmd);
  });
  auto clip = out.as<glm::vec4>();
  return {clip.begin(), clip.end()};
}

TEST_P(TerrainRenderShapeTest, VerticesDoNotJitterOneCentimetreAboveEarth) {
  TerrainStyle style;
  style.sky = false;
  TerrainRenderer renderer(device(), kCells, style);
  CpuPayloads payloads(device(), model_, 4);
  auto ranges = LodRanges::create({}, model_.radius_m());
  ASSERT_TRUE(ranges.ok());
  const double lat = 46.5, lon = 7.5;
  const NodeId id = nodeAt(RhombusFaceMapping::get().locate(directionFromLatLon(lat, lon)), 20);
  const CpuPayloads::Entry& e = payloads.entry(id);
  const DrawNode node{id, e.slot, ranges->morphFor(id, false), false, e.centre_m};
  const auto positions = payloads.slot(e.slot);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), directionFromLatLon(lat, lon)));
  double worst_px = 0.0;
  int compared = 0;
  for (double rebase_m : {0.0, 100.0}) {
    FloatingOrigin origin(rebase_m, payloadQuantum_m(0, model_.radius_m()));
    const Camera start = cameraAt(lat, lon, 0.01, 20.0, -25.0);
    for (int step = 0; step < 8; ++step) {
      Camera camera = start;
      camera.position_m += double(step) * 0.001 * east;  // 1 mm steps
      origin.update(camera.position_m);
      const auto clip = gpuClipPositions(device(), renderer, camera, origin.origin_m(), node, payloads.pages());
      const glm::dmat4 clipFromCamera = camera.projection() * camera.viewFromWorld(camera.position_m);
      for (uint32_t j = 0; j <= kCells; ++j) {
        for (uint32_t i = 0; i <= kCells; ++i) {
          const glm::vec4 p = positions[size_t(j + 1) * (kCells + 3) + (i + 1)];
          // Double reference: the exact sample position relative to the camera, then projected.
          const glm::dvec3 rel = (e.centre_m + glm::dvec3(glm::vec3(p))) - camera.position_m;
          const glm::dvec4 ref = clipFromCamera * glm::dvec4(rel, 1.0);
          const glm::vec4 gpu = clip[j * (kCells + 1) + i];
          if (ref.w < camera.near_m) continue;
          const double rx = ref.x / ref.w, ry = ref.y / ref.w;
          if (std::abs(rx) > 1.5 || std::abs(ry) > 1.5) continue;
          ASSERT_GT(gpu.w, 0.0f);
          const double dx = (double(gpu.x) / gpu.w - rx) * 0.5 * kWidth;
          const double dy = (double(gpu.y) / gpu.w - ry) * 0.5 * kHeight;
          const double err = std::sqrt(dx * dx + dy * dy);
          worst_px = std::max(worst_px, err);
          ++compared;
          EXPECT_LT(err, 0.05) << "vertex " << i << "," << j << " step " << step << " rebase " << rebase_m;
        }
      }
    }
  }
  std::printf("[ info ] jitter (%s): %d projected vertices, worst %.2e px from the double projection\n",
              GetParam().name, compared, worst_px);
  EXPECT_GT(compared, 50);
}

TEST_F(TerrainRenderTest, ShadedViewDebugViewsAndStats) {
  TerrainStyle style;
  TerrainRenderer renderer(device(), kCells, style);
  CpuPayloads payloads(device(), model_, 4000);
  LodSelector selector = makeSelector();
  const Camera camera = cameraAt(30.0, 20.0, 3000.0, 60.0, -8.0);
  Frame shaded = render(renderer, payloads, selector, camera);
  save(shaded, "terrain_shaded");
  // Full nodes, partial nodes, skirts of each; no sky: the test planet has no atmosphere (the
  // atmosphere's sky is AtmosphereRenderTest's).
  EXPECT_EQ(shaded.stats.drawCalls, 4u);
  EXPECT_EQ(shaded.stats.nodes, uint32_t(shaded.nodes.size()));
  uint32_t partial = 0;
  for (const DrawNode& n : shaded.nodes) partial += n.partial ? 1u : 0u;
  EXPECT_EQ(shaded.stats.partialNodes, partial);
  // Skirts: one strip per node edge whose same-level neighbour is not drawn the same way.
  std::set<std::pair<uint64_t, bool>> drawn;
  for (const DrawNode& n : shaded.nodes) drawn.insert({n.id.key(), n.partial});
  uint32_t skirted = 0;
  uint64_t skirtTriangles = 0;
  for (const DrawNode& n : shaded.nodes) {
    for (int e = 0; e < 4; ++e) {
      if (drawn.count({edgeNeighbour(n.id, e).key(), n.partial}) > 0) continue;
      ++skirted;
      skirtTriangles += (n.partial ? renderer.halfSkirtIndexCount() : renderer.fullSkirtIndexCount()) / 3;
    }
  }
  EXPECT_EQ(shaded.stats.skirtEdges, skirted);
  EXPECT_GT(skirted, 0u);
  EXPECT_LT(skirted, 2 * shaded.stats.nodes) << "most edges are between nodes of one level";
  const uint64_t fullTriangles = renderer.fullIndexCount() / 3, halfTriangles = renderer.halfIndexCount() / 3;
  EXPECT_EQ(shaded.stats.triangles,
            fullTriangles * (shaded.stats.nodes - partial) + halfTriangles * partial + skirtTriangles);
  // Nothing drawn at the top row (no atmosphere: the clear colour, alpha 0, is space), opaque
  // terrain at the bottom row.
  const float* top = shaded.image.pixel(kWidth / 2, 0);
  const float* bottom = shaded.image.pixel(kWidth / 2, kHeight - 1);
  EXPECT_EQ(top[3], 0.0f) << "no atmosphere, no sky";
  EXPECT_EQ(shaded.image.depthAt(kWidth / 2, 0), 0.0f);
  EXPECT_GT(shaded.image.depthAt(kWidth / 2, kHeight - 1), 0.0f);
  EXPECT_EQ(bottom[3], 1.0f);

  // LOD colours: flat per level, so at least two distinct colours with several levels drawn.
  TerrainStyle lod = style;
  lod.debug = TerrainDebugView::kLodColours;
  renderer.setStyle(lod);
  Frame coloured = render(renderer, payloads, selector, camera);
  save(coloured, "terrain_lod_colours");
  EXPECT_NE(std::vector<float>(coloured.image.pixel(kWidth / 2, kHeight - 1),
                               coloured.image.pixel(kWidth / 2, kHeight - 1) + 3),
            std::vector<float>(bottom, bottom + 3));
  if (renderer.wireframeSupported()) {
    renderer.setDebugView(TerrainDebugView::kWireframe);
    Frame wire = render(renderer, payloads, selector, camera);
    save(wire, "terrain_wireframe");
    EXPECT_NE(wire.image.rgba, coloured.image.rgba) << "wireframe differs from filled LOD colours";
  }

  // From orbit too nothing is drawn behind the planet.
  renderer.setStyle(style);
  const Camera orbit = cameraAt(0.0, 0.0, 2.0e7, 0.0, -60.0);
  Frame space = render(renderer, payloads, selector, orbit);
  EXPECT_EQ(space.image.pixel(0, 0)[3], 0.0f);
  EXPECT_EQ(space.image.depthAt(0, 0), 0.0f);
}

TEST_F(TerrainRenderTest, NoAllocationAfterWarmUpAndGrowth) {
  TerrainRenderer renderer(device(), kCells, {}, VertexPositions::kStored, 4);
  CpuPayloads payloads(device(), model_, 16);
  std::vector<DrawNode> nodes;
  for (uint32_t i = 0; i < 10; ++i) {
    NodeId id{uint8_t(i), 0, 0, 0};
    const auto& e = payloads.entry(id);
    nodes.push_back({id, e.slot, {}, false, e.centre_m});
  }
  const Camera camera = cameraAt(0.0, 0.0, 1.0e7, 0.0, -90.0);
  VkBuffer before = VK_NULL_HANDLE;
  for (int frame = 0; frame < 4; ++frame) {
    OffscreenTarget target(device(), {kWidth, kHeight});
    device().submitAndWait([&](VkCommandBuffer cmd) {
      target.begin(cmd, kBackground);
      renderer.record(cmd, camera, glm::dvec3(0.0), nodes, payloads.pages(), uint32_t(frame % 2));
      target.end(cmd);
    });
    if (frame == 2) before = renderer.frameBuffer(0).handle();
  }
  EXPECT_EQ(renderer.frameBuffer(0).handle(), before) << "grown once, then reused";
}

}  // namespace
}  // namespace globe::testing
