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

TEST(Error, EscapesControlCharacters) {
  // A planet named "\x1b]0;pwned\x07" must not reach the terminal as an escape sequence.
  Error e{"f", 0, 0, "name", "bad \x1b]0;x\x07 and\ttab"};
  EXPECT_EQ(e.format(), "f: name: bad \\x1b]0;x\\x07 and\\x09tab");
}

TEST(Error, EscapeControlCharactersLeavesOtherTextAlone) {
  EXPECT_EQ(escapeControlCharacters("Terra \xc3\xa9 1"), "Terra \xc3\xa9 1");  // UTF-8 stays
  EXPECT_EQ(escapeControlCharacters("a\x1b[2Jb\x7f"), "a\\x1b[2Jb\\x7f");
  EXPECT_EQ(escapeControlCharacters("\xce\x94"
                                    "E \xc2\xb1 \xf0\x9f\x8c\x8d"),
            "\xce\x94"
            "E \xc2\xb1 \xf0\x9f\x8c\x8d");  // ΔE ± (globe)
}

// Bytes that are not UTF-8, echoed from a hostile file, reached the terminal raw (issue 40).
TEST(Error, EscapesBytesThatAreNotUtf8) {
  EXPECT_EQ(escapeControlCharacters("a\xff\xfe"
                                    "b"),
            "a\\xff\\xfe"
            "b");
  EXPECT_EQ(escapeControlCharacters("cut \xc3"), "cut \\xc3");                     // a sequence cut short
  EXPECT_EQ(escapeControlCharacters("\xc0\xaf"), "\\xc0\\xaf");                    // an overlong '/'
  EXPECT_EQ(escapeControlCharacters("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // a surrogate
  EXPECT_EQ(escapeControlCharacters("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(escapeControlCharacters("\xe2\x82"), "\\xe2\\x82");
}

TEST(Error, ListIsCappedWithACountOfTheRest) {
  std::vector<Error> errors(25, Error{"f", 1, 0, "k", "unknown key"});
  const std::vector<std::string> lines = formatErrorList(errors, 20);
  ASSERT_EQ(lines.size(), 21U);
  EXPECT_EQ(lines[0], "f:1: k: unknown key");
  EXPECT_EQ(lines.back(), "\u2026 and 5 more");
  EXPECT_EQ(formatErrorList(std::vector<Error>(3, errors[0]), 20).size(), 3U);
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
