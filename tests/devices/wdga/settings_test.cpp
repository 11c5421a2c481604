// WDGA configuration settings ([R] knobs of docs/devices/wdga.md) as the bus sees them.
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

class Alias : public WdgaTest {
 protected:
  Alias() : WdgaTest({{"cyclic_timer_alias", "on"}}) {}
};

TEST_F(Alias, CyclicTimerIsTheEventTimerOfTpdo1) {
  ASSERT_EQ(h().write(0x6200, 0, 50, 2), 0u);
  EXPECT_EQ(u(0x1800, 5), 50u);
  ASSERT_EQ(h().write(0x1800, 5, 40, 2), 0u);
  EXPECT_EQ(u(0x6200), 40u);
  start();
  h().take();
  h().run_ms(201);
  EXPECT_EQ(h().take().size(), 5u);  // FEh with a timer: every 40 ms with the shaft still
}

class StrictCobId : public WdgaTest {
 protected:
  StrictCobId() : WdgaTest({{"strict_cobid", "on"}}) {}
};

TEST_F(StrictCobId, RestrictedIdentifiersAbort) {
  EXPECT_EQ(h().write(0x1800, 1, 0x40000701, 4), 0x06090030u);
  EXPECT_EQ(h().write(0x1800, 1, 0x40000581, 4), 0x06090030u);
  EXPECT_EQ(h().write(0x1800, 1, 0xC0000701, 4), 0u);  // invalid PDO: any identifier
  EXPECT_EQ(h().write(0x1800, 1, 0x40000190, 4), 0u);
}

class FixedRate : public WdgaTest {
 protected:
  FixedRate()
      : WdgaTest({{"factory_bit_rate", "2"}, {"factory_node_id", "9"}, {"temperature_period_s", "5"},
                  {"hardware_version_4_bytes", "on"}, {"total_range_max", "0x80000000"}, {"boot_delay_ms", "20"}},
                 "", false) {}
};

TEST_F(FixedRate, FactorySettings) {
  device().power_on(h().now());
  h().run_ms(19);
  EXPECT_TRUE(h().take().empty());
  h().run_ms(2);
  EXPECT_EQ(h().take(), Frames{Frame(0x709, {0x00})});  // boots without detection, after the delay
  EXPECT_EQ(u(0x2100), 2u);
  EXPECT_EQ(sdo({0x40, 0x09, 0x10, 0x00}), resp({0x43, 0x09, 0x10, 0x00, 0x41, 0x41, 0x00, 0x00}));
  EXPECT_EQ(h().write(0x6002, 0, 0x80000001, 4), 0x06090031u);
  EXPECT_EQ(h().write(0x6002, 0, 0x80000000, 4), 0u);
  device().set_input("temperature", 120);
  h().run_ms(5001);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x42, 0x08, 0x10})});
}

class ScriptedShaft : public WdgaTest {
 protected:
  ScriptedShaft() : WdgaTest({{"signal", "ramp:6.283185307179586"}}) {}
};

TEST_F(ScriptedShaft, StandaloneSignalTurnsTheShaft) {
  const auto t0 = u(0x6004);
  h().run_ms(500);
  EXPECT_NEAR(static_cast<double>(u(0x6004) - t0), 8192.0, 20.0);
}

class RestoreAtOnce : public WdgaTest {
 protected:
  RestoreAtOnce() : WdgaTest({{"restore_at_once", "on"}}) {}
};

TEST_F(RestoreAtOnce, LoadAppliesTheDefaultsWithoutAReset) {
  // A-39 option: the values in use change with the 1011h answer, not at the next reset.
  ASSERT_EQ(h().write(0x1017, 0, 100, 2), 0u);
  ASSERT_EQ(h().write(0x2120, 3, 0x12345678, 4), 0u);
  ASSERT_EQ(h().write(0x2101, 0, 9, 1), 0u);
  ASSERT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
  turn_to(0.25);
  h().run_ms(2);
  ASSERT_EQ(h().write(0x6003, 0, 100, 4), 0u);
  EXPECT_EQ(u(0x6004), 100u);
  h().take();
  h().run_ms(250);
  EXPECT_EQ(h().take(), (Frames{Frame(0x77F, {0x7F}), Frame(0x77F, {0x7F})}));
  EXPECT_EQ(sdo({0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64}), resp({0x60, 0x11, 0x10, 0x01}));
  EXPECT_EQ(sdo({0x40, 0x17, 0x10, 0x00}), resp({0x4B, 0x17, 0x10, 0x00, 0x00, 0x00}));
  EXPECT_EQ(u(0x6001), 16384u);
  EXPECT_EQ(u(0x6003), 0u);
  h().run_ms(2);
  EXPECT_EQ(u(0x6004), 4096u);  // offset gone, default scaling
  h().take();
  h().run_ms(500);
  EXPECT_TRUE(h().take().empty());  // the heartbeat stopped at once
  EXPECT_EQ(id(), 127);             // node-ID, bit rate and customer data are not restored
  EXPECT_EQ(u(0x2101), 9u);
  EXPECT_EQ(u(0x2120, 3), 0x12345678u);
}

TEST_F(RestoreAtOnce, CommunicationGroupOnlyAndCobIdsTrackAgain) {
  ASSERT_EQ(h().write(0x1010, 1, kSave, 4), 0u);  // freezes the COB-IDs
  ASSERT_EQ(h().write(0x1800, 1, 0x40000190, 4), 0u);
  ASSERT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
  EXPECT_EQ(sdo({0x23, 0x11, 0x10, 0x02, 0x6C, 0x6F, 0x61, 0x64}), resp({0x60, 0x11, 0x10, 0x02}));
  EXPECT_EQ(u(0x1800, 1), 0x400001FFu);
  EXPECT_EQ(u(0x6001), 4096u);  // application group untouched
  start();
  h().take();
  turn_to(0.5);
  h().run_ms(3);
  const auto frames = h().take();
  ASSERT_FALSE(frames.empty());
  for (const auto& f : frames) EXPECT_EQ(f.id, 0x1FFu);
}

TEST(WdgaSettings, BadValuesAreRejected) {
  Settings s;
  EXPECT_NE(parse_settings("", {{"total_range_max", "0"}}, s), "");
  EXPECT_NE(parse_settings("singleturn", {{"factory_total_range", "20000"}}, s), "");
  EXPECT_NE(parse_settings("singleturn", {{"is_32bit_variant", "on"}}, s), "");
  EXPECT_NE(parse_settings("", {{"hardware_version", "ABC"}}, s), "");
  EXPECT_NE(parse_settings("dual", {}, s), "");
  EXPECT_NE(parse_settings("", {{"speed_units", "rpm"}}, s), "");
}

}  // namespace
}  // namespace wdga::test
