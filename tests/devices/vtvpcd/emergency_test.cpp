// EMCY, error register, 0x1003 and Bus Status for every fault the emulator can simulate
// (manual §3.5, §4.42; digest §2.10, §3.3, §4.9; checklist 37; TV24).
#include <gtest/gtest.h>

#include "devices/vtvpcd/fault_monitor.h"
#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using vtest::Frame;
using vtest::Frames;
using Bytes = std::vector<std::uint8_t>;

namespace {
void acknowledge(vtest::Vtvpcd& n) {
  n.set("enable", 0);
  n->run_ms(2);
  n.set("enable", 1);
  n->run_ms(2);
}
}  // namespace

TEST(VtvpcdEmcy, PressureTransducerBBreak) {  // checklist 37, TV24
  vtest::Vtvpcd n;
  EXPECT_EQ(n.sdo({0x40, 0x68, 0x2C, 0x00}), (Bytes{0x4B, 0x68, 0x2C, 0x00, 0x00, 0x00, 0, 0}));
  ASSERT_EQ(n.dev().inject_fault("pressure_b_sensor_break", true), "");
  n->run_ms(1);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0x35, 0x52, 0x81, 0, 0, 0, 0, 0})});
  EXPECT_EQ(n.sdo({0x40, 0x68, 0x2C, 0x00}), (Bytes{0x4B, 0x68, 0x2C, 0x00, 0x03, 0x81, 0, 0}));
  EXPECT_EQ(n.raw(0x2F1F), 0);
  EXPECT_EQ(n.raw(0x2F26) & 0x02, 0);  // OK = 0
  EXPECT_FALSE(n.dev().control().energised);
  EXPECT_EQ(n.raw(0x2F0F), 0);  // a broken transducer reads 0
  // The cause stays: acknowledging does not clear it.
  acknowledge(n);
  EXPECT_TRUE(n->take().empty());
  ASSERT_EQ(n.dev().inject_fault("pressure_b_sensor_break", false), "");
  n->run_ms(5);
  EXPECT_TRUE(n->take().empty());  // latched
  acknowledge(n);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})});
  EXPECT_EQ(n.raw(0x2C68), 0);
}

TEST(VtvpcdEmcy, EveryFaultHasItsCodeRegisterAndNumber) {
  struct Case {
    const char* name;
    std::uint16_t code;
    std::uint8_t er;
    int number;  // -1: EMCY only
    bool stop;
  };
  const Case cases[] = {
      {"angle_cmd_input_break", 0x3400, 0x03, 0, true},    {"pressure_cmd_input_break", 0x3400, 0x03, 1, true},
      {"power_cmd_input_break", 0x3400, 0x03, 2, true},    {"pressure_b_sensor_break", 0x5235, 0x81, 3, true},
      {"pressure_a_sensor_break", 0x5235, 0x81, 4, true},  {"res_angle_cmd_input_break", 0x3400, 0x03, 5, true},
      {"lvdt_fault", 0x5236, 0x81, 6, true},               {"bus_timeout", 0x8100, 0x11, 16, true},
      {"trigger_fault", 0x1000, 0x01, 18, true},           {"loop_fault", 0x8300, 0x81, 19, true},
      {"loop_fault_position", 0x8301, 0x81, 19, true},     {"loop_fault_pressure", 0x8302, 0x81, 19, true},
      {"parameter_checksum", 0x6310, 0x81, 22, true},      {"configuration_checksum", 0x6320, 0x81, 23, true},
      {"supply_voltage", 0x3422, 0x05, 24, true},          {"reference_voltage", 0x3422, 0x05, 25, true},
      {"do1_short", 0x1000, 0x03, 26, false},              {"ok_short", 0x1000, 0x03, 27, false},
      {"do2_short", 0x1000, 0x03, 28, false},              {"do3_short", 0x1000, 0x03, 29, false},
      {"do4_short", 0x1000, 0x03, 30, false},              {"do5_short", 0x1000, 0x03, 31, false},
      {"do6_short", 0x1000, 0x03, 32, false},              {"do7_short", 0x1000, 0x03, 33, false},
      {"sensor_general", 0x5230, 0x81, -1, false},         {"software", 0x6000, 0x81, -1, false},
      {"internal_software", 0x6100, 0x81, -1, false},      {"user_software", 0x6200, 0x81, -1, false},
      {"data_set", 0x6300, 0x81, -1, false},
  };
  vtest::Vtvpcd n;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    ASSERT_EQ(n.dev().inject_fault(c.name, true), "");
    n->run_ms(1);
    EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {static_cast<std::uint8_t>(c.code), static_cast<std::uint8_t>(c.code >> 8),
                                              c.er, 0, 0, 0, 0, 0})});
    EXPECT_EQ(n.od().get<std::uint8_t>(0x1001), c.er);
    EXPECT_EQ(n->read_u(0x1003, 1), c.code);
    const auto status = static_cast<std::uint16_t>(n.raw(0x2C68));
    EXPECT_EQ(status >> 8, c.er);
    if (c.number >= 0) {
      EXPECT_EQ(status & 0xFF, c.number);
    }
    EXPECT_EQ(n.dev().control().energised, !c.stop);
    EXPECT_EQ(n.raw(0x2F26) & 0x02, 0);  // OK = 0 while any error is active
    if (c.number >= 26) {
      EXPECT_EQ(n.raw(0x2F26) & (1 << (c.number - 26)), 0);
    }
    ASSERT_EQ(n.dev().inject_fault(c.name, false), "");
    n->run_ms(1);
    if (c.stop) acknowledge(n);
    EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})});
    EXPECT_EQ(n.raw(0x2C68), 0);
  }
  EXPECT_NE(n.dev().inject_fault("no_such_fault", true), "");
  EXPECT_EQ(n.dev().faults().size(), vtvpcd::fault_definitions().size());
}

