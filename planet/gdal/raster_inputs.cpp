#include "planet/gdal/raster_inputs.h"

#include "planet/core/input_file.h"
#include "planet/gdal/gdal_raster.h"

#include <cpl_vsi.h>
#include <fmt/format.h>
#include <pugixml.hpp>

#include <filesystem>
#include <string_view>

namespace globe {
namespace {

// Archive readers: the part of the path naming the archive ("/vsizip/{a.zip}/x" or "/vsizip/a.zip/x").
constexpr std::string_view kArchivePrefixes[] = {"/vsizip/", "/vsigzip/", "/vsitar/"};

std::string archiveOf(std::string_view inner) {
  if (!inner.empty() && inner[0] == '{') {
    auto close = inner.find('}');
    return std::string(inner.substr(1, close == std::string_view::npos ? std::string_view::npos : close - 1));
  }
  for (std::string_view ext : {".zip", ".gz", ".tar", ".tgz"}) {
    auto at = inner.find(ext);
    if (at != std::string_view::npos) return std::string(inner.substr(0, at + ext.size()));
  }
  return std::string(inner);
}

// A GDAL virtual path: the archive must be a regular file and its member bounded in size.
Status checkVirtualPath(const std::string& path, const std::string& source) {
  for (std::string_view prefix : kArchivePrefixes) {
    if (path.rfind(prefix, 0) != 0) continue;
    if (Status s = checkInputFileKind(archiveOf(std::string_view(path).substr(prefix.size())), "archive"); !s)
      return Error::inFile(source, s.error().file + ": " + s.error().message);
    VSIStatBufL info{};
    if (VSIStatL(path.c_str(), &info) == 0 && static_cast<std::uint64_t>(info.st_size) > kMaxArchiveMemberBytes)
      return Error::inFile(source, fmt::format("'{}' uncompresses to {} bytes, beyond the limit of {} GiB", path,
                                               info.st_size, kMaxArchiveMemberBytes >> 30));
    return Ok{};
  }
  return Error::inFile(source, fmt::format("'{}': only local files and archives (/vsizip/, /vsigzip/, /vsitar/) "
                                           "are read",
                                           path));
}

bool isVrt(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".vrt" || ext == ".VRT";
}

// `path` and, for a VRT, every SourceFilename in it, down to kMaxVrtDepth VRTs deep.
Status checkFile(const std::string& path, const std::string& source, int depth) {
  if (path.rfind("/vsi", 0) == 0) return checkVirtualPath(path, source);
  const bool top = depth == 0;
  if (Status s = checkInputFileKind(path, top ? "raster" : "raster source", /*directoryToo=*/top); !s)
    return top ? s : Error::inFile(source, fmt::format("its source '{}': {}", path, s.error().message));
  if (!isVrt(path)) return Ok{};
  if (depth >= kMaxVrtDepth)
    return Error::inFile(source, fmt::format("VRTs nested more than {} deep (at '{}')", kMaxVrtDepth, path));
  auto text = readInputFile(path, "VRT");
  if (!text) return Error::inFile(source, text.error().format());
  pugi::xml_document doc;
  if (!doc.load_buffer(text->data(), text->size())) return Ok{};  // GDAL reports the XML error itself
  // Every SourceFilename, found without recursion (find_node-style walk over the whole tree).
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  for (pugi::xml_node n = doc.first_child(); n;) {
    if (n.type() == pugi::node_element && std::string_view(n.name()) == "SourceFilename") {
      std::string name = n.child_value();
      if (n.attribute("relativeToVRT").as_int() == 1 && name.rfind("/vsi", 0) != 0) name = (dir / name).string();
      if (Status s = checkFile(name, source, depth + 1); !s) return s;
    }
    if (n.first_child()) {
      n = n.first_child();
      continue;
    }
    while (n && !n.next_sibling()) n = n.parent();
    if (n) n = n.next_sibling();
  }
  return Ok{};
}

}  // namespace

Status checkRasterInputs(const std::string& path) { return checkFile(path, path, 0); }

}  // namespace globe
