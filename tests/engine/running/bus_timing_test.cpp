// Scenarios on a bit-timed virtual bus: sub-tick trace stamps, bus load and fault-confinement
// signals, the tx_errors fault and its EMCYs, `timing: ideal`, and determinism with timing on.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/engine/run_helper.h"
#include "tests/support/temp_path.h"
#include "tests/support/read_file.h"

using vtest::kMachine;
using vtest::run_text;

namespace {

using vtest::read_file;

const std::string kBus125k = "buses:\n  - {name: main, bitrate: 125000}\n";

}  // namespace

TEST(BusTimingScenario, TraceStampsAreTheFramesEndsNotTheTicks) {
  const std::string trace = vtest::unique_temp_path("bus_timing", ".log");
  scenario::RunOptions o;
  o.trace = trace;
  const auto r = run_text(kBus125k + kMachine + R"(
clock: {duration: 100ms}
script:
  - wait: 10ms
  - nmt: start
  - sync: 10ms
)", o);
  ASSERT_EQ(r.rc, 0) << r.output;
  const auto text = read_file(trace);
  std::remove(trace.c_str());
  // The SYNC sent at 20 ms (tick start) is 48 bits long up to the end of its EOF (51 with the
  // intermission), at 8 us per bit: 384 us.
  EXPECT_NE(text.find("(0000000000.020384) main 080#"), std::string::npos) << text;
  EXPECT_NE(r.output.find("bit timing at 125 kbit/s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("load by COB-ID: 185"), std::string::npos) << r.output;
}

TEST(BusTimingScenario, IdealTimingKeepsTheTickStamps) {
  const std::string trace = vtest::unique_temp_path("bus_timing_ideal", ".log");
  scenario::RunOptions o;
  o.trace = trace;
  const auto r = run_text("buses:\n  - {name: main, bitrate: 125000, timing: ideal}\n" + kMachine + R"(
clock: {duration: 100ms}
script:
  - wait: 10ms
  - nmt: start
  - sync: 10ms
)", o);
  ASSERT_EQ(r.rc, 0) << r.output;
  const auto text = read_file(trace);
  std::remove(trace.c_str());
  EXPECT_NE(text.find("(0000000000.020000) main 080#"), std::string::npos) << text;
}

TEST(BusTimingScenario, LoadSignalFollowsTheSyncRate) {
  // SYNC (51 bits) and the axis node's TPDO1 (85 bits) every 5 ms at 125 kbit/s: 136 of 625
  // bits, 0.218; 19 to 20 cycles fall into the 100 ms window: 0.20 to 0.22.
  const auto r = run_text(kBus125k + kMachine + R"(
script:
  - wait: 10ms
  - nmt: start
  - expect: {signal: bus.main.load, below: 0.05}
  - sync: 5ms
  - wait: 200ms
  - expect: {signal: bus.main.load, between: [0.20, 0.22], during: 100ms}
  - wait: 100ms
  - sync: off
  - wait: 150ms
  - expect: {signal: bus.main.load, value: 0, tolerance: 0}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text() << r.output;
}

TEST(BusTimingScenario, TxErrorsDriveTheCountersAndTheEmcys) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms
  - sdo_write: {node: ax, index: 0x1017, value: 10}
  - expect: {signal: bus.main.ax.tec, value: 0, tolerance: 0}
  - fault: {tx_errors: {node: ax, count: 16}}
  - name: 16 destroyed attempts - error passive, EMCY 8120h
    wait_frame: {id: 0x085, data: "20 81 *", timeout: 50ms}
  - name: the retransmission succeeded - error active again
    wait_until: {signal: bus.main.ax.error_state, value: 0, tolerance: 0, timeout: 50ms}
  - expect: {signal: bus.main.ax.tec, between: [100, 127]}
  - fault: {tx_errors: {node: ax, count: 32}}
  - name: bus-off - no heartbeat
    wait_until: {signal: bus.main.ax.error_state, value: 2, tolerance: 0, timeout: 50ms}
  - name: 128 x 11 recessive bits later - EMCY 8140h
    wait_frame: {id: 0x085, data: "40 81 *", timeout: 20ms}
  - expect_frames: {id: 0x705, during: 50ms, count: {min: 4, max: 6}}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text() << r.output;
  EXPECT_NE(r.output.find("error frames: 48"), std::string::npos) << r.output;
}

TEST(BusTimingScenario, UnknownBusSignalIsALoadError) {
  EXPECT_THROW(run_text(kMachine + R"(
clock: {duration: 10ms}
script:
  - expect: {signal: bus.nope.load, below: 1}
)"), scenario::LoadError);
  EXPECT_THROW(run_text(kMachine + R"(
clock: {duration: 10ms}
script:
  - expect: {signal: bus.main.ax.nope, below: 1}
)"), scenario::LoadError);
}
