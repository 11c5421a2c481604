// The scripted master against a real CiA 301 node (the test axis) and a plant, in virtual time.
#include <gtest/gtest.h>

#include "tests/engine/run_helper.h"

using vtest::kMachine;
using vtest::run_text;

TEST(ScriptedMaster, CommissionsAndMovesTheAxisThroughThePlant) {
  const auto r = run_text(kMachine + R"(
script:
  - wait_frame: {id: 0x705, data: "00", timeout: 100ms}
  - sdo_read: {node: ax, index: 0x1000, expect: 0x194}
  - sdo_read: {node: ax, index: 0x1008, expect: "vplant test axis"}
  - sdo_read: {node: ax, index: 0x2002, expect: "hello segmented world"}
  - sdo_write: {node: ax, index: 0x2002, value: "a longer text, written in segments"}
  - sdo_read: {node: ax, index: 0x2002, expect: "a longer text, written in segments"}
  - sdo_write: {node: ax, index: 0x2001, value: 100}
  - sdo_write: {node: ax, index: 0x2001, value: 101, expect_abort: 0x06090031}
  - sdo_read: {node: ax, index: 0x2001, expect: 100}
  - sdo_read: {node: ax, index: 0x3000, type: u8, expect_abort: 0x06020000}
  - sdo_write: {node: 5, index: 0x2000, type: u8, value: 9}
  - sdo_read: {node: 5, index: 0x2000, expect_data: "09"}
  - nmt: start
  - wait_until: {signal: ax.nmt_state, value: 5, tolerance: 0, timeout: 10ms}
  - sync: 10ms
  - rpdo: {node: ax, pdo: 1, values: {"0x6001": 100000}}
  - expect: {signal: axis.velocity, value: 0.1, tolerance: 1e-9, within: 20ms}
  - wait: 100ms
  - expect: {signal: "frame(0x185)[0:4] as i32 * 1e-6", slope: 0.1, tolerance: 0.002, over: 500ms}
  - expect_frames: {id: 0x185, during: 500ms, count: 50, period: 10ms, period_tolerance: 100us}  # stamps move with stuff bits
  - expect_frames: {id: 0x080, during: 100ms, count: {min: 9, max: 11}}
  - wait_until: {signal: axis.position, above: 0.1, timeout: 2s}
  - expect: {signal: axis.position, below: 0.5, during: end}
  - rpdo: {id: 0x205, data: "00 00 00 00"}
  - wait: 20ms
  - expect: {signal: axis.velocity, value: 0, tolerance: 0}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text() << r.output;
  EXPECT_EQ(r.failures(), 0u);
  EXPECT_EQ(r.outcomes.size(), 20u);
}

TEST(ScriptedMaster, ConditionsOnTheDifferenceOfTwoSignals) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms
  - nmt: start
  - sync: 10ms
  - rpdo: {node: ax, pdo: 1, values: {"0x6001": 100000}}
  - wait_until: {signal: axis.position, above: 0.05, timeout: 1s}
  - name: the TPDO lags the plant by at most one SYNC period and a tick (0.1 m/s * 11 ms)
    expect: {signal: "frame(0x185)[0:4] as i32 * 1e-6 - axis.position", between: [-0.00111, 0], during: 200ms}
  - wait: 200ms
  - name: a sum that cannot hold
    expect: {signal: "axis.position - axis.position + 1", value: 0, tolerance: 0.5}
)");
  EXPECT_EQ(r.rc, 1);
  ASSERT_EQ(r.outcomes.size(), 3u) << r.failure_text();
  EXPECT_TRUE(r.outcomes[1].passed) << r.failure_text();
  EXPECT_FALSE(r.outcomes[2].passed);
  EXPECT_NE(r.outcomes[2].actual.find("1"), std::string::npos) << r.outcomes[2].actual;
}

