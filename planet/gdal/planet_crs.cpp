#include "planet/gdal/planet_crs.h"

#include <cpl_conv.h>
#include <ogr_spatialref.h>

namespace globe {

std::string planetCrsWkt(double radius_m, const std::string& planetName, double flattening) {
  OGRSpatialReference srs;
  const bool sphere = flattening == 0.0;
  srs.SetGeogCS(("globe " + planetName).c_str(), sphere ? "globe sphere" : "globe ellipsoid",
                sphere ? "sphere" : "ellipsoid", radius_m, sphere ? 0.0 : 1.0 / flattening, "Reference meridian", 0.0,
                SRS_UA_DEGREE, CPLAtof(SRS_UA_DEGREE_CONV));
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  std::string text = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  return text;
}

}  // namespace globe
