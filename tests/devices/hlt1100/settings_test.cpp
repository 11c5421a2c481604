// HLT 1100 configuration settings ([REC] knobs of docs/devices/hlt1100.md) as the bus sees them.
#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

class DynamicMapping : public Hlt1100Test {
 protected:
  DynamicMapping() : Hlt1100Test({{"dynamic_mapping", "on"}}) {}
};

TEST_F(DynamicMapping, PositionAndSpeedInOneTpdoConfiguredInPreOperational) {
  ASSERT_EQ(h().write(0x1A00, 0, 0, 1), 0u);
  EXPECT_EQ(h().write(0x1A00, 2, 0x60100120, 4), 0x06040041u);  // only 6020h:01 and 6030h:01
  ASSERT_EQ(h().write(0x1A00, 2, 0x60300110, 4), 0u);
  ASSERT_EQ(h().write(0x1A00, 0, 2, 1), 0u);
  EXPECT_EQ(start(), Frames{Frame(0x185, {0xE8, 0x03, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(h().write(0x1A00, 0, 0, 1), 0x08000022u);  // not in Operational
}

class LenientSync : public Hlt1100Test {
 protected:
  LenientSync() : Hlt1100Test({{"sync_dlc_strict", "off"}}) {}
};

TEST_F(LenientSync, SyncWithACounterByteAlsoTriggers) {
  start();
  h().send(Frame(0x080, {0x01}));
  EXPECT_EQ(h().take(), Frames{Frame(0x285, {0xE8, 0x03, 0x00, 0x00})});
}

class SlowLssStore : public Hlt1100Test {
 protected:
  SlowLssStore() : Hlt1100Test({{"lss_store_delay_ms", "500"}}) {}
};

TEST_F(SlowLssStore, StoreConfigurationIsAnsweredAfterTheDelay) {
  h().take();
  h().send(Frame(0x7E5, eight({0x04, 0x01})));
  ASSERT_EQ(h().take(), Frames{});
  h().send(Frame(0x7E5, eight({0x17})));
  h().run_ms(499);
  EXPECT_TRUE(h().take().empty());  // silent: no answer, no PDO
  h().run_ms(2);
  const Frames after = h().take();
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.front(), Frame(0x7E4, eight({0x17, 0x00, 0x00})));
}

class FastscanForAll : public Hlt1100Test {
 protected:
  FastscanForAll() : Hlt1100Test({{"lss_fastscan_configured", "on"}}) {}
};

TEST_F(FastscanForAll, ConfiguredNodeAnswersFastscan) {
  h().send(Frame(0x7E5, eight({0x51, 0, 0, 0, 0, 0x80, 0, 0})));
  EXPECT_EQ(h().take(), Frames{Frame(0x7E4, eight({0x4F}))});
}

class Timing : public Hlt1100Test {
 protected:
  Timing() : Hlt1100Test({{"boot_delay_ms", "250"}, {"sample_period_ms", "10"}}, 5, false) {}
};

TEST_F(Timing, BootDelayAndSamplePeriod) {
  h().power_on();
  h().run_ms(247);
  EXPECT_TRUE(h().take().empty());
  h().run_ms(5);
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});
  // Samples fall at power-on + k * 10 ms (virtual time is exact): the move at 252 ms is seen by
  // the 260 ms sample, and until then 6020h:01 holds the 250 ms one.
  magnet_mm(200.0);
  h().run_ms(1);
  EXPECT_EQ(read_i32(0x6020, 1), 1000);
  h().run_ms(6);  // 259 ms
  EXPECT_EQ(read_i32(0x6020, 1), 1000);
  h().run_ms(2);  // 261 ms
  EXPECT_EQ(read_i32(0x6020, 1), 2000);
}

class Identity2 : public Hlt1100Test {
 protected:
  Identity2()
      : Hlt1100Test({{"speed_step", "20"},
                     {"supported_alarms", "0x0001"},
                     {"position_emcy_code", "0x7300"},
                     {"software_version_bcd", "0x0105"},
                     {"product_code", "0x12345678"},
                     {"serial", "4711"},
                     {"measuring_length_mm", "1000"},
                     {"manufacturer_offset", "100"}}) {}
};

TEST_F(Identity2, NameplateAndReadingsKnobs) {
  EXPECT_EQ(h().read_u(0x6005, 2), 20u);
  EXPECT_EQ(h().read_u(0x6504, 0), 0x0001u);
  EXPECT_EQ(h().read_u(0x6507, 0), 0x01050302u);
  EXPECT_EQ(h().read_u(0x1018, 2), 0x12345678u);
  EXPECT_EQ(h().read_u(0x650B, 0), 4711u);
  EXPECT_EQ(h().read_u(0x650A, 3), 9999u);
  EXPECT_EQ(read_i32(0x6020, 1), 1100);  // 100.0 mm + manufacturer offset 100
  start();
  device().inject_fault("magnet_lost", true);
  h().run_ms(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x73, 0x21})});
}

TEST(Hlt1100Settings, BadValuesAreRejected) {
  Settings s;
  EXPECT_NE(parse_settings({{"bit_rate_kbit", "100"}}, s), "");
  EXPECT_NE(parse_settings({{"factory_node_id", "128"}}, s), "");
  EXPECT_NE(parse_settings({{"signal", "sine:1"}}, s), "");
  EXPECT_NE(parse_settings({{"parameter_error", "maybe"}}, s), "");
  EXPECT_NE(parse_settings({{"eeprom_abort", "0x1"}}, s), "");
  Settings ok;
  EXPECT_EQ(parse_settings({{"factory_node_id", "255"}}, ok), "");
  EXPECT_EQ(ok.node_id, 255);
}

}  // namespace
}  // namespace hlt1100::test
