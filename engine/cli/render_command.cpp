// globe render: one headless frame written as PNG or EXR.
#include "commands.h"
#include "engine/device.h"
#include "engine/offscreen_target.h"
#include "engine/render_output.h"
#include "engine/sphere_preview.h"
#include "options.h"
#include "planet/atomic_file.h"
#include "planet/camera.h"

#include <cstdio>

namespace globe::cli {

namespace {

struct RenderOptions {
  DeviceFlags device;
  std::string at = "20,10,2000000";
  std::string size = "1280x720";
  std::string out = "out/render.png";
  double radius_m = 6371000.0;
};

int runRender(const RenderOptions& o) {
  auto pose = parsePose(o.at, "--at");
  if (!pose) return usageError(pose.error());
  auto size = parseSize(o.size, "--size");
  if (!size) return usageError(size.error());
  if (auto s = checkWritable(o.out, "--out"); !s) return usageError(s.error());
  if (auto s = checkImageExtension(o.out, "--out"); !s) return usageError(s.error());

  vk::Device device(deviceOptions(o.device));
  vk::OffscreenTarget target(device, {size->width, size->height});
  SpherePreview preview(device);
  double aspect = double(size->width) / double(size->height);
  Camera camera = cameraFromPose(*pose, o.radius_m, o.radius_m, aspect);
  const glm::dvec3 sun = glm::normalize(glm::dvec3(1.0, 0.6, 0.4));
  const float clear[4] = {0, 0, 0, 1};
  device.submitAndWait([&](VkCommandBuffer cmd) {
    target.begin(cmd, clear);
    preview.record(cmd, camera, o.radius_m, sun);
    target.end(cmd);
  });
  ImageRgba image = toImage(target.readback(), camera);
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
  CLI::App* cmd = app.add_subcommand("render", "Render one frame headless to a PNG or OpenEXR file");
  cmd->add_option("--at", opts->at,
                  "Camera: LAT,LON,HEIGHT[,HEADING,PITCH,ROLL] in degrees and metres above the surface; "
                  "heading clockwise from north, pitch 0 horizontal and -90 down; without the angles the "
                  "camera looks at the horizon")
      ->capture_default_str();
  cmd->add_option("--size", opts->size, "Image size WxH in pixels")->capture_default_str();
  cmd->add_option("--out", opts->out, "Output file: .png (8-bit sRGB) or .exr (half RGB + float Z, metres)")
      ->capture_default_str();
  addDeviceFlags(*cmd, opts->device);
  cmd->callback([opts, &run] { run = [opts] { return runRender(*opts); }; });
}

}  // namespace globe::cli
