#pragma once
// GDAL and OGR as the readers of real data (planet/sources/raster_file.h, planet/vectors/
// vector_features.h). A program that opens planet files with [[sources]], [[imagery]] or [[vectors]]
// calls installGdalReaders() once before; the planet component itself links no GDAL.
namespace globe {

// Registers GDAL's drivers (registerGdalDrivers) and installs GdalRaster::open and the OGR vector
// reader as the readers openRaster and readVectorFeatures call. Thread-safe; calls after the first
// do nothing.
void installGdalReaders();

// GDAL's drivers, our baked-tileset driver among them, and GDAL's safety options; once (thread-safe).
void registerGdalDrivers();

}  // namespace globe
