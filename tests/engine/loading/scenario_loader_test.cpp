// The YAML format: every section read into the model, signal expressions, frame patterns,
// durations.
#include <gtest/gtest.h>

#include "engine/loading/frame_pattern.h"
#include "engine/loading/scenario_loader.h"
#include "engine/loading/signal_expression.h"
#include "engine/running/world.h"

using namespace scenario;

TEST(ScenarioLoader, ReadsEverySection) {
  const auto s = parse_scenario(R"(
name: demo
description: all sections
buses:
  - {name: main, transport: virtual, bitrate: 250000}
  - {name: aux, transport: "socketcan:vcan1"}
nodes:
  - name: ax
    device: axis
    variant: standard
    node_id: 5
    bus: main
    settings: {knob: "on"}
    parameters: {"0x1017": 100, "0x1A00:0x01": 0x60000020}
    store: ax.store
plant:
  axis: {gain: 2}
wires:
  - {from: ax.velocity, to: axis.velocity_command, scale: 2, offset: 0.5, noise: 0.1}
clock: {tick: 500us, mode: virtual, duration: 2.5s, seed: 42}
outputs:
  trace: out/demo.log
  sample_period: 100Hz
  csv: {file: out/demo.csv, signals: [axis.position, "frame(aux:0x185)[0:2] as i16 / 10"]}
  plots:
    - title: Demo
      y_label: position [mm]
      signals: [{signal: axis.position * 1000, label: position}]
  junit: out/demo.xml
script:
  - nmt: start
  - at: 1s
    name: late sync
    sync: {period: 1ms, counter: 16}
faults:
  - {at: 1s, for: 10ms, bus_off: ax}
)",
                                "demo.yaml", "/scenarios");
  EXPECT_EQ(s.name, "demo");
  ASSERT_EQ(s.buses.size(), 2u);
  EXPECT_EQ(s.buses[0].bitrate, 250000u);
  EXPECT_EQ(s.buses[1].iface, "vcan1");
  ASSERT_EQ(s.nodes.size(), 1u);
  EXPECT_EQ(s.nodes[0].node_id, 5);
  EXPECT_EQ(s.nodes[0].settings.at("knob"), "on");
  ASSERT_EQ(s.nodes[0].parameters.size(), 2u);
  EXPECT_EQ(s.nodes[0].parameters[1].index, 0x1A00);
  EXPECT_EQ(s.nodes[0].parameters[1].sub, 1);
  EXPECT_EQ(s.nodes[0].parameters[1].value.integer, 0x60000020);
  EXPECT_EQ(s.nodes[0].store, "/scenarios/ax.store");
  EXPECT_TRUE(s.plant.IsMap());
  ASSERT_EQ(s.wires.size(), 1u);
  EXPECT_EQ(s.wires[0].scale, 2);
  EXPECT_EQ(s.clock.tick, sim::microseconds(500));
  EXPECT_EQ(*s.clock.duration, sim::milliseconds(2500));
  EXPECT_EQ(s.clock.seed, 42u);
  EXPECT_EQ(s.outputs.sample_period, sim::milliseconds(10));
  ASSERT_TRUE(s.outputs.csv);
  EXPECT_EQ(s.outputs.csv->signals[1].frame.bus, "aux");
  EXPECT_DOUBLE_EQ(s.outputs.csv->signals[1].scale, 0.1);
  ASSERT_EQ(s.outputs.plots.size(), 1u);
  EXPECT_EQ(s.outputs.plots[0].labels[0], "position");
  ASSERT_EQ(s.script.size(), 2u);
  EXPECT_EQ(*s.script[1].at, sim::milliseconds(1000));
  EXPECT_EQ(s.script[1].name, "late sync");
  EXPECT_EQ(std::get<SyncStep>(s.script[1].action).counter_overflow, 16);
  ASSERT_EQ(s.faults.size(), 1u);
  EXPECT_EQ(*s.faults[0].duration, sim::milliseconds(10));
  EXPECT_EQ(std::get<BusOff>(s.faults[0].action).node, "ax");
}

