// VectorIndex's queries (vector_index.h); building it is vector_index_build.cpp's job.
#include "planet/vectors/vector_index.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace globe {
namespace {

constexpr std::int64_t kMaxWindowRows = 16;   // a query's cells, before it moves to a coarser level
constexpr std::int64_t kMaxWindowCols = 256;  // (more columns near the poles, where they are narrow)
constexpr double kMinCosLatitude = 1e-9;
constexpr std::size_t kMayTouchEntries = 4096;  // entries compared with a box before answering "maybe"

double cosLatitude(double lat_deg) { return std::max(std::cos(lat_deg * std::numbers::pi / 180.0), kMinCosLatitude); }

// Squared distance from the origin to the segment a-b (local metres).
double segmentDistance2(double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, length2 = dx * dx + dy * dy;
  const double t = length2 > 0.0 ? std::clamp(-(ax * dx + ay * dy) / length2, 0.0, 1.0) : 0.0;
  const double px = ax + t * dx, py = ay + t * dy;
  return px * px + py * py;
}

std::int64_t floorToInt(double v) { return static_cast<std::int64_t>(std::floor(v)); }

std::uint64_t cellKey(const IndexLevel& level, std::int64_t row, std::int64_t col) {
  return std::uint64_t(row * level.cols + ((col % level.cols) + level.cols) % level.cols);
}

}  // namespace

std::uint32_t KeyTable::find(std::uint64_t key) const {
  if (keys_.empty()) return kNone;
  for (std::uint64_t h = hash(key);; h = (h + 1) & mask_) {
    if (keys_[h] == key) return values_[h];
    if (keys_[h] == kEmpty) return kNone;
  }
}

FeatureProximity& VectorIndex::slot(std::uint32_t feature, ProximityScratch& s) const {
  if (s.stamp[feature] != s.generation) {
    s.stamp[feature] = s.generation;
    s.slot[feature] = static_cast<std::uint32_t>(s.found.size());
    s.found.push_back({});
    s.found.back().feature = feature;
  }
  return s.found[s.slot[feature]];
}

// The finest level whose cells hold the search radius, unless a coarser one is within the accuracy
// asked for; coarser still when the window would take too many cells (wide lines, the poles).
std::size_t VectorIndex::chooseLevel(double lat_deg, double accuracy_deg, double radius_deg) const {
  const std::size_t top = levels_.size() - 1;
  std::size_t fit = 0, accurate = 0;
  while (fit < top && levels_[fit].cell_deg < radius_deg) ++fit;
  while (accurate < top && levels_[accurate + 1].tolerance_deg <= accuracy_deg) ++accurate;
  std::size_t k = std::min(fit, accurate);
  const double cosLat = cosLatitude(lat_deg);
  for (; k < top; ++k) {
    const double d = levels_[k].cell_deg;
    if (2.0 * radius_deg / d + 2.0 <= double(kMaxWindowRows) &&
        2.0 * radius_deg / (d * cosLat) + 2.0 <= double(kMaxWindowCols))
      break;
  }
  return k;
}

VectorIndex::Window VectorIndex::window(const IndexLevel& level, double lat_deg, double lon_deg,
                                        double radius_deg) const {
  const double d = level.cell_deg;
  Window w;
  w.row0 = std::clamp(floorToInt((lat_deg - radius_deg + 90.0) / d), std::int64_t{0}, level.rows - 1);
  w.row1 = std::clamp(floorToInt((lat_deg + radius_deg + 90.0) / d), std::int64_t{0}, level.rows - 1);
  const double radiusLon_deg = std::min(radius_deg / cosLatitude(lat_deg), 360.0);
  w.col0 = floorToInt((lon_deg - radiusLon_deg + 180.0) / d);
  w.colCount = std::min(floorToInt((lon_deg + radiusLon_deg + 180.0) / d) - w.col0 + 1, level.cols);
  return w;
}

