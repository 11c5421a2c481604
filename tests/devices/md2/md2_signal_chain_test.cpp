// The MD2 signal chain against the digest's formulas (§5): solenoid current
// Imin + (Imax − Imin)·|u| above the dead band, ramp timing, dither, closed loops, n-point.
#include <algorithm>
#include <set>

#include "tests/devices/md2/md2_fixture.h"

namespace md2test {

namespace {
class Md2ChainTest : public Md2Test {
 protected:
  void SetUp() override { make({{"dither_level", "0"}}); }
  void active() { ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u); }
  void command(std::int16_t v) { ASSERT_EQ(write(0x6300, 1, static_cast<std::uint16_t>(v), 2), 0u); }
};
}  // namespace

TEST_F(Md2ChainTest, CurrentIsIminPlusSpanTimesCommand) {
  active();
  for (std::int16_t v : {16384, 8192, 4096, 1638}) {
    command(v);
    h->run_ms(1);
    EXPECT_NEAR(ch().solenoid_a, 0.2 + 0.8 * v / 16384.0, 1e-9) << v;
    EXPECT_EQ(ch().solenoid_b, 0.0);
  }
  command(-8192);
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_NEAR(ch().solenoid_b, 0.6, 1e-9);
}

TEST_F(Md2ChainTest, DeadBandJumpsFromZeroToImin) {
  active();
  command(164);  // = dead band (1 %): still off
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  command(165);
  h->run_ms(1);
  EXPECT_NEAR(ch().solenoid_a, 0.2 + 0.8 * 165 / 16384.0, 1e-9);  // the jump to ≈ Imin
  command(-164);
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_b, 0.0);
}

TEST_F(Md2ChainTest, CurrentLimitsFollowTheSettings) {
  make({{"dither_level", "0"}, {"i_min_a", "0.1"}, {"i_max_a", "0.7"}, {"i_min_b", "0.3"}, {"i_max_b", "1.2"}});
  active();
  command(16384);
  h->run_ms(1);
  EXPECT_DOUBLE_EQ(ch().solenoid_a, 0.7);
  command(-16384);
  h->run_ms(1);
  EXPECT_DOUBLE_EQ(ch().solenoid_b, 1.2);
  // RPDO values out of range are clamped to ±16384, never beyond Imax.
  start();
  h->send(0x201, {0x07, 0x00, 0xFF, 0x7F});
  h->run_ms(1);
  EXPECT_EQ(read(0x6300, 1), 16384u);
  EXPECT_DOUBLE_EQ(ch().solenoid_a, 0.7);
}

TEST_F(Md2ChainTest, OneSolenoidValveIgnoresNegativeCommands) {
  make({{"dither_level", "0"}, {"solenoids", "1"}});
  active();
  command(-8192);
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_EQ(ch().solenoid_b, 0.0);
}

TEST_F(Md2ChainTest, RampDownAndThroughZeroWithinOneCycle) {
  make({{"dither_level", "0"}, {"ramp_up_ms", "400"}, {"ramp_down_ms", "200"}});
  active();
  command(16384);
  h->run_ms(400);
  EXPECT_DOUBLE_EQ(ch().solenoid_a, 1.0);
  EXPECT_EQ(status(), 0x000F);
  command(-16384);  // 200 ms down to 0, then 400 ms up on B
  h->run_ms(150);
  EXPECT_NEAR(ch().solenoid_a, 0.2 + 0.8 * 0.25, 0.8 * 0.006);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(449);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(2);
  EXPECT_DOUBLE_EQ(ch().solenoid_b, 1.0);
  EXPECT_EQ(status(), 0x000F);
}

// The MD2 shares the DSV's setting names; its older spellings (dither_freq, nv_control_mode) still
// work, with a warning naming the new one, and give the same device.
TEST_F(Md2ChainTest, DeprecatedSettingNamesGiveTheSameDeviceWithAWarning) {
  const auto run = [this](std::map<std::string, std::string> settings, const std::string& variant) {
    settings["dither_level"] = "0.05";
    make(settings, variant);
    active();
    command(8192);
    std::vector<double> samples;
    for (int i = 0; i < 60; ++i) {
      h->run_ticks(1);
      samples.push_back(ch().solenoid_a);
    }
    samples.push_back(read(0x6043));  // the delivered control mode
    return samples;
  };
  const auto dither = run({{"dither_frequency", "50"}}, "");
  EXPECT_EQ(run({{"dither_freq", "50"}}, ""), dither);
  EXPECT_NE(run({{"dither_frequency", "100"}}, ""), dither);  // the knob matters
  const auto mode = run({{"control_mode", "4"}}, "controller");
  EXPECT_EQ(run({{"nv_control_mode", "4"}}, "controller"), mode);
  EXPECT_EQ(mode.back(), 4);  // the delivered mode, not the controller's default 3

  devices::DeviceOptions o;
  o.variant = "controller";
  o.settings = {{"dither_freq", "50"}, {"nv_control_mode", "4"}};
  std::vector<std::string> warnings;
  o.warnings = &warnings;
  std::string error;
  ASSERT_TRUE(md2::Md2Device::create(o, error)) << error;
  EXPECT_EQ(warnings, (std::vector<std::string>{"setting 'nv_control_mode' is deprecated: use 'control_mode'",
                                                "setting 'dither_freq' is deprecated: use 'dither_frequency'"}));
  o.settings["control_mode"] = "4";  // both spellings of one setting
  EXPECT_FALSE(md2::Md2Device::create(o, error));
  EXPECT_EQ(error, "setting 'nv_control_mode' is the deprecated name of 'control_mode': give only 'control_mode'");
}

