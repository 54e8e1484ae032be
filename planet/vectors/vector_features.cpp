#include "planet/vectors/vector_features.h"

#include <atomic>

namespace globe {
namespace {

std::atomic<VectorReader> installedReader{nullptr};

}  // namespace

void installVectorReader(VectorReader reader) { installedReader.store(reader); }

Result<VectorFeatures> readVectorFeatures(const VectorLayer& layer, const VectorLimits& limits) {
  const VectorReader reader = installedReader.load();
  if (reader == nullptr)
    return Error::inFileField(layer.path, "path",
                              "this program reads no vector files (it installed no reader: see "
                              "globe::installGdalReaders, planet/gdal/gdal_readers.h)");
  return reader(layer, limits);
}

}  // namespace globe
