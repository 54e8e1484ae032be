#pragma once
// The planet side of vector layers draped on the terrain: the colour that a planet's [[vectors]]
// paint at any point of the sphere, antialiased with the surface texel as the filter, for the
// payload path to bake into each node's surface texture. Each layer is read once (the installed
// VectorReader) and indexed (indexed_vector_layer.h), so a query costs about the same whatever the
// layer's size.
#include "planet/core/error.h"
#include "planet/vectors/indexed_vector_layer.h"
#include "planet/vectors/vector_layer.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace globe {

// Linear colour with straight (not premultiplied) alpha; alpha 0 where nothing is painted.
struct OverlayColour {
  glm::vec3 albedo{0.0f};
  float alpha = 0.0f;
};

class VectorOverlay {
 public:
  // Every layer read and indexed (openIndexedVectorLayer: those the planet file's check read are
  // shared, not read again; a layer that fails now is an Error too, naming its file). `radius_m`:
  // the sphere on which distances are measured.
  static Result<std::unique_ptr<VectorOverlay>> open(const std::vector<VectorLayer>& layers, double radius_m);
  ~VectorOverlay();
  VectorOverlay(const VectorOverlay&) = delete;
  VectorOverlay& operator=(const VectorOverlay&) = delete;

  // The layers composited "over" in file order (later on top; within a layer, fills, then lines
  // and outlines, then markers, each in feature order) at a planet-fixed unit direction
  // (latitude/longitude as latLonFromPosition gives them).
  //
  // `texel_m`: the surface texel the colour is for, in metres; it is the antialiasing filter
  // (coverage goes from 0 to 1 over one texel across an edge) and the narrowest line or marker
  // drawn, so a thin line stays continuous at every level. `pixel_m`: the size of a screen pixel on
  // the ground, in metres, which the caller derives from the node's level: *_px widths and marker
  // sizes are honoured through it (width_m = width_px * pixel_m). Thread-safe.
  //
  // Distances are measured on a tangent plane at the point (equirectangular), which suits features
  // small beside the planet; consecutive vertices join the short way round, so features may cross
  // the antimeridian in either longitude convention. Geometry is simplified by up to 1/8 of a
  // texel where that bounds the cost (coverage off by at most 0.125); within a few texels of a pole
  // a coarser level is read.
  OverlayColour colourAt(const glm::dvec3& unitDirection, double texel_m, double pixel_m) const;

  // Cheap reject for a whole node: false when no feature, grown by its widest metric line or
  // marker (width_m, point_size_m) and `margin_m`, touches the latitude/longitude box (degrees;
  // longitudes may run past +-180). Pixel-sized widths are not known here: the caller includes them
  // (and half a texel) in `margin_m`. Conservative: true may only mean "near". Thread-safe.
  bool mayTouch(double latMin_deg, double latMax_deg, double lonMin_deg, double lonMax_deg, double margin_m) const;

  bool empty() const;  // no layer draws anything

 private:
  VectorOverlay();
  std::vector<std::shared_ptr<const IndexedVectorLayer>> layers_;
  double metres_per_degree_ = 0.0;  // of arc, on the sphere of radius_m
};

}  // namespace globe