TEST_F(Md2ChainTest, DitherAmplitudeAndFrequencyInTheCurrent) {
  make({{"dither_frequency", "100"}, {"dither_level", "0.05"}});  // 5 % of Imax peak-to-peak = 50 mA
  active();
  command(8192);  // DC 0.6 A
  std::vector<double> samples;
  for (int i = 0; i < 100; ++i) {
    h->run_ticks(1);
    samples.push_back(ch().solenoid_a);
  }
  const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
  EXPECT_NEAR(*hi - *lo, 0.05, 1e-9);
  EXPECT_NEAR((*hi + *lo) / 2, 0.6, 1e-9);
  // 100 Hz: the square wave changes level every 5 ms, i.e. 20 edges in 100 ms.
  int edges = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) edges += samples[i] != samples[i - 1];
  EXPECT_GE(edges, 19);
  EXPECT_LE(edges, 20);
  // No dither on a switched-off solenoid.
  EXPECT_EQ(ch().solenoid_b, 0.0);
  command(0);
  h->run_ms(20);
  EXPECT_EQ(ch().solenoid_a, 0.0);
}

TEST_F(Md2ChainTest, HoldKeepsTheLastSetPointAndOutputsOffOutsideActive) {
  active();
  command(8192);
  h->run_ms(1);
  ASSERT_EQ(write(0x6040, 0, 0x0003, 2), 0u);  // HOLD from ACTIVE: set point frozen
  command(16384);
  h->run_ms(5);
  EXPECT_NEAR(ch().solenoid_a, 0.6, 1e-9);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(1);
  EXPECT_NEAR(ch().solenoid_a, 1.0, 1e-9);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);  // DISABLED: off
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  ASSERT_EQ(write(0x6040, 0, 0x0003, 2), 0u);  // HOLD from DISABLED: nothing held
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
}

TEST_F(Md2ChainTest, LocalCommandWithDeviceMode2) {
  ASSERT_EQ(write(0x6042, 0, 2, 1), 0u);
  ASSERT_EQ(dev->set_input("ch1.local_command", 0.5), "");
  active();
  h->run_ms(1);
  EXPECT_NEAR(ch().solenoid_a, 0.6, 1e-9);
  // Bus command values are refused while the source is local.
  EXPECT_EQ(write(0x6300, 1, 100, 2), 0x08000021u);
}

TEST_F(Md2ChainTest, PressureClosedLoopWithLocalSensor) {
  make({{"dither_level", "0"}, {"kp", "4"}, {"ki", "20"}, {"p_range", "20000000"}}, "controller");
  ASSERT_EQ(write(0x6043, 0, 4, 1), 0u);
  ASSERT_EQ(write(0x6380, 1, 8192, 2), 0u);  // 50 % = 100 bar
  ASSERT_EQ(dev->set_input("actual", 60e5), "");  // 60 bar → 4915 counts
  active();
  h->run_ms(2);
  EXPECT_EQ(read(0x6381, 1), 4915u);
  EXPECT_EQ(read(0x63D0, 1), 8192u - 4915u);
  EXPECT_GT(ch().solenoid_a, 0.2);
  EXPECT_EQ(ch().solenoid_b, 0.0);  // mode 4 drives one solenoid only
  EXPECT_EQ(status() & 0x1000, 0);
  dev->set_input("actual", 100e5);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x100F);  // within the window
  // Above the set point (150 bar = 12288 counts) the single-solenoid loop lowers its output to
  // nothing (u is clamped at 0; there is no B side to push the pressure down).
  dev->set_input("actual", 150e5);
  h->run_ms(200);
  EXPECT_EQ(static_cast<std::int16_t>(read(0x63D0, 1)), 8192 - 12288);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_EQ(status(), 0x000F);  // outside the window
}

