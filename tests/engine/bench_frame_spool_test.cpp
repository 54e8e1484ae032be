// The benchmark's row spool: rows come back in order, the heap does not grow with the number of
// rows, the file leaves nothing in the directory, and a full disk is one Error naming it. No GPU.
#include "engine/report/bench_frame_spool.h"
#include "planet/core/fault_injection.h"

#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <filesystem>

namespace globe {
namespace {

using testing::TempDir;

BenchFrame row(uint64_t k) {
  BenchFrame f;
  f.frame = k;
  f.t_s = double(k) / 60.0;
  f.altitude_m = 1000.0 + double(k);
  f.stats.frame_ms = 10.0 + double(k % 7);
  f.stats.triangles = k * 3;
  return f;
}

TEST(BenchFrameSpool, RowsComeBackInOrder) {
  TempDir dir("spool_order");
  BenchFrameSpool spool;
  ASSERT_TRUE(spool.open(dir.str()).ok());
  for (uint64_t k = 0; k < 1000; ++k) ASSERT_TRUE(spool.append(row(k)).ok());
  auto rows = spool.rows();
  ASSERT_TRUE(rows.ok()) << rows.error().format();
  ASSERT_EQ(rows->size(), 1000u);
  for (uint64_t k = 0; k < 1000; ++k) {
    EXPECT_EQ((*rows)[k].frame, k);
    EXPECT_EQ((*rows)[k].altitude_m, 1000.0 + double(k));
    EXPECT_EQ((*rows)[k].stats.triangles, k * 3);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.str())) << "the spool is an unnamed file";
}

// An hour at 60 Hz: the heap holds the buffer, not the rows.
TEST(BenchFrameSpool, HeapDoesNotGrowWithTheRows) {
  TempDir dir("spool_heap");
  BenchFrameSpool spool;
  ASSERT_TRUE(spool.open(dir.str()).ok());
  ASSERT_TRUE(spool.append(row(0)).ok());
  const std::size_t before = mallinfo2().uordblks;
  for (uint64_t k = 1; k < 216000; ++k) ASSERT_TRUE(spool.append(row(k)).ok());
  const std::size_t after = mallinfo2().uordblks;
  EXPECT_LT(after, before + (64u << 10)) << "216000 rows of " << sizeof(BenchFrame) << " bytes grew the heap by "
                                         << (after - before) << " bytes";
  auto rows = spool.rows();
  ASSERT_TRUE(rows.ok());
  EXPECT_EQ(rows->back().frame, 215999u);
}

TEST(BenchFrameSpool, FullDiskIsOneErrorNamingTheDirectory) {
  TempDir dir("spool_full");
  ::setenv("GLOBE_FAULT", "write@1", 1);
  resetFaultInjection();
  BenchFrameSpool spool;
  ASSERT_TRUE(spool.open(dir.str()).ok());
  Status status = Ok{};
  for (uint64_t k = 0; k < 1000 && status.ok(); ++k) status = spool.append(row(k));
  ::unsetenv("GLOBE_FAULT");
  resetFaultInjection();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().format(), dir.str() + ": cannot write the benchmark's rows: No space left on device");
}

TEST(BenchFrameSpool, MissingDirectoryIsAnError) {
  BenchFrameSpool spool;
  Status opened = spool.open("/nonexistent/globe-spool");
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.error().format().find("/nonexistent/globe-spool: cannot create the benchmark's row file"),
            std::string::npos)
      << opened.error().format();
}

}  // namespace
}  // namespace globe
