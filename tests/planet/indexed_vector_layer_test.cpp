// A vector layer is read and indexed once and shared (planet/vectors/indexed_vector_layer.h): the
// planet file's check, the overlay and `planet check`'s description find the same layer; an edited
// file is read again; one index serves spheres of any radius.
#include "planet/vectors/indexed_vector_layer.h"
#include "planet/camera/camera.h"
#include "planet/vectors/vector_overlay.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

namespace globe {
namespace {

std::string lineAlongTheEquator(double lon1_deg) {
  return R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},)"
         R"( "geometry": {"type": "LineString", "coordinates": [[0, 0], [)" +
         std::to_string(lon1_deg) + ", 0]]}}]}";
}

class IndexedVectorLayerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::make_unique<testing::TempDir>("indexed_vector_layer");
    layer_.path = (*dir_ / "line.geojson").string();
    layer_.width_m = 100.0;
    layer_.width_px = 0.0;
    write(1.0);
  }
  void write(double lon1_deg) const { std::ofstream(layer_.path, std::ios::binary) << lineAlongTheEquator(lon1_deg); }
  std::shared_ptr<const IndexedVectorLayer> open(const VectorLayer& layer) const {
    Result<std::shared_ptr<const IndexedVectorLayer>> opened = openIndexedVectorLayer(layer);
    EXPECT_TRUE(opened.ok()) << (opened ? "" : opened.error().format());
    return opened ? *opened : nullptr;
  }
  std::unique_ptr<testing::TempDir> dir_;
  VectorLayer layer_;
};

TEST_F(IndexedVectorLayerTest, TheSameLayerIsReadOnceAndShared) {
  const auto first = open(layer_);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->facts.lines, 1u);
  EXPECT_EQ(first->facts.vertices, 2u);
  EXPECT_EQ(open(layer_), first);  // what the overlay finds after the planet file's check
  Result<std::unique_ptr<VectorOverlay>> overlay = VectorOverlay::open({layer_}, 6371000.0);
  ASSERT_TRUE(overlay.ok());
  EXPECT_EQ(open(layer_), first);  // the overlay read nothing again (a read would replace the kept one)

  VectorLayer restyled = layer_;
  restyled.width_m = 50.0;
  const auto other = open(restyled);
  ASSERT_TRUE(other);
  EXPECT_NE(other, first);
  EXPECT_EQ(other->style.width_m, 50.0);
}

TEST_F(IndexedVectorLayerTest, AnEditedFileIsReadAgain) {
  const auto before = open(layer_);
  ASSERT_TRUE(before);
  EXPECT_DOUBLE_EQ(before->facts.lon_max_deg, 1.0);
  write(2.5);  // another size: the stamp differs even within the file system's time resolution
  const auto after = open(layer_);
  ASSERT_TRUE(after);
  EXPECT_NE(after, before);
  EXPECT_DOUBLE_EQ(after->facts.lon_max_deg, 2.5);
}

TEST_F(IndexedVectorLayerTest, AFileThatNoLongerReadsIsAnError) {
  ASSERT_TRUE(open(layer_));
  std::ofstream(layer_.path, std::ios::binary) << "{ not json";
  Result<std::shared_ptr<const IndexedVectorLayer>> opened = openIndexedVectorLayer(layer_);
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.error().format().find("line.geojson"), std::string::npos) << opened.error().format();
}

// The index is in degrees; each overlay measures metres on its own sphere. 80 m off a 100 m wide
// line on the Earth's sphere is off it; the same angle on a sphere of half the radius is 40 m: on it.
TEST_F(IndexedVectorLayerTest, OneIndexServesSpheresOfAnyRadius) {
  const double earth_m = 6371000.0, half_m = 0.5 * earth_m;
  const double offset_deg = 80.0 / (earth_m * std::numbers::pi / 180.0);
  const glm::dvec3 at = directionFromLatLon(offset_deg, 0.5);
  Result<std::unique_ptr<VectorOverlay>> earth = VectorOverlay::open({layer_}, earth_m);
  Result<std::unique_ptr<VectorOverlay>> half = VectorOverlay::open({layer_}, half_m);
  ASSERT_TRUE(earth.ok() && half.ok());
  const double texel_m = 1.0;
  EXPECT_EQ((*earth)->colourAt(at, texel_m, 1.0).alpha, 0.0f);
  EXPECT_EQ((*half)->colourAt(at, texel_m, 1.0).alpha, 1.0f);
  EXPECT_TRUE((*half)->mayTouch(offset_deg, offset_deg, 0.5, 0.5, 0.0));
}

}  // namespace
}  // namespace globe
