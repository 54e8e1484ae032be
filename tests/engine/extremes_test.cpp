// Stability at the extremes (docs/rendering.md, "Floating origin and precision"; docs/lod.md): the real frame (Terrain
// + HeadlessRenderer, GPU payloads, converged) on three radii — the asteroid (1 km), earthlike (6371 km) and
// gasgiant-core (7e7 m) presets — with cameras from 1 mm to 1e11 m above the ground, over the 32 polyhedron vertices
// (the poles are vertices 0 and 11), face seams and ±180°. Per frame: no NaN/Inf in the read-back
// colour and depth, the selection, the drawn nodes' payloads and the instance data; zero background
// pixels inside the silhouette of the lowest drawn surface; payload elevations = CPU reference;
// depth order (every depth lies between the drawn surface's outer and inner spheres along its ray).
// Per radius: vertex jitter for 1 mm camera steps at 1 mm and 1 m. Plus the limits: float exactness
// of payload positions at every level, the drawn mesh above the true ground (camera placement), the
// local vertical seen from 1e11 m. The matrix and the measured values are in docs/tradeoffs.md.
//
// Matrix (kept small for lavapipe: 96x64 images, grid 16):
//   each radius x 6 heights (1 mm, 1 m, 1 km, 1e6, 1e9, 1e11 m) x 2 positions (a face seam and
//   vertex 8 on ±180°), then each radius x 36 positions (32 vertices, 2 seams, lon +180 and -180)
//   at 1 m; jitter at 1 mm and 1 m over a seam.
#include "engine/render/headless_renderer.h"
#include "engine/render/offscreen_target.h"
#include "engine/render/render_output.h"
#include "engine/render/terrain.h"
#include "engine/vk/compute_pipeline.h"
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_bounds.h"
#include "planet/geometry/triacontahedron.h"
#include "planet/lod/lod_ranges.h"
#include "planet/model/planet_file.h"
#include "planet/streaming/payload_reference.h"
#include "shaders/include/payload_layout.h"
#include "shaders/include/terrain_layout.h"
#include "tests/support/gpu_test.h"
#include "tests/support/render_test_geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace globe::testing {
namespace {

constexpr uint32_t kCells = 16;
constexpr uint32_t kWidth = 96, kHeight = 64;
// Jitter is measured in pixels of a 1920-pixel-wide view with the same field of view: 20 times
// stricter than the 96-pixel test image.
constexpr double kJitterWidth_px = 1920.0;
constexpr double kMaxJitter_px = 0.05;
constexpr double kHeights_m[] = {1e-3, 1.0, 1e3, 1e6, 1e9, 1e11};

PlanetDescription preset(const std::string& name) {
  auto p = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/" + name + ".toml");
  if (!p) throw std::runtime_error(p.error().format());
  return *p;
}

bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Ray (o, unit d) against the sphere of radius r at 0: entry distance (negative when o is inside),
// or NaN when the ray misses.
double raySphereEntry(const glm::dvec3& o, const glm::dvec3& d, double r) {
  const double b = glm::dot(o, d);
  const double len = glm::length(o);
  const double c = (len - r) * (len + r);
  const double disc = b * b - c;
  if (disc < 0.0) return std::numeric_limits<double>::quiet_NaN();
  return -b - std::sqrt(disc);
}

struct Position {
  std::string name;
  glm::dvec3 direction;
};

std::vector<Position> allPositions() {
  const auto& t = Triacontahedron::get();
  const auto& m = RhombusFaceMapping::get();
  std::vector<Position> out;
  for (int v = 0; v < 32; ++v) out.push_back({"vertex" + std::to_string(v), t.vertexDirection(v)});
  out.push_back({"seam_f3", m.unitPoint(3, 0.5, 0.0)});
  out.push_back({"seam_f17", m.unitPoint(17, 0.0, 0.3)});
  out.push_back({"lon+180", directionFromLatLon(5.0, 180.0)});
  out.push_back({"lon-180", directionFromLatLon(-40.0, -180.0)});
  return out;
}

// Worst values over every frame of a test (printed, and quoted in docs/tradeoffs.md).
struct Worst {
  int frames = 0;
  long nonFinite = 0;        // NaN/Inf in colour, depth, selection, payloads, instances
  long cracks = 0;           // background pixels inside the lowest drawn surface's silhouette
  long depthOrder = 0;       // depths outside [outer entry, inner hit] along their ray
  double elevation_m = 0;    // max |payload w - CPU elevation|
  double elevation_ulp = 0;  // max |payload w - float(CPU elevation)| in float ulps of the value
  double position_m = 0;     // max |centre + payload xyz - CPU surface point| (quantum included)
  double jitter_px = 0;      // max GPU vs double projection error (1920-px view)
  long samples = 0;          // payload samples compared
  long projected = 0;        // vertices compared for jitter
};

class ExtremesTest : public GpuTest {
 protected:
  // One planet's terrain with the standard settings at grid 16.
  struct Scene {
    explicit Scene(vk::Device& device, const std::string& name) : description(preset(name)), model(description) {
      TerrainSettings settings;
      settings.gridCells = kCells;
      settings.style.sky = false;  // the background must stay the clear colour: holes show as alpha 0
      auto t = Terrain::create(device, model, settings);
      if (!t) throw std::runtime_error(t.error().format());
      terrain = std::move(*t);
      renderer = std::make_unique<HeadlessRenderer>(device, VkExtent2D{kWidth, kHeight});
      renderer->setClearColour({1.0f, 0.0f, 1.0f, 0.0f});  // magenta, alpha 0: terrain writes alpha 1
    }
    PlanetDescription description;
    ElevationModel model;
    std::unique_ptr<Terrain> terrain;
    std::unique_ptr<HeadlessRenderer> renderer;
    uint64_t jitterFrame = 0;  // frames of checkJitter, after the renderer's
  };

