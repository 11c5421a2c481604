// The DSV signal chain against the digest's formulas (§5): Imin/Imax, dead-band jump,
// characteristic optimisation, dither, inversion, modes of operation, four-quadrant ramps,
// closed loops with their windows, actual-value acquisition, fault reaction.
#include <algorithm>

#include "tests/devices/dsv/dsv_fixture.h"

namespace dsvtest {

namespace {
class DsvChainTest : public DsvTest {
 protected:
  void SetUp() override { make(bus_mode({{"dither_amplitude", "0"}})); }
  void active() { ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u); }
  void command(std::int16_t v) { ASSERT_EQ(write(0x6300, 1, static_cast<std::uint16_t>(v), 2), 0u); }
  void step() { h->run_ms(1); }
};
}  // namespace

TEST_F(DsvChainTest, IminPlusSpanTimesDemandOnBothSides) {
  active();
  command(8192);
  step();
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
  command(-16384);
  step();
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  EXPECT_NEAR(dev->solenoid_b(), amps(1.0), 1e-9);
  command(0);
  step();
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
}

TEST_F(DsvChainTest, CurrentScaleFollowsImaxAndTheSupply) {
  ASSERT_EQ(write(0x2340, 1, 16384, 2), 0u);
  active();
  command(16384);
  step();
  EXPECT_NEAR(dev->solenoid_a(), 1.536, 1e-9);  // 16384 counts = 1536 mA at 24 V
  make(bus_mode({{"dither_amplitude", "0"}, {"supply_voltage_nominal", "12"}}));
  ASSERT_EQ(write(0x2340, 1, 16384, 2), 0u);
  active();
  command(16384);
  step();
  EXPECT_NEAR(dev->solenoid_a(), 2.560, 1e-9);  // … and 2560 mA at 12 V
}

TEST_F(DsvChainTest, DeadBandCompensationJumpsToIminAtTheThreshold) {
  ASSERT_EQ(write(0x6342, 0, 1, 1), 0u);
  ASSERT_EQ(write(0x6345, 1, 1638, 2), 0u);  // 1638/32768 = 5 %
  active();
  command(819);  // 5 %: inside the dead band
  step();
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  command(820);
  step();
  EXPECT_NEAR(dev->solenoid_a(), amps(0.0), 1e-3);  // the jump: Imin
  command(static_cast<std::int16_t>(16384 * 0.525));
  step();
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-3);  // (a − θ)/(1 − θ) = 0.5
  ASSERT_EQ(write(0x6B45, 1, 3277, 2), 0u);       // B: 10 %
  command(static_cast<std::int16_t>(-16384 * 0.1));
  step();
  EXPECT_EQ(dev->solenoid_b(), 0.0);
}

TEST_F(DsvChainTest, CharacteristicOptimisationThroughTheSelector) {
  EXPECT_EQ(read(0x2344, 4), 0);  // point 1 of A: (0 %, 0 ‰)
  ASSERT_EQ(write(0x2344, 3, 6, 2), 0u);
  EXPECT_EQ(read(0x2344, 4), 50);
  EXPECT_EQ(read(0x2344, 5), 500);
  ASSERT_EQ(write(0x2344, 5, 200, 2), 0u);  // A at 50 % preset → 20 % of the current span
  ASSERT_EQ(write(0x2344, 2, 1, 2), 0u);
  EXPECT_EQ(read(0x2344, 5), 500);  // B's point 6 unchanged
  ASSERT_EQ(write(0x2344, 2, 0, 2), 0u);
  EXPECT_EQ(read(0x2344, 5), 200);
  active();
  command(8192);
  step();
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);  // optimisation still off
  ASSERT_EQ(write(0x2344, 1, 1, 2), 0u);
  step();
  EXPECT_NEAR(dev->solenoid_a(), amps(0.2), 1e-9);
  EXPECT_EQ(write(0x2344, 3, 12, 2), 0x06090031u);
  EXPECT_EQ(write(0x2344, 3, 0, 2), 0x06090032u);
  EXPECT_EQ(write(0x2344, 5, 1001, 2), 0x06090031u);
}

