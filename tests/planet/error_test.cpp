#include "planet/core/error.h"

#include <gtest/gtest.h>

namespace globe {
namespace {

TEST(Error, FormatsFileLineColumnFieldMessage) {
  Error e{"a.toml", 3, 7, "radius", "must be > 0"};
  EXPECT_EQ(e.format(), "a.toml:3:7: radius: must be > 0");
  EXPECT_EQ((Error{"", 0, 0, "--size", "expected WxH"}).format(), "--size: expected WxH");
  EXPECT_EQ((Error{"p.txt", 2, 0, "", "bad"}).format(), "p.txt:2: bad");
}

TEST(Error, IsAlwaysOneLine) {
  Error e{"f", 1, 1, "k", "a\nb"};
  EXPECT_EQ(e.format().find('\n'), std::string::npos);
}

TEST(Result, HoldsValueOrError) {
  Result<int> a = 4;
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(*a, 4);
  Result<int> b = Error{"", 0, 0, "", "nope"};
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.error().message, "nope");
}

}  // namespace
}  // namespace globe
