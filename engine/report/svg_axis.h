#pragma once
// Axis arithmetic and number formatting shared by the report's SVG plots (timeline, frame-time
// distribution): one definition of "a round step" and of tick labels, so every plot reads alike.
#include <string>

namespace globe {

// An SVG coordinate: one decimal, locale-independent.
std::string svgNumber(double v);

// 1, 2 or 5 times a power of ten, giving about `targetTicks` intervals over `range`.
double niceStep(double range, double targetTicks);

// Tick label with k/M suffixes so large counts stay short; the step sets the decimals.
std::string tickLabel(double value, double step);

// A light horizontal grid line across [left, right] at y with its label right-aligned left of it.
std::string svgHorizontalTick(double y, double left, double right, const std::string& label);

}  // namespace globe
