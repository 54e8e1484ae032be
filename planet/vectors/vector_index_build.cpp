// Building VectorIndex (vector_index.h): the exact and simplified geometries, then per level the
// cells' edge lists and the rows' crossings. Queries are in vector_index.cpp.
#include "planet/vectors/vector_index.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

namespace globe {
namespace {

constexpr std::size_t kExactLevels = 4;          // levels 0..3 keep the exact geometry (cells up to 8x the finest)
constexpr double kSimplifyFraction = 1.0 / 8.0;  // of a level's cell
constexpr int kMinCellExponent = 1;              // finest cell = 180 / 2^m degrees, m in [1, 28]
constexpr int kMaxCellExponent = 28;             // 180 / 2^28 degrees: 7 cm
// Cell entries and inside-list entries of one layer, all levels together (8 and 4 bytes each).
constexpr std::size_t kMaxIndexEntries = std::size_t{96} << 20;
// What one query may have to read: entries of one finest cell, polygons overlapping at one place.
constexpr std::size_t kMaxCellEntries = 8192;
constexpr std::size_t kMaxOverlap = 1024;
constexpr int kMaxRefinements = 6;  // halvings of the finest cell to meet kMaxCellEntries
constexpr const char* kTooDense = "has too many vertices in too small an area to be indexed";

using KeyedEntry = std::pair<std::uint64_t, CellEntry>;

struct Crossing {
  std::int64_t row = 0;
  double lon_deg = 0.0;
  std::uint32_t feature = 0;
};

bool isEdgePart(const VectorPart& p) { return p.kind != VectorPartKind::kPoint && p.count >= 2; }

IndexGeometry exactGeometry(const VectorFeatures& f) {
  IndexGeometry g;
  g.vertices.reserve(f.lat_deg.size() + f.parts.size());
  for (VectorPart part : f.parts) {
    const std::uint32_t first = part.first;
    part.first = static_cast<std::uint32_t>(g.vertices.size());
    for (std::uint32_t i = first; i < first + part.count; ++i) {
      g.vertices.push_back({f.lat_deg[i], f.lon_deg[i]});
    }
    if (part.kind == VectorPartKind::kRing) {  // closed by repeating the first vertex
      g.vertices.push_back({f.lat_deg[first], f.lon_deg[first]});
      ++part.count;
    }
    g.parts.push_back(part);
  }
  return g;
}

// Radial-distance simplification of one line or ring: a vertex is kept when it lies `t` degrees or
// more from the last one kept, so the result stays within `t` of the original. Rings left with
// fewer than 3 vertices vanish (they are smaller than the tolerance).
void simplifyPart(const IndexGeometry& from, const VectorPart& part, double t, IndexGeometry& to) {
  const bool ring = part.kind == VectorPartKind::kRing;
  const std::uint32_t end = part.first + part.count - (ring ? 1 : 0);
  VectorPart out = part;
  out.first = static_cast<std::uint32_t>(to.vertices.size());
  std::uint32_t last = part.first;
  to.vertices.push_back(from.vertices[last]);
  for (std::uint32_t i = part.first + 1; i < end; ++i) {
    const bool lastVertex = !ring && i + 1 == end;
    if (!lastVertex && std::hypot(from.vertices[i].lat_deg - from.vertices[last].lat_deg,
                                  from.vertices[i].lon_deg - from.vertices[last].lon_deg) < t)
      continue;
    to.vertices.push_back(from.vertices[i]);
    last = i;
  }
  out.count = static_cast<std::uint32_t>(to.vertices.size()) - out.first;
  if (ring && out.count < 3) {
    to.vertices.resize(out.first);
    return;
  }
  if (ring) {
    to.vertices.push_back(from.vertices[part.first]);
    ++out.count;
  }
  to.parts.push_back(out);
}

// Points of one colour closer than `t` are drawn as one at coarse levels.
std::vector<bool> distinctPoints(const IndexGeometry& g, double t, const std::vector<VectorFeature>& features) {
  std::vector<std::tuple<std::int64_t, std::int64_t, std::int32_t, std::size_t>> keys;
  for (std::size_t i = 0; i < g.parts.size(); ++i) {
    const VectorPart& p = g.parts[i];
    if (p.kind != VectorPartKind::kPoint) continue;
    keys.emplace_back(std::int64_t(std::floor(g.vertices[p.first].lat_deg / t)),
                      std::int64_t(std::floor(g.vertices[p.first].lon_deg / t)), features[p.feature].colour, i);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<bool> keep(g.parts.size(), true);
  for (std::size_t k = 1; k < keys.size(); ++k) {
    const auto& [a0, a1, a2, ai] = keys[k - 1];
    const auto& [b0, b1, b2, bi] = keys[k];
    if (a0 == b0 && a1 == b1 && a2 == b2) keep[bi] = false;
  }
  return keep;
}

IndexGeometry simplifiedGeometry(const IndexGeometry& exact, double t, const std::vector<VectorFeature>& features) {
  IndexGeometry g;
  const std::vector<bool> keep = distinctPoints(exact, t, features);
  for (std::size_t i = 0; i < exact.parts.size(); ++i) {
    const VectorPart& p = exact.parts[i];
    if (p.kind == VectorPartKind::kPoint || p.count < 2) {
      if (!keep[i]) continue;
      VectorPart out = p;
      out.first = static_cast<std::uint32_t>(g.vertices.size());
      for (std::uint32_t v = p.first; v < p.first + p.count; ++v) {
        g.vertices.push_back(exact.vertices[v]);
      }
      g.parts.push_back(out);
    } else {
      simplifyPart(exact, p, t, g);
    }
  }
  return g;
}

// m such that the finest cell, 180 / 2^m degrees, is about twice the median edge (at least half
// the mean, which bounds the cell entries to a few per edge); for points alone, about one per cell.
int finestCellExponent(const IndexGeometry& g) {
  std::vector<double> lengths;
  double sum = 0.0, latMin = 90.0, latMax = -90.0, lonMin = 540.0, lonMax = -540.0;
  std::size_t points = 0;
  for (const VectorPart& p : g.parts) {
    for (std::uint32_t i = p.first; i < p.first + p.count; ++i) {
      latMin = std::min(latMin, g.vertices[i].lat_deg), latMax = std::max(latMax, g.vertices[i].lat_deg);
      lonMin = std::min(lonMin, g.vertices[i].lon_deg), lonMax = std::max(lonMax, g.vertices[i].lon_deg);
      if (!isEdgePart(p) || i + 1 == p.first + p.count) continue;
      const double length = std::max(std::abs(g.vertices[i + 1].lat_deg - g.vertices[i].lat_deg),
                                     std::abs(g.vertices[i + 1].lon_deg - g.vertices[i].lon_deg));
      if (length > 0.0) lengths.push_back(length), sum += length;
    }
    points += isEdgePart(p) ? 0 : 1;
  }
  double cell = 90.0;
  if (!lengths.empty()) {
    auto middle = lengths.begin() + std::ptrdiff_t(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    cell = std::max(2.0 * *middle, 0.5 * sum / double(lengths.size()));
  } else if (points > 0) {
    cell = std::sqrt(std::max(latMax - latMin, 1e-6) * std::max(lonMax - lonMin, 1e-6) / double(points));
  }
  const int m = static_cast<int>(std::floor(std::log2(180.0 / std::max(cell, 1e-9))));
  return std::clamp(m, kMinCellExponent, kMaxCellExponent);
}

std::int64_t rowOf(const IndexLevel& level, double lat_deg) {
  return std::clamp(static_cast<std::int64_t>(std::floor((lat_deg + 90.0) / level.cell_deg)), std::int64_t{0},
                    level.rows - 1);
}

std::int64_t wrapColumn(const IndexLevel& level, std::int64_t col) {
  return ((col % level.cols) + level.cols) % level.cols;
}

// The cells an edge a-b crosses, row by row: the edge clipped to the row's band gives its columns,
// widened a little so that rounding never leaves out a cell it touches.
void addEdgeCells(const IndexLevel& level, const IndexGeometry& g, std::uint32_t a, std::uint32_t b, CellEntry entry,
                  std::vector<KeyedEntry>& out) {
  const double d = level.cell_deg, eps = d * 1e-6;
  const double alat = g.vertices[a].lat_deg, alon = g.vertices[a].lon_deg, blat = g.vertices[b].lat_deg,
               blon = g.vertices[b].lon_deg;
  const std::int64_t r0 = rowOf(level, std::min(alat, blat) - eps), r1 = rowOf(level, std::max(alat, blat) + eps);
  for (std::int64_t r = r0; r <= r1; ++r) {
    double xlo = std::min(alon, blon), xhi = std::max(alon, blon);
    if (alat != blat) {
      const double bandLo = -90.0 + double(r) * d - eps, bandHi = bandLo + d + 2.0 * eps;
      const double t0 = std::clamp((bandLo - alat) / (blat - alat), 0.0, 1.0);
      const double t1 = std::clamp((bandHi - alat) / (blat - alat), 0.0, 1.0);
      const double x0 = alon + t0 * (blon - alon), x1 = alon + t1 * (blon - alon);
      xlo = std::min(x0, x1), xhi = std::max(x0, x1);
    }
    const auto c0 = static_cast<std::int64_t>(std::floor((xlo - eps + 180.0) / d));
    const auto c1 = static_cast<std::int64_t>(std::floor((xhi + eps + 180.0) / d));
    const std::int64_t count = std::min(c1 - c0 + 1, level.cols);
    for (std::int64_t c = c0; c < c0 + count; ++c)
      out.push_back({std::uint64_t(r * level.cols + wrapColumn(level, c)), entry});
  }
}

std::vector<std::uint64_t> buildCells(IndexLevel& level, const IndexGeometry& g) {
  std::vector<KeyedEntry> keyed;
  for (const VectorPart& p : g.parts) {
    const std::uint32_t edges = isEdgePart(p) ? p.count - 1 : 1;
    for (std::uint32_t i = p.first; i < p.first + edges; ++i) {
      const std::uint32_t hasNext = isEdgePart(p) ? 1 : 0;
      const CellEntry entry{i, p.feature << 3 | std::uint32_t(p.kind) << 1 | hasNext};
      addEdgeCells(level, g, i, i + hasNext, entry, keyed);
    }
  }
  // Within a cell, entries stay in vertex order, which is feature order (in place: no second copy).
  std::sort(keyed.begin(), keyed.end(), [](const KeyedEntry& x, const KeyedEntry& y) {
    return x.first != y.first ? x.first < y.first : x.second.vertex < y.second.vertex;
  });
  std::vector<std::uint64_t> keys;
  level.entries.reserve(keyed.size());
  for (const KeyedEntry& k : keyed) {
    if (keys.empty() || keys.back() != k.first) {
      keys.push_back(k.first);
      level.cell_start.push_back(static_cast<std::uint32_t>(level.entries.size()));
    }
    level.entries.push_back(k.second);
  }
  level.cell_start.push_back(static_cast<std::uint32_t>(level.entries.size()));
  level.cells.build(keys);
  return keys;
}

// Where each row's centre line crosses ring edges (half-open in latitude, so every closed ring is
// crossed an even number of times).
std::vector<Crossing> rowCrossings(const IndexLevel& level, const IndexGeometry& g) {
  std::vector<Crossing> crossings;
  const double d = level.cell_deg;
  for (const VectorPart& p : g.parts) {
    if (p.kind != VectorPartKind::kRing) continue;
    for (std::uint32_t i = p.first; i + 1 < p.first + p.count; ++i) {
      const double alat = g.vertices[i].lat_deg, blat = g.vertices[i + 1].lat_deg, alon = g.vertices[i].lon_deg,
                   blon = g.vertices[i + 1].lon_deg;
      const double lo = std::min(alat, blat), hi = std::max(alat, blat);
      if (lo == hi) continue;
      for (std::int64_t r = std::max<std::int64_t>(0, std::int64_t(std::floor((lo + 90.0) / d - 0.5))); r < level.rows;
           ++r) {
        const double centre = -90.0 + (double(r) + 0.5) * d;
        if (centre >= hi) break;
        if (centre < lo) continue;
        crossings.push_back({r, alon + (centre - alat) * (blon - alon) / (blat - alat), p.feature});
      }
    }
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
    return x.row != y.row ? x.row < y.row : x.lon_deg < y.lon_deg;
  });
  return crossings;
}

// Sweeps each row's crossings west to east, toggling the features inside.
Status buildRows(IndexLevel& level, const IndexGeometry& g, std::size_t& budget) {
  const std::vector<Crossing> crossings = rowCrossings(level, g);
  std::vector<std::uint64_t> rowKeys;
  std::vector<std::uint32_t> inside;
  for (const Crossing& c : crossings) {
    if (rowKeys.empty() || rowKeys.back() != std::uint64_t(c.row)) {
      rowKeys.push_back(std::uint64_t(c.row));
      level.row_start.push_back(static_cast<std::uint32_t>(level.crossing_lon_deg.size()));
      inside.clear();
    }
    auto it = std::find(inside.begin(), inside.end(), c.feature);
    if (it != inside.end()) {
      *it = inside.back();
      inside.pop_back();
    } else {
      inside.push_back(c.feature);
    }
    level.crossing_lon_deg.push_back(c.lon_deg);
    level.span_start.push_back(static_cast<std::uint32_t>(level.span_features.size()));
    if (inside.size() > kMaxOverlap || inside.size() > budget - std::min(budget, level.span_features.size()))
      return Error::inField("", fmt::format("more than {} of its polygons overlap at one place", kMaxOverlap));
    level.span_features.insert(level.span_features.end(), inside.begin(), inside.end());
  }
  level.row_start.push_back(static_cast<std::uint32_t>(level.crossing_lon_deg.size()));
  level.span_start.push_back(static_cast<std::uint32_t>(level.span_features.size()));
  level.rows_table.build(rowKeys);
  budget -= std::min(budget, level.span_features.size());
  return Ok{};
}

// Cells of a coarse level holding exact geometry: the parents of the finest level's cells.
void buildOccupancy(IndexLevel& level, const IndexLevel& finest, const std::vector<std::uint64_t>& finestKeys,
                    int shift) {
  std::vector<std::uint64_t> keys;
  keys.reserve(finestKeys.size());
  for (std::uint64_t k : finestKeys) {
    const auto row = std::int64_t(k / std::uint64_t(finest.cols)) >> shift;
    const auto col = std::int64_t(k % std::uint64_t(finest.cols)) >> shift;
    keys.push_back(std::uint64_t(row * level.cols + col));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  level.occupied.build(keys);
}

IndexLevel emptyLevel(int m, int k) {
  IndexLevel level;
  level.cell_deg = 180.0 / std::ldexp(1.0, m - k);
  level.rows = std::int64_t{1} << (m - k);
  level.cols = 2 * level.rows;
  return level;
}

// At least as many entries as buildCells makes (rows plus columns each edge spans), counted first so
// that a hostile layer fails before it takes the memory.
std::size_t entryBound(const IndexLevel& level, const IndexGeometry& g) {
  double bound = 0.0;
  for (const VectorPart& p : g.parts) {
    const std::uint32_t edges = isEdgePart(p) ? p.count - 1 : 1;
    for (std::uint32_t i = p.first; i < p.first + edges; ++i) {
      const IndexVertex a = g.vertices[i], b = g.vertices[i + (isEdgePart(p) ? 1 : 0)];
      bound += 3.0 + (std::abs(a.lat_deg - b.lat_deg) + std::abs(a.lon_deg - b.lon_deg)) / level.cell_deg;
    }
  }
  return bound >= double(kMaxIndexEntries) ? kMaxIndexEntries + 1 : std::size_t(bound);
}

// The finest level, its cells refined (up to kMaxRefinements times) while one holds more than
// kMaxCellEntries: a query reads every entry of its cells.
Result<IndexLevel> finestLevel(const IndexGeometry& g, std::size_t& budget, std::vector<std::uint64_t>& keys, int& m) {
  m = finestCellExponent(g);
  for (int attempt = 0;; ++attempt, ++m) {
    IndexLevel level = emptyLevel(m, 0);
    if (entryBound(level, g) > budget) return Error::inField("", kTooDense);
    keys = buildCells(level, g);
    std::size_t densest = 0;
    for (std::size_t i = 0; i + 1 < level.cell_start.size(); ++i)
      densest = std::max<std::size_t>(densest, level.cell_start[i + 1] - level.cell_start[i]);
    if (densest <= kMaxCellEntries) {
      budget -= std::min(budget, level.entries.size());
      return level;
    }
    if (attempt == kMaxRefinements || m == kMaxCellExponent)
      return Error::inField("", fmt::format("has {} edges or points within {:.2g} degrees of each other (repeated or "
                                            "overlapping features?); the limit is {}",
                                            densest, level.cell_deg, kMaxCellEntries));
  }
}

}  // namespace

void KeyTable::build(std::span<const std::uint64_t> keys) {
  int bits = 4;
  while ((std::size_t{1} << bits) < 2 * keys.size()) ++bits;
  keys_.assign(std::size_t{1} << bits, kEmpty);
  values_.assign(keys_.size(), kNone);
  mask_ = keys_.size() - 1;
  shift_ = 64 - bits;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    std::uint64_t h = hash(keys[i]);
    while (keys_[h] != kEmpty) h = (h + 1) & mask_;
    keys_[h] = keys[i];
    values_[h] = static_cast<std::uint32_t>(i);
  }
}

Result<VectorIndex> VectorIndex::build(const VectorFeatures& features) {
  if (features.features.size() >= (std::size_t{1} << 29))  // CellEntry::tag keeps the feature in 29 bits
    return Error::inField("", "has too many features to be indexed");
  VectorIndex index;
  index.feature_count_ = features.features.size();
  index.geometries_.push_back(exactGeometry(features));
  std::size_t budget = kMaxIndexEntries;
  std::vector<std::uint64_t> finestKeys;
  int m = 0;
  Result<IndexLevel> finest = finestLevel(index.geometries_[0], budget, finestKeys, m);
  if (!finest) return finest.error();
  for (int k = 0; k < m; ++k) {
    IndexLevel level = k == 0 ? std::move(*finest) : emptyLevel(m, k);
    if (std::size_t(k) >= kExactLevels) {
      level.tolerance_deg = level.cell_deg * kSimplifyFraction;
      index.geometries_.push_back(simplifiedGeometry(index.geometries_[0], level.tolerance_deg, features.features));
      level.geometry = index.geometries_.size() - 1;
    }
    const IndexGeometry& g = index.geometries_[level.geometry];
    if (k > 0) {
      if (entryBound(level, g) > budget) return Error::inField("", kTooDense);
      buildCells(level, g);
      budget -= std::min(budget, level.entries.size());
    }
    if (Status s = buildRows(level, g, budget); !s) return s.error();
    if (std::size_t(k) >= kExactLevels) buildOccupancy(level, index.levels_[0], finestKeys, k);
    index.levels_.push_back(std::move(level));
  }
  return index;
}

}  // namespace globe