TEST(SignalExpression, PortsFramesAndArithmetic) {
  const auto a = parse_signal("cyl.position * 1000 - 5", {});
  EXPECT_EQ(a.kind, SignalExpr::Kind::Port);
  EXPECT_EQ(a.owner, "cyl");
  EXPECT_EQ(a.port, "position");
  EXPECT_DOUBLE_EQ(a.scale, 1000);
  EXPECT_DOUBLE_EQ(a.offset, -5);
  const auto b = parse_signal("valve-cyl.solenoid_a_current", {});
  EXPECT_EQ(b.owner, "valve-cyl");
  const auto c = parse_signal("frame(0x185)[0:4] as i32 * 0.1e-3", {});
  EXPECT_EQ(c.kind, SignalExpr::Kind::Frame);
  EXPECT_EQ(c.frame.id, 0x185u);
  EXPECT_EQ(c.frame.count, 4);
  EXPECT_DOUBLE_EQ(c.scale, 1e-4);
  const std::uint8_t data[] = {0xFE, 0xFF, 0xFF, 0xFF, 0x10};
  EXPECT_DOUBLE_EQ(decode_field(c.frame, data, 5), -2.0);
  const auto d = parse_signal("frame(main:0x1F0)[4]", {});
  EXPECT_EQ(d.frame.bus, "main");
  EXPECT_DOUBLE_EQ(decode_field(d.frame, data, 5), 16.0);
  EXPECT_TRUE(std::isnan(decode_field(d.frame, data, 4)));  // frame too short
  EXPECT_THROW(parse_signal("position", {}), LoadError);
  EXPECT_THROW(parse_signal("frame(0x185)[6:10]", {}), LoadError);
  EXPECT_THROW(parse_signal("cyl.position * x", {}), LoadError);
}

TEST(SignalExpression, SumsOfTermsWithPrecedence) {
  const auto a = parse_signal("frame(0x1FF)[0:4] as i32 - shaft.angle * 360 / 4 + 2 * 3", {});
  EXPECT_EQ(a.kind, SignalExpr::Kind::Frame);
  EXPECT_DOUBLE_EQ(a.scale, 1);
  EXPECT_DOUBLE_EQ(a.offset, 6);  // '*' binds tighter than '+'
  ASSERT_EQ(a.more.size(), 1u);
  EXPECT_EQ(a.more[0].qualified_port(), "shaft.angle");
  EXPECT_DOUBLE_EQ(a.more[0].scale, -90);
  EXPECT_DOUBLE_EQ(a.more[0].offset, 0);
  const auto b = parse_signal("cyl.position + 5 * 2", {});
  EXPECT_DOUBLE_EQ(b.offset, 10);
  EXPECT_DOUBLE_EQ(b.scale, 1);
  const auto c = parse_signal("1 - 2 * cyl.position", {});  // a number first, the signal second
  EXPECT_EQ(c.qualified_port(), "cyl.position");
  EXPECT_DOUBLE_EQ(c.scale, -2);
  EXPECT_DOUBLE_EQ(c.offset, 1);
  EXPECT_TRUE(c.more.empty());
  const auto d = parse_signal("-cyl.position - valve-cyl.spool - 1e-3", {});
  EXPECT_DOUBLE_EQ(d.scale, -1);
  ASSERT_EQ(d.more.size(), 1u);
  EXPECT_EQ(d.more[0].owner, "valve-cyl");
  EXPECT_DOUBLE_EQ(d.more[0].scale, -1);
  EXPECT_DOUBLE_EQ(d.offset, -1e-3);
  EXPECT_THROW(parse_signal("cyl.position * shaft.angle", {}), LoadError);
  EXPECT_THROW(parse_signal("cyl.position / shaft.angle", {}), LoadError);
  EXPECT_THROW(parse_signal("cyl.position / 0", {}), LoadError);
  EXPECT_THROW(parse_signal("cyl.position -", {}), LoadError);
  EXPECT_THROW(parse_signal("5 + 3", {}), LoadError);
}

