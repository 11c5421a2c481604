// Fault injection on the wire, on a device and in the plant, scheduled and on condition.
#include <gtest/gtest.h>

#include "tests/engine/run_helper.h"

using vtest::kMachine;
using vtest::run_text;

TEST(FaultInjection, WireDropDelayAndCorrupt) {
  const auto r = run_text(kMachine + R"(
faults:
  - {at: 100ms, for: 50ms, drop: {id: 0x185}}
  - {at: 200ms, for: 50ms, delay: {id: 0x185, by: 3ms}}
  - {at: 300ms, for: 50ms, corrupt: {id: 0x185, byte: 3, value: 0x80}}
script:
  - wait: 10ms  # boot-up
  - nmt: start
  - sync: 10ms
  - at: 100ms
    expect_frames: {id: 0x185, during: 50ms, count: 0}
  - at: 150ms
    expect_frames: {id: 0x185, during: 50ms, count: 5, period: 10ms}
  - at: 200ms
    expect_frames: {id: 0x185, during: 50ms, count: 5}
  - expect_frames: {id: 0x080, during: 50ms, count: 5}
  - name: the TPDO of the SYNC at 200 ms arrives at 203 ms
    at: 202ms
    expect_frames: {id: 0x185, during: 3ms, count: 1}
  - at: 300ms
    expect_frames: {id: 0x185, during: 50ms, count: 5, data: "?? ?? ?? 80"}
  - at: 350ms
    expect_frames: {id: 0x185, during: 50ms, count: 5, data: "?? ?? ?? 00"}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text();
  EXPECT_EQ(r.summary.faults, 3u);
}

TEST(FaultInjection, BusOffSilencesTheNodeUntilItRecovers) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms  # boot-up
  - sdo_write: {node: ax, index: 0x1017, value: 10}
  - fault: {bus_off: ax, for: 100ms}
  - expect_frames: {id: 0x705, during: 100ms, count: 0}
  - sdo_read: {node: ax, index: 0x1017, timeout: 50ms, expect_abort: 0x05040000}
  - name: back from bus-off, the node reports the communication error
    wait_frame: {id: 0x085, timeout: 60ms}
  - expect_frames: {id: 0x705, during: 100ms, count: {min: 9, max: 11}}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text();
}

TEST(FaultInjection, DeviceFaultSendsEmcyOnConditionAndClearsAfterItsDuration) {
  const auto r = run_text(kMachine + R"(
faults:
  - when: {signal: axis.position, above: 0.01}
    for: 200ms
    device_fault: {node: ax, fault: sensor_lost}
script:
  - wait: 10ms  # boot-up
  - nmt: start
  - sync: 10ms
  - rpdo: {node: ax, values: {"0x6001": 100000}}
  - wait_frame: {id: 0x085, data: "00 73 81 * ", timeout: 200ms}
  - name: position frozen while the sensor is lost
    expect: {signal: "frame(0x185)[0:4] as i32", between: [9000, 11000], during: 150ms}
  - name: the fault clears 200 ms after it was injected
    wait_frame: {id: 0x085, data: "00 00 00 *", timeout: 300ms}
  - wait: 20ms
  - expect: {signal: "frame(0x185)[0:4] as i32 * 1e-6", above: 0.025}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text();
}

TEST(FaultInjection, PowerCycleAndResetBootTheNodeAgain) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms  # boot-up
  - nmt: start
  - wait: 10ms
  - fault: {power_cycle: {node: ax, off: 50ms}}
  - expect: {signal: ax.nmt_state, value: 0, tolerance: 0}
  - wait_frame: {id: 0x705, data: "00", timeout: 60ms}
  - expect: {signal: ax.nmt_state, value: 127, tolerance: 0}
  - nmt: start
  - wait: 5ms
  - fault: {reset: ax}
  - wait_frame: {id: 0x705, data: "00", timeout: 5ms}
  - fault: {power_off: ax, for: 20ms}
  - wait_frame: {id: 0x705, timeout: 30ms}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text();
}

TEST(FaultInjection, APowerOffIsOverOnceTheNodeHasPowerAgain) {
  const auto r = run_text(kMachine + R"(
script:
  - wait: 10ms  # boot-up
  - fault: {power_off: ax, for: 50ms}
  - wait: 5ms
  - fault: {power_on: ax}
  - wait_frame: {id: 0x705, data: "00", timeout: 10ms}
  - wait: 1ms  # past the boot-up's tick
  - name: the power-off's end finds the node powered and leaves it alone (no second boot-up)
    expect_frames: {id: 0x705, data: "00", during: 80ms, count: 0}
  - wait: 80ms  # expect_frames watches in the background
  - fault: {power_cycle: {node: ax, off: 40ms}}
  - wait: 5ms
  - fault: {reset: ax}
  - wait_frame: {id: 0x705, data: "00", timeout: 10ms}
  - wait: 1ms
  - name: the cycle's end finds the node powered (by the reset) and leaves it alone
    expect_frames: {id: 0x705, data: "00", during: 80ms, count: 0}
)");
  EXPECT_EQ(r.rc, 0) << r.failure_text();
}

TEST(FaultInjection, PlantParameterChangesTheMotionAndIsRestored) {
  const auto r = run_text(kMachine + R"(
faults:
  - {at: 500ms, for: 500ms, plant: {parameter: axis.gain, value: 0.5}}
script:
  - wait: 10ms  # boot-up
  - nmt: start
  - rpdo: {node: ax, values: {"0x6001": 100000}}
  - at: 100ms
    expect: {signal: axis.position, slope: 0.1, tolerance: 1e-6, over: 300ms}
  - at: 600ms
    expect: {signal: axis.position, slope: 0.05, tolerance: 1e-6, over: 300ms}
  - at: 1100ms
    expect: {signal: axis.position, slope: 0.1, tolerance: 1e-6, over: 300ms}
  - fault: {plant: {parameter: axis.gain, value: 20}}
)");
  EXPECT_EQ(r.rc, 1);
  ASSERT_EQ(r.failures(), 1u) << r.failure_text();
  EXPECT_EQ(r.outcomes.size(), 4u);
  for (const auto& o : r.outcomes) {
    if (!o.passed) {
      EXPECT_EQ(o.actual, "axis.gain out of range [0, 10]");
    }
  }
}