  // Low cameras look 30° down (ground to the horizon: every level at once); high ones, and the
  // position sweep, straight down (the seams and the vertex's faces under the camera).
  Camera cameraAt(const Scene& s, const glm::dvec3& direction, double height_m, bool down = false,
                  double pitch_deg = std::nan("")) const {
    const glm::dvec2 ll = latLonFromPosition(direction);
    const double pitch = !std::isnan(pitch_deg) ? pitch_deg : height_m <= 1e4 && !down ? -30.0 : -90.0;
    GeodeticPose pose{ll.x, ll.y, height_m, 30.0, pitch, 0.0};
    return cameraFromPose(pose, s.terrain->cameraGroundRadius(direction), s.model.radius_m(), double(kWidth) / kHeight);
  }

  // Copies the meshes of the drawn nodes' payload slots to the host, in selection order (not the
  // normal maps: their texels are not floats).
  std::vector<glm::vec4> readSlots(const Scene& s, const std::vector<uint32_t>& slots) {
    const VkDeviceSize slotBytes = GpuPayloadGenerator::bufferSlotBytes(kCells);
    const VkDeviceSize meshBytes = GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells) * 16u;
    vk::Buffer host(device(), std::max<VkDeviceSize>(1, slots.size()) * meshBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    vk::MemoryUse::HostVisible, "extremes payload readback");
    if (!slots.empty()) {
      std::vector<VkBufferCopy> regions;
      for (size_t k = 0; k < slots.size(); ++k) regions.push_back({slots[k] * slotBytes, k * meshBytes, meshBytes});
      device().submitAndWait([&](VkCommandBuffer cmd) {
        vkCmdCopyBuffer(cmd, s.terrain->generator().payloads().handle(), host.handle(), uint32_t(regions.size()),
                        regions.data());
      });
    }
    auto data = host.as<glm::vec4>();
    return {data.begin(), data.begin() + std::ptrdiff_t(slots.size() * GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells))};
  }

  // What checkSelection found: the drawn nodes' slots, in selection order, and the spheres every
  // drawn triangle lies between.
  struct SelectionCheck {
    std::vector<uint32_t> slots;
    double inner_m = std::numeric_limits<double>::infinity();
    double outer_m = 0.0;
    long bad = 0;           // non-finite or inconsistent values
    bool complete = false;  // false: a drawn node had no payload (a fatal failure)
  };

  // Selection: morph bands (finite below depth 0, +inf at depth 0), radius ranges, bounds.
  void checkSelection(Scene& s, SelectionCheck& out) {
    const auto& mapping = RhombusFaceMapping::get();
    long selectionBad = 0;
    for (const SelectedNode& n : s.terrain->selection().nodes) {
      const int drawn = n.id.level - (n.partial ? 1 : 0);
      const MorphRange morph = n.morph.at(0.5, 0.5);
      if (drawn == 0) {
        selectionBad +=
            morph.start_m == std::numeric_limits<double>::infinity() && morph.end_m == morph.start_m ? 0 : 1;
      } else {
        selectionBad += std::isfinite(morph.start_m) && std::isfinite(morph.end_m) && morph.start_m >= 0.0 &&
                                morph.start_m <= morph.end_m
                            ? 0
                            : 1;
      }
      const auto range = s.terrain->pool().knownRadiusRange(n.id);
      const auto slot = s.terrain->pool().slotOf(n.id);
      ASSERT_TRUE(range && slot) << "drawn node without payload";
      selectionBad += std::isfinite(range->min_m) && std::isfinite(range->max_m) && range->min_m > 0.0 &&
                              range->min_m <= range->max_m
                          ? 0
                          : 1;
      const NodeBounds bounds = NodeBounds::forNode(mapping, n.id, *range);
      for (const glm::dvec3& c : bounds.corners) selectionBad += finite3(c) ? 0 : 1;
      for (const glm::dvec4& p : bounds.planes) selectionBad += std::isfinite(p.x + p.y + p.z + p.w) ? 0 : 1;
      out.slots.push_back(*slot);
      // Every drawn triangle (morphed to the parent's cells, skirts aside) lies above the sphere of
      // the node's lowest radius times the cosine of twice a drawn cell's diagonal angle.
      const double diagonal =
          std::max(angleBetween_rad(nodeCornerDirection(mapping, n.id, 0), nodeCornerDirection(mapping, n.id, 2)),
                   angleBetween_rad(nodeCornerDirection(mapping, n.id, 1), nodeCornerDirection(mapping, n.id, 3)));
      const double angle = 2.0 * 1.25 * diagonal / double(n.partial ? kCells / 2 : kCells);
      out.inner_m = std::min(out.inner_m, range->min_m * std::cos(angle));
      out.outer_m = std::max(out.outer_m, range->max_m);
    }
    EXPECT_EQ(selectionBad, 0) << "selection";
    out.bad = selectionBad;
    out.complete = true;
  }

  // Payloads of the drawn nodes: finite; elevations and positions = CPU reference at sampled points
  // (positions on the visible surface: the sea's over lower ground on a planet with water).
  // Returns the number of non-finite values.
  long checkPayloads(Scene& s, const std::vector<uint32_t>& slots, Worst& worst) {
    const std::vector<glm::vec4> payloads = readSlots(s, slots);
    const size_t perSlot = GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells);
    long payloadBad = 0;
    for (const glm::vec4& v : payloads) payloadBad += std::isfinite(v.x + v.y + v.z + v.w) ? 0 : 1;
    EXPECT_EQ(payloadBad, 0) << "payloads";
    const int n = int(kCells), side = n + 3;
    const int picks[] = {-1, 0, n / 2, n, n + 1};
    const Selection& selection = s.terrain->selection();
    for (size_t k = 0; k < selection.nodes.size(); ++k) {
      const NodeId& id = selection.nodes[k].id;
      const gpu::PayloadJob job = makePayloadJob(id, slots[k], s.model, /*waterSurface=*/true);
      EXPECT_EQ(glm::dvec3(job.centre.x, job.centre.y, job.centre.z), s.terrain->generator().slotCentre(slots[k]));
      for (int j : picks) {
        for (int i : picks) {
          const glm::vec4 p = payloads[k * perSlot + size_t((j + 1) * side + (i + 1))];
          const glm::dvec3 dir = payloadSampleDirection(job, kCells, i, j);
          const double e = s.model.elevation_m(dir);
          const double de = std::abs(double(p.w) - e);
          worst.elevation_m = std::max(worst.elevation_m, de);
          const float ef = float(e);
          const double ulp =
              double(std::nextafter(std::abs(ef), std::numeric_limits<float>::infinity()) - std::abs(ef));
          worst.elevation_ulp = std::max(worst.elevation_ulp, std::abs(double(p.w) - double(ef)) / ulp);
          // float rounding of the value (half an ulp) plus the GPU/CPU agreement bound of elevation.h.
          EXPECT_LE(de, 1e-6 + std::abs(e) * 0x1p-24)
              << "node " << int(id.face) << "/" << int(id.level) << " sample " << i << "," << j;
          const glm::dvec3 world = glm::dvec3(job.centre.x, job.centre.y, job.centre.z) + glm::dvec3(glm::vec3(p));
          const double dp = glm::length(world - s.model.shape().position(dir, s.model.visibleElevation_m(dir)));
          worst.position_m = std::max(worst.position_m, dp / job.centre.w);
          // Quantised to the level's quantum: at most half a quantum per axis (plus rounding).
          EXPECT_LE(dp, job.centre.w * 0.87 + std::abs(e) * 1e-6 + 1e-6);
          ++worst.samples;
        }
      }
    }
    return payloadBad;
  }

  // Instance data the draw used (TerrainFrame + one TerrainInstance per drawn node). Returns the
  // number of non-finite or inconsistent values.
  long checkInstances(Scene& s) {
    const vk::Buffer& frameBuffer = s.terrain->renderer().frameBuffer(uint32_t(s.renderer->frame() % 2));
    const auto* bytes = static_cast<const unsigned char*>(frameBuffer.mapped());
    gpu::TerrainFrame frame;
    std::memcpy(&frame, bytes, sizeof(frame));
    long bad = 0;
    for (float f : frame.clipFromCamera.m) bad += std::isfinite(f) ? 0 : 1;
    for (const gpu::TerrainVec4& v : {frame.cameraHigh, frame.cameraLow, frame.planetCentre, frame.sun})
      bad += std::isfinite(v.x + v.y + v.z + v.w) ? 0 : 1;
    for (size_t k = 0; k < s.terrain->selection().nodes.size(); ++k) {
      gpu::TerrainInstance inst;
      std::memcpy(&inst, s.terrain->renderer().instanceBytes(uint32_t(s.renderer->frame() % 2)) + k * sizeof(inst),
                  sizeof(inst));
      bad += std::isfinite(inst.offset.x + inst.offset.y + inst.offset.z + inst.offset.w) ? 0 : 1;
      const gpu::TerrainVec4& e = inst.morphEnd;
      bool finite = true;  // FLT_MAX (never morphs) is finite; a sum of them would not be
      for (float v : {inst.morph.x, inst.morph.y, inst.morph.z, e.x, e.y, e.z, e.w})
        finite = finite && std::isfinite(v);
      bad += finite && inst.morph.y <= std::min(std::min(e.x, e.y), std::min(e.z, e.w)) ? 0 : 1;
    }
    EXPECT_EQ(bad, 0) << "instances";
    return bad;
  }

  // Cracks and depth order, per pixel: {background pixels inside the inner sphere's silhouette,
  // depths outside [outer entry, inner hit]}.
  std::pair<long, long> checkPixels(const Camera& camera, const ReadbackImage& image, double inner, double outer) {
    std::pair<long, long> out{0, 0};
    long& cracks = out.first;
    long& order = out.second;
    for (uint32_t y = 0; y < kHeight; ++y) {
      for (uint32_t x = 0; x < kWidth; ++x) {
        const glm::dvec3 ray = testing::pixelPositionRay(camera, x + 0.5, y + 0.5, kWidth, kHeight);
        const double innerHit = raySphereEntry(camera.position_m, ray, inner);
        bool inside = innerHit > 0.0;
        for (auto [dx, dy] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}})
          inside =
              inside && raySphereEntry(camera.position_m,
                                       testing::pixelPositionRay(camera, x + dx, y + dy, kWidth, kHeight), inner) > 0.0;
        const float depth = image.depthAt(x, y);
        if (inside && image.pixel(x, y)[3] == 0.0f) ++cracks;
        if (depth > 0.0f) {
          // The nearest surface wins: the hit is no nearer than the outer sphere of the drawn
          // nodes and no farther than the inner one (if the ray reaches it).
          const double d = rayDistanceFromDepth(camera, kWidth, kHeight, x, y, depth);
          const double tol = d * 1e-5 + 1e-7;
          const double outerEntry = raySphereEntry(camera.position_m, ray, outer);
          bool ok = std::isfinite(d) && d > 0.0;
          if (ok && std::isfinite(outerEntry)) ok = d >= outerEntry - tol;
          if (ok && innerHit > 0.0) ok = d <= innerHit + tol;
          if (!ok && order++ == 0)
            ADD_FAILURE() << "depth order at pixel " << x << "," << y << ": ray distance " << d
                          << " m, outer sphere entry " << outerEntry << " m, inner sphere hit " << innerHit
                          << " m (inner " << inner << ", outer " << outer << ")";
        }
      }
    }
    return out;
  }

  // Renders one converged frame and checks everything in it; accumulates into `worst`.
  void checkFrame(Scene& s, const Camera& camera, const std::string& label, Worst& worst) {
    SCOPED_TRACE(label);
    const uint64_t generatedBefore = s.terrain->generator().nodesGenerated();
    const auto start = std::chrono::steady_clock::now();
    const FrameStats stats = s.renderer->renderFrame(*s.terrain, camera, true);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const uint64_t generated = s.terrain->generator().nodesGenerated() - generatedBefore;
    const ReadbackImage image = s.renderer->readback();
    ++worst.frames;
    long nonFinite = 0;

    // Read-back colour and depth.
    for (float c : image.rgba) nonFinite += std::isfinite(c) ? 0 : 1;
    for (float d : image.depth) nonFinite += std::isfinite(d) && d >= 0.0f && d <= 1.0f ? 0 : 1;
    EXPECT_EQ(nonFinite, 0) << "colour/depth";

    SelectionCheck selection;
    checkSelection(s, selection);
    if (!selection.complete) return;
    nonFinite += selection.bad;
    nonFinite += checkPayloads(s, selection.slots, worst);
    nonFinite += checkInstances(s);
    worst.nonFinite += nonFinite;
    const auto [cracks, order] = checkPixels(camera, image, selection.inner_m, selection.outer_m);
    EXPECT_EQ(cracks, 0);
    EXPECT_EQ(order, 0) << "depth order";
    worst.cracks += cracks;
    worst.depthOrder += order;
    std::printf(
        "[ info ] %-28s nodes %4u (partial %3u) cracks %ld depth %ld non-finite %ld (%llu generated, %.0f ms)\n",
        label.c_str(), stats.nodes_selected, stats.nodes_partial, cracks, order, nonFinite,
        (unsigned long long)generated, ms);
  }

  // Vertex jitter: GPU projection (the vertex shader's code, test_terrain_vertex.comp) of the finest
  // node nearest the camera vs the double projection, over 8 camera steps of 1 mm. Moves the terrain
  // to frames beyond the headless renderer's: call after the scene's last checkFrame.
  void checkJitter(Scene& s, const glm::dvec3& direction, double height_m, Worst& worst) {
    SCOPED_TRACE("jitter at " + std::to_string(height_m) + " m");
    // Looking 5° down: the horizon, where a ground camera's nearby finest nodes appear, mid-view.
    const Camera start = cameraAt(s, direction, height_m, false, -5.0);
    // Converge with the scene's own frame counter (the headless renderer's is left behind).
    uint64_t& frame = s.jitterFrame;
    frame = std::max(frame, s.renderer->frame());
    for (int round = 0; round < 10000; ++round) {
      ++frame;
      s.terrain->update(frame, start, frame - 1);
      if (s.terrain->converged()) break;
      s.terrain->waitForGeneration();
    }
    struct Push {
      uint32_t drawnCells, instance, vertexCount, pad0;
    };
    const uint32_t count = (kCells + 1) * (kCells + 1);
    vk::Buffer out(device(), count * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible,
                   "extremes vertex readback");
    vk::ComputePipeline kernel(device(), GLOBE_TEST_SHADER_DIR "/test_terrain_vertex.comp", 4, sizeof(Push),
                               /*uniformMask=*/1u << 2);
    OffscreenTarget target(device(), {kWidth, kHeight});
    const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), direction) + glm::dvec3(1e-9, 0, 0));
    const double scale = kJitterWidth_px * 0.5, scaleY = kJitterWidth_px / start.aspect * 0.5;
    int compared = 0, dbgBehind = 0, dbgOff = 0, dbgMorph = 0;
    for (int step = 0; step < 8; ++step) {
      Camera camera = start;
      camera.position_m += double(step) * 1e-3 * east;
      ++frame;
      s.terrain->update(frame, camera, frame - 1);
      // The finest full node whose centre projects inside the view, nearest its centre. A centre
      // merely ahead is not enough: a finest node under a ground camera can be ahead yet entirely
      // below the view.
      const Selection& selection = s.terrain->selection();
      const glm::dmat4 clipFromCentre = camera.projection() * camera.viewFromWorld(camera.position_m);
      int best = -1;
      double bestScore = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k < selection.nodes.size(); ++k) {
        const SelectedNode& n = selection.nodes[k];
        if (n.partial) continue;
        const glm::dvec3 rel = s.terrain->generator().slotCentre(*s.terrain->pool().slotOf(n.id)) - camera.position_m;
        const double ahead = glm::dot(rel, camera.forward);
        const glm::dvec4 clipCentre = clipFromCentre * glm::dvec4(rel, 1.0);
        const bool inView = clipCentre.w > 0.0 && std::abs(clipCentre.x / clipCentre.w) < 0.9 &&
                            std::abs(clipCentre.y / clipCentre.w) < 0.9;
        if (ahead > 0.0 && inView) {
          const double offAxis = glm::length(rel - ahead * camera.forward) / ahead;
          const double score = offAxis - 1e3 * n.id.level;  // finest level first
          if (score < bestScore) {
            bestScore = score;
            best = int(k);
          }
        }
      }
      ASSERT_GE(best, 0);
      const SelectedNode& node = selection.nodes[size_t(best)];
      const uint32_t slot = *s.terrain->pool().slotOf(node.id);
      const glm::dvec3 centre = s.terrain->generator().slotCentre(slot);
      const uint32_t frameIndex = uint32_t(frame % 2);
      device().submitAndWait([&](VkCommandBuffer cmd) {
        const float clear[4] = {1.0f, 0.0f, 1.0f, 0.0f};
        target.begin(cmd, clear);
        s.terrain->record(cmd, camera, frameIndex);
        target.end(cmd);
        // The node's grid instance, found in what record() just wrote (grid instances come first,
        // grouped by payload page): same slot offset, same node offset.
        const PayloadPages& pages = s.terrain->generator().pages();
        const auto* records =
            reinterpret_cast<const gpu::TerrainInstance*>(s.terrain->renderer().instanceBytes(frameIndex));
        const glm::vec3 offset(centre - s.terrain->origin());
        uint32_t instance = UINT32_MAX;
        for (uint32_t i = 0; i < selection.nodes.size() && instance == UINT32_MAX; ++i) {
          const gpu::TerrainInstance& r = records[i];
          if (r.info.x == pages.localSlot(slot) * GLOBE_PAYLOAD_SLOT_VEC4(kCells) && r.info.y == 1u &&
              r.offset.x == offset.x && r.offset.y == offset.y && r.offset.z == offset.z)
            instance = i;
        }
        ASSERT_NE(instance, UINT32_MAX);
        Push push{kCells, instance, count, 0};
        kernel.bind(cmd,
                    {s.terrain->renderer().instanceDescriptor(frameIndex),
                     s.terrain->generator().pages().window(s.terrain->generator().pages().page(slot)),
                     s.terrain->renderer().constantsDescriptor(frameIndex), out.descriptor()},
                    &push, sizeof(push));
        vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
        vk::computeWriteBarrier(cmd);
      });
      const std::vector<glm::vec4> payload = readSlots(s, {slot});
      const auto clip = out.as<glm::vec4>();
      const glm::dmat4 clipFromCamera = camera.projection() * camera.viewFromWorld(camera.position_m);
      for (uint32_t j = 0; j <= kCells; ++j) {
        for (uint32_t i = 0; i <= kCells; ++i) {
          const glm::vec4 p = payload[size_t(j + 1) * (kCells + 3) + (i + 1)];
          const glm::dvec3 rel = (centre + glm::dvec3(glm::vec3(p))) - camera.position_m;
          // Unmorphed vertices only (even-even ones never move; others only before the band).
          const bool even = (i % 2 == 0) && (j % 2 == 0);
          if (!even && !(glm::length(rel) < node.morph.at(double(i) / kCells, double(j) / kCells).start_m * 0.99)) {
            ++dbgMorph;
            continue;
          }
          const glm::dvec4 ref = clipFromCamera * glm::dvec4(rel, 1.0);
          if (ref.w < camera.near_m) {
            ++dbgBehind;
            continue;
          }
          const double rx = ref.x / ref.w, ry = ref.y / ref.w;
          if (std::abs(rx) > 1.0 || std::abs(ry) > 1.0) {
            ++dbgOff;
            continue;
          }
          const glm::vec4 gpu = clip[j * (kCells + 1) + i];
          ASSERT_GT(gpu.w, 0.0f);
          const double dx = (double(gpu.x) / gpu.w - rx) * scale, dy = (double(gpu.y) / gpu.w - ry) * scaleY;
          const double err = std::sqrt(dx * dx + dy * dy);
          worst.jitter_px = std::max(worst.jitter_px, err);
          ++compared;
          EXPECT_LE(err, kMaxJitter_px) << "vertex " << i << "," << j << " step " << step;
        }
      }
    }
    worst.projected += compared;
    EXPECT_GT(compared, 20) << "the nearest node should be on screen; " << dbgBehind << " behind, " << dbgOff
                            << " off, " << dbgMorph << " morphing, near " << start.near_m;
  }

  void runPlanet(const std::string& name) {
    Scene s(device(), name);
    Worst worst;
    const auto positions = allPositions();
    const Position& seam = positions[32];
    const Position& vertex8 = positions[8];  // five-fold, on ±180°
    for (double h : kHeights_m) {
      for (const Position* p : {&seam, &vertex8}) {
        char label[64];
        std::snprintf(label, sizeof(label), "%s %s %g m", name.c_str(), p->name.c_str(), h);
        checkFrame(s, cameraAt(s, p->direction, h), label, worst);
      }
    }
    for (const Position& p : positions) {
      checkFrame(s, cameraAt(s, p.direction, 1.0, true), name + " " + p.name + " 1 m down", worst);
    }
    for (double h : {1e-3, 1.0}) checkJitter(s, seam.direction, h, worst);
    std::printf(
        "[ info ] %s: %d frames, non-finite %ld, cracks %ld, depth order %ld, max |gpu-cpu| elevation %.3g m "
        "= %.1f float ulp of the value (%ld samples), max position error %.3f quanta, max jitter %.2e px at "
        "1920 px (%ld vertices)\n",
        name.c_str(), worst.frames, worst.nonFinite, worst.cracks, worst.depthOrder, worst.elevation_m,
        worst.elevation_ulp, worst.samples, worst.position_m, worst.jitter_px, worst.projected);
  }
};

