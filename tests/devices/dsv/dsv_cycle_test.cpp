// The control cycle against the bus: a parameter written by SDO between two cycles acts in the
// very next one (nothing is held over from an earlier cycle), and the status word each cycle
// publishes into 6041h (what a change-driven TPDO sends) is the word status_word() computes
// from scratch. 6041h is looked at in the dictionary directly: an SDO read would rebuild it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tests/devices/dsv/dsv_fixture.h"

namespace dsvtest {

namespace {
class DsvCycleTest : public DsvTest {
 protected:
  void SetUp() override { make(bus_mode({{"dither_amplitude", "0"}})); }
  void control(std::uint16_t cw) { ASSERT_EQ(write(0x6040, 0, cw, 2), 0u); }
  void command(std::int16_t v) { ASSERT_EQ(write(0x6300, 1, static_cast<std::uint16_t>(v), 2), 0u); }
  std::uint16_t published() { return dev->node().od().get<std::uint16_t>(0x6041); }
  /// `n` cycles, each checked: the word published is the word computed.
  void cycles(int n) {
    for (int i = 0; i < n; ++i) {
      h->run_ms(1);
      ASSERT_EQ(published(), dev->control().status_word()) << "cycle " << i << " of " << n;
      words.push_back(published());
    }
  }
  static double counts_to_amps(double counts) { return counts * 1.536 / 16384; }
  std::vector<std::uint16_t> words;
};
}  // namespace

TEST_F(DsvCycleTest, PublishedStatusWordThroughRampsHoldAndModesOfOperation) {
  ASSERT_EQ(write(0x6330, 0, 3, 1), 0u);  // ramps on
  ASSERT_EQ(write(0x6332, 1, 100, 2), 0u);
  ASSERT_EQ(write(0x6335, 1, 50, 2), 0u);
  ASSERT_EQ(write(0x6333, 1, 80, 2), 0u);
  ASSERT_EQ(write(0x6336, 1, 40, 2), 0u);
  cycles(3);
  control(0x0007);
  command(16384);
  cycles(40);
  ASSERT_EQ(write(0x6332, 1, 20, 2), 0u);  // a shorter ramp mid-way: it ends at once
  cycles(5);
  command(-8192);
  cycles(30);
  ASSERT_EQ(write(0x6330, 0, 0, 1), 0u);  // ramps off mid-way: no ramp running any more
  cycles(2);
  ASSERT_EQ(write(0x6330, 0, 3, 1), 0u);
  command(8192);
  cycles(20);
  control(0x0003);  // HOLD mid-ramp
  cycles(5);
  control(0x0007);
  cycles(60);
  // Mode of operation 3: two set points, each solenoid released by the control word.
  control(0x0001);
  cycles(2);
  ASSERT_EQ(write(0x2042, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x6B00, 1, 12000, 2), 0u);
  command(6000);
  control(0x2007);
  cycles(30);
  control(0x6007);
  cycles(30);
  ASSERT_EQ(write(0x6B00, 1, 2000, 2), 0u);
  control(0x4007);
  cycles(30);
  control(0x0001);
  cycles(2);
  // Pressure open loop (mode 3) with the inversion of the set point.
  ASSERT_EQ(write(0x2042, 0, 2, 1), 0u);
  ASSERT_EQ(write(0x6043, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x62F0, 0, static_cast<std::uint8_t>(-1), 1), 0u);
  ASSERT_EQ(write(0x6380, 1, 9000, 2), 0u);
  control(0x0007);
  cycles(60);
  // The walk saw ramps running and at rest, HOLD and both solenoids released.
  auto seen = [this](std::uint16_t bits) {
    for (std::uint16_t w : words)
      if ((w & bits) == bits) return true;
    return false;
  };
  EXPECT_TRUE(seen(0x020F));
  EXPECT_TRUE(seen(0x000B));
  EXPECT_TRUE(seen(0x600F));
}

TEST_F(DsvCycleTest, PublishedStatusWordOfTheClosedLoopWindows) {
  make(bus_mode({{"control_mode", "9"}, {"sensor_max", "0.2"}, {"dither_amplitude", "0"}}), "controller");
  ASSERT_EQ(write(0x6231, 1, 200000, 4), 0u);
  ASSERT_EQ(write(0x6234, 1, 10000, 4), 0u);
  ASSERT_EQ(write(0x6670, 0, 2, 1), 0u);
  ASSERT_EQ(write(0x6673, 1, 1000, 4), 0u);
  ASSERT_EQ(write(0x2671, 1, 5, 4), 0u);
  ASSERT_EQ(write(0x6651, 0, 2, 1), 0u);
  ASSERT_EQ(write(0x6653, 1, 20000, 4), 0u);
  ASSERT_EQ(write(0x6652, 1, 3, 4), 0u);
  ASSERT_EQ(write(0x6600, 1, 100000, 4), 0u);
  ASSERT_EQ(dev->set_input("actual", 0.0998), "");
  control(0x0007);
  cycles(10);
  ASSERT_EQ(dev->set_input("actual", 0.05), "");
  cycles(10);
  control(0x0003);
  cycles(5);
  ASSERT_EQ(write(0x6673, 1, 60000, 4), 0u);  // a wider window while HOLD shows it
  cycles(10);
  control(0x0001);
  cycles(3);
  auto seen = [this](std::uint16_t w) { return std::find(words.begin(), words.end(), w) != words.end(); };
  EXPECT_TRUE(seen(0x100F));
  EXPECT_TRUE(seen(0x002F));
  EXPECT_TRUE(seen(0x102B));  // HOLD: the wider window reached, still beyond the trailing window
}

TEST_F(DsvCycleTest, CurrentParametersWrittenBetweenCyclesActInTheNextCycle) {
  control(0x0007);
  command(8192);
  cycles(1);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-12);
  ASSERT_EQ(write(0x2340, 1, 12000, 2), 0u);  // Imax A
  cycles(1);
  EXPECT_NEAR(dev->solenoid_a(), counts_to_amps(2731 + (12000 - 2731) * 0.5), 1e-12);
  ASSERT_EQ(write(0x6343, 1, 4000, 2), 0u);  // Imin A
  cycles(1);
  EXPECT_NEAR(dev->solenoid_a(), counts_to_amps(4000 + (12000 - 4000) * 0.5), 1e-12);
  ASSERT_EQ(write(0x6342, 0, 1, 1), 0u);     // dead band compensation on,
  ASSERT_EQ(write(0x6345, 1, 8192, 2), 0u);  // threshold A 25 %: u = (0.5 − 0.25) / 0.75
  cycles(1);
  EXPECT_NEAR(dev->solenoid_a(), counts_to_amps(4000 + (12000 - 4000) * (0.25 / 0.75)), 1e-12);
  command(-8192);  // B: its own limits and threshold (still the defaults, threshold 0)
  cycles(1);
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  EXPECT_NEAR(dev->solenoid_b(), amps(0.5), 1e-12);
  ASSERT_EQ(write(0x2341, 1, 10000, 2), 0u);  // Imax B
  cycles(1);
  EXPECT_NEAR(dev->solenoid_b(), counts_to_amps(2731 + (10000 - 2731) * 0.5), 1e-12);
  ASSERT_EQ(write(0x6342, 0, 0, 1), 0u);
  ASSERT_EQ(write(0x62F0, 0, static_cast<std::uint8_t>(-1), 1), 0u);  // inversion: back to A
  cycles(1);
  EXPECT_NEAR(dev->solenoid_a(), counts_to_amps(4000 + (12000 - 4000) * 0.5), 1e-12);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
}