// Distances from the point to the entries of one cell that lie within `radius_m`; `x`/`y`: the
// local metres per degree of longitude and latitude at the point.
void VectorIndex::measureCell(const IndexLevel& level, std::uint32_t cell, double lat_deg, double lon_deg,
                              double radius_m, double xScale, double yScale, ProximityScratch& s) const {
  const IndexGeometry& g = geometries_[level.geometry];
  for (std::uint32_t e = level.cell_start[cell]; e < level.cell_start[cell + 1]; ++e) {
    const CellEntry entry = level.entries[e];
    const IndexVertex va = g.vertices[entry.vertex], vb = g.vertices[entry.vertex + (entry.tag & 1U)];
    const double ay = (va.lat_deg - lat_deg) * yScale, by = (vb.lat_deg - lat_deg) * yScale;
    if ((ay > radius_m && by > radius_m) || (ay < -radius_m && by < -radius_m)) continue;
    // The copy of the query longitude (+-360) nearest the edge.
    double x = lon_deg;
    const double mid = 0.5 * (va.lon_deg + vb.lon_deg);
    if (std::abs(mid - lon_deg) > 180.0) x += 360.0 * std::round((mid - lon_deg) / 360.0);
    const double ax = (va.lon_deg - x) * xScale, bx = (vb.lon_deg - x) * xScale;
    if ((ax > radius_m && bx > radius_m) || (ax < -radius_m && bx < -radius_m)) continue;
    const double distance2 = segmentDistance2(ax, ay, bx, by);
    if (distance2 > radius_m * radius_m) continue;
    const double distance = std::sqrt(distance2);
    FeatureProximity& f = slot(entry.tag >> 3, s);
    const auto kind = static_cast<VectorPartKind>((entry.tag >> 1) & 3U);
    double& nearest = kind == VectorPartKind::kRing ? f.ring_m : kind == VectorPartKind::kLine ? f.line_m : f.point_m;
    nearest = std::min(nearest, distance);
  }
}

// Distances from the point to every edge and point listed in the window's cells, skipping the
// cells wholly farther than the radius.
void VectorIndex::measure(const IndexLevel& level, const Window& w, double metres_per_degree, double lat_deg,
                          double lon_deg, double radius_m, ProximityScratch& s) const {
  const double yScale = metres_per_degree, xScale = metres_per_degree * cosLatitude(lat_deg);
  const double d = level.cell_deg;
  for (std::int64_t row = w.row0; row <= w.row1; ++row) {
    const double rowCentre = -90.0 + (double(row) + 0.5) * d;
    const double dy = std::max(std::abs(lat_deg - rowCentre) - 0.5 * d, 0.0) * yScale;
    for (std::int64_t col = w.col0; col < w.col0 + w.colCount; ++col) {
      const double colCentre = -180.0 + (double(col) + 0.5) * d;
      const double dx = std::max(std::abs(lon_deg - colCentre) - 0.5 * d, 0.0) * xScale;
      if (dx * dx + dy * dy > radius_m * radius_m && w.colCount < level.cols) continue;
      const std::uint32_t cell = level.cells.find(cellKey(level, row, col));
      if (cell != KeyTable::kNone) measureCell(level, cell, lat_deg, lon_deg, radius_m, xScale, yScale, s);
    }
  }
}