TEST_F(ExtremesTest, Asteroid1km) { runPlanet("asteroid"); }
TEST_F(ExtremesTest, Earthlike6371km) { runPlanet("earthlike"); }
TEST_F(ExtremesTest, GasGiantCore7e7m) { runPlanet("gasgiant-core"); }

// Float budget of payload positions (payload_layout.h): relative to their node centre and quantised
// to q(level) = 2^(ceil(log2 width) - 18), they are exact floats while |xyz| < 2^24 q, i.e. 64 node
// widths. A level-0 node reaches ~0.55 R from its centre (half the rhombus' long diagonal as a chord),
// which is < 1 width, at every radius: the limit is scale-free. Checked on real level-0 and deepest
// payloads of the three presets; the numbers go to docs/tradeoffs.md.
TEST_F(ExtremesTest, PayloadPositionsFitFloatAtEveryRadius) {
  for (const char* name : {"asteroid", "earthlike", "gasgiant-core"}) {
    const PlanetDescription description = preset(name);
    const ElevationModel model(description);
    const double radius = model.radius_m();
    for (int level : {0, 20, kMaxNodeLevel}) {
      const NodeId id = nodeAt(RhombusFaceMapping::get().locate(glm::normalize(glm::dvec3(0.3, 0.5, 0.8))), level);
      const gpu::PayloadJob job = makePayloadJob(id, 0, model);
      std::vector<glm::vec4> slot(GLOBE_PAYLOAD_VEC4_PER_SLOT(kCells));
      fillPayloadReference(model, job, kCells, slot);
      const double q = job.centre.w;
      double largest = 0.0;
      long offGrid = 0;
      for (size_t k = 0; k < size_t((kCells + 3) * (kCells + 3)); ++k) {
        for (int c = 0; c < 3; ++c) {
          const double v = double(slot[k][c]);
          largest = std::max(largest, std::abs(v));
          offGrid += std::fmod(v, q) == 0.0 ? 0 : 1;  // every component a whole number of quanta
        }
      }
      const float lf = float(largest);
      const double ulp = double(std::nextafter(lf, std::numeric_limits<float>::infinity()) - lf);
      std::printf(
          "[ info ] %-13s R %.0f m level %2d: width %.4g m, quantum %.4g m, max |xyz| %.4g m = %.3g quanta "
          "(exact below 2^24 = 1.68e7), float step there %.3g m; centre double step %.3g m\n",
          name, radius, level, nominalNodeWidth(level, radius), q, largest, largest / q, ulp,
          std::nextafter(radius, 2.0 * radius) - radius);
      EXPECT_EQ(offGrid, 0) << name << " level " << level;
      EXPECT_LT(largest / q, 0x1p24) << name << " level " << level << ": positions would round";
      EXPECT_LE(ulp, q) << name << " level " << level;
      // The deepest quantum still holds many double steps of the centre's magnitude.
      EXPECT_GE(q, 16.0 * (std::nextafter(radius * 1.1, radius * 2.0) - radius * 1.1)) << name << " level " << level;
    }
  }
}

