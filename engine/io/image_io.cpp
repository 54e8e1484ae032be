#include "engine/io/image_io.h"

#include "engine/io/exr_stream.h"
#include "planet/core/atomic_file.h"
#include "planet/core/srgb.h"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace globe {

uint8_t linearToSrgb8(float linear) { return static_cast<uint8_t>(std::lround(srgbEncode(linear) * 255.0)); }

namespace {
float srgb8ToLinear(uint8_t v) { return float(srgbDecode(double(v) / 255.0)); }

std::string extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}
}  // namespace

Result<std::string> encodePng(const ImageRgba& image) {
  std::vector<uint8_t> bytes(size_t(image.width) * image.height * 4);
  for (size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] = (i % 4 == 3) ? uint8_t(std::lround(std::clamp(image.rgba[i], 0.0f, 1.0f) * 255.0f))
                            : linearToSrgb8(image.rgba[i]);
  }
  // In memory: stbi_write_png ignores write errors, the checked atomic writer does not.
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 4, bytes.data(), int(image.width * 4)))
    return Error::inField("", "cannot encode PNG");
  return png;
}

Status writePng(const std::string& path, const ImageRgba& image) {
  if (auto s = checkWritable(path, ""); !s) return s;
  Result<std::string> png = encodePng(image);
  if (!png) return Error::inFile(path, png.error().message);
  return writeFileAtomically(path, *png, "");
}

Status writeExr(const std::string& path, const ImageRgba& image) {
  if (auto s = checkWritable(path, ""); !s) return s;
  AtomicFile file(path);
  try {
    size_t n = size_t(image.width) * image.height;
    std::vector<Imath::half> r(n), g(n), b(n);
    for (size_t i = 0; i < n; ++i) {
      r[i] = Imath::half(image.rgba[i * 4 + 0]);
      g[i] = Imath::half(image.rgba[i * 4 + 1]);
      b[i] = Imath::half(image.rgba[i * 4 + 2]);
    }
    Imf::Header header(int(image.width), int(image.height));
    header.channels().insert("R", Imf::Channel(Imf::HALF));
    header.channels().insert("G", Imf::Channel(Imf::HALF));
    header.channels().insert("B", Imf::Channel(Imf::HALF));
    bool hasZ = !image.z.empty();
    if (hasZ) header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    Imf::FrameBuffer fb;
    auto slice = [&](Imf::PixelType type, void* data, size_t stride) {
      return Imf::Slice(type, static_cast<char*>(data), stride, stride * image.width);
    };
    fb.insert("R", slice(Imf::HALF, r.data(), sizeof(Imath::half)));
    fb.insert("G", slice(Imf::HALF, g.data(), sizeof(Imath::half)));
    fb.insert("B", slice(Imf::HALF, b.data(), sizeof(Imath::half)));
    std::vector<float> z = image.z;
    if (hasZ) fb.insert("Z", slice(Imf::FLOAT, z.data(), sizeof(float)));
    if (auto made = makeParentDirectories(path); !made) return made.error();
    CheckedExrStream stream(file.tempPath(), path);
    {
      Imf::OutputFile out(stream, header);
      out.setFrameBuffer(fb);
      out.writePixels(int(image.height));
    }
    if (auto s = stream.finish(); !s) return s;
  } catch (const std::exception& e) {
    return Error::inFile(path, std::string("cannot write EXR: ") + e.what());
  }
  return file.commit();
}

Status writeImage(const std::string& path, const ImageRgba& image, const std::string& field) {
  std::string ext = extension(path);
  if (ext == ".png") return writePng(path, image);
  if (ext == ".exr") return writeExr(path, image);
  return Error::inField(field, "'" + path + "' must end in .png or .exr");
}

Result<ImageRgba> readImage8(const std::string& path) {
  int w = 0, h = 0, comp = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &comp, 4);
  if (!data) return Error::inFile(path, std::string("cannot read PNG: ") + stbi_failure_reason());
  ImageRgba image;
  image.width = uint32_t(w);
  image.height = uint32_t(h);
  image.rgba.resize(size_t(w) * size_t(h) * 4);
  for (size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = (i % 4 == 3) ? float(data[i]) / 255.0f : srgb8ToLinear(data[i]);
  stbi_image_free(data);
  return image;
}

Result<ImageRgba> readExr(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str());
    Imath::Box2i dw = in.header().dataWindow();
    int w = dw.max.x - dw.min.x + 1;
    int h = dw.max.y - dw.min.y + 1;
    ImageRgba image;
    image.width = uint32_t(w);
    image.height = uint32_t(h);
    size_t n = size_t(w) * size_t(h);
    std::vector<float> r(n), g(n), b(n);
    bool hasZ = in.header().channels().findChannel("Z") != nullptr;
    if (hasZ) image.z.resize(n);
    Imf::FrameBuffer fb;
    auto slice = [&](float* data) {
      char* base = reinterpret_cast<char*>(data) - (dw.min.x + size_t(dw.min.y) * size_t(w)) * sizeof(float);
      return Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * size_t(w));
    };
    fb.insert("R", slice(r.data()));
    fb.insert("G", slice(g.data()));
    fb.insert("B", slice(b.data()));
    if (hasZ) fb.insert("Z", slice(image.z.data()));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    image.rgba.resize(n * 4);
    for (size_t i = 0; i < n; ++i) {
      image.rgba[i * 4 + 0] = r[i];
      image.rgba[i * 4 + 1] = g[i];
      image.rgba[i * 4 + 2] = b[i];
      image.rgba[i * 4 + 3] = 1.0f;
    }
    return image;
  } catch (const std::exception& e) {
    return Error::inFile(path, std::string("cannot read EXR: ") + e.what());
  }
}

}  // namespace globe