// Even-odd insideness at the point, for each of the longitude copies lon - 360, lon, lon + 360
// (bits 0, 1, 2): the row's inside list where its centre line passes the point's longitude, then
// the ring edges of the point's cell crossed on the way from the centre line to the point.
void VectorIndex::classify(const IndexLevel& level, double lat_deg, double lon_deg, ProximityScratch& s) const {
  const IndexGeometry& g = geometries_[level.geometry];
  const std::int64_t row = std::clamp(floorToInt((lat_deg + 90.0) / level.cell_deg), std::int64_t{0}, level.rows - 1);
  const double centre = -90.0 + (double(row) + 0.5) * level.cell_deg;
  if (const std::uint32_t r = level.rows_table.find(std::uint64_t(row)); r != KeyTable::kNone) {
    const auto begin = level.crossing_lon_deg.begin() + level.row_start[r];
    const auto end = level.crossing_lon_deg.begin() + level.row_start[r + 1];
    for (int copy = 0; copy < 3; ++copy) {
      const double x = lon_deg + 360.0 * (copy - 1);
      const auto after = std::upper_bound(begin, end, x);
      if (after == begin || after == end) continue;  // west of the first crossing or east of the last
      const auto span = std::size_t(after - level.crossing_lon_deg.begin() - 1);
      for (std::uint32_t i = level.span_start[span]; i < level.span_start[span + 1]; ++i)
        slot(level.span_features[i], s).row_copies |= std::uint8_t(1U << copy);
    }
  }
  const std::uint32_t cell = level.cells.find(cellKey(level, row, floorToInt((lon_deg + 180.0) / level.cell_deg)));
  if (cell == KeyTable::kNone) return;
  for (std::uint32_t e = level.cell_start[cell]; e < level.cell_start[cell + 1]; ++e) {
    const CellEntry entry = level.entries[e];
    if (static_cast<VectorPartKind>((entry.tag >> 1) & 3U) != VectorPartKind::kRing) continue;
    const std::uint32_t a = entry.vertex, b = a + 1;
    const double alon = g.vertices[a].lon_deg, blon = g.vertices[b].lon_deg, alat = g.vertices[a].lat_deg,
                 blat = g.vertices[b].lat_deg;
    for (int copy = 0; copy < 3; ++copy) {
      const double x = lon_deg + 360.0 * (copy - 1);
      if ((alon > x) == (blon > x)) continue;
      const double y = alat + (x - alon) * (blat - alat) / (blon - alon);
      if ((y > centre) != (y > lat_deg)) slot(entry.tag >> 3, s).cell_copies ^= std::uint8_t(1U << copy);
    }
  }
}

void VectorIndex::near(double metres_per_degree, double lat_deg, double lon_deg, double accuracy_m, double radius_m,
                       ProximityScratch& s) const {
  s.found.clear();
  if (s.stamp.size() < feature_count_) {
    s.stamp.resize(feature_count_, 0);
    s.slot.resize(feature_count_, 0);
  }
  if (++s.generation == 0) {  // wrapped: no stale stamp may match
    std::fill(s.stamp.begin(), s.stamp.end(), 0U);
    s.generation = 1;
  }
  if (empty() || !std::isfinite(lat_deg) || !std::isfinite(lon_deg)) return;
  lat_deg = std::clamp(lat_deg, -90.0, 90.0);
  lon_deg -= 360.0 * std::floor((lon_deg + 180.0) / 360.0);
  radius_m = std::clamp(radius_m, 0.0, 1e300);
  const double radius_deg = radius_m / metres_per_degree;
  const IndexLevel& level = levels_[chooseLevel(lat_deg, accuracy_m / metres_per_degree, radius_deg)];
  measure(level, window(level, lat_deg, lon_deg, radius_deg), metres_per_degree, lat_deg, lon_deg, radius_m, s);
  classify(level, lat_deg, lon_deg, s);
  std::erase_if(s.found, [](const FeatureProximity& f) {
    return !f.inside() && std::isinf(f.ring_m) && std::isinf(f.line_m) && std::isinf(f.point_m);
  });
  std::sort(s.found.begin(), s.found.end(),
            [](const FeatureProximity& x, const FeatureProximity& y) { return x.feature < y.feature; });
}