TEST_F(DsvCycleTest, DitherWrittenBetweenCyclesActsInTheNextCycle) {
  control(0x0007);
  command(8192);
  cycles(2);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-12);  // no dither (amplitude 0)
  ASSERT_EQ(write(0x6360, 0, 1, 1), 0u);    // square dither
  ASSERT_EQ(write(0x6362, 1, 20, 2), 0u);   // 20 Hz
  ASSERT_EQ(write(0x6361, 1, 640, 2), 0u);  // 640 counts = 60 mA peak-to-peak
  cycles(1);
  const double half = 640 * 0.4 / 4266 / 2;
  EXPECT_NEAR(std::abs(dev->solenoid_a() - amps(0.5)), half, 1e-12);
  ASSERT_EQ(write(0x6361, 1, 320, 2), 0u);
  cycles(1);
  EXPECT_NEAR(std::abs(dev->solenoid_a() - amps(0.5)), half / 2, 1e-12);
  // 500 Hz: the square wave's sign alternates every 1 ms cycle from the first one on.
  ASSERT_EQ(write(0x6362, 1, 500, 2), 0u);
  double last = 0;
  for (int i = 0; i < 4; ++i) {
    cycles(1);
    const double d = dev->solenoid_a() - amps(0.5);
    EXPECT_NEAR(std::abs(d), half / 2, 1e-12);
    if (i > 0) {
      EXPECT_LT(d * last, 0) << i;
    }
    last = d;
  }
  ASSERT_EQ(write(0x6360, 0, 0, 1), 0u);  // dither off
  cycles(1);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-12);
}

TEST_F(DsvCycleTest, AConditionStillPresentAfterAResetNodeRaisesItsEmcyAgain) {
  auto supply_emcys = [](const Frames& frames) {
    return std::count_if(frames.begin(), frames.end(), [](const Frame& f) {
      return f.id == 0x081 && f.data.size() >= 2 && f.data[0] == 0x12 && f.data[1] == 0x34;
    });
  };
  ASSERT_EQ(dev->set_input("supply_voltage", 12), "");  // below u_supply_min
  h->run_ms(5);
  EXPECT_EQ(supply_emcys(h->take()), 1);
  h->nmt(0x81, 1);  // reset node: the errors are forgotten and detected afresh
  h->run_ms(5);
  EXPECT_EQ(supply_emcys(h->take()), 1);
}

}  // namespace dsvtest