// The drawn mesh misses the relief finer than its samples and can lie above the true ground; a
// camera placed by the true ground would be under it (seeing through the planet: background or the
// far side). Terrain::cameraGroundRadius measures heights from the higher of the two. Measured over
// 200 random directions per preset at the default depth 20, grid 16.
TEST_F(ExtremesTest, CameraHeightIsAboveTheDrawnMesh) {
  for (const char* name : {"asteroid", "earthlike", "gasgiant-core"}) {
    const PlanetDescription description = preset(name);
    const ElevationModel model(description);
    TerrainSettings settings;
    settings.gridCells = kCells;
    auto terrain = Terrain::create(device(), model, settings);
    ASSERT_TRUE(terrain.ok());
    double worstAbove = 0.0;
    int above1mm = 0;
    uint32_t state = 12345u;
    auto next = [&] {
      state = state * 1664525u + 1013904223u;
      return double(state) / 4294967296.0 * 2.0 - 1.0;
    };
    for (int k = 0; k < 200; ++k) {
      glm::dvec3 d{next(), next(), next()};
      if (glm::length(d) < 0.1) continue;
      d = glm::normalize(d);
      const double ground = (*terrain)->groundRadius(d);
      const double mesh = drawnSurfaceRadius(model, d, settings.ranges.maxDepth, kCells);
      const double camera = (*terrain)->cameraGroundRadius(d);
      EXPECT_EQ(camera, std::max(ground, mesh));
      worstAbove = std::max(worstAbove, mesh - ground);
      above1mm += mesh - ground > 1e-3 ? 1 : 0;
    }
    std::printf(
        "[ info ] %-13s drawn mesh (depth 20, grid 16) above the true ground by up to %.3g m; "
        "more than 1 mm in %d of 200 directions\n",
        name, worstAbove, above1mm);
  }
}

