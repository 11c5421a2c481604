// The one diagnostic's text: as much of `file:line:col: reason` as is known.
#include "sim/diagnostic.h"

#include <gtest/gtest.h>

namespace sim {
namespace {

TEST(Diagnostic, PrintsTheKnownPartOfTheMark) {
  EXPECT_EQ((Diagnostic{{"a.yaml", 3, 7}, "bad"}).to_string(), "a.yaml:3:7: bad");
  EXPECT_EQ((Diagnostic{{"a.eds", 12, 0}, "bad"}).to_string(), "a.eds:12: bad");  // a line-based format
  EXPECT_EQ((Diagnostic{{"a.eds", 0, 0}, "cannot open"}).to_string(), "a.eds: cannot open");
  EXPECT_EQ((Diagnostic{{}, "built in code"}).to_string(), "built in code");
  EXPECT_EQ((Diagnostic{{"a.eds", 4, 0}, "odd", true}).to_string(), "a.eds:4: warning: odd");
}

TEST(DiagnosticError, CarriesTheDiagnosticAndPrintsIt) {
  try {
    throw DiagnosticError(SourceMark{"s.yaml", 2, 5}, "unknown key 'x'");
  } catch (const DiagnosticError& e) {
    EXPECT_STREQ(e.what(), "s.yaml:2:5: unknown key 'x'");
    EXPECT_EQ(e.mark().line, 2);
    EXPECT_EQ(e.mark().column, 5);
    EXPECT_EQ(e.reason(), "unknown key 'x'");
    EXPECT_FALSE(e.diagnostic().warning);
  }
}

}  // namespace
}  // namespace sim
