// The one strict YAML reader (plant, scenarios, exercises, HTTP bodies): unknown and duplicate
// keys, typed scalars with ranges, each reported at its node.
#include "sim/yaml_fields.h"

#include <gtest/gtest.h>

#include <string>

namespace sim {
namespace {

// The error text of `f`, which must throw.
template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const DiagnosticError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(YamlFields, AMappingRejectsUnknownAndDuplicateKeysAtTheKey) {
  const auto doc = parse_yaml("a: 1\nb: 2\nc: 3\n", "f.yaml");
  MapReader r(doc, "f.yaml", "thing");
  EXPECT_TRUE(r.get("a"));
  EXPECT_TRUE(r.require("b"));
  EXPECT_EQ(error_of([&] { r.finish(); }), "f.yaml:3:1: unknown key 'c' in thing (known: a, b)");
  EXPECT_EQ(error_of([&] { r.require("d"); }), "f.yaml:1:1: thing: missing key 'd'");
  EXPECT_EQ(error_of([] { MapReader(parse_yaml("a: 1\na: 2\n", "g.yaml"), "g.yaml", "thing"); }),
            "g.yaml:2:1: thing: duplicate key 'a'");
  EXPECT_EQ(error_of([] { MapReader(parse_yaml("[1]\n", "h.yaml"), "h.yaml", "thing"); }),
            "h.yaml:1:1: thing: expected a mapping of keys");
}

TEST(YamlFields, ScalarsAreTypedAndRangeChecked) {
  const auto doc = parse_yaml("n: 0x10\nx: 2.5\nd: 10ms\nb: on\nw: ten\n", "v.yaml");
  EXPECT_EQ(read_integer(doc["n"], "v.yaml", "n", 0, 100), 16);
  EXPECT_EQ(read_number(doc["x"], "v.yaml", "x", 0, 5), 2.5);
  EXPECT_EQ(read_duration(doc["d"], "v.yaml", "d"), milliseconds(10));
  EXPECT_TRUE(read_bool(doc["b"], "v.yaml", "b"));
  EXPECT_EQ(error_of([&] { read_integer(doc["n"], "v.yaml", "n", 0, 10); }), "v.yaml:1:4: n: value 0x10 out of range [0, 10]");
  EXPECT_EQ(error_of([&] { read_number(doc["x"], "v.yaml", "x", 0, 1); }), "v.yaml:2:4: x: value 2.5 out of range [0, 1]");
  EXPECT_EQ(error_of([&] { read_number(doc["w"], "v.yaml", "w"); }), "v.yaml:5:4: w: 'ten' is not a number");
}

TEST(YamlFields, ASyntaxErrorIsPlaced) {
  EXPECT_EQ(error_of([] { parse_yaml("a: [1,\n", "s.yaml"); }), "s.yaml:2:1: YAML syntax error: end of sequence flow not found");
}

}  // namespace
}  // namespace sim
