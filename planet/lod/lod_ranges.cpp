#include "planet/lod/lod_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planet/geometry/triacontahedron.h"

namespace globe {
namespace {

constexpr double kRestrictionSlack = 1e-9;  // relative, covers rounding in the distance tests
constexpr double kRestrictionPad_m = 1e-3;  // absolute, likewise

}  // namespace

double morphFactor(const MorphRange& morph, double distance_m) {
  if (!std::isfinite(morph.start_m)) return 0.0;
  if (morph.end_m <= morph.start_m) return distance_m >= morph.end_m ? 1.0 : 0.0;
  return std::clamp((distance_m - morph.start_m) / (morph.end_m - morph.start_m), 0.0, 1.0);
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
  LodRanges r;
  r.config_ = c;
  r.maxError_.fill(-1.0);
  r.pixelsPerRadian_ = pixelsPerRadian(720.0, 1.0471975511965976);  // until the view sets its own
  const double base =
      (c.baseRange_m > 0.0 ? c.baseRange_m : kAutoBaseRangeInNodeWidths * nominalNodeWidth(c.maxDepth, radius_m)) *
      c.distanceMultiplier;
  double value = base;
  for (int d = c.maxDepth - 1; d >= 0; --d) {
    r.nominal_[static_cast<size_t>(d)] = value;
    value *= c.rangeRatio;
  }
  r.recompute();
  return r;
}

double LodRanges::estimatedError(int depth) const {
  // The deepest observed payload depth k <= depth + 1, its error scaled by 1 / ratio per level.
  for (int k = std::min(depth + 1, kMaxNodeLevel); k >= 0; --k) {
    const double e = maxError_[static_cast<size_t>(k)];
    if (e >= 0.0) return e * std::pow(config_.rangeRatio, -(depth + 1 - k));
  }
  return 0.0;
}

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

bool LodRanges::recompute() {
  bool changed = false;
  double finer = 0.0;  // R(d+1), none below the last refinable depth
  for (int d = config_.maxDepth - 1; d >= 0; --d) {
    const size_t i = static_cast<size_t>(d);
    double value = toleranceDriven() ? pixelsPerRadian_ * estimatedError(d) / config_.tolerance_px : nominal_[i];
    if (d + 1 <= config_.maxDepth - 1) {
      value = std::max(value, (finer + maxDiagonal_[i + 1]) * (1.0 + kRestrictionSlack) + kRestrictionPad_m);
    }
    changed = changed || value != range_[i];
    range_[i] = value;
    finer = value;
  }
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
      const double unmorphedUntil = (start + diagonal) * (1.0 + kRestrictionSlack) + kRestrictionPad_m;
      band.start_m = std::min(band.end_m, std::max(band.start_m, unmorphedUntil));
    }
    morph_[static_cast<size_t>(d)] = band;
  }
  return changed;
}

void LodRanges::resetObservedDiagonals() {
  maxDiagonal_.fill(0.0);
  maxError_.fill(-1.0);
  recompute();
}

}  // namespace globe
