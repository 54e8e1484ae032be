// Terrain warnings in the options a person sets (issue 37 item 8: a budget hit says what to do, in
// the user's terms).
#include "engine/render/terrain_warnings.h"

#include <gtest/gtest.h>

namespace globe {
namespace {

TEST(TerrainWarnings, NameTheOptionsThatActOnThem) {
  EXPECT_EQ(inOptionTerms("payload pool exhausted (100 slots): drawing coarser terrain; raise the VRAM budget"),
            "payload pool exhausted (100 slots): drawing coarser terrain; raise --vram-mib");
  EXPECT_EQ(inOptionTerms("imagery tiles: payload pool exhausted (9 slots): drawing coarser terrain; raise the "
                          "imagery budget (at most 4 pages' worth)"),
            "imagery tiles: payload pool exhausted (9 slots): drawing coarser terrain; raise --imagery-mib (at most 4 "
            "pages' worth)");
  EXPECT_EQ(inOptionTerms("node pool full (5 nodes): drawing coarser terrain; raise the RAM budget"),
            "node pool full (5 nodes): drawing coarser terrain; use a larger --tolerance or a coarser --quality");
  EXPECT_EQ(inOptionTerms("frame budget reached (300 nodes, 16000000 triangles): drawing coarser terrain (levels up "
                          "to 9 of 24)"),
            "frame budget reached (300 nodes, 16000000 triangles): drawing coarser terrain (levels up to 9 of 24); "
            "raise --max-nodes or --max-triangles, or use a larger --tolerance");
  EXPECT_EQ(inOptionTerms("generation failed"), "generation failed");
}

}  // namespace
}  // namespace globe
