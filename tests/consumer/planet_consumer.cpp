// Links the domain from an installed globe: reads a planet file and samples its elevation on the CPU.
// Built twice (tests/consumer/CMakeLists.txt): with the planet component alone, where a planet with
// real sources must be refused by name (no reader installed), and with the gdal component, which
// installs GDAL and OGR as the readers and so reads it.
#include <globe/planet/model/elevation_model.h>
#include <globe/planet/model/planet_file.h>
#ifdef CONSUMER_READS_REAL_DATA
#include <globe/planet/gdal/gdal_readers.h>
#endif

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
#ifdef CONSUMER_READS_REAL_DATA
  globe::installGdalReaders();
#endif
  const auto planet = globe::loadPlanetFile(argv[1]);
  if (!planet) {
    std::fprintf(stderr, "consumer: %s\n", planet.error().format().c_str());
    return 1;
  }
  const globe::ElevationModel model(*planet);
  const double elevation_m = model.elevation_m(glm::dvec3(1.0, 0.0, 0.0));
  std::printf("consumer: %s, radius %.0f m, elevation at (1, 0, 0) %.1f m\n", planet->name.c_str(), model.radius_m(),
              elevation_m);
  return model.radius_m() > 0.0 ? 0 : 1;
}