TEST(FramePattern, WildcardsAndOpenEnd) {
  FramePattern p;
  p.id = 0x585;
  ASSERT_EQ(parse_data_pattern("43 00 10 ?? *", p), "");
  EXPECT_TRUE(p.matches(sim::CanFrame::data_frame(0x585, {0x43, 0x00, 0x10, 0x00, 1, 2, 3, 4})));
  EXPECT_TRUE(p.matches(sim::CanFrame::data_frame(0x585, {0x43, 0x00, 0x10, 0x07})));
  EXPECT_FALSE(p.matches(sim::CanFrame::data_frame(0x585, {0x43, 0x00, 0x11, 0x00})));
  EXPECT_FALSE(p.matches(sim::CanFrame::data_frame(0x585, {0x43, 0x00, 0x10})));
  EXPECT_FALSE(p.matches(sim::CanFrame::data_frame(0x586, {0x43, 0x00, 0x10, 0x00})));
  ASSERT_EQ(parse_data_pattern("00", p), "");
  EXPECT_FALSE(p.matches(sim::CanFrame::data_frame(0x585, {0x00, 0x00})));  // exact length without *
  EXPECT_NE(parse_data_pattern("* 00", p), "");
  EXPECT_NE(parse_data_pattern("0G", p), "");
  EXPECT_EQ(p.describe().substr(0, 5), "0x585");
}

TEST(Durations, UnitsAndRates) {
  EXPECT_EQ(*parse_duration("250us"), sim::microseconds(250));
  EXPECT_EQ(*parse_duration("10ms"), sim::milliseconds(10));
  EXPECT_EQ(*parse_duration("1.5s"), sim::milliseconds(1500));
  EXPECT_EQ(*parse_duration("2"), sim::milliseconds(2000));
  EXPECT_EQ(*parse_duration("1min"), sim::milliseconds(60000));
  EXPECT_FALSE(parse_duration("-1s"));
  EXPECT_FALSE(parse_duration("1 h"));
  EXPECT_EQ(*parse_integer("0x7F"), 127);
  EXPECT_EQ(*parse_integer("-12"), -12);
  EXPECT_EQ(*parse_integer("0b101"), 5);
  EXPECT_FALSE(parse_integer("12a"));
}

// `send`: the payload and the flags are independent. `data:` must not reset an explicit
// `extended: true` on an 11-bit ID; `rtr:` is kept; rtr with data is rejected (a remote frame
// carries no data), as is `extended: false` on a 29-bit ID.
TEST(ScriptLoader, SendKeepsExtendedAndRtr) {
  const auto s = parse_scenario(R"(
script:
  - send: {id: 0x123, data: "01 02", extended: true}
  - send: {id: 0x123, data: "01 02"}
  - send: {id: 0x12345, data: "0A"}
  - send: {id: 0x185, rtr: 4}
  - send: {id: 0x185, rtr: 2, extended: true}
  - rpdo: {id: 0x205, data: "0F 00", extended: true}
)",
                                "send.yaml", ".");
  ASSERT_EQ(s.script.size(), 6u);
  const auto frame = [&](std::size_t i) { return std::get<SendStep>(s.script[i].action).frame; };
  EXPECT_EQ(frame(0).id, 0x123u);
  EXPECT_TRUE(frame(0).extended);
  EXPECT_FALSE(frame(0).rtr);
  EXPECT_EQ(frame(0).dlc, 2);
  EXPECT_EQ(frame(0).data[1], 0x02);
  EXPECT_FALSE(frame(1).extended);
  EXPECT_TRUE(frame(2).extended);
  EXPECT_EQ(frame(2).dlc, 1);
  EXPECT_TRUE(frame(3).rtr);
  EXPECT_FALSE(frame(3).extended);
  EXPECT_EQ(frame(3).dlc, 4);
  EXPECT_TRUE(frame(4).rtr);
  EXPECT_TRUE(frame(4).extended);
  EXPECT_EQ(frame(4).dlc, 2);
  EXPECT_TRUE(frame(5).extended);
  EXPECT_EQ(frame(5).dlc, 2);

  EXPECT_THROW(parse_scenario("script:\n  - send: {id: 0x185, rtr: 4, data: \"01\"}\n", "x.yaml", "."), LoadError);
  EXPECT_THROW(parse_scenario("script:\n  - send: {id: 0x12345, extended: false}\n", "x.yaml", "."), LoadError);
  try {
    parse_scenario("script:\n  - send: {id: 0x185, data: \"01\", rtr: 4}\n", "x.yaml", ".");
    ADD_FAILURE() << "rtr with data accepted";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("x.yaml:2:", 0), 0u) << e.what();
  }
}