TEST_F(DsvChainTest, CharacteristicPointsAreSavedWithTheApplicationGroup) {
  make(bus_mode({{"dither_amplitude", "0"}}), "", 0, temp_store("curve"));
  ASSERT_EQ(write(0x2344, 3, 6, 2), 0u);
  ASSERT_EQ(write(0x2344, 5, 200, 2), 0u);
  ASSERT_EQ(write(0x1010, 3, 0x65766173, 4), 0u);
  ASSERT_EQ(write(0x2344, 5, 300, 2), 0u);  // not saved
  power_cycle();
  h->take();
  ASSERT_EQ(write(0x2344, 3, 6, 2), 0u);
  EXPECT_EQ(read(0x2344, 5), 200);
  ASSERT_EQ(write(0x1011, 3, 0x64616F6C, 4), 0u);
  h->nmt(0x81, 1);
  h->run_ticks(1);
  h->take();
  EXPECT_EQ(read(0x6043), 0);  // the application group is back to its defaults
  ASSERT_EQ(write(0x6043, 0, 1, 1), 0u);
  ASSERT_EQ(write(0x2344, 3, 6, 2), 0u);
  EXPECT_EQ(read(0x2344, 5), 500);  // and so are the characteristic points
}

TEST_F(DsvChainTest, DitherAmplitudeAndFrequencyInTheCurrent) {
  ASSERT_EQ(write(0x6360, 0, 1, 1), 0u);
  ASSERT_EQ(write(0x6362, 1, 100, 2), 0u);
  ASSERT_EQ(write(0x6361, 1, 533, 2), 0u);  // 533 counts = 49.98 mA peak-to-peak
  active();
  command(8192);
  std::vector<double> samples;
  for (int i = 0; i < 100; ++i) {
    step();
    samples.push_back(dev->solenoid_a());
  }
  const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
  EXPECT_NEAR(*hi - *lo, 533 * 0.4 / 4266, 1e-9);
  EXPECT_NEAR((*hi + *lo) / 2, amps(0.5), 1e-9);
  int edges = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) edges += samples[i] != samples[i - 1];
  EXPECT_GE(edges, 19);
  EXPECT_LE(edges, 20);
  EXPECT_EQ(dev->solenoid_b(), 0.0);  // no dither on the idle solenoid
}

TEST_F(DsvChainTest, InversionAndModesOfOperation) {
  ASSERT_EQ(write(0x62F0, 0, static_cast<std::uint8_t>(-1), 1), 0u);
  active();
  command(8192);  // bipolar, inverted: B
  step();
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  EXPECT_NEAR(dev->solenoid_b(), amps(0.5), 1e-9);
  ASSERT_EQ(write(0x62F0, 0, 1, 1), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  ASSERT_EQ(write(0x2042, 0, 1, 1), 0u);  // unipolar 2-solenoid: 50 % is neutral
  active();
  command(8192);
  step();
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
  command(16384);
  step();
  EXPECT_NEAR(dev->solenoid_a(), amps(1.0), 1e-9);
  command(0);
  step();
  EXPECT_NEAR(dev->solenoid_b(), amps(1.0), 1e-9);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  ASSERT_EQ(write(0x2042, 0, 0, 1), 0u);  // unipolar 1-solenoid: negative is nothing
  active();
  command(-8192);
  step();
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
}

TEST_F(DsvChainTest, FourQuadrantRampWithinOneCycle) {
  ASSERT_EQ(write(0x6330, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x6332, 1, 400, 2), 0u);   // A up
  ASSERT_EQ(write(0x6335, 1, 200, 2), 0u);   // A down
  ASSERT_EQ(write(0x6333, 1, 800, 2), 0u);   // B up
  ASSERT_EQ(write(0x6336, 1, 100, 2), 0u);   // B down
  active();
  command(16384);
  h->run_ms(399);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
  command(-16384);  // 200 ms to 0, 800 ms to −100 %
  h->run_ms(100);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-3);
  h->run_ms(500);  // 600 ms: 400 ms into B up = 50 %
  EXPECT_NEAR(dev->solenoid_b(), amps(0.5), 1e-3);
  h->run_ms(399);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
  command(0);  // B down 100 ms
  h->run_ms(99);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
}