// Whether a level's cell (row, col) holds something within the box. At exact levels the entries'
// bounding boxes are compared with it (up to `budget` entries, then "yes"); at simplified levels the
// occupancy of the cell, taken from the exact geometry, answers.
bool VectorIndex::cellTouches(const IndexLevel& level, std::int64_t row, std::int64_t col, const Box& box,
                              std::size_t& budget) const {
  if (level.tolerance_deg > 0.0) return level.occupied.find(cellKey(level, row, col)) != KeyTable::kNone;
  const std::uint32_t cell = level.cells.find(cellKey(level, row, col));
  if (cell == KeyTable::kNone) return false;
  const IndexGeometry& g = geometries_[level.geometry];
  for (std::uint32_t e = level.cell_start[cell]; e < level.cell_start[cell + 1]; ++e) {
    if (budget == 0) return true;
    --budget;
    const std::uint32_t a = level.entries[e].vertex, b = a + (level.entries[e].tag & 1U);
    if (std::max(g.vertices[a].lat_deg, g.vertices[b].lat_deg) < box.lat0 ||
        std::min(g.vertices[a].lat_deg, g.vertices[b].lat_deg) > box.lat1)
      continue;
    const double lonMin = std::min(g.vertices[a].lon_deg, g.vertices[b].lon_deg),
                 lonMax = std::max(g.vertices[a].lon_deg, g.vertices[b].lon_deg);
    for (int copy = -2; copy <= 2; ++copy)
      if (lonMax >= box.lon0 + 360.0 * copy && lonMin <= box.lon1 + 360.0 * copy) return true;
  }
  return false;
}

bool VectorIndex::mayTouch(double metres_per_degree, double latMin_deg, double latMax_deg, double lonMin_deg,
                           double lonMax_deg, double grow_m, ProximityScratch& s) const {
  if (empty()) return false;
  const double grow_deg = std::max(grow_m, 0.0) / metres_per_degree;
  Box box{std::max(latMin_deg - grow_deg, -90.0), std::min(latMax_deg + grow_deg, 90.0), 0.0, 0.0};
  const double growLon_deg = grow_deg / cosLatitude(std::max(std::abs(box.lat0), std::abs(box.lat1)));
  box.lon0 = lonMin_deg - growLon_deg;
  box.lon1 = lonMax_deg + growLon_deg;
  if (box.lon1 - box.lon0 >= 360.0) box.lon0 = -180.0, box.lon1 = 180.0;
  const double shift = 360.0 * std::floor((box.lon0 + 180.0) / 360.0);  // lon0 in [-180, 180)
  box.lon0 -= shift, box.lon1 -= shift;
  if (!(box.lat0 <= box.lat1) || !(box.lon0 <= box.lon1)) return false;
  const double size_deg = std::max(box.lat1 - box.lat0, box.lon1 - box.lon0);
  std::size_t k = 0;
  while (k + 1 < levels_.size() && levels_[k].cell_deg < 0.5 * size_deg) ++k;
  const IndexLevel& level = levels_[k];
  const double d = level.cell_deg;
  const std::int64_t row0 = std::clamp(floorToInt((box.lat0 + 90.0) / d), std::int64_t{0}, level.rows - 1);
  const std::int64_t row1 = std::clamp(floorToInt((box.lat1 + 90.0) / d), std::int64_t{0}, level.rows - 1);
  const std::int64_t col0 = floorToInt((box.lon0 + 180.0) / d);
  const std::int64_t cols = std::min(floorToInt((box.lon1 + 180.0) / d) - col0 + 1, level.cols);
  std::size_t budget = kMayTouchEntries;
  for (std::int64_t row = row0; row <= row1; ++row)
    for (std::int64_t col = col0; col < col0 + cols; ++col)
      if (cellTouches(level, row, col, box, budget)) return true;
  // Nothing reaches the box: it lies wholly inside or outside each polygon, as its centre does.
  near(metres_per_degree, 0.5 * (box.lat0 + box.lat1), 0.5 * (box.lon0 + box.lon1), 0.0, 0.0, s);
  return std::any_of(s.found.begin(), s.found.end(), [](const FeatureProximity& f) { return f.inside(); });
}

}  // namespace globe