TEST(ScenarioLoader, BusTransportsIncludeSocketcand) {
  const auto s = parse_scenario(R"(
buses:
  - {name: main, transport: "socketcand:127.0.0.1:29536"}
  - {name: remote, transport: "socketcand-client:10.0.0.2:29536/can0"}
)",
                                "x.yaml", ".");
  EXPECT_EQ(s.buses[0].iface, "socketcand:127.0.0.1:29536");
  EXPECT_EQ(s.buses[1].iface, "socketcand-client:10.0.0.2:29536/can0");
  try {
    parse_scenario("buses:\n  - {name: main, transport: \"tcp:1\"}\n", "x.yaml", ".");
    ADD_FAILURE() << "an unknown transport accepted";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("x.yaml:2:", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("'socketcand:ADDR:PORT'"), std::string::npos) << e.what();
  }
}

TEST(Durations, OutOfRangeIsNotCalledMalformed) {
  std::string problem;
  EXPECT_FALSE(parse_duration("1e300s", &problem));
  EXPECT_EQ(problem, "is out of range (at most 1e9 s, about 31 years)");
  EXPECT_FALSE(parse_duration("1e400", &problem));
  EXPECT_EQ(problem, "is out of range (at most 1e9 s, about 31 years)");
  EXPECT_FALSE(parse_duration("-1s", &problem));
  EXPECT_EQ(problem, "is negative (a duration is 0 or more)");
  EXPECT_FALSE(parse_duration("10 parsecs", &problem));
  EXPECT_EQ(problem, "is not a duration (e.g. 10ms, 1.5s, 250us)");
}

// yaml-cpp gives up at its depth limit with the message "bad file"; the message says why, where.
TEST(ScenarioLoader, DeepNestingIsReportedAsNesting) {
  try {
    parse_scenario("nodes: " + std::string(100000, '['), "deep.yaml", ".");
    ADD_FAILURE() << "accepted";
  } catch (const LoadError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("deep.yaml:", 0), 0u) << message;
    EXPECT_NE(message.find(": nesting deeper than "), std::string::npos) << message;
  }
}

// A deprecated device setting still builds the node; the warning names the new spelling at the
// settings' position (vplant run prints it on stderr).
TEST(ScenarioLoader, ADeprecatedDeviceSettingIsAWarningAtItsLine) {
  const auto s = parse_scenario(R"(
name: old names
nodes:
  - name: valve
    device: md2
    settings: {dither_freq: "50"}
clock: {duration: 1s}
)",
                                "old.yaml", ".");
  World world(s, default_environment(), {}, 1);
  EXPECT_EQ(world.warnings(),
            std::vector<std::string>{"old.yaml:6:15: warning: node 'valve': setting 'dither_freq' is deprecated: use 'dither_frequency'"});
}
