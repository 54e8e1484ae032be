// [climate] and [[land_cover]] in planet files: every key is read, every bad value is one error at
// its file, line, column and field, and the writer gives back the same description.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>

#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/model/planet_file_writer.h"
#include "tests/support/planet_file_cases.h"
#include "tests/support/temp_dir.h"

namespace globe {
namespace {

using testing::BadPlanetCase;
using testing::expectBadPlanetCase;

// A valid planet (lines 1-6) and a valid class (lines 7-9), appended where a case needs them.
#define LAYER "[[layers]]\nname = \"base\"\noctaves = 4\nwavelength_m = 1e6\namplitude_m = 1000\n"
#define BASE "radius_m = 5e6\n" LAYER
#define CLASS "[[land_cover]]\nname = \"grass\"\ncolour = [0.1, 0.3, 0.05]\n"

TEST(LandCoverFile, EveryKeyIsRead) {
  testing::TempDir dir("land_cover_file_keys");
  std::filesystem::create_directories(dir / "textures");
  std::ofstream(dir / "textures/sand.png", std::ios::binary) << "\x89PNG\r\n\x1a\n(the rest is not read here)";
  const std::string text = BASE
      "[climate]\nequator_temperature_c = 30\npole_temperature_c = -40\nlapse_rate_c_per_km = 5\n"
      "temperature_noise_c = 2\nmoisture_base = 0.4\nmoisture_noise = 0.3\ninland_drying_m = 1500\n"
      "noise_wavelength_m = 1e6\ntemperature_blend_c = 3\nmoisture_blend = 0.05\nelevation_blend_m = 20\n"
      "slope_blend_deg = 4\n"
      "[[land_cover]]\nname = \"beach\"\ncolour = [0.5, 0.45, 0.3]\nelevation_m = [-inf, 15]\n"
      "texture = \"textures/sand.png\"\n"
      "[[land_cover]]\nname = \"forest\"\ncolour = [0.05, 0.1, 0.03]\ntemperature_c = [0, 30]\n"
      "moisture = [0.5, 1]\nelevation_m = [15, 2500]\nslope_deg = [0, 35]\ndetail_contrast = 0.6\n";
  const Result<PlanetDescription> r = parsePlanetToml(text, (dir / "p.toml").string());
  ASSERT_TRUE(r.ok()) << r.error().format();
  const LandCover& cover = r->land_cover;
  Climate climate;
  climate.equator_temperature_c = 30.0;
  climate.pole_temperature_c = -40.0;
  climate.lapse_rate_c_per_km = 5.0;
  climate.temperature_noise_c = 2.0;
  climate.moisture_base = 0.4;
  climate.moisture_noise = 0.3;
  climate.inland_drying_m = 1500.0;
  climate.noise_wavelength_m = 1e6;
  climate.temperature_blend_c = 3.0;
  climate.moisture_blend = 0.05;
  climate.elevation_blend_m = 20.0;
  climate.slope_blend_deg = 4.0;
  EXPECT_EQ(cover.climate, climate);
  ASSERT_EQ(cover.classes.size(), 2U);
  LandCoverClass beach;  // unbounded ranges but the one given, slope [0, 90], default contrast
  beach.name = "beach";
  beach.colour = glm::vec3(0.5f, 0.45f, 0.3f);
  beach.elevation_max_m = 15.0;
  beach.texture = (dir / "textures/sand.png").string();  // resolved against the file's folder
  EXPECT_EQ(cover.classes[0], beach);
  const LandCoverClass& forest = cover.classes[1];
  EXPECT_EQ(forest.temperature_min_c, 0.0);
  EXPECT_EQ(forest.temperature_max_c, 30.0);
  EXPECT_EQ(forest.moisture_min, 0.5);
  EXPECT_EQ(forest.moisture_max, 1.0);
  EXPECT_EQ(forest.elevation_min_m, 15.0);
  EXPECT_EQ(forest.elevation_max_m, 2500.0);
  EXPECT_EQ(forest.slope_max_deg, 35.0);
  EXPECT_EQ(forest.detail_contrast, 0.6);
  EXPECT_TRUE(forest.texture.empty());
  // The model packs it.
  const ElevationModel model(*r);
  EXPECT_EQ(model.landCover().class_count, 2U);
  EXPECT_FLOAT_EQ(model.landCover().lapse_rate_c_per_m, 0.005f);
  EXPECT_EQ(model.landCover().classes[0].elevation_min_m, -1e30f);
}

TEST(LandCoverFile, ClassesWithoutClimateTakeItsDefaults) {
  const Result<PlanetDescription> r = parsePlanetToml(BASE CLASS, "c.toml");
  ASSERT_TRUE(r.ok()) << r.error().format();
  EXPECT_EQ(r->land_cover.climate, Climate{});
  EXPECT_TRUE(r->land_cover.enabled());
  const Result<PlanetDescription> none = parsePlanetToml(BASE, "n.toml");
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none->land_cover.enabled());
  EXPECT_EQ(ElevationModel(*none).landCover().class_count, 0U);
}

using BadCase = BadPlanetCase;

std::string nineClasses() {
  std::string text = BASE;
  for (int i = 0; i < 9; ++i) text += "[[land_cover]]\nname = \"c" + std::to_string(i) + "\"\ncolour = [0, 0, 0]\n";
  return text;
}

const BadCase kBadCases[] = {
    {"unknown class key", BASE CLASS "texure = \"a.png\"\n", 10, 1, "land_cover[0].texure",
     "unknown key (did you mean 'texture'?)"},
    {"moisture reversed", BASE CLASS "moisture = [0.8, 0.2]\n", 10, 12, "land_cover[0].moisture",
     "the first value must be below the second"},
    {"open end first", BASE CLASS "temperature_c = [inf, 5]\n", 10, 17, "land_cover[0].temperature_c",
     "the first value must be below the second"},
    {"one value", BASE CLASS "temperature_c = [1]\n", 10, 17, "land_cover[0].temperature_c",
     "expected 2 values [min, max], got 1"},
    {"range not an array", BASE CLASS "slope_deg = 35\n", 10, 13, "land_cover[0].slope_deg",
     "expected an array [min, max], got an integer"},
    {"range of a string", BASE CLASS "elevation_m = [0, \"high\"]\n", 10, 19, "land_cover[0].elevation_m",
     "expected a number, got a string"},
    {"slope beyond 90", BASE CLASS "slope_deg = [30, 95]\n", 10, 13, "land_cover[0].slope_deg",
     "each end must be within [0, 90]"},
    {"contrast", BASE CLASS "detail_contrast = 2\n", 10, 19, "land_cover[0].detail_contrast", "[0, 1]"},
    {"bad name", BASE "[[land_cover]]\nname = \"Grass\"\ncolour = [0, 0, 0]\n", 8, 8, "land_cover[0].name",
     "must be 1 to 32 characters of a-z, 0-9, _ and -"},
    {"duplicate name", BASE CLASS CLASS, 11, 8, "land_cover[1].name", "'grass' is already the name"},
    {"reserved name", BASE "[[land_cover]]\nname = \"sea\"\ncolour = [0, 0, 1]\n", 8, 8, "land_cover[0].name",
     "'sea' is reserved"},
    {"missing name", BASE "[[land_cover]]\ncolour = [0, 0, 0]\n", 7, 1, "land_cover[0].name", "missing (required)"},
    {"missing colour", BASE "[[land_cover]]\nname = \"grass\"\n", 7, 1, "land_cover[0].colour", "missing (required)"},
    {"colour out of range", BASE "[[land_cover]]\nname = \"grass\"\ncolour = [0.1, 1.5, 0]\n", 9, 10,
     "land_cover[0].colour", "each component must be within [0, 1]"},
    {"missing texture", BASE CLASS "texture = \"no/such.png\"\n", 10, 11, "land_cover[0].texture",
     "no such file 'no/such.png'"},
    {"empty texture", BASE CLASS "texture = \"\"\n", 10, 11, "land_cover[0].texture", "must not be empty"},
    {"too many classes", nineClasses(), 31, 1, "land_cover", "at most 8 classes"},
    {"classes not tables", "radius_m = 5e6\nland_cover = 3\n" LAYER, 2, 14, "land_cover",
     "expected an array of tables ([[land_cover]])"},
    {"unknown climate key", BASE CLASS "[climate]\nlapse_rate = 6\n", 11, 1, "climate.lapse_rate",
     "unknown key (did you mean 'lapse_rate_c_per_km'?)"},
    {"climate type", BASE CLASS "[climate]\nmoisture_base = \"wet\"\n", 11, 17, "climate.moisture_base",
     "expected a number, got a string"},
    {"climate range", BASE CLASS "[climate]\nlapse_rate_c_per_km = -1\n", 11, 23, "climate.lapse_rate_c_per_km",
     "must be within [0, 100]"},
    {"zero blend", BASE CLASS "[climate]\nmoisture_blend = 0\n", 11, 18, "climate.moisture_blend", "(0, 10]"},
    {"climate not a table", "radius_m = 5e6\nclimate = 3\n" LAYER CLASS, 2, 11, "climate",
     "expected a table ([climate])"},
    {"climate without classes", BASE "[climate]\nmoisture_base = 0.5\n", 7, 1, "climate",
     "[climate] needs at least one [[land_cover]] class"},
};

TEST(LandCoverFile, EveryErrorHasFileLineColumnAndField) {
  for (const BadCase& c : kBadCases) expectBadPlanetCase(c);
}

TEST(LandCoverFile, TextureMustBeAPng) {
  const std::string readme = std::string(GLOBE_SOURCE_DIR) + "/README.md";
  const Result<PlanetDescription> r = parsePlanetToml(BASE CLASS "texture = \"" + readme + "\"\n", "t.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().format(), "t.toml:10:11: land_cover[0].texture: '" + readme + "' is not a PNG file");
}

TEST(LandCoverFile, EveryProblemIsReportedAtOnce) {
  const PlanetFileCheck check = checkPlanetToml(BASE
                                                "[climate]\nmoisture_noise = -1\nnoise_wavelength = 5\n"
                                                "[[land_cover]]\nname = \"a\"\ncolour = [0, 0, 0]\n"
                                                "moisture = [1, 0]\n"
                                                "[[land_cover]]\nname = \"a\"\ncolour = [0, 0]\nslope_deg = [0, 91]\n",
                                                "many.toml");
  const char* const expected[] = {
      "many.toml:8:18: climate.moisture_noise: must be within [0, 10]",
      "many.toml:9:1: climate.noise_wavelength: unknown key (did you mean 'noise_wavelength_m'?)",
      "many.toml:13:12: land_cover[0].moisture: the first value must be below the second",
      "many.toml:15:8: land_cover[1].name: 'a' is already the name of an earlier class",
      "many.toml:16:10: land_cover[1].colour: expected 3 components [r, g, b], got 2",
      "many.toml:17:13: land_cover[1].slope_deg: each end must be within [0, 90]",
  };
  ASSERT_EQ(check.errors.size(), std::size(expected));
  for (std::size_t i = 0; i < std::size(expected); ++i) EXPECT_EQ(check.errors[i].format(), expected[i]);
}

TEST(LandCoverFile, RoundTripsThroughTheWriter) {
  const std::string text = BASE
      "[climate]\nequator_temperature_c = 31.5\nlapse_rate_c_per_km = 6.25\n"
      "[[land_cover]]\nname = \"beach\"\ncolour = [0.5, 0.45, 0.3]\nelevation_m = [-inf, 15]\n"
      "[[land_cover]]\nname = \"forest\"\ncolour = [0.05, 0.1, 0.03]\ntemperature_c = [0.1, 30]\n"
      "moisture = [0.5, 1e30]\nslope_deg = [0, 35]\ndetail_contrast = 0.6\n"
      "[[land_cover]]\nname = \"rock\"\ncolour = [0.2, 0.2, 0.2]\nslope_deg = [35, 90]\n"
      "texture = \"rock \\\"quoted\\\".png\"\n";
  // The texture does not exist: read the rest, then put it in as a loader would have resolved it.
  PlanetFileCheck check = checkPlanetToml(text, "rt.toml");
  ASSERT_EQ(check.errors.size(), 1U);
  EXPECT_EQ(check.errors[0].field, "land_cover[2].texture");
  const PlanetDescription& p = check.planet;
  ASSERT_EQ(p.land_cover.classes[2].texture, "rock \"quoted\".png");
  const std::string written = formatPlanetToml(p);
  EXPECT_NE(written.find("\n[climate]\nequator_temperature_c = 31.5\n"), std::string::npos) << written;
  EXPECT_NE(written.find("\nelevation_m = [-1e+30, 15]\n"), std::string::npos) << written;
  EXPECT_NE(written.find("\nmoisture = [0.5, 1e+30]\n"), std::string::npos) << written;
  EXPECT_NE(written.find("\nslope_deg = [35, 90]\n"), std::string::npos) << written;
  EXPECT_EQ(written.find("temperature_c = [-1e+30"), std::string::npos) << written;  // unbounded: left out
  EXPECT_EQ(written.find("slope_deg = [0, 90]"), std::string::npos) << written;      // the default: left out
  const PlanetFileCheck again = checkPlanetToml(written, "again.toml");
  ASSERT_EQ(again.errors.size(), 1U);  // the same missing texture, nothing else
  EXPECT_EQ(again.planet, p) << written;
  EXPECT_EQ(formatPlanetToml(again.planet), written);
  const gpu::LandCoverParams a = packLandCover(p.land_cover, p.radius_m, p.seed, p.sea_level_m);
  const gpu::LandCoverParams b =
      packLandCover(again.planet.land_cover, again.planet.radius_m, again.planet.seed, again.planet.sea_level_m);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  // Without land cover nothing is written.
  PlanetDescription bare = p;
  bare.land_cover = {};
  EXPECT_EQ(formatPlanetToml(bare).find("climate"), std::string::npos);
}

}  // namespace
}  // namespace globe