TEST_F(Md2ChainTest, VelocityLoopDrivesBothWaysAndSpeedLimitsTheSetPoint) {
  // The small loop outputs below are inside the 1 % dead band of the default (every mode).
  make({{"dither_level", "0"}, {"unit", "mm/s"}, {"deadband_modes", "open_loop"}}, "controller");
  ASSERT_EQ(write(0x6043, 0, 9, 1), 0u);
  ASSERT_EQ(write(0x2400, 0, 10000, 4), 0u);  // Speed+ 10 mm/s
  ASSERT_EQ(dev->set_input("actual", 0.0), "");
  ASSERT_EQ(write(0x6600, 1, 100000, 4), 0u);  // 100 mm/s ... as position in this unit
  active();
  // Pure P loop (kp 1, ki 0): u = (r − y) / span with span = 2 000 000 for mm/s, and the current
  // Imin + (Imax − Imin)·u (dead band off in the closed loop here). r, the set point rate-limited to
  // Speed+, climbs 10000 per second; unlimited it would be 100000 at once (0.24 A).
  const auto current_for = [](double r) { return 0.2 + 0.8 * r / 2e6; };
  const double tick = 0.8 * 10 / 2e6;  // one 1 ms control cycle of the ramp
  h->run_ms(500);
  EXPECT_NEAR(ch().solenoid_a, current_for(5000), tick);
  h->run_ms(500);
  EXPECT_NEAR(ch().solenoid_a, current_for(10000), tick);
  EXPECT_EQ(read(0x6650, 1), 100000u);  // deviation is reported against the set point
  h->run_ms(9000);  // r reaches w after 10 s and stays there
  EXPECT_NEAR(ch().solenoid_a, current_for(100000), tick);
  h->run_ms(1000);
  EXPECT_NEAR(ch().solenoid_a, current_for(100000), 1e-12);
  dev->set_input("actual", 0.2);  // 200 mm/s in mm/s... above the set point
  h->run_ms(2);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_GT(ch().solenoid_b, 0.0);
}

TEST_F(Md2ChainTest, NPointControllers) {
  make({{"dither_level", "0"}, {"hysteresis", "0.01"}}, "controller");  // h = 20000
  ASSERT_EQ(write(0x6043, 0, static_cast<std::uint8_t>(-7), 1), 0u);
  ASSERT_EQ(write(0x2200, 0, 1, 1), 0u);
  ASSERT_EQ(write(0x2280, 0, 100000, 4), 0u);
  active();
  ASSERT_EQ(write(0x2202, 0, 50000, 4), 0u);  // e = 50000 > h: A fully on
  h->run_ms(1);
  EXPECT_DOUBLE_EQ(ch().solenoid_a, 1.0);
  EXPECT_EQ(ch().solenoid_b, 0.0);
  ASSERT_EQ(write(0x2202, 0, 95000, 4), 0u);  // inside the hysteresis: unchanged
  h->run_ms(1);
  EXPECT_DOUBLE_EQ(ch().solenoid_a, 1.0);
  ASSERT_EQ(write(0x2202, 0, 150000, 4), 0u);  // e < −h: B on
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_DOUBLE_EQ(ch().solenoid_b, 1.0);
  // 3-point: both off inside the band.
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  ASSERT_EQ(write(0x6043, 0, static_cast<std::uint8_t>(-8), 1), 0u);
  active();
  ASSERT_EQ(write(0x2202, 0, 95000, 4), 0u);
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_EQ(ch().solenoid_b, 0.0);
}

TEST_F(Md2ChainTest, TemperatureRisesWithTheCurrent) {
  active();
  command(16384);
  EXPECT_EQ(read(0x2002), 25u);
  h->run_ms(60000);
  // 1 A on A: target 25 + 10·1² = 35 °C; after one time constant ≈ 63 %.
  const auto t = static_cast<std::int16_t>(read(0x2002));
  EXPECT_GE(t, 31);
  EXPECT_LE(t, 32);
}

TEST_F(Md2ChainTest, ChannelsAreIndependent) {
  ASSERT_EQ(write(0x6840, 0, 0x0007, 2), 0u);
  ASSERT_EQ(write(0x6B00, 1, 16384, 2), 0u);
  h->run_ms(1);
  EXPECT_EQ(read(0x6841), 0x000Fu);
  EXPECT_EQ(status(), 0x0008);
  EXPECT_DOUBLE_EQ(ch(2).solenoid_a, 1.0);
  EXPECT_EQ(ch(1).solenoid_a, 0.0);
  start();
  h->send(0x301, {0x01, 0x00, 0x00, 0x00});  // RPDO2 → channel 2, TPDO2 answers
  EXPECT_EQ(h->take(), Frames{Frame(0x281, {0x09, 0x00})});
  EXPECT_EQ(read(0x9841), 0x0008u);  // channel 8 exists
}

}  // namespace md2test
