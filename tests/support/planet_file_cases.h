#pragma once
// Table rows of bad planet files and their one expected error (file, line, column, field, message),
// shared by the planet-file tests.
#include "planet/model/planet_file.h"

#include <gtest/gtest.h>

#include <string>

namespace globe::testing {

struct BadPlanetCase {
  const char* what;
  std::string text;
  int line;
  int column;
  const char* field;
  const char* message_part;  // a part of the message
};

// Parsing `c.text` as "bad.toml" fails with exactly the error the row gives, on one line.
inline void expectBadPlanetCase(const BadPlanetCase& c) {
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

}  // namespace globe::testing
