// planet_tests' main: GoogleTest, with GDAL and OGR installed as the readers of real data (as the
// globe program does), so that the tests of sources, imagery and vectors read their fixtures.
#include "planet/gdal/gdal_readers.h"

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  globe::installGdalReaders();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
