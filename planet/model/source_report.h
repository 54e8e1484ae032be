#pragma once
// What `globe planet check` reports about a valid planet's sources: per source its size, CRS,
// pixel size, latitude/longitude box, value range and valid-pixel coverage, then every pair whose
// boxes overlap (and which one wins there: the finer, then the higher priority); then per imagery
// raster its size, bands, CRS, pixel size and box; then per vector layer its features, parts,
// vertices and box.
#include "planet/model/planet_description.h"

#include <string>
#include <vector>

namespace globe {

std::vector<std::string> describeSources(const PlanetDescription& planet);

class SourceMosaic;
class ImageryMosaic;

// One line on how the source data streamed (`globe bench`, docs/elevation-data.md): tiles read and
// decoded per second of I/O-thread time, request -> resident latency p50/p99 of the payloads that
// carried source terms (`latencies_s`), peak RAM tier as a fraction of the sources' decoded size,
// and the frame loop's waits (always 0 unless something is broken) and misses.
std::string sourceStreamingSummary(const SourceMosaic& mosaic, const std::vector<double>& latencies_s);
// The same line for the imagery's tiles (its latencies: the payloads prepared by the I/O thread).
std::string imageryStreamingSummary(const ImageryMosaic& mosaic, const std::vector<double>& latencies_s);

}  // namespace globe
