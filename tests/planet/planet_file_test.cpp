// TOML planet files: the earthlike preset loads; every bad input gives file:line:column and the key.
#include <gtest/gtest.h>
#include <string>

#include "planet/elevation.h"
#include "planet/planet_file.h"

namespace globe {
namespace {

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
  EXPECT_EQ(p.layers[1].kind, LayerKind::Ridged);
  EXPECT_EQ(p.layers[1].modulated_by, 0);
  EXPECT_EQ(p.layers[2].modulated_by, 0);
  // Twelve octaves like the primary source: 4 continent octaves modulating 8 detail octaves.
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
  EXPECT_EQ(r->layers[0].kind, LayerKind::Fbm);
  EXPECT_EQ(r->layers[0].modulated_by, -1);
}

TEST(PlanetFile, MissingFileIsAnError) {
  const Result<PlanetDescription> r = loadPlanetFile("/nonexistent/planet.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "/nonexistent/planet.toml");
  EXPECT_NE(r.error().message.find("cannot open"), std::string::npos);
}

struct BadCase {
  const char* what;
  const char* text;
  int line;
  int column;
  const char* field;
  const char* message_part;
};

// A valid layer, appended where a case needs one (lines 1-5 of the layer part).
#define LAYER "[[layers]]\nname = \"base\"\noctaves = 4\nwavelength_m = 1e6\namplitude_m = 1000\n"

const BadCase kBadCases[] = {
    {"syntax error", "radius_m = \n" LAYER, 1, 12, "", ""},
    {"unknown top-level key", "radius = 5\n" LAYER, 1, 1, "radius", "did you mean 'radius_m'"},
    {"unknown layer key", "radius_m = 5\n" LAYER "octave_count = 3\n", 7, 1, "layers[0].octave_count", "unknown key"},
    {"wrong type", "radius_m = \"big\"\n" LAYER, 1, 12, "radius_m", "expected a number, got a string"},
    {"nan", "radius_m = nan\n" LAYER, 1, 12, "radius_m", "finite"},
    {"inf", "radius_m = 5\n" LAYER "gain = -inf\n", 7, 8, "layers[0].gain", "finite"},
    {"zero radius", "radius_m = 0.0\n" LAYER, 1, 12, "radius_m", "must be > 0"},
    {"negative radius", "\n\nradius_m = -6371000\n" LAYER, 3, 12, "radius_m", "must be > 0"},
    {"gain out of range", "radius_m = 5\n" LAYER "gain = 1.5\n", 7, 8, "layers[0].gain", "<= 1"},
    {"lacunarity out of range", "radius_m = 5\n" LAYER "lacunarity = 1\n", 7, 14, "layers[0].lacunarity", "> 1"},
    {"octaves out of range", "radius_m = 5\n[[layers]]\noctaves = 0\nwavelength_m = 1\namplitude_m = 1\n", 3, 11,
     "layers[0].octaves", "[1, 24]"},
    {"octaves wrong type", "radius_m = 5\n[[layers]]\noctaves = 2.5\nwavelength_m = 1\namplitude_m = 1\n", 3, 11,
     "layers[0].octaves", "expected an integer, got a float"},
    {"negative amplitude",
     "radius_m = 5\n" LAYER "offset_m = 1\n[[layers]]\noctaves = 1\nwavelength_m = 1\n"
     "amplitude_m = -2\n",
     11, 15, "layers[1].amplitude_m", "[0, 1e6]"},
    {"missing radius", LAYER, 1, 1, "radius_m", "missing"},
    {"missing amplitude", "radius_m = 5\n[[layers]]\noctaves = 1\nwavelength_m = 1\n", 2, 1, "layers[0].amplitude_m",
     "missing"},
    {"wavelength and frequency", "radius_m = 5\n" LAYER "frequency_per_m = 0.1\n", 7, 19, "layers[0].frequency_per_m",
     "not both"},
    {"unknown kind", "radius_m = 5\n" LAYER "kind = \"perlin\"\n", 7, 8, "layers[0].kind", "unknown kind"},
    {"modulator not earlier",
     "radius_m = 5\n" LAYER "modulated_by = \"base\"\nmodulation_low_m = 0\n"
     "modulation_high_m = 1\n",
     7, 16, "layers[0].modulated_by", "no earlier layer named 'base'"},
    {"modulation range",
     "radius_m = 5\n" LAYER "[[layers]]\noctaves = 1\nwavelength_m = 1\namplitude_m = 1\n"
     "modulated_by = \"base\"\nmodulation_low_m = 10\nmodulation_high_m = 10\n",
     13, 21, "layers[1].modulation_high_m", "> modulation_low_m"},
    {"too many octaves for double",
     "radius_m = 7e7\n[[layers]]\noctaves = 24\nwavelength_m = 1\n"
     "lacunarity = 4\namplitude_m = 1\n",
     3, 11, "layers[0].octaves", "too many octaves"},
    {"negative seed", "seed = -3\nradius_m = 5\n" LAYER, 1, 8, "seed", ">= 0"},
    {"layers not tables", "radius_m = 5\nlayers = 3\n", 2, 10, "layers", "array of tables"},
    {"duplicate layer name", "radius_m = 5\n" LAYER LAYER, 8, 8, "layers[1].name", "duplicate"},
};

TEST(PlanetFile, EveryErrorHasFileLineColumnAndKey) {
  for (const BadCase& c : kBadCases) {
    SCOPED_TRACE(c.what);
    const Result<PlanetDescription> r = parsePlanetToml(c.text, "bad.toml");
    ASSERT_FALSE(r.ok());
    const Error& e = r.error();
    EXPECT_EQ(e.file, "bad.toml");
    EXPECT_EQ(e.line, c.line) << e.format();
    EXPECT_EQ(e.column, c.column) << e.format();
    EXPECT_EQ(e.field, c.field) << e.format();
    EXPECT_NE(e.message.find(c.message_part), std::string::npos) << e.format();
    EXPECT_EQ(e.format().find('\n'), std::string::npos);
  }
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