// A long-lived pool that has filled up declines prefetch (it only evicts what is farther than the
// prefetched node); such requests stay queued while the view stays. converged() used to wait for
// them: the headless renderer then spun 100 000 rounds (about 2 minutes on lavapipe) per frame.
TEST_F(ExtremesTest, FullPoolStillConverges) {
  const PlanetDescription description = preset("earthlike");
  const ElevationModel model(description);
  TerrainSettings settings;
  settings.gridCells = kCells;
  settings.streaming.maxSlots = 1200;  // fills after about one ground view
  auto terrain = Terrain::create(device(), model, settings);
  ASSERT_TRUE(terrain.ok());
  const auto positions = allPositions();
  uint64_t frame = 0;
  for (int v : {0, 1, 2}) {
    const glm::dvec3 d = positions[size_t(v)].direction;
    const glm::dvec2 ll = latLonFromPosition(d);
    const Camera camera =
        cameraFromPose({ll.x, ll.y, 1.0, 30.0, -90.0, 0.0}, (*terrain)->cameraGroundRadius(d), model.radius_m(), 1.5);
    int rounds = 0;
    for (; rounds < 5000; ++rounds) {
      ++frame;
      (*terrain)->update(frame, camera, frame - 1);
      if ((*terrain)->converged()) break;
      (*terrain)->waitForGeneration();
    }
    const StreamingStats& stats = (*terrain)->pool().stats();
    std::printf("[ info ] vertex %d: converged after %d rounds, %u resident of %u slots, %u prefetch left queued\n", v,
                rounds, stats.residentNodes, (*terrain)->pool().slotCapacity(), stats.queueLength);
    EXPECT_LT(rounds, 2000) << "vertex " << v;
    EXPECT_EQ((*terrain)->selection().stats.fallbacks, 0u);
  }
}

