#pragma once
// The VectorReader of planet/vectors/vector_features.h through OGR: GeoJSON, GeoPackage, Shapefile,
// KML, anything GDAL reads as vectors, every geometry reprojected to WGS84 latitude/longitude degrees.
#include "planet/vectors/vector_features.h"

namespace globe {

Result<VectorFeatures> readOgrVectorFeatures(const VectorLayer& layer, const VectorLimits& limits);

}  // namespace globe