TEST(VtvpcdEmcy, ErrorListHoldsPresentErrorsNewestFirstAtMostFour) {  // A22, A23
  vtest::Vtvpcd n;
  for (const char* f : {"supply_voltage", "lvdt_fault", "parameter_checksum", "software", "data_set"}) {
    n.dev().inject_fault(f, true);
    n->run_ms(1);
  }
  EXPECT_EQ(n->take().size(), 5u);  // one EMCY per new error
  EXPECT_EQ(n->read_u(0x1003, 0), 4u);
  EXPECT_EQ(n->read_u(0x1003, 1), 0x6300u);
  EXPECT_EQ(n->read_u(0x1003, 2), 0x6000u);
  EXPECT_EQ(n->read_u(0x1003, 3), 0x6310u);
  EXPECT_EQ(n->read_u(0x1003, 4), 0x5236u);
  EXPECT_EQ(n.od().get<std::uint8_t>(0x1001), 0x85);
  EXPECT_EQ(n.raw(0x2C68), 0x8516);  // the latest numbered fault: 22
  // A partial clear sends nothing and closes the list up.
  n.dev().inject_fault("software", false);
  n->run_ms(1);
  EXPECT_TRUE(n->take().empty());
  EXPECT_EQ(n->read_u(0x1003, 0), 3u);
  EXPECT_EQ(n->read_u(0x1003, 1), 0x6300u);
  EXPECT_EQ(n->read_u(0x1003, 2), 0x6310u);
  // Writing 0 empties the list but acknowledges nothing.
  ASSERT_EQ(n->write(0x1003, 0, 0, 1), 0u);
  EXPECT_EQ(n->read_u(0x1003, 0), 0u);
  uint32_t abort = 0;
  EXPECT_FALSE(n->read_u(0x1003, 1, &abort));
  EXPECT_EQ(abort, 0x06090011u);
  EXPECT_EQ(n.od().get<std::uint8_t>(0x1001), 0x85);
}

TEST(VtvpcdEmcy, TwoFaultsWithOneCodeSignalOnceAndClearTogether) {
  vtest::Vtvpcd n;
  n.dev().inject_fault("pressure_b_sensor_break", true);
  n->run_ms(1);
  n.dev().inject_fault("pressure_a_sensor_break", true);
  n->run_ms(1);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0x35, 0x52, 0x81, 0, 0, 0, 0, 0})});
  EXPECT_EQ(n.raw(0x2C68), 0x8104);
  n.dev().inject_fault("pressure_b_sensor_break", false);
  acknowledge(n);
  EXPECT_TRUE(n->take().empty());  // A still broken
  EXPECT_EQ(n.raw(0x2C68), 0x8104);
  n.dev().inject_fault("pressure_a_sensor_break", false);
  acknowledge(n);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})});
}