TEST(ScriptedMaster, ReportsEachFailureWithTimeExpectedAndActual) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms  # boot-up
  - nmt: start
  - sdo_read: {node: ax, index: 0x1000, expect: 0x195}
  - sdo_write: {node: ax, index: 0x2001, value: 50, expect_abort: 0x06090031}
  - sdo_read: {node: 9, index: 0x1000, type: u32, timeout: 50ms}
  - wait_frame: {id: 0x185, timeout: 30ms}
  - wait_until: {signal: axis.position, above: 1, timeout: 100ms}
  - expect: {signal: axis.position, value: 1, tolerance: 0.1}
  - expect: {signal: axis.position, above: 1, within: 50ms}
)");
  EXPECT_EQ(r.rc, 1);
  ASSERT_EQ(r.outcomes.size(), 7u);
  for (const auto& o : r.outcomes) EXPECT_FALSE(o.passed) << o.name;
  EXPECT_EQ(r.outcomes[0].expected, "0x1000:00 = 0x195");
  EXPECT_EQ(r.outcomes[0].actual, "404 (0x194)");
  EXPECT_EQ(r.outcomes[0].mark.line, 13);
  EXPECT_EQ(r.outcomes[1].actual, "success");
  EXPECT_NE(r.outcomes[2].actual.find("no SDO response from node 9"), std::string::npos);
  EXPECT_EQ(r.outcomes[3].actual, "none");  // no SYNC: no TPDO
  EXPECT_NE(r.output.find("test.yaml:13:5: FAILED at "), std::string::npos) << r.output;
}

TEST(ScriptedMaster, RpdoByMappingFollowsAMappingChangedBySdo) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms  # boot-up
  - sdo_write: {node: ax, index: 0x1400, sub: 1, value: 0x80000205}
  - sdo_write: {node: ax, index: 0x1600, sub: 0, value: 0}
  - sdo_write: {node: ax, index: 0x1600, sub: 1, value: 0x00050008}
  - sdo_write: {node: ax, index: 0x1600, sub: 2, value: 0x60010020}
  - sdo_write: {node: ax, index: 0x1600, sub: 0, value: 2}
  - sdo_write: {node: ax, index: 0x1400, sub: 1, value: 0x00000305}
  - nmt: {command: start, node: ax}
  - rpdo: {node: ax, values: {"0x6001": -2000}}
  - wait_frame: {id: 0x305, data: "00 30 F8 FF FF", timeout: 10ms}
  - wait: 10ms
  - expect: {signal: ax.velocity, value: -0.002, tolerance: 1e-12}
  - rpdo: {node: ax, values: {"0x6001": 1, "0x2000": 3}}
)");
  EXPECT_EQ(r.rc, 1);
  ASSERT_FALSE(r.outcomes.empty());
  EXPECT_EQ(r.failures(), 1u) << r.failure_text();
  EXPECT_EQ(r.outcomes.back().actual, "0x2000:00 is not mapped");
}

TEST(ScriptedMaster, StepsWaitForTheirAtTimeAndTheScriptEndsTheRun) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms  # boot-up
  - nmt: start
  - at: 1.5s
    expect: {signal: ax.nmt_state, value: 5, tolerance: 0}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text();
  EXPECT_NEAR(r.summary.simulated_s, 1.501, 1e-9);
}

TEST(ScriptedMaster, ARunThatEndsBeforeTheScriptFails) {
  const auto r = run_text(kMachine + R"(
clock: {duration: 100ms}
script:
  - wait: 1s
  - nmt: start
)");
  EXPECT_EQ(r.rc, 1);
  ASSERT_EQ(r.outcomes.size(), 1u);
  EXPECT_EQ(r.outcomes[0].actual, "the run ended (1 later steps not run)");
}

TEST(ScriptedMaster, SyncWithCounterWraps) {
  const auto r = run_text(kMachine + R"(
script:
  - sync: {period: 1ms, counter: 3}
  - wait_frame: {id: 0x080, data: "01", timeout: 5ms}
  - wait_frame: {id: 0x080, data: "02", timeout: 5ms}
  - wait_frame: {id: 0x080, data: "03", timeout: 5ms}
  - wait_frame: {id: 0x080, data: "01", timeout: 5ms}
  - sync: off
  - expect_frames: {id: 0x080, during: 10ms, count: 0}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text();
}