TEST_F(DsvChainTest, HoldFreezesTheRampAndDisabledSwitchesOff) {
  ASSERT_EQ(write(0x6330, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x6332, 1, 1000, 2), 0u);
  active();
  command(16384);
  h->run_ms(500);
  ASSERT_EQ(write(0x6040, 0, 0x0003, 2), 0u);
  h->run_ms(500);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-3);
  EXPECT_EQ(status(), 0x000B);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  h->run_ms(1);
  EXPECT_EQ(dev->solenoid_a(), 0.0);
}

TEST_F(DsvChainTest, ErrorHandlingBothSolenoidsOn) {
  ASSERT_EQ(write(0x2043, 0, 3, 1), 0u);
  active();
  dev->inject_fault("general_error", true);
  step();
  EXPECT_NEAR(dev->solenoid_a(), amps(1.0), 1e-9);
  EXPECT_NEAR(dev->solenoid_b(), amps(1.0), 1e-9);
  make(bus_mode({{"solenoids", "1"}, {"mode_of_operation", "0"}}));
  EXPECT_EQ(write(0x2043, 0, 2, 1), 0x06090032u);
}

TEST_F(DsvChainTest, SharedParametersFollowTheControlMode) {
  ASSERT_EQ(write(0x6343, 1, 3000, 2), 0u);
  ASSERT_EQ(write(0x6043, 0, 3, 1), 0u);
  EXPECT_EQ(read(0x63C3, 1), 3000);
  EXPECT_EQ(read_abort(0x6343, 1), 0x06020000u);
}

// ---- closed loop (controller) -------------------------------------------------------------------

namespace {
class DsvLoopTest : public DsvTest {
 protected:
  void SetUp() override {
    make(bus_mode({{"control_mode", "9"}, {"sensor_max", "0.2"}, {"dither_amplitude", "0"}}), "controller");
    ASSERT_EQ(write(0x6231, 1, 200000, 4), 0u);  // 0..200 mm over 0..10 V
    ASSERT_EQ(write(0x6234, 1, 10000, 4), 0u);
    ASSERT_EQ(write(0x6603, 1, 2000, 4), 0u);    // Kp 2 for a positive deviation
    ASSERT_EQ(write(0x2604, 1, 2000, 4), 0u);    // and for a negative one
  }
  void position(double metres) { ASSERT_EQ(dev->set_input("actual", metres), ""); }
};
}  // namespace

TEST_F(DsvLoopTest, PositionLoopDrivesTowardTheSetPoint) {
  position(0.05);
  ASSERT_EQ(write(0x6600, 1, 100000, 4), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(2);
  EXPECT_EQ(read(0x6601, 1), 50000);
  EXPECT_EQ(read(0x6650, 1), 50000);
  // e = 50 mm of a 200 mm span, Kp 2 → u = 0.5 on A; B at Imin ("Imin always active").
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);
  EXPECT_NEAR(dev->solenoid_b(), amps(0.0), 1e-9);
  position(0.15);
  h->run_ms(1);
  EXPECT_NEAR(dev->solenoid_b(), amps(0.5), 1e-9);
  ASSERT_EQ(write(0x2047, 0, 1, 1), 0u);  // Imin always active: NO
  h->run_ms(1);
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  ASSERT_EQ(write(0x2044, 0, 1, 1), 0u);  // system control inverted: A instead of B
  h->run_ms(1);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
  ASSERT_EQ(write(0x2045, 0, 1, 1), 0u);  // output A inverted: falling curve
  h->run_ms(1);
  EXPECT_NEAR(dev->solenoid_a(), (8192 - (8192 - 2731) * 0.5) * 1.536 / 16384, 1e-9);
}