TEST(VtvpcdEmcy, TwoBitTriggerIsFault18WithEmcy1000) {  // checklist 31, trigger_multibit = fault
  vtest::Vtvpcd n({{"trigger_multibit", "fault"}});
  ASSERT_EQ(n.write4(0x2C67, 0x0008), 0u);  // one set: fine
  n->run_ms(5);
  EXPECT_TRUE(n->take().empty());
  ASSERT_EQ(n.write4(0x2C67, 0x0101), 0u);  // two sets: fault 18, a stop fault, generic error
  n->run_ms(1);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0x00, 0x10, 0x01, 0, 0, 0, 0, 0})});
  EXPECT_EQ(n.sdo({0x40, 0x68, 0x2C, 0x00}), (Bytes{0x4B, 0x68, 0x2C, 0x00, 0x12, 0x01, 0, 0}));
  EXPECT_EQ(n.sdo({0x40, 0x01, 0x10, 0x00}), (Bytes{0x4F, 0x01, 0x10, 0x00, 0x01, 0, 0, 0}));
  EXPECT_EQ(n->read_u(0x1003, 1), 0x1000u);
  EXPECT_FALSE(n.dev().control().energised);  // stop
  n->run_ms(100);
  EXPECT_TRUE(n->take().empty());  // once
  // A valid Trigger again, then the acknowledgement: the "no error" EMCY.
  ASSERT_EQ(n.write4(0x2C67, 0x0008), 0u);
  acknowledge(n);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})});
  EXPECT_EQ(n.raw(0x2C68), 0);
}

TEST(VtvpcdEmcy, DifferentErrorRegisterBitsUnderOneCode) {
  vtest::Vtvpcd n({{"trigger_multibit", "fault"}});
  n.dev().inject_fault("do3_short", true);
  n->run_ms(1);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0x00, 0x10, 0x03, 0, 0, 0, 0, 0})});
  ASSERT_EQ(n.write4(0x2C67, 0x0101), 0u);  // checklist 31: two sets -> fault 18
  n->run_ms(1);
  EXPECT_TRUE(n->take().empty());  // 0x1000 is already signalled
  EXPECT_EQ(n.raw(0x2C68), 0x0312);
  n.dev().inject_fault("do3_short", false);
  n->run_ms(1);
  EXPECT_TRUE(n->take().empty());  // 0x1000 still present (Trigger)
  EXPECT_EQ(n.od().get<std::uint8_t>(0x1001), 0x01);
  EXPECT_EQ(n.raw(0x2C68), 0x0112);
}

TEST(VtvpcdEmcy, ResetOfAmplifierCardReRaisesPresentCausesAfterBootUp) {
  vtest::Vtvpcd n;
  n.dev().inject_fault("supply_voltage", true);
  n.dev().inject_fault("software", true);
  n->run_ms(1);
  n->take();
  n.dev().inject_fault("software", false);
  n->send(0x000, {0x81, 0x3F});
  n->run_ms(50);
  EXPECT_EQ(n->take(), (Frames{Frame(0x73F, {0x00}), Frame(0x0BF, {0x22, 0x34, 0x05, 0, 0, 0, 0, 0})}));
  EXPECT_EQ(n->read_u(0x1003, 0), 1u);
}

TEST(VtvpcdEmcy, WatchdogResetRestartsTheCardAndReportsIt) {
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, 16384), 0u);
  n.start();
  ASSERT_EQ(n.dev().inject_fault("watchdog_reset", true), "");
  n->run_ms(299);
  EXPECT_TRUE(n->take().empty());
  n->run_ms(2);
  EXPECT_EQ(n->take(), (Frames{Frame(0x73F, {0x00}), Frame(0x0BF, {0x10, 0x60, 0x81, 0, 0, 0, 0, 0})}));
  EXPECT_EQ(n.raw(0x2C72), 0);  // RAM lost
  EXPECT_EQ(n.device->node().nmt_state(), canopen::NmtState::PreOperational);
  EXPECT_TRUE(n.dev().control().energised);  // reported, no stop
  n->run_ms(100);
  EXPECT_TRUE(n->take().empty());
  acknowledge(n);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})});
}

TEST(VtvpcdEmcy, InhibitTimeSpacesFrames) {
  vtest::Vtvpcd n;
  ASSERT_EQ(n->write(0x1015, 0, 100, 2), 0u);  // 10 ms
  n.dev().inject_fault("supply_voltage", true);
  n.dev().inject_fault("lvdt_fault", true);
  n->run_ms(1);
  EXPECT_EQ(n->take().size(), 1u);
  n->run_ms(10);
  EXPECT_EQ(n->take().size(), 1u);
}

TEST(VtvpcdEmcy, PreOperationalEmcyCanBeSwitchedOff) {  // emcy_in_preoperational = false
  vtest::Vtvpcd n({{"emcy_in_preoperational", "false"}});
  n.dev().inject_fault("supply_voltage", true);
  n->run_ms(5);
  EXPECT_TRUE(n->take().empty());
  EXPECT_EQ(n.raw(0x2C68), 0x0518);
  n.start();
  n.dev().inject_fault("lvdt_fault", true);
  n->run_ms(1);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0x36, 0x52, 0x85, 0, 0, 0, 0, 0})});
}
