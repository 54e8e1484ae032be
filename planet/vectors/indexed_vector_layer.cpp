#include "planet/vectors/indexed_vector_layer.h"

#include "planet/vectors/vector_features.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <optional>

namespace globe {

namespace {

// The files as last seen: the layer's and those beside it with the same stem (a Shapefile's .prj,
// .dbf and .shx), each by name, size and modification time. A path GDAL reads but the file system
// does not know as a file (/vsizip/..., a URL, a folder) has no stamp and is read every time.
struct FileStamp {
  struct File {
    std::string name;
    std::uintmax_t size = 0;
    std::filesystem::file_time_type modified;
    bool operator==(const File&) const = default;
  };
  std::vector<File> files;  // in directory order, which is stable while nothing changes
  bool operator==(const FileStamp&) const = default;
};

std::optional<FileStamp> stampOf(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path file(path);
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  FileStamp s;
  fs::path folder = file.parent_path();
  if (folder.empty()) folder = ".";
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    if (e.path().stem() != file.stem() || !e.is_regular_file(ec)) continue;
    FileStamp::File f{e.path().filename().string(), e.file_size(ec), e.last_write_time(ec)};
    if (ec) return std::nullopt;
    s.files.push_back(std::move(f));
  }
  if (ec || s.files.empty()) return std::nullopt;
  return s;
}

struct CachedLayer {
  FileStamp stamp;
  std::shared_ptr<const IndexedVectorLayer> layer;
};

// The layers kept after their use, oldest first.
class RecentLayers {
 public:
  std::shared_ptr<const IndexedVectorLayer> find(const VectorLayer& style, const FileStamp& stamp) {
    const std::lock_guard lock(mutex_);
    for (const CachedLayer& c : layers_)
      if (c.stamp == stamp && c.layer->style == style) return c.layer;
    return nullptr;
  }

  void keep(const FileStamp& stamp, std::shared_ptr<const IndexedVectorLayer> layer) {
    const std::lock_guard lock(mutex_);
    std::erase_if(layers_, [&](const CachedLayer& c) { return c.layer->style == layer->style; });
    layers_.push_back({stamp, std::move(layer)});
    const auto vertices = [&] {
      std::size_t n = 0;
      for (const CachedLayer& c : layers_) n += c.layer->facts.vertices;
      return n;
    };
    while (layers_.size() > 1 && (layers_.size() > kMaxVectorLayers || vertices() > VectorLimits{}.max_vertices))
      layers_.erase(layers_.begin());
  }

 private:
  std::mutex mutex_;
  std::vector<CachedLayer> layers_;
};

RecentLayers& recentLayers() {
  static RecentLayers recent;
  return recent;
}

VectorLayerFacts factsOf(const VectorFeatures& read) {
  VectorLayerFacts f;
  f.layer_name = read.layer_name;
  f.features = read.features.size();
  for (const VectorPart& part : read.parts) {
    f.rings += part.kind == VectorPartKind::kRing;
    f.lines += part.kind == VectorPartKind::kLine;
    f.points += part.kind == VectorPartKind::kPoint;
  }
  f.vertices = read.lat_deg.size();
  if (f.vertices == 0) return f;
  const auto [latMin, latMax] = std::minmax_element(read.lat_deg.begin(), read.lat_deg.end());
  f.lat_min_deg = *latMin;
  f.lat_max_deg = *latMax;
  const auto [lonMin, lonMax] = std::minmax_element(read.lon_deg.begin(), read.lon_deg.end());
  f.lon_min_deg = *lonMin;
  f.lon_max_deg = *lonMax;
  return f;
}

Result<std::shared_ptr<const IndexedVectorLayer>> readAndIndex(const VectorLayer& style) {
  Result<VectorFeatures> features = readVectorFeatures(style);
  if (!features) return features.error();
  Result<VectorIndex> index = VectorIndex::build(*features);
  if (!index)
    return Error::inFileField(style.path, "path",
                              fmt::format("layer '{}': {}", features->layer_name, index.error().message));
  auto layer = std::make_shared<IndexedVectorLayer>();
  layer->style = style;
  layer->index = std::move(*index);
  for (const VectorFeature& f : features->features) layer->colour.push_back(f.colour);
  for (const auto& [value, colour] : style.colours) layer->table.push_back(colour);
  layer->facts = factsOf(*features);
  layer->has_rings = layer->facts.rings > 0;
  layer->has_lines = layer->facts.lines > 0;
  layer->has_points = layer->facts.points > 0;
  return std::shared_ptr<const IndexedVectorLayer>(std::move(layer));
}

}  // namespace

Result<std::shared_ptr<const IndexedVectorLayer>> openIndexedVectorLayer(const VectorLayer& style) {
  const std::optional<FileStamp> stamp = stampOf(style.path);
  if (stamp)
    if (std::shared_ptr<const IndexedVectorLayer> kept = recentLayers().find(style, *stamp)) return kept;
  Result<std::shared_ptr<const IndexedVectorLayer>> opened = readAndIndex(style);
  // Stamped before the read: a file changed meanwhile is read again next time.
  if (opened && stamp) recentLayers().keep(*stamp, *opened);
  return opened;
}

}  // namespace globe
