#include "planet/lod/lod_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planet/geometry/triacontahedron.h"

namespace globe {
namespace {

constexpr double kRestrictionSlack = 1e-9;  // relative, covers rounding in the distance tests
constexpr double kRestrictionPad_m = 1e-3;  // absolute, likewise

// The growth rule's step: base plus a gap, with the slack above (so rounding only widens ranges).
inline double grown(double base_m, double gap_m) {
  return (base_m + gap_m) * (1.0 + kRestrictionSlack) + kRestrictionPad_m;
}
// A range field steeper than this (metres of range per metre of ground) is flattened to its largest
// value: the growth rule pads by the finer field's slope times a diagonal, which for ranges as wide
// as the map's cells (coarse depths) would cost more than the field saves.
constexpr double kMaxFieldSlope = 0.25;

}  // namespace

double morphFactor(const MorphRange& morph, double distance_m) {
  if (!std::isfinite(morph.start_m)) return 0.0;
  if (morph.end_m <= morph.start_m) return distance_m >= morph.end_m ? 1.0 : 0.0;
  return std::clamp((distance_m - morph.start_m) / (morph.end_m - morph.start_m), 0.0, 1.0);
}

MorphRange NodeMorph::at(double s, double t) const {
  const double inf = std::numeric_limits<double>::infinity();
  if (!std::isfinite(end_m[0])) return {inf, inf};
  const bool uniform = end_m[0] == end_m[1] && end_m[0] == end_m[2] && end_m[0] == end_m[3];
  const double end =
      uniform ? end_m[0]
              : (end_m[0] * (1.0 - s) + end_m[1] * s) * (1.0 - t) + (end_m[2] * (1.0 - s) + end_m[3] * s) * t;
  return {std::min(end, std::max(end - fraction * (end - ownRange_m), startFloor_m)), end};
}

double pixelsPerRadian(double height_px, double verticalFov_rad) {
  return height_px / (2.0 * std::tan(0.5 * verticalFov_rad));
}

double nominalNodeWidth(int depth, double radius_m) {
  return std::ldexp(Triacontahedron::get().edgeArc() * radius_m, -depth);
}

double metresPerSample(int depth, int gridCells, double radius_m) {
  return nominalNodeWidth(depth, radius_m) / static_cast<double>(gridCells);
}

Result<LodRanges> LodRanges::create(const LodRangeConfig& c, double radius_m) {
  const auto bad = [](const char* field, const char* message) { return Error::inField(field, message); };
  if (!(std::isfinite(radius_m) && radius_m > 0.0)) return bad("radius", "must be finite and > 0");
  if (c.maxDepth < 0 || c.maxDepth > kMaxNodeLevel) return bad("maxDepth", "must be in 0..26");
  if (!(std::isfinite(c.baseRange_m) && c.baseRange_m >= 0.0)) return bad("baseRange", "must be finite and >= 0");
  if (!(std::isfinite(c.rangeRatio) && c.rangeRatio >= 1.0)) return bad("rangeRatio", "must be finite and >= 1");
  if (!(std::isfinite(c.distanceMultiplier) && c.distanceMultiplier > 0.0)) {
    return bad("distanceMultiplier", "must be finite and > 0");
  }
  if (!(c.morphFraction > 0.0 && c.morphFraction <= 1.0)) return bad("morphFraction", "must be in (0, 1]");
  if (!(std::isfinite(c.tolerance_px) && c.tolerance_px >= 0.0)) return bad("tolerance", "must be finite and >= 0");
  if (!(std::isfinite(c.texel_px) && c.texel_px >= 0.0)) return bad("texel_px", "must be finite and >= 0");
  LodRanges r;
  r.config_ = c;
  r.maxError_.fill(-1.0);
  r.maxCalibrated_.fill(-1.0);
  r.pixelsPerRadian_ = pixelsPerRadian(720.0, 1.0471975511965976);  // until the view sets its own
  const double base =
      (c.baseRange_m > 0.0 ? c.baseRange_m : kAutoBaseRangeInNodeWidths * nominalNodeWidth(c.maxDepth, radius_m)) *
      c.distanceMultiplier;
  double value = base;
  for (int d = c.maxDepth - 1; d >= 0; --d) {
    r.nominal_[static_cast<size_t>(d)] = value;
    value *= c.rangeRatio;
    // The texel rule's range over lambda (a node's texel width seen at texel_px).
    if (c.texel_px > 0.0 && c.texelsPerNode > 0)
      r.texelRadians_[static_cast<size_t>(d)] = nominalNodeWidth(d, radius_m) / (c.texelsPerNode * c.texel_px);
  }
  r.recompute();
  return r;
}

namespace {

// The deepest observed payload depth k <= depth + 1, its value scaled by 1 / ratio per level; 0 when
// nothing was observed.
double extrapolated(const std::array<double, kMaxNodeLevel + 1>& perPayloadDepth, int depth, double ratio) {
  for (int k = std::min(depth + 1, kMaxNodeLevel); k >= 0; --k) {
    const double e = perPayloadDepth[static_cast<size_t>(k)];
    if (e >= 0.0) return e * std::pow(ratio, -(depth + 1 - k));
  }
  return 0.0;
}

}  // namespace

double LodRanges::estimatedError(int depth) const { return extrapolated(maxError_, depth, config_.rangeRatio); }

bool LodRanges::observeError(int depth, double error_m) {
  if (!toleranceDriven() || !(error_m > maxError_[static_cast<size_t>(depth)])) return false;
  maxError_[static_cast<size_t>(depth)] = error_m;
  return recompute();
}

bool LodRanges::setPixelsPerRadian(double lambda) {
  if (!toleranceDriven() || !(std::isfinite(lambda) && lambda > 0.0) || lambda == pixelsPerRadian_) return false;
  pixelsPerRadian_ = lambda;
  return recompute();
}

bool LodRanges::observeError(const NodeId& node, double error_m) {
  if (!toleranceDriven()) return false;
  bool changed = observeError(node.level, error_m);
  const int depth = node.level - 1;  // a payload measures what drawing its parent's depth costs
  if (depth < 0 || !fieldDepth(depth)) return changed;
  const double calibrated = error_m / map_->maxOver(map_->relative(depth), node);
  if (calibrated > maxCalibrated_[node.level]) {
    maxCalibrated_[node.level] = calibrated;
    changed = recompute() || changed;
  }
  return changed;
}

void LodRanges::setRoughness(std::shared_ptr<const RoughnessMap> map) {
  map_ = std::move(map);
  field_.clear();
  recompute();
  refresh();
}

double LodRanges::refineRangeOver(const NodeId& node) const {
  if (!fieldDepth(node.level)) return range_[node.level];
  return map_->maxOver(std::span<const double>(field_[node.level]), node);
}

NodeMorph LodRanges::morphFor(const NodeId& node, bool partial) const {
  const int depth = node.level - (partial ? 1 : 0);  // the depth it is drawn at
  NodeMorph m;
  m.fraction = config_.morphFraction;
  if (depth == 0) {
    const double inf = std::numeric_limits<double>::infinity();
    m.end_m.fill(inf);
    m.ownRange_m = m.startFloor_m = inf;
    return m;
  }
  if (fieldDepth(depth - 1)) {
    m.end_m = map_->corners(std::span<const double>(field_[static_cast<size_t>(depth - 1)]), node);
  } else {
    m.end_m.fill(range_[static_cast<size_t>(depth - 1)]);
  }
  if (depth >= config_.maxDepth) return m;  // no finer level: starts at end - fraction * end
  m.ownRange_m = refineRangeOver(partial ? node.parent() : node);
  // Crack-freedom: where this node meets a finer neighbour it must not have started morphing. That
  // neighbour's parent met its own range, at most the slope times a diagonal above ours.
  const double diagonal = maxDiagonal_[static_cast<size_t>(depth)];
  const double slope = fieldDepth(depth) ? fieldSlope_[static_cast<size_t>(depth)] : 0.0;
  if (diagonal > 0.0) {
    m.startFloor_m = grown(m.ownRange_m, diagonal * (1.0 + slope));
  }
  return m;
}

void LodRanges::refresh() {
  if (!dirty_) return;
  dirty_ = false;
  recomputeFields();
}

void LodRanges::recomputeFields() {
  const std::size_t points = map_->pointCount();
  field_.resize(static_cast<size_t>(config_.maxDepth));
  const std::vector<double>* finer = nullptr;  // R_{d+1} per point, when d+1 has a field
  double finerMax = 0.0;                       // the largest R_{d+1}
  double finerSlope = 0.0;
  for (int d = config_.maxDepth - 1; d >= 0; --d) {
    const size_t i = static_cast<size_t>(d);
    const double perDepth = estimatedError(d);
    const double scale = pixelsPerRadian_ / config_.tolerance_px;
    const bool grows = d + 1 <= config_.maxDepth - 1;
    const double diagonal = grows ? maxDiagonal_[i + 1] : 0.0;
    double largest = 0.0;
    if (fieldDepth(d)) {
      // The error the map predicts, K * w, never above the largest one observed at this depth; its
      // largest value is at w = 1, and min(K w, E) changes no faster than K w.
      const double k = extrapolated(maxCalibrated_, d, config_.rangeRatio);
      const double calibration = k > 0.0 ? k : perDepth;
      const double pad = diagonal * (1.0 + finerSlope);
      largest = scale * std::min(calibration, perDepth);
      if (grows) largest = std::max(largest, grown(finerMax, pad));
      fieldSlope_[i] = std::max(scale * calibration * map_->slope(d), finerSlope * (1.0 + kRestrictionSlack));
      std::vector<double>& table = field_[i];
      table.resize(points);
      if (fieldSlope_[i] > kMaxFieldSlope) {
        std::fill(table.begin(), table.end(), largest);
        fieldSlope_[i] = 0.0;
      } else {
        const std::span<const float> w = map_->relative(d);
        const double cap = scale * perDepth, k2 = scale * calibration;
        for (size_t p = 0; p < points; ++p) table[p] = std::min(k2 * w[p], cap);
        if (grows) {
          const std::vector<double>& f = *finer;
          for (size_t p = 0; p < points; ++p) table[p] = std::max(table[p], grown(f[p], pad));
        }
      }
      finer = &table;
      finerSlope = fieldSlope_[i];
    } else {
      largest = scale * perDepth;
      if (grows) largest = std::max(largest, grown(finerMax, diagonal));
      finer = nullptr;
      finerSlope = 0.0;
    }
    range_[i] = largest;
    finerMax = largest;
  }
  recomputeBands();
}

bool LodRanges::recompute() {
  if (map_ && toleranceDriven()) {  // fields: once per selection pass (refresh), not per observation
    dirty_ = true;
    return true;
  }
  bool changed = false;
  double finer = 0.0;  // R(d+1), none below the last refinable depth
  for (int d = config_.maxDepth - 1; d >= 0; --d) {
    const size_t i = static_cast<size_t>(d);
    double value = toleranceDriven()
                       ? pixelsPerRadian_ * std::max(estimatedError(d) / config_.tolerance_px, texelRadians_[i])
                       : nominal_[i];
    if (d + 1 <= config_.maxDepth - 1) {
      value = std::max(value, grown(finer, maxDiagonal_[i + 1]));
    }
    changed = changed || value != range_[i];
    range_[i] = value;
    finer = value;
  }
  recomputeBands();
  return changed;
}

void LodRanges::recomputeBands() {
  // Morph bands: depth 0 never morphs; depth d lives in [R(d), R(d-1)] (R(maxDepth) = 0).
  const double inf = std::numeric_limits<double>::infinity();
  morph_[0] = {inf, inf};
  for (int d = 1; d <= config_.maxDepth; ++d) {
    const double end = range_[static_cast<size_t>(d - 1)];
    const double start = d < config_.maxDepth ? range_[static_cast<size_t>(d)] : 0.0;
    MorphRange band{end - config_.morphFraction * (end - start), end};
    // Crack-freedom: where a depth-d node meets a finer neighbour (at most R(d) + D(d) from the
    // camera, D = largest depth-d diagonal seen) it must not have started morphing yet, or its
    // edge would leave the finer node's unmorphed vertices. The band may narrow, never invert.
    const double diagonal = d < config_.maxDepth ? maxDiagonal_[static_cast<size_t>(d)] : 0.0;
    if (diagonal > 0.0) {
      const double unmorphedUntil = grown(start, diagonal);
      band.start_m = std::min(band.end_m, std::max(band.start_m, unmorphedUntil));
    }
    morph_[static_cast<size_t>(d)] = band;
  }
}

void LodRanges::restore(const Observations& o) {
  maxDiagonal_ = o.maxDiagonal;
  maxError_ = o.maxError;
  maxCalibrated_ = o.maxCalibrated;
  recompute();
  refresh();
}

void LodRanges::resetObservedDiagonals() {
  maxDiagonal_.fill(0.0);
  maxError_.fill(-1.0);
  maxCalibrated_.fill(-1.0);
  recompute();
}

}  // namespace globe
