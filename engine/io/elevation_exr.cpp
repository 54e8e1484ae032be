#include "engine/io/elevation_exr.h"

#include "engine/io/exr_stream.h"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <memory>
#include <span>

namespace globe {

namespace {

// Rows per block: about 1M samples (~0.2 s on one core), so progress moves and memory stays small.
std::uint32_t rowsPerBlock(std::uint32_t width, std::uint32_t height) {
  return std::clamp<std::uint32_t>((1U << 20) / width, 1U, height);
}

// A slice whose row `first_row` is at data[0]: OpenEXR addresses pixels from the origin.
Imf::Slice floatSlice(float* data, std::size_t width, std::size_t first_row) {
  char* base = reinterpret_cast<char*>(data) - first_row * width * sizeof(float);
  return Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * width);
}

}  // namespace

Status writeElevationExr(const ElevationModel& model, const ElevationExportOptions& options, AtomicFile& file,
                         const ProgressFn& progress) {
  const std::uint32_t width = options.width;
  const std::uint32_t height = width / 2;
  if (width < 2 || width > 65536 || width % 2 != 0) {
    return Error::inField("--width", "must be even and within [2, 65536] pixels");
  }
  try {
    Imf::Header header(static_cast<int>(width), static_cast<int>(height));
    header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
    header.insert("globe.planet", Imf::StringAttribute(options.planet_name));
    header.insert("globe.radius_m", Imf::DoubleAttribute(model.radius_m()));
    // Rows and columns are geodetic latitude/longitude; an ellipsoid says its flattening too.
    if (!model.shape().isSphere()) header.insert("globe.flattening", Imf::DoubleAttribute(model.shape().flattening()));
    header.insert("globe.sea_level_m", Imf::DoubleAttribute(model.seaLevel_m()));
    header.insert("globe.units", Imf::StringAttribute("metres"));
    if (auto made = makeParentDirectories(file.targetPath()); !made) return made.error();
    CheckedExrStream stream(file.tempPath(), file.targetPath());
    auto out = std::make_unique<Imf::OutputFile>(stream, header);
    if (options.keep != nullptr) options.keep->assign(static_cast<std::size_t>(width) * height, 0.0f);

    const std::uint32_t block = rowsPerBlock(width, height);
    std::vector<float> rows(static_cast<std::size_t>(block) * width);
    for (std::uint32_t y0 = 0; y0 < height; y0 += block) {
      const std::uint32_t n = std::min(block, height - y0);
      const std::span<float> out_rows(rows.data(), static_cast<std::size_t>(n) * width);
      const double done = static_cast<double>(y0) / height;
      const double share = static_cast<double>(n) / height;
      sampleEquirectRows(model, width, height, y0, out_rows, options.threads, [&](double f) {
        if (progress) progress(done + share * f);
      });
      Imf::FrameBuffer fb;
      fb.insert("Y", floatSlice(rows.data(), width, y0));
      out->setFrameBuffer(fb);
      out->writePixels(static_cast<int>(n));
      if (options.keep != nullptr) {
        std::copy(out_rows.begin(), out_rows.end(), options.keep->begin() + static_cast<std::ptrdiff_t>(y0) * width);
      }
    }
    out.reset();  // writes the line-offset table; its errors surface in finish()
    if (auto s = stream.finish(); !s) return s;
  } catch (const std::exception& e) {
    return Error::inFile(file.targetPath(), std::string("cannot write EXR: ") + e.what());
  }
  return Ok{};
}

Result<ElevationMap> readElevationExr(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    if (in.header().channels().findChannel("Y") == nullptr) {
      return Error::inFile(path, "no Y (elevation) channel");
    }
    ElevationMap map;
    map.width = static_cast<std::uint32_t>(dw.max.x - dw.min.x + 1);
    map.height = static_cast<std::uint32_t>(dw.max.y - dw.min.y + 1);
    map.elevation_m.resize(static_cast<std::size_t>(map.width) * map.height);
    if (const auto* a = in.header().findTypedAttribute<Imf::StringAttribute>("globe.planet")) map.planet = a->value();
    if (const auto* a = in.header().findTypedAttribute<Imf::DoubleAttribute>("globe.radius_m")) {
      map.radius_m = a->value();
    }
    Imf::FrameBuffer fb;
    char* base = reinterpret_cast<char*>(map.elevation_m.data()) -
                 (static_cast<std::ptrdiff_t>(dw.min.x) + static_cast<std::ptrdiff_t>(dw.min.y) * map.width) *
                     static_cast<std::ptrdiff_t>(sizeof(float));
    fb.insert("Y", Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * map.width));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return map;
  } catch (const std::exception& e) {
    return Error::inFile(path, std::string("cannot read EXR: ") + e.what());
  }
}

}  // namespace globe
