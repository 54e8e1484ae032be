// TOML planet files: the earthlike preset loads; every bad input gives file:line:column and the key.
#include <gtest/gtest.h>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/model/planet_file_writer.h"
#include "planet/surface/colour_ramp.h"
#include "tests/support/planet_file_cases.h"

namespace globe {
namespace {

using testing::BadPlanetCase;
using testing::expectBadPlanetCase;

const std::string kEarthlike = std::string(GLOBE_SOURCE_DIR) + "/" + std::string(kDefaultPlanetFile);

TEST(PlanetFile, EarthlikeLoads) {
  const Result<PlanetDescription> r = loadPlanetFile(kEarthlike);
  ASSERT_TRUE(r.ok()) << r.error().format();
  const PlanetDescription& p = *r;
  EXPECT_EQ(p.name, "earthlike");
  EXPECT_EQ(p.radius_m, 6371000.0);
  EXPECT_EQ(p.sea_level_m, 0.0);
  ASSERT_EQ(p.layers.size(), 3U);
  EXPECT_EQ(p.layers[0].name, "continents");
  EXPECT_EQ(p.layers[1].kind, LayerKind::kRidged);
  EXPECT_EQ(p.layers[1].modulated_by, 0);
  EXPECT_EQ(p.layers[2].modulated_by, 0);
  // Twelve octaves like [Frasson 2018]: 4 continent octaves modulating 8 detail octaves.
  EXPECT_EQ(p.layers[0].octaves + p.layers[1].octaves + p.layers[2].octaves, 12);
  EXPECT_LE(finestWavelength_m(p.layers[2]), 1.0);  // sub-metre detail
  const ElevationRange b = elevationBounds(p);
  EXPECT_LT(b.min_m, -8000.0);
  EXPECT_GT(b.max_m, 9000.0);
  EXPECT_GT(b.min_m, -20000.0);
  EXPECT_LT(b.max_m, 20000.0);
  EXPECT_TRUE(validatePlanet(p).ok());
}

TEST(PlanetFile, MinimalFileUsesDefaults) {
  const char* text = R"(radius_m = 1000
[[layers]]
octaves = 2
frequency_per_m = 0.01
amplitude_m = 5
)";
  const Result<PlanetDescription> r = parsePlanetToml(text, "dir/tiny.toml");
  ASSERT_TRUE(r.ok()) << r.error().format();
  EXPECT_EQ(r->name, "tiny");
  EXPECT_EQ(r->seed, 0U);
  EXPECT_EQ(r->radius_m, 1000.0);
  EXPECT_EQ(r->layers[0].wavelength_m, 100.0);
  EXPECT_EQ(r->layers[0].lacunarity, 2.0);
  EXPECT_EQ(r->layers[0].gain, 0.5);
  EXPECT_EQ(r->layers[0].kind, LayerKind::kFbm);
  EXPECT_EQ(r->layers[0].modulated_by, -1);
}

TEST(PlanetFile, MissingFileIsAnError) {
  const Result<PlanetDescription> r = loadPlanetFile("/nonexistent/planet.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "/nonexistent/planet.toml");
  EXPECT_NE(r.error().message.find("cannot open"), std::string::npos);
}

using BadCase = BadPlanetCase;

// A valid layer, appended where a case needs one (lines 1-5 of the layer part).
#define LAYER "[[layers]]\nname = \"base\"\noctaves = 4\nwavelength_m = 1e6\namplitude_m = 1000\n"

const BadCase kBadCases[] = {
    {"syntax error", "radius_m = \n" LAYER, 1, 12, "", ""},
    {"unknown top-level key", "radius = 5\n" LAYER, 1, 1, "radius", "did you mean 'radius_m'"},
    {"unknown layer key", "radius_m = 5e6\n" LAYER "octave_count = 3\n", 7, 1, "layers[0].octave_count", "unknown key"},
    {"wrong type", "radius_m = \"big\"\n" LAYER, 1, 12, "radius_m", "expected a number, got a string"},
    {"nan", "radius_m = nan\n" LAYER, 1, 12, "radius_m", "finite"},
    {"inf", "radius_m = 5e6\n" LAYER "gain = -inf\n", 7, 8, "layers[0].gain", "finite"},
    {"zero radius", "radius_m = 0.0\n" LAYER, 1, 12, "radius_m", "must be > 0"},
    {"negative radius", "\n\nradius_m = -6371000\n" LAYER, 3, 12, "radius_m", "must be > 0"},
    {"gain out of range", "radius_m = 5e6\n" LAYER "gain = 1.5\n", 7, 8, "layers[0].gain", "<= 1"},
    {"lacunarity out of range", "radius_m = 5e6\n" LAYER "lacunarity = 1\n", 7, 14, "layers[0].lacunarity", "> 1"},
    {"octaves out of range", "radius_m = 5e6\n[[layers]]\noctaves = 0\nwavelength_m = 1\namplitude_m = 1\n", 3, 11,
     "layers[0].octaves", "[1, 24]"},
    {"octaves wrong type", "radius_m = 5e6\n[[layers]]\noctaves = 2.5\nwavelength_m = 1\namplitude_m = 1\n", 3, 11,
     "layers[0].octaves", "expected an integer, got a float"},
    {"negative amplitude",
     "radius_m = 5e6\n" LAYER "offset_m = 1\n[[layers]]\noctaves = 1\nwavelength_m = 1\n"
     "amplitude_m = -2\n",
     11, 15, "layers[1].amplitude_m", "[0, 1e6]"},
    {"missing radius", LAYER, 1, 1, "radius_m", "missing"},
    {"missing amplitude", "radius_m = 5e6\n[[layers]]\noctaves = 1\nwavelength_m = 1\n", 2, 1, "layers[0].amplitude_m",
     "missing"},
    {"wavelength and frequency", "radius_m = 5e6\n" LAYER "frequency_per_m = 0.1\n", 7, 19, "layers[0].frequency_per_m",
     "not both"},
    // 1 / 4e-320 is infinite: the error names the key in the file, not wavelength_m.
    {"denormal frequency", "radius_m = 5e6\n[[layers]]\noctaves = 1\nfrequency_per_m = 4e-320\namplitude_m = 1\n", 4,
     19, "layers[0].frequency_per_m", "gives wavelength_m = 1 / frequency_per_m, which must be finite"},
    {"unknown kind", "radius_m = 5e6\n" LAYER "kind = \"perlin\"\n", 7, 8, "layers[0].kind", "unknown kind"},
    {"modulator not earlier",
     "radius_m = 5e6\n" LAYER "modulated_by = \"base\"\nmodulation_low_m = 0\n"
     "modulation_high_m = 1\n",
     7, 16, "layers[0].modulated_by", "no earlier layer named 'base'"},
    {"modulation range",
     "radius_m = 5e6\n" LAYER "[[layers]]\noctaves = 1\nwavelength_m = 1\namplitude_m = 1\n"
     "modulated_by = \"base\"\nmodulation_low_m = 10\nmodulation_high_m = 10\n",
     13, 21, "layers[1].modulation_high_m", "> modulation_low_m"},
    {"too many octaves for double",
     "radius_m = 7e7\n[[layers]]\noctaves = 24\nwavelength_m = 1\n"
     "lacunarity = 4\namplitude_m = 1\n",
     3, 11, "layers[0].octaves", "too many octaves"},
    {"negative seed", "seed = -3\nradius_m = 5e6\n" LAYER, 1, 8, "seed", ">= 0"},
    {"layers not tables", "radius_m = 5e6\nlayers = 3\n", 2, 10, "layers", "array of tables"},
    {"duplicate layer name", "radius_m = 5e6\n" LAYER LAYER, 8, 8, "layers[1].name", "duplicate"},
    {"octaves message names the limit",
     "radius_m = 7e7\n[[layers]]\noctaves = 24\nwavelength_m = 1\nlacunarity = 4\namplitude_m = 1\n", 3, 11,
     "layers[0].octaves", "at most 7 octaves here"},
    {"radius too large", "radius_m = 2e9\n" LAYER, 1, 12, "radius_m", "<= 1e+09"},
    {"sea level out of range", "radius_m = 5e6\nsea_level_m = 2e6\n" LAYER, 2, 15, "sea_level_m", "[-1e6, 1e6]"},
    {"terrain deeper than the radius", "radius_m = 1000\n" LAYER, 2, 1, "layers", "deeper than radius_m"},
    {"modulation without modulator", "radius_m = 5e6\n" LAYER "modulation_floor = 0.5\n", 7, 20,
     "layers[0].modulation_floor", "without modulated_by"},
    {"unknown quality", "default_quality = \"ultra\"\nradius_m = 5e6\n" LAYER, 1, 19, "default_quality",
     "fast, balanced, exact"},
    {"misspelt colour_ramp", "radius_m = 5e6\n" LAYER "[[color_ramp]]\n", 7, 3, "color_ramp",
     "did you mean 'colour_ramp'"},
    {"misspelt stop key: the missing key comes first (the table's line), the suggestion next",
     "radius_m = 5e6\n" LAYER "[[colour_ramp]]\nelevation_m = 0\ncolour = [0, 0, 0]\n"
     "[[colour_ramp]]\nelevation = 1\ncolour = [1, 1, 1]\n",
     10, 1, "colour_ramp[1].elevation_m", "missing"},
    {"unknown rock key", "radius_m = 5e6\n" LAYER "[rock]\ncolor = [0, 0, 0]\n", 8, 1, "rock.color",
     "did you mean 'colour'"},
    {"colour not an array", "radius_m = 5e6\n" LAYER "[rock]\ncolour = 0.5\n", 8, 10, "rock.colour",
     "expected an array [r, g, b], got a float"},
    {"colour with 2 components", "radius_m = 5e6\n" LAYER "[rock]\ncolour = [0.5, 0.5]\n", 8, 10, "rock.colour",
     "expected 3 components"},
    {"colour component out of range", "radius_m = 5e6\n" LAYER "[rock]\ncolour = [0.5, 1.5, 0.5]\n", 8, 10,
     "rock.colour", "within [0, 1]"},
    {"colour component nan", "radius_m = 5e6\n" LAYER "[snow]\nelevation_m = 1\ncolour = [0.5, nan, 0.5]\n", 9, 16,
     "snow.colour", "finite"},
    {"stops not increasing",
     "radius_m = 5e6\n" LAYER "[[colour_ramp]]\nelevation_m = 10\ncolour = [0, 0, 0]\n"
     "[[colour_ramp]]\nelevation_m = 10\ncolour = [1, 1, 1]\n",
     11, 15, "colour_ramp[1].elevation_m", "greater than the previous stop's (10 m)"},
    {"one stop", "radius_m = 5e6\n" LAYER "[[colour_ramp]]\nelevation_m = 10\ncolour = [0, 0, 0]\n", 7, 1,
     "colour_ramp", "need 2 to 16 stops"},
    {"stop missing colour", "radius_m = 5e6\n" LAYER "[[colour_ramp]]\nelevation_m = 10\n", 7, 1,
     "colour_ramp[0].colour", "missing"},
    {"rock slope out of range", "radius_m = 5e6\n" LAYER "[rock]\nslope_deg = 95\n", 8, 13, "rock.slope_deg",
     "[0, 90]"},
    {"rock not a table", "radius_m = 5e6\nrock = 3\n" LAYER, 2, 8, "rock", "expected a table ([rock])"},
    {"snow without elevation", "radius_m = 5e6\n" LAYER "[snow]\nblend_m = 10\n", 7, 1, "snow.elevation_m", "missing"},
    // shape = { equatorial_radius_m, flattening } (issue #18).
    {"shape and radius_m", "radius_m = 5e6\nshape = { equatorial_radius_m = 5e6, flattening = 0.1 }\n" LAYER, 2, 9,
     "shape", "not both"},
    {"flattening 0.5", "shape = { equatorial_radius_m = 5e6, flattening = 0.5 }\n" LAYER, 1, 51, "shape.flattening",
     "[0, 0.5)"},
    {"negative flattening", "shape = { equatorial_radius_m = 5e6, flattening = -0.01 }\n" LAYER, 1, 51,
     "shape.flattening", "[0, 0.5)"},
    {"shape radius zero", "shape = { equatorial_radius_m = 0, flattening = 0.1 }\n" LAYER, 1, 33,
     "shape.equatorial_radius_m", "must be > 0"},
    {"shape radius negative", "shape = { equatorial_radius_m = -6e6, flattening = 0.1 }\n" LAYER, 1, 33,
     "shape.equatorial_radius_m", "must be > 0"},
    {"unknown shape key: the missing key comes first (the table's column)",
     "shape = { equatorial_radius_m = 5e6, flatening = 0.1 }\n" LAYER, 1, 9, "shape.flattening", "missing"},
    {"misspelt shape key suggested", "shape = { equatorial_radius_m = 5e6, flattening = 0.1, inverse = 3 }\n" LAYER, 1,
     56, "shape.inverse", "unknown key"},
    {"shape without flattening", "shape = { equatorial_radius_m = 5e6 }\n" LAYER, 1, 9, "shape.flattening", "missing"},
    {"shape not a table", "shape = \"WGS84\"\n" LAYER, 1, 9, "shape", "expected a table"},
    {"flattening not a number", "shape = { equatorial_radius_m = 5e6, flattening = \"1/298\" }\n" LAYER, 1, 51,
     "shape.flattening", "expected a number"},
    {"snow negative blend", "radius_m = 5e6\n" LAYER "[snow]\nelevation_m = 1\nblend_m = -1\n", 9, 11, "snow.blend_m",
     "[0, 1e7]"},
    {"unknown water key", "radius_m = 5e6\n" LAYER "[water]\ncolour = [0, 0, 1]\n", 8, 1, "water.colour",
     "unknown key"},
    {"water depth scale zero", "radius_m = 5e6\n" LAYER "[water]\ndepth_scale_m = 0\n", 8, 17, "water.depth_scale_m",
     "(0, 1e5]"},
    {"water colour out of range", "radius_m = 5e6\n" LAYER "[water]\nshallow_colour = [0, 2, 0]\n", 8, 18,
     "water.shallow_colour", "within [0, 1]"},
    {"water not a table", "radius_m = 5e6\nwater = true\n" LAYER, 2, 9, "water", "expected a table ([water])"},
    {"unknown atmosphere key", "radius_m = 5e6\n" LAYER "[atmosphere]\nthickness = 1\n", 8, 1, "atmosphere.thickness",
     "did you mean 'thickness_m'"},
    {"atmosphere not a table", "radius_m = 5e6\natmosphere = 3\n" LAYER, 2, 14, "atmosphere",
     "expected a table ([atmosphere])"},
    {"atmosphere thickness negative", "radius_m = 5e6\n" LAYER "[atmosphere]\nthickness_m = -5\n", 8, 15,
     "atmosphere.thickness_m", "must be > 0"},
    {"atmosphere coefficient with 2 components",
     "radius_m = 5e6\n" LAYER "[atmosphere]\nrayleigh_scattering_per_m = [1e-6, 1e-6]\n", 8, 29,
     "atmosphere.rayleigh_scattering_per_m", "3 components"},
    {"atmosphere coefficient NaN", "radius_m = 5e6\n" LAYER "[atmosphere]\nozone_absorption_per_m = [1e-6, nan, 0]\n",
     8, 33, "atmosphere.ozone_absorption_per_m", "finite"},
    {"Mie extinction below its scattering",
     "radius_m = 5e6\n" LAYER
     "[atmosphere]\nmie_scattering_per_m = [1e-5, 1e-5, 1e-5]\nmie_extinction_per_m = [1e-6, 1e-5, 1e-5]\n",
     9, 24, "atmosphere.mie_extinction_per_m", ">= mie_scattering_per_m"},
    {"Mie g out of range", "radius_m = 5e6\n" LAYER "[atmosphere]\nmie_g = 1.5\n", 8, 9, "atmosphere.mie_g",
     "[0, 0.999]"},
    {"sun radius zero", "radius_m = 5e6\n" LAYER "[atmosphere]\nsun_angular_radius_deg = 0\n", 8, 26,
     "atmosphere.sun_angular_radius_deg", "> 0"},
};

TEST(PlanetFile, EveryErrorHasFileLineColumnAndKey) {
  for (const BadCase& c : kBadCases) expectBadPlanetCase(c);
}

TEST(PlanetFile, EveryProblemIsReportedAtOnce) {
  // Five independent problems on five lines, plus a broken layer that later layers still see.
  const char* text = R"(radius = 6371000
seed = "one"
[[layers]]
name = "base"
octaves = 30
wavelength_m = 1e6
gain = inf
amplitude_m = 1000
[[layers]]
octaves = 2
wavelength_m = 1e3
amplitude_m = 10
modulated_by = "base"
modulation_low_m = 5
modulation_high_m = 1
[rock]
colour = [2, 0, 0]
)";
  const PlanetFileCheck check = checkPlanetToml(text, "many.toml");
  ASSERT_FALSE(check.ok());
  struct Expected {
    int line;
    int column;
    const char* field;
    const char* message_part;
  };
  const Expected expected[] = {
      {1, 1, "radius", "did you mean 'radius_m'"},
      {1, 1, "radius_m", "missing"},
      {2, 8, "seed", "expected an integer, got a string"},
      {5, 11, "layers[0].octaves", "[1, 24]"},
      {7, 8, "layers[0].gain", "finite"},
      {15, 21, "layers[1].modulation_high_m", "> modulation_low_m"},
      {17, 10, "rock.colour", "within [0, 1]"},
  };
  ASSERT_EQ(check.errors.size(), std::size(expected));
  for (std::size_t i = 0; i < std::size(expected); ++i) {
    SCOPED_TRACE(check.errors[i].format());
    EXPECT_EQ(check.errors[i].file, "many.toml");
    EXPECT_EQ(check.errors[i].line, expected[i].line);
    EXPECT_EQ(check.errors[i].column, expected[i].column);
    EXPECT_EQ(check.errors[i].field, expected[i].field);
    EXPECT_NE(check.errors[i].message.find(expected[i].message_part), std::string::npos);
  }
  // The first-error API reports the first of them.
  const Result<PlanetDescription> first = parsePlanetToml(text, "many.toml");
  ASSERT_FALSE(first.ok());
  EXPECT_EQ(first.error().format(), check.errors.front().format());
}

TEST(PlanetFile, MisspeltKeyIsSuggestedInsideArraysOfTables) {
  const PlanetFileCheck check = checkPlanetToml("radius_m = 5e6\n" LAYER
                                                "[[colour_ramp]]\nelevation_m = 0\ncolour = [0, 0, 0]\n"
                                                "[[colour_ramp]]\nelevation = 1\ncolour = [1, 1, 1]\n",
                                                "bad.toml");
  ASSERT_EQ(check.errors.size(), 2U);
  EXPECT_EQ(check.errors[1].format(),
            "bad.toml:11:1: colour_ramp[1].elevation: unknown key (did you mean 'elevation_m'?)");
}

TEST(PlanetFile, SyntaxErrorIsTheOnlyError) {
  const PlanetFileCheck check = checkPlanetToml("radius_m = 5e6\nseed = [1,\n", "syntax.toml");
  ASSERT_EQ(check.errors.size(), 1U);
  EXPECT_GE(check.errors[0].line, 2);
  EXPECT_TRUE(check.errors[0].field.empty());
}

TEST(PlanetFile, ColourRampAndQualityDefaults) {
  const Result<PlanetDescription> r = parsePlanetToml("radius_m = 5e6\n" LAYER, "plain.toml");
  ASSERT_TRUE(r.ok()) << r.error().format();
  EXPECT_EQ(r->default_quality, QualityPreset::kBalanced);
  EXPECT_EQ(r->colour_ramp.stops, defaultColourRampStops());
  EXPECT_FALSE(r->colour_ramp.snow);
  EXPECT_EQ(r->colour_ramp, ColourRamp{});
}

TEST(PlanetFile, WaterIsReadOnlyFromItsTable) {
  const Result<PlanetDescription> dry = parsePlanetToml("radius_m = 5e6\n" LAYER, "dry.toml");
  ASSERT_TRUE(dry.ok()) << dry.error().format();
  EXPECT_FALSE(dry->water.enabled);  // sea_level_m alone is a datum, not a sea
  const Result<PlanetDescription> r = parsePlanetToml(
      "radius_m = 5e6\nsea_level_m = 12\n" LAYER "[water]\ndeep_colour = [0, 0, 0.5]\ndepth_scale_m = 7\n", "wet.toml");
  ASSERT_TRUE(r.ok()) << r.error().format();
  EXPECT_TRUE(r->water.enabled);
  EXPECT_EQ(r->water.deep_colour, glm::vec3(0.0f, 0.0f, 0.5f));
  EXPECT_EQ(r->water.shallow_colour, Water{}.shallow_colour);
  EXPECT_EQ(r->water.depth_scale_m, 7.0);
  const Result<PlanetDescription> again = parsePlanetToml(formatPlanetToml(*r), "again.toml");
  ASSERT_TRUE(again.ok()) << again.error().format();
  EXPECT_EQ(again->water, r->water);
  const ElevationModel model(*r);
  EXPECT_TRUE(model.drawsWater());
  const glm::dvec3 up(0.0, 0.0, 1.0);
  EXPECT_EQ(model.visibleElevation_m(up), std::max(model.elevation_m(up), 12.0));
}

TEST(PlanetFile, ColourRampIsRead) {
  const char* text = "radius_m = 5e6\ndefault_quality = \"fast\"\n" LAYER
                     "[[colour_ramp]]\nelevation_m = -10\ncolour = [0, 0, 1]\n"
                     "[[colour_ramp]]\nelevation_m = 10\ncolour = [0, 1, 0]\n"
                     "[rock]\nslope_deg = 40\nblend_deg = 0\ncolour = [0.5, 0.5, 0.5]\n"
                     "[snow]\nelevation_m = 5\nblend_m = 1\nmax_slope_deg = 30\ncolour = [1, 1, 1]\n";
  const Result<PlanetDescription> r = parsePlanetToml(text, "ramp.toml");
  ASSERT_TRUE(r.ok()) << r.error().format();
  EXPECT_EQ(r->default_quality, QualityPreset::kFast);
  const ColourRamp& ramp = r->colour_ramp;
  ASSERT_EQ(ramp.stops.size(), 2U);
  EXPECT_EQ(ramp.stops[0].elevation_m, -10.0);
  EXPECT_EQ(ramp.stops[1].colour, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(ramp.rock_slope_deg, 40.0);
  EXPECT_EQ(ramp.rock_blend_deg, 0.0);
  EXPECT_TRUE(ramp.snow);
  EXPECT_EQ(ramp.snow_max_slope_deg, 30.0);

  const gpu::ColourRampParams p = packColourRamp(ramp);
  EXPECT_EQ(p.stop_count, 2U);
  EXPECT_EQ(p.rock_inv_range, 1e30f);  // blend 0: a hard edge, no division by zero
  EXPECT_FLOAT_EQ(p.rock_cos_start, static_cast<float>(std::cos(40.0 * std::numbers::pi / 180.0)));
  EXPECT_EQ(p.snow_enabled, 1U);
  EXPECT_FLOAT_EQ(p.snow_inv_blend, 1.0f);
  // The reference evaluation: stops, interpolation, clamping, rock, snow.
  const double flat = 1.0;
  const double steep = std::cos(60.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(rampColour(p, -10.0, flat), glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(rampColour(p, -1000.0, flat), glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(rampColour(p, 0.0, flat), glm::vec3(0.0f, 0.5f, 0.5f));
  EXPECT_EQ(rampColour(p, 0.0, steep), glm::vec3(0.5f, 0.5f, 0.5f));   // rock above 40 degrees
  EXPECT_EQ(rampColour(p, 100.0, flat), glm::vec3(1.0f, 1.0f, 1.0f));  // snow above 5 + 1 m
  const glm::vec3 half_snow = rampColour(p, 5.5, flat);                // base (0, 0.775, 0.225), half snow
  EXPECT_NEAR(half_snow.x, 0.5f, 1e-6f);
  EXPECT_NEAR(half_snow.y, 0.8875f, 1e-6f);
  EXPECT_NEAR(half_snow.z, 0.6125f, 1e-6f);
  EXPECT_EQ(rampColour(p, 100.0, steep), glm::vec3(0.5f, 0.5f, 0.5f));  // too steep for snow
}

TEST(PlanetFile, QualityPresetNames) {
  EXPECT_EQ(qualityPresetName(QualityPreset::kFast), "fast");
  EXPECT_EQ(qualityPresetName(QualityPreset::kBalanced), "balanced");
  EXPECT_EQ(qualityPresetName(QualityPreset::kExact), "exact");
}

const char* const kPresets[] = {"earthlike", "marslike", "moonlike", "asteroid", "gasgiant-core"};

std::string presetPath(const char* name) { return std::string(GLOBE_SOURCE_DIR) + "/assets/planets/" + name + ".toml"; }

TEST(PlanetPresets, EveryPresetLoadsAndRoundTrips) {
  for (const char* name : kPresets) {
    SCOPED_TRACE(name);
    const PlanetFileCheck check = checkPlanetFile(presetPath(name));
    for (const Error& e : check.errors) ADD_FAILURE() << e.format();
    ASSERT_TRUE(check.ok());
    const PlanetDescription& p = check.planet;
    EXPECT_EQ(p.name, name);
    EXPECT_TRUE(validatePlanet(p).ok());
    EXPECT_GE(p.colour_ramp.stops.size(), 3U);  // every preset has its own ramp
    // Written back and read again: the same description, the same GPU bytes.
    const std::string text = formatPlanetToml(p);
    const Result<PlanetDescription> again = parsePlanetToml(text, "roundtrip.toml");
    ASSERT_TRUE(again.ok()) << again.error().format() << "\n" << text;
    EXPECT_EQ(*again, p) << text;
    const gpu::ElevationParams a = packElevationParams(p);
    const gpu::ElevationParams b = packElevationParams(*again);
    EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
    const gpu::ColourRampParams ca = packColourRamp(p.colour_ramp);
    const gpu::ColourRampParams cb = packColourRamp(again->colour_ramp);
    EXPECT_EQ(std::memcmp(&ca, &cb, sizeof ca), 0);
    const gpu::LandCoverParams la = packLandCover(p.land_cover, p.radius_m, p.seed, p.sea_level_m);
    const gpu::LandCoverParams lb = packLandCover(again->land_cover, again->radius_m, again->seed, again->sea_level_m);
    EXPECT_EQ(std::memcmp(&la, &lb, sizeof la), 0);
    EXPECT_EQ(formatPlanetToml(*again), text);
  }
}

// An ellipsoid's shape is read, validated and written back: WGS84's flattening survives the writer to
// the last bit, and a sphere keeps writing radius_m.
TEST(PlanetFile, ShapeRoundTripsThroughTheWriter) {
  const std::string text =
      "name = \"wgs84\"\nshape = { equatorial_radius_m = 6378137.0, flattening = "
      "0.0033528106647474805 }\n" LAYER;
  const Result<PlanetDescription> p = parsePlanetToml(text, "wgs84.toml");
  ASSERT_TRUE(p.ok()) << p.error().format();
  EXPECT_EQ(p->radius_m, 6378137.0);
  EXPECT_EQ(p->flattening, 1.0 / 298.257223563);
  EXPECT_EQ(planetShape(*p).polarRadius_m(), Ellipsoid::wgs84().polarRadius_m());
  const std::string written = formatPlanetToml(*p);
  EXPECT_NE(written.find("shape = { equatorial_radius_m = 6378137, flattening = 0.0033528106647474805 }"),
            std::string::npos)
      << written;
  EXPECT_EQ(written.find("\nradius_m ="), std::string::npos) << written;
  const Result<PlanetDescription> again = parsePlanetToml(written, "again.toml");
  ASSERT_TRUE(again.ok()) << again.error().format();
  EXPECT_EQ(*again, *p);
  const gpu::ElevationParams a = packElevationParams(*p), b = packElevationParams(*again);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  EXPECT_EQ(a.polar_radius_m, 6378137.0 * (1.0 - 1.0 / 298.257223563));
  EXPECT_EQ(elevationSpecialization(a)[GLOBE_ELEVATION_SPEC_ELLIPSOID], 1U);
  // Flattening 0 in a shape is a sphere, written as radius_m.
  const Result<PlanetDescription> sphere =
      parsePlanetToml("shape = { equatorial_radius_m = 5e6, flattening = 0 }\n" LAYER, "sphere.toml");
  ASSERT_TRUE(sphere.ok()) << sphere.error().format();
  EXPECT_NE(formatPlanetToml(*sphere).find("radius_m = 5000000\n"), std::string::npos);
  const gpu::ElevationParams s = packElevationParams(*sphere);
  EXPECT_EQ(s.polar_radius_m, s.radius_m);
  EXPECT_EQ(elevationSpecialization(s)[GLOBE_ELEVATION_SPEC_ELLIPSOID], 0U);
}

TEST(PlanetFile, EarthDemIsOnWgs84) {
  const Result<PlanetDescription> p = loadPlanetFile(presetPath("earth-dem"));
  ASSERT_TRUE(p.ok()) << p.error().format();
  EXPECT_EQ(p->radius_m, 6378137.0);
  EXPECT_EQ(p->flattening, 1.0 / 298.257223563);
}

TEST(PlanetPresets, AtmospheresWhereThereIsAir) {
  // Earth's values (the reference implementation's defaults) on the earthlike planet, air on Mars
  // and the gas giant, none on the Moon and the asteroid (black sky, hard light).
  for (const char* name : kPresets) {
    SCOPED_TRACE(name);
    auto planet = loadPlanetFile(presetPath(name));
    ASSERT_TRUE(planet.ok());
    const std::string n = name;
    EXPECT_EQ(planet->atmosphere.has_value(), n == "earthlike" || n == "marslike" || n == "gasgiant-core");
    if (n == "earthlike") {
      EXPECT_EQ(*planet->atmosphere, AtmosphereParameters{});
    }
  }
  // No [atmosphere] section: no atmosphere; an empty one: Earth's.
  auto bare =
      parsePlanetToml("radius_m = 5e6\n[[layers]]\noctaves = 1\nwavelength_m = 1e6\namplitude_m = 1\n", "a.toml");
  ASSERT_TRUE(bare.ok());
  EXPECT_FALSE(bare->atmosphere.has_value());
  auto empty = parsePlanetToml(
      "radius_m = 5e6\n[[layers]]\noctaves = 1\nwavelength_m = 1e6\namplitude_m = 1\n[atmosphere]\n", "b.toml");
  ASSERT_TRUE(empty.ok()) << empty.error().format();
  EXPECT_EQ(empty->atmosphere, AtmosphereParameters{});
}

TEST(PlanetPresets, RadiiAndPrecisionMargins) {
  struct Case {
    const char* name;
    double radius_m;
  };
  const Case cases[] = {{"earthlike", 6371000.0},
                        {"marslike", 3389500.0},
                        {"moonlike", 1737400.0},
                        {"asteroid", 1000.0},
                        {"gasgiant-core", 7.0e7}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Result<PlanetDescription> r = loadPlanetFile(presetPath(c.name));
    ASSERT_TRUE(r.ok()) << r.error().format();
    EXPECT_EQ(r->radius_m, c.radius_m);
    // The terrain stays well clear of the centre (the asteroid trap).
    EXPECT_GT(elevationBounds(*r).min_m, -0.5 * r->radius_m);
  }
  // The stress case sits just under the precision limit: one more detail octave is refused.
  Result<PlanetDescription> giant = loadPlanetFile(presetPath("gasgiant-core"));
  ASSERT_TRUE(giant.ok());
  ElevationLayer& detail = giant->layers.back();
  EXPECT_EQ(maxOctavesForPrecision(giant->radius_m, detail), detail.octaves);
  detail.octaves += 1;
  const Status s = validatePlanet(*giant);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "layers[2].octaves");
}

TEST(PlanetDescription, ValidateRejectsProgrammaticMistakes) {
  PlanetDescription p;
  p.layers = {ElevationLayer{}};
  EXPECT_TRUE(validatePlanet(p).ok());
  p.radius_m = -1.0;
  EXPECT_EQ(validatePlanet(p).error().field, "radius_m");
  p.radius_m = 1000.0;
  p.layers[0].modulated_by = 0;  // itself
  EXPECT_EQ(validatePlanet(p).error().field, "layers[0].modulated_by");
  p.layers[0].modulated_by = -1;
  p.layers.resize(9);
  EXPECT_EQ(validatePlanet(p).error().field, "layers");
}

}  // namespace
}  // namespace globe