TEST_F(DsvLoopTest, TargetWindowWithDelayAndTrailingWindowWarning) {
  ASSERT_EQ(write(0x6670, 0, 2, 1), 0u);
  ASSERT_EQ(write(0x6673, 1, 1000, 4), 0u);  // 1 mm
  ASSERT_EQ(write(0x2671, 1, 50, 4), 0u);    // 50 ms
  ASSERT_EQ(write(0x6651, 0, 2, 1), 0u);
  ASSERT_EQ(write(0x6653, 1, 20000, 4), 0u);  // 20 mm
  ASSERT_EQ(write(0x6652, 1, 10, 4), 0u);
  ASSERT_EQ(write(0x6600, 1, 100000, 4), 0u);
  position(0.0998);  // 0.2 mm off (ADC: 99805 raw)
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(49);
  EXPECT_EQ(status(), 0x000F);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x100F);
  position(0.05);  // 50 mm off: out of the window at once, warning after 10 ms
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
  h->run_ms(10);
  EXPECT_EQ(status(), 0x002F);
}

TEST_F(DsvLoopTest, SolenoidOffWindowAndSpeedLimit) {
  ASSERT_EQ(write(0x2673, 1, 2000, 4), 0u);  // 2 mm
  ASSERT_EQ(write(0x2672, 1, 5, 4), 0u);
  ASSERT_EQ(write(0x6600, 1, 100000, 4), 0u);
  position(0.0995);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(3);
  EXPECT_GT(dev->solenoid_a(), 0.0);
  h->run_ms(5);
  EXPECT_EQ(dev->solenoid_a(), 0.0);  // inside the solenoid-off window long enough
  EXPECT_EQ(dev->solenoid_b(), 0.0);
  ASSERT_EQ(write(0x2048, 0, 1, 1), 0u);  // solenoids stay active in position
  h->run_ms(1);
  EXPECT_GT(dev->solenoid_a(), 0.0);
  // Speed+ 10 mm/s: a step of the set point is followed at that rate.
  ASSERT_EQ(write(0x22B2, 1, 10000, 4), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  position(0.0);
  ASSERT_EQ(write(0x6600, 1, 200000, 4), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(1000);
  // Limited set point 10000 (10 mm), actual 0: u = 2·10000/200000 = 0.1.
  EXPECT_NEAR(dev->solenoid_a(), amps(0.1), 1e-3);
}

TEST_F(DsvLoopTest, ActualValueSignalTypesAndCableBreak) {
  ASSERT_EQ(write(0x6040, 0, 0x0000, 2), 0u);
  ASSERT_EQ(write(0x6043, 0, 4, 1), 0u);
  ASSERT_EQ(write(0x2200, 0, 3, 1), 0u);  // 4..20 mA
  position(0.1);  // half of 0..0.2: 12 mA
  EXPECT_EQ(read(0x6381, 1), 9831);
  position(0.0);  // 4 mA
  EXPECT_EQ(read(0x6381, 1), 3277);
  EXPECT_EQ(write(0x2201, 0, 1, 1), 0u);
  ASSERT_EQ(dev->set_input("actual_cable_break", 1), "");
  h->run_ms(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x22, 0x34, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(status(), 0x0001);
  ASSERT_EQ(write(0x2200, 0, 2, 1), 0u);  // 0..20 mA
  EXPECT_EQ(write(0x2201, 0, 1, 1), 0x06040043u);  // cable break needs 4..20 mA
}

TEST_F(DsvLoopTest, VelocityModeScaling) {
  ASSERT_EQ(write(0x6043, 0, 7, 1), 0u);
  ASSERT_EQ(write(0x2202, 0, 1, 1), 0u);       // mm/s
  ASSERT_EQ(write(0x2223, 1, 400000, 4), 0u);  // 0..400 mm/s
  ASSERT_EQ(write(0x2221, 1, 10000, 4), 0u);   // over 0..10 V
  position(0.05);                              // sensor 0..0.2: 2.5 V → count 256
  EXPECT_EQ(read(0x6501, 1), 100000);
  EXPECT_EQ(read(0x2050, 1), 390);  // 400000 / 1024
}

}  // namespace dsvtest
