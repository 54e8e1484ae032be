// globe render: one headless frame of the terrain (or the reference sphere) written as PNG or EXR.
#include "commands.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "engine/render/sphere_preview.h"
#include "engine/render/terrain_warnings.h"
#include "engine/vk/device.h"
#include "options.h"
#include "planet/analysis/terrain_queries.h"
#include "planet/camera/camera.h"
#include "planet/core/atomic_file.h"
#include "planet/model/planet_file.h"
#include "planet/streaming/payload_reference.h"
#include "progress_bar.h"
#include "render_terrain.h"

#include <algorithm>
#include <cstdio>

namespace globe::cli {

// One converged terrain frame: waits until every node the view needs is resident before drawing.
Result<ImageRgba> renderTerrain(vk::Device& device, const Camera& camera, const ElevationModel& model,
                                TerrainSettings settings, uint32_t width, uint32_t height) {
  // The caller put the sun in settings.style.sunDirection.
  announceAtmosphereTables(model, settings);
  auto terrain = Terrain::create(device, model, settings);
  if (!terrain) return budgetOptionError(terrain.error());
  HeadlessRenderer renderer(device, {width, height});
  // Converging can take tens of seconds (`exact`): the share of the payloads asked for so far that
  // are done, never moving back though each round may reveal finer nodes to ask for.
  ProgressBar bar("converging");
  uint64_t done = 0;
  double shown = 0.0;
  FrameStats stats = renderer.renderFrame(**terrain, camera, true, [&](const FrameStats& round) {
    done += round.gen_completed;
    const double waiting = double(round.queue_length) + double(round.gen_in_flight);
    shown = std::max(shown, double(done) / std::max(1.0, double(done) + waiting));
    bar.update(shown);
  });
  bar.finish();
  TerrainWarnings warnings;
  printNewWarnings(warnings, **terrain);
  std::printf("%u nodes (%u partial), %llu triangles, %u payloads resident (%.1f MiB), frame %.1f ms (GPU %.1f ms)\n",
              stats.nodes_selected, stats.nodes_partial, (unsigned long long)stats.triangles,
              (*terrain)->pool().stats().residentNodes, stats.resident_mib, stats.frame_ms, stats.gpu_ms);
  if (stats.texel_magnification_px > 0)
    std::printf("texels: at most %.2f px (p95 %.2f px)%s\n", stats.texel_magnification_px,
                stats.texel_magnification_p95_px,
                (*terrain)->imagery() ? (", " + std::to_string(stats.imagery_tiles) + " imagery tiles").c_str() : "");
  if (const AtmosphereLuts* a = (*terrain)->atmosphere())
    std::printf("atmosphere tables: %s in %.0f ms\n", a->fromCache() ? "read from the cache" : "computed",
                a->build_ms());
  if ((*terrain)->depthCap() < settings.ranges.maxDepth)
    std::printf("frame budget: levels up to %d of %d\n", (*terrain)->depthCap(), settings.ranges.maxDepth);
  return toImage(renderer.readback(), camera);
}

namespace {

struct RenderOptions {
  DeviceFlags device;
  std::string planet;
  std::string at = "20,10,2000000";
  std::string heightRef = "ground";
  std::string size = "1280x720";
  std::string out = "out/render.png";
  std::string mode = "terrain";
  std::string sun;         // --sun AZIMUTH,ELEVATION; empty: the default sun
  QualityOptions quality;  // --quality, --grid, --tolerance
  BudgetOptions budget;
};

// The reference sphere, lit by `sun`.
ImageRgba renderSphere(vk::Device& device, const Camera& camera, const ElevationModel& model, const ImageSize& size,
                       const glm::dvec3& sun) {
  OffscreenTarget target(device, {size.width, size.height});
  SpherePreview preview(device);
  const float clear[4] = {0, 0, 0, 1};
  device.submitAndWait([&](VkCommandBuffer cmd) {
    target.begin(cmd, clear);
    preview.record(cmd, camera, model.radius_m(), sun);
    target.end(cmd);
  });
  return toImage(target.readback(), camera);
}

int runRender(const RenderOptions& o) {
  auto reference = parseHeightReference(o.heightRef, "--height-ref");
  if (!reference) return usageError(reference.error());
  auto pose = parsePose(o.at, "--at", *reference);
  if (!pose) return usageError(pose.error());
  auto size = parseSize(o.size, "--size");
  if (!size) return usageError(size.error());
  if (auto s = checkWritable(o.out, "--out"); !s) return usageError(s.error());
  if (auto s = checkImageExtension(o.out, "--out"); !s) return usageError(s.error());
  auto planet = loadPlanetFile(o.planet);
  if (!planet) return usageError(planet.error());
  auto settings = renderSettingsFromOptions(o.quality, o.budget, *planet, *size);
  if (!settings) return usageError(settings.error());

  ElevationModel model(*planet);
  double aspect = double(size->width) / double(size->height);
  glm::dvec3 down = directionFromLatLon(pose->latitude_deg, pose->longitude_deg);
  // Heights are above what is drawn: the finest mesh can lie decimetres above the true ground
  // (Terrain::cameraGroundRadius), and a low camera under it would see through the planet.
  const TerrainQueries queries(model);
  const double ground = o.mode == "terrain"
                            ? queries.cameraFloorRadius(down, settings->ranges.maxDepth, settings->gridCells)
                            : model.radius_m() + queries.exactHeight_m(down);
  if (*reference == HeightReference::sphere) {
    pose = poseAboveGround(*pose, ground, model.radius_m(), "--at");
    if (!pose) return usageError(pose.error());
  }
  Camera camera = cameraFromPose(*pose, ground, model.shape(), aspect);
  auto sun = sunFromOption(o.sun, camera.position_m);
  if (!sun) return usageError(sun.error());
  settings->style.sunDirection = *sun;

  vk::Device device(deviceOptions(o.device));
  printDeviceChoice(device);
  if (auto s = checkImageExtent(device, {size->width, size->height}, "--size"); !s) return usageError(s.error());
  ImageRgba image;
  if (o.mode == "sphere") {
    image = renderSphere(device, camera, model, *size, *sun);
  } else {
    auto terrain = renderTerrain(device, camera, model, *settings, size->width, size->height);
    if (!terrain) return usageError(terrain.error());
    image = std::move(*terrain);
  }
  if (auto s = writeImage(o.out, image, "--out"); !s) {
    printError(s.error().format());
    return kExitFailure;
  }
  if (int code = validationExitCode(device); code != kExitOk) return code;
  std::printf("wrote %s (%ux%u, %s)\n", o.out.c_str(), size->width, size->height, device.name().c_str());
  return kExitOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, Runner& run) {
  auto opts = std::make_shared<RenderOptions>();
  opts->planet = defaultPlanetPath();
  CLI::App* cmd = app.add_subcommand("render", "Render one frame headless to a PNG or OpenEXR file");
  cmd->add_option("--planet", opts->planet, "Planet file (TOML)")->capture_default_str();
  cmd->add_option("--at", opts->at,
                  "Camera: LAT,LON,HEIGHT[,HEADING,PITCH,ROLL] in degrees and metres above the terrain (or the "
                  "reference surface, --height-ref); "
                  "heading clockwise from north, pitch 0 horizontal and -90 down; without the angles the "
                  "camera looks at the horizon")
      ->capture_default_str();
  addHeightReferenceOption(*cmd, opts->heightRef);
  cmd->add_option("--size", opts->size, "Image size WxH in pixels")->capture_default_str();
  cmd->add_option("--out", opts->out, "Output file: .png (8-bit sRGB) or .exr (half RGB + float Z, metres)")
      ->capture_default_str();
  cmd->add_option("--mode", opts->mode, "terrain (the planet) or sphere (its reference sphere, analytic)")
      ->check(CLI::IsMember({"terrain", "sphere"}))
      ->capture_default_str();
  addSunOption(*cmd, opts->sun);
  addQualityOptions(*cmd, opts->quality);
  addBudgetOptions(*cmd, opts->budget);
  addDeviceFlags(*cmd, opts->device);
  cmd->callback([opts, &run] { run = [opts] { return runRender(*opts); }; });
}

}  // namespace globe::cli