// Seen from 1e11 m, a 1 km asteroid is 2e-8 rad wide; the floating origin is at the camera, so node
// offsets are ~1e11 m in float (steps of 8 km) and so is the planet centre: the local vertical
// normalize(world - planetCentre) loses all precision. That only touches sub-pixel geometry (the
// projection stays accurate to float precision of the distance, 2^-24 rad): rendered into an
// odd-sized image whose centre pixel looks straight at the planet, every pixel stays finite.
TEST_F(ExtremesTest, SubPixelPlanetAt1e11mStaysFinite) {
  const PlanetDescription description = preset("asteroid");
  const ElevationModel model(description);
  TerrainSettings settings;
  settings.gridCells = kCells;
  auto terrain = Terrain::create(device(), model, settings);
  ASSERT_TRUE(terrain.ok());
  HeadlessRenderer renderer(device(), {33, 33});
  for (double h : {1e9, 1e10, 1e11, 1e12}) {
    const glm::dvec3 d = directionFromLatLon(10.0, 20.0);
    const Camera camera =
        cameraFromPose({10.0, 20.0, h, 0.0, -90.0, 0.0}, (*terrain)->cameraGroundRadius(d), model.radius_m(), 1.0);
    renderer.renderFrame(**terrain, camera, true);
    const ReadbackImage image = renderer.readback();
    long bad = 0;
    for (float c : image.rgba) bad += std::isfinite(c) ? 0 : 1;
    for (float z : image.depth) bad += std::isfinite(z) ? 0 : 1;
    const float* centre = image.pixel(16, 16);
    std::printf("[ info ] asteroid from %.0e m: centre pixel %.3f %.3f %.3f depth %.3g, %ld non-finite\n", h, centre[0],
                centre[1], centre[2], image.depthAt(16, 16), bad);
    EXPECT_EQ(bad, 0) << h;
  }
}

}  // namespace
}  // namespace globe::testing
