#include "tests/support/imagery_fixture.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <memory>
#include <stdexcept>
#include <vector>

namespace globe::testing {

void writeCheckerboard(const std::string& path, const Checkerboard& board) {
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  const int bands = board.alpha ? 4 : 3;
  char** options = board.alpha ? CSLSetNameValue(nullptr, "ALPHA", "YES") : nullptr;
  std::unique_ptr<GDALDataset> ds(driver->Create(path.c_str(), board.width, board.height, bands, GDT_Byte, options));
  CSLDestroy(options);
  if (!ds) throw std::runtime_error("cannot create " + path);
  ds->SetGeoTransform(const_cast<double*>(board.geo));
  OGRSpatialReference srs;
  srs.SetFromUserInput(board.crs.c_str());
  ds->SetSpatialRef(&srs);
  std::vector<unsigned char> values(std::size_t(board.width) * std::size_t(board.height));
  for (int b = 0; b < bands; ++b) {
    for (int y = 0; y < board.height; ++y) {
      for (int x = 0; x < board.width; ++x) {
        const bool light = (x / board.square_px + y / board.square_px) % 2 == 0;
        const unsigned char alpha = x < board.width / 2 ? 255 : 0;
        values[std::size_t(y) * std::size_t(board.width) + std::size_t(x)] =
            b == 3 ? alpha : (light ? kCheckerLight[b] : kCheckerDark[b]);
      }
    }
    if (ds->GetRasterBand(b + 1)->RasterIO(GF_Write, 0, 0, board.width, board.height, values.data(), board.width,
                                           board.height, GDT_Byte, 0, 0) != CE_None)
      throw std::runtime_error("cannot write " + path);
  }
}

void latLonOfCrsPoint(const std::string& crs, double x, double y, double& latitude_deg, double& longitude_deg) {
  OGRSpatialReference from, wgs84;
  from.SetFromUserInput(crs.c_str());
  wgs84.SetWellKnownGeogCS("WGS84");
  from.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&from, &wgs84));
  if (!t || !t->Transform(1, &x, &y)) throw std::runtime_error("cannot transform from " + crs);
  longitude_deg = x;
  latitude_deg = y;
}

void writePlainPng(const std::string& path, int width, int height) {
  GDALAllRegister();
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  std::unique_ptr<GDALDataset> ds(mem->Create("", width, height, 3, GDT_Byte, nullptr));
  for (int b = 1; b <= 3; ++b) ds->GetRasterBand(b)->Fill(128.0);
  GDALDriver* png = GetGDALDriverManager()->GetDriverByName("PNG");
  std::unique_ptr<GDALDataset> out(png->CreateCopy(path.c_str(), ds.get(), FALSE, nullptr, nullptr, nullptr));
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace globe::testing
