// The API's bodies are read by the scenario's strict reader: the same mistakes refused the same way.
#include "control/request_body.h"

#include <gtest/gtest.h>

#include <functional>

namespace control {
namespace {

std::string refusal(const std::function<void()>& read) {
  try {
    read();
  } catch (const BodyError& e) {
    return e.reason;
  }
  return "(accepted)";
}

TEST(RequestBody, ReadsTypedFieldsAndDefaults) {
  RequestBody b(R"({"index": "0x6040", "sub": 1, "speed": 2.5, "rtr": true, "name": "dsv"})", "the request");
  EXPECT_EQ(b.integer("index", 0, 0xFFFF), 0x6040);
  EXPECT_EQ(b.integer_or("sub", 0, 255), 1);
  EXPECT_DOUBLE_EQ(*b.number_or("speed"), 2.5);
  EXPECT_TRUE(b.flag_or("rtr", false));
  EXPECT_EQ(b.text("name"), "dsv");
  EXPECT_FALSE(b.integer_or("dlc", 0, 8).has_value());
  EXPECT_EQ(refusal([&] { b.finish(); }), "(accepted)");
}

TEST(RequestBody, AMisspeltOptionalKeyIsRefusedWithWhereAndTheKnownKeys) {
  RequestBody b(R"({"index": 24640, "subindex": 1})", "the SDO read");
  b.integer("index", 0, 0xFFFF);
  b.integer_or("sub", 0, 255);
  EXPECT_EQ(refusal([&] { b.finish(); }), "<body>:1:18: unknown key 'subindex' in the SDO read (known: index, sub)");
}

TEST(RequestBody, WrongTypesAndRangesNameTheFieldAndItsPlace) {
  {
    RequestBody b(R"({"index": "six"})", "the SDO read");
    EXPECT_EQ(refusal([&] { b.integer("index", 0, 0xFFFF); }), "<body>:1:11: index: 'six' is not an integer");
  }
  {
    RequestBody b(R"({"index": 70000})", "the SDO read");
    EXPECT_EQ(refusal([&] { b.integer("index", 0, 0xFFFF); }), "<body>:1:11: index: value 70000 out of range [0, 65535]");
  }
  {
    RequestBody b("{\n  \"speed\": [1]\n}", "the clock action");
    EXPECT_EQ(refusal([&] { b.number("speed"); }).substr(0, 12), "<body>:2:12:");
  }
  {
    RequestBody b("{}", "the NMT command");
    EXPECT_EQ(refusal([&] { b.text("command"); }), "<body>:1:1: the NMT command: missing key 'command'");
  }
}

TEST(RequestBody, OnlyOneJsonObjectIsABody) {
  EXPECT_EQ(refusal([] { RequestBody("{a: 1}", "x"); }), "malformed JSON body");  // YAML, not JSON
  EXPECT_EQ(refusal([] { RequestBody("[1, 2]", "x"); }), "the body must be a JSON object");
  EXPECT_EQ(refusal([] { RequestBody("{\"a\": \"\xff\"}", "x"); }), "malformed JSON body");  // not UTF-8
  EXPECT_EQ(refusal([] { RequestBody(R"({"a": 1, "a": 2})", "the frame"); }), "<body>:1:10: the frame: duplicate key 'a'");
}

TEST(RequestBody, NodeOrAllTakesANameZeroOrNull) {
  RequestBody nmt(R"({"a": "dsv", "b": 0, "c": "0", "d": 5, "e": null})", "the NMT command");
  EXPECT_EQ(nmt.node_or_all("a", false), "dsv");
  EXPECT_EQ(nmt.node_or_all("b", false), std::nullopt);
  EXPECT_EQ(nmt.node_or_all("c", false), "0");  // quoted: a name, which the caller looks up
  EXPECT_EQ(refusal([&] { nmt.node_or_all("d", false); }), "<body>:1:37: d: a node's name or 0");
  EXPECT_EQ(refusal([&] { nmt.node_or_all("e", false); }), "<body>:1:45: e: a node's name or 0");
  RequestBody stream(R"({"node": null})", "the stream's node");
  EXPECT_EQ(stream.node_or_all("node", true), std::nullopt);
}

TEST(RequestBody, BytesAndLiteralsAsAScenarioWritesThem) {
  RequestBody b(R"({"data": "0f 00", "long": "00112233445566778899", "value": 15, "real": 0.5, "text": "15"})", "the frame");
  EXPECT_EQ(b.bytes("data", 0, 8), (std::vector<std::uint8_t>{0x0F, 0x00}));
  EXPECT_EQ(refusal([&] { b.bytes("long", 0, 8); }), "<body>:1:27: long: 10 bytes, expected 0..8");
  EXPECT_EQ(b.literal("value").kind, scenario::Literal::Kind::Integer);
  EXPECT_EQ(b.literal("real").kind, scenario::Literal::Kind::Real);
  EXPECT_EQ(b.literal("text").kind, scenario::Literal::Kind::Text);
}

}  // namespace
}  // namespace control
