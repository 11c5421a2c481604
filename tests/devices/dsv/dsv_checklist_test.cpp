// The DSV digest's "Emulator test checklist" (§9), item by item, frame level.
#include "tests/devices/dsv/dsv_fixture.h"

namespace dsvtest {

TEST_F(DsvTest, C01_PowerOn) {
  EXPECT_EQ(boot, Frames{Frame(0x701, {0x00})});
  h->run_ms(1000);
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(status(), 0x0008);
}

TEST_F(DsvTest, C02_DeviceType) {
  EXPECT_EQ(sdo({0x40, 0x00, 0x10, 0x00}), Frames{resp({0x43, 0x00, 0x10, 0x00, 0x98, 0x01, 0x00, 0x00})});
}

TEST_F(DsvTest, C03_Identity) {
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x00}), Frames{resp({0x4F, 0x18, 0x10, 0x00, 0x01, 0x00, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x01}), Frames{resp({0x43, 0x18, 0x10, 0x01, 0x4D, 0x01, 0x00, 0x00})});
  EXPECT_EQ(read_abort(0x1018, 2), 0x06090011u);
}

TEST_F(DsvTest, C04_C05_VendorNameAndToggle) {
  EXPECT_EQ(sdo({0x40, 0x57, 0x60, 0x00}), Frames{resp({0x41, 0x57, 0x60, 0x00, 0x0B, 0x00, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x60}), Frames{resp({0x00, 0x57, 0x61, 0x6E, 0x64, 0x66, 0x6C, 0x75})});
  EXPECT_EQ(sdo({0x70}), Frames{resp({0x17, 0x68, 0x20, 0x41, 0x47, 0x00, 0x00, 0x00})});
  sdo({0x40, 0x57, 0x60, 0x00});
  EXPECT_EQ(sdo({0x70}), Frames{resp({0x80, 0x57, 0x60, 0x00, 0x00, 0x00, 0x03, 0x05})});
}

TEST_F(DsvTest, C06_MissingObjectsSubIndicesAndOtherModes) {
  EXPECT_EQ(read_abort(0x1008), 0x06020000u);
  EXPECT_EQ(read_abort(0x1400, 3), 0x06090011u);
  EXPECT_EQ(read_abort(0x63B0), 0x06020000u);
}

TEST_F(DsvTest, C07_ReadOnlyObjects) {
  EXPECT_EQ(write(0x6041, 0, 0, 2), 0x06010000u);
  EXPECT_EQ(write(0x1400, 1, 0x201, 4), 0x06010000u);
}

TEST_F(DsvTest, C08_NodeGuardingToggle) {
  for (std::uint8_t expected : {0x7F, 0xFF, 0x7F}) {
    h->send(Frame::remote(0x701, 1));
    EXPECT_EQ(h->take(), Frames{Frame(0x701, {expected})});
  }
  start();
  h->send(Frame::remote(0x701, 1));
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x85})});
  h->nmt(0x82, 1);
  h->run_ticks(1);
  h->take();
  h->send(Frame::remote(0x701, 1));
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x7F})});
}

TEST_F(DsvTest, C09_Heartbeat) {
  EXPECT_EQ(sdo({0x2B, 0x17, 0x10, 0x00, 0xC8, 0x00}), Frames{resp({0x60, 0x17, 0x10, 0x00, 0, 0, 0, 0})});
  const auto t0 = h->now();
  h->run_ms(601);
  const auto times = h->take_times();
  ASSERT_EQ(times.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(times[static_cast<std::size_t>(i)] - t0, sim::milliseconds(200 * (i + 1)));
  start();
  h->run_ms(200);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x05})});
  h->nmt(0x02, 1);
  h->run_ms(200);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x04})});
}

TEST_F(DsvTest, C10_GuardTimeLockedWhileHeartbeatRuns) {
  ASSERT_EQ(write(0x1017, 0, 200, 2), 0u);
  EXPECT_EQ(sdo({0x2B, 0x0C, 0x10, 0x00, 0x64, 0x00}), Frames{resp({0x80, 0x0C, 0x10, 0x00, 0x23, 0x00, 0x0A, 0x06})});
  ASSERT_EQ(write(0x1017, 0, 0, 2), 0u);
  EXPECT_EQ(sdo({0x2B, 0x0C, 0x10, 0x00, 0x64, 0x00}), Frames{resp({0x60, 0x0C, 0x10, 0x00, 0, 0, 0, 0})});
}

TEST_F(DsvTest, C11_LifeGuardingTimeout) {
  ASSERT_EQ(write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(write(0x100D, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->send(Frame::remote(0x701, 1));
  h->take();
  const auto t0 = h->now();
  // One tick (1 ms) at a time up to 400 ms of silence: the first frame and the tick that sent it.
  const auto [frames, at] = h->run_until_frames(t0, sim::milliseconds(400));
  EXPECT_EQ(frames, Frames{Frame(0x081, {0x00, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00})});
  // "About 300 ms after the last RTR": life time 100 ms x 3, not earlier, within a control cycle.
  EXPECT_GE(at, sim::milliseconds(300));
  EXPECT_LE(at, sim::milliseconds(301));
  h->run_ms(400);
  EXPECT_TRUE(h->take().empty());  // the event fires once
  EXPECT_EQ(status(), 0x0001);
}

TEST_F(DsvTest, C12_RpdoActivatesAndDrivesSolenoidA) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
  EXPECT_EQ(status(), 0x000F);
  h->run_ms(1);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
}

TEST_F(DsvTest, C13_ControlWordSequence) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x00});
  h->take();
  const std::pair<std::uint8_t, std::uint8_t> steps[] = {{0x03, 0x0B}, {0x01, 0x09}, {0x00, 0x08},
                                                         {0x01, 0x09}, {0x03, 0x0B}, {0x07, 0x0F}};
  for (auto [cw, st] : steps) {
    h->send(0x201, {cw, 0x00, 0x00, 0x00});
    EXPECT_EQ(h->take(), Frames{Frame(0x181, {st, 0x00})}) << int(cw);
  }
}

TEST_F(DsvTest, C14_NoMatchingTransitionStaysActive) {
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0005, 2), 0u);
  EXPECT_EQ(status(), 0x000F);
}

TEST_F(DsvTest, C15_RpdoInPreOperationalSdoWorks) {
  h->send(0x201, {0x07, 0x00, 0x00, 0x00});
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(status(), 0x0008);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  EXPECT_EQ(status(), 0x000F);
}

TEST_F(DsvTest, C16_ControlModeLockAndObjectSetSwitch) {
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x03}), Frames{resp({0x80, 0x43, 0x60, 0x00, 0x22, 0x00, 0x00, 0x08})});
  ASSERT_EQ(write(0x6040, 0, 0x0000, 2), 0u);
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x03}), Frames{resp({0x60, 0x43, 0x60, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(read(0x6380, 1), 0);
  EXPECT_EQ(read_abort(0x6300, 1), 0x06020000u);
}

TEST_F(DsvTest, C17_ControlModeSavedAndResetRemapsThePdos) {
  make(bus_mode({{"control_mode", "0"}}), "controller");
  ASSERT_EQ(write(0x6043, 0, 4, 1), 0u);
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65}), Frames{resp({0x60, 0x10, 0x10, 0x01, 0, 0, 0, 0})});
  h->nmt(0x81, 1);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  EXPECT_EQ(read(0x6043), 4);
  EXPECT_EQ(read(0x1A01, 0), 2);
  EXPECT_EQ(read(0x1A01, 2), 0x63810010);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  const auto f = h->take();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].id, 0x281u);
  ASSERT_EQ(f[0].data.size(), 4u);
  EXPECT_EQ(f[0].data[0], 0x0F);
  EXPECT_EQ(f[0].data[1], 0x00);
}

TEST_F(DsvTest, C18_UnsavedControlModeIsLostAtResetNode) {
  ASSERT_EQ(write(0x6043, 0, 3, 1), 0u);
  h->nmt(0x81, 1);
  h->run_ticks(1);
  h->take();
  EXPECT_EQ(read(0x6043), 1);
}

TEST_F(DsvTest, C19_WrongSignature) {
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x66}), Frames{resp({0x80, 0x10, 0x10, 0x01, 0x20, 0x00, 0x00, 0x08})});
}

TEST_F(DsvTest, C20_SavedHeartbeatAfterPowerCycle) {
  make(bus_mode(), "", 0, temp_store("c20"));
  ASSERT_EQ(write(0x1017, 0, 500, 2), 0u);
  ASSERT_EQ(write(0x1010, 2, 0x65766173, 4), 0u);
  power_cycle();
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  h->run_ms(1001);
  EXPECT_EQ(h->take(), (Frames{Frame(0x701, {0x7F}), Frame(0x701, {0x7F})}));
}

TEST_F(DsvTest, C21_RestoreBecomesValidAtResetAndPowerCycleBringsTheOldValueBack) {
  make(bus_mode(), "", 0, temp_store("c21"));
  ASSERT_EQ(write(0x1017, 0, 500, 2), 0u);
  ASSERT_EQ(write(0x1010, 1, 0x65766173, 4), 0u);
  EXPECT_EQ(sdo({0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64}), Frames{resp({0x60, 0x11, 0x10, 0x01, 0, 0, 0, 0})});
  EXPECT_EQ(read(0x1017), 500);
  h->nmt(0x82, 1);
  h->run_ticks(1);
  h->take();
  EXPECT_EQ(read(0x1017), 0);
  power_cycle();
  h->take();
  EXPECT_EQ(read(0x1017), 500);
}

TEST_F(DsvTest, C22_NodeIdChangeWithForcedFault) {
  make(bus_mode(), "", 0, temp_store("c22"));
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  ASSERT_EQ(write(0x2000, 0, 5, 1), 0u);
  h->nmt(0x82, 1);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), (Frames{Frame(0x705, {0x00}), Frame(0x085, {0x00, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00})}));
  h->send(0x605, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(h->take(), Frames{Frame(0x585, {0x4B, 0x41, 0x60, 0x00, 0x01, 0x00, 0x00, 0x00})});
  h->send(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(h->take().empty());
  power_cycle();
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  // From INIT, Reset Communication only boots.
  ASSERT_EQ(write(0x2000, 0, 6, 1), 0u);
  h->nmt(0x82, 1);
  h->run_ms(5);
  EXPECT_EQ(h->take(), Frames{Frame(0x706, {0x00})});
  h->send(0x606, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(h->take(), Frames{Frame(0x586, {0x4B, 0x41, 0x60, 0x00, 0x08, 0x00, 0x00, 0x00})});
}

TEST_F(DsvTest, C23_C24_BitRateAndNodeAddressRanges) {
  EXPECT_EQ(write(0x2001, 0, 30, 2), 0x06040043u);
  EXPECT_EQ(write(0x2001, 0, 125, 2), 0u);
  EXPECT_EQ(dev->active_bit_rate_kbit(), 20);
  h->nmt(0x82, 1);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  EXPECT_EQ(dev->active_bit_rate_kbit(), 125);
  EXPECT_EQ(write(0x2000, 0, 0, 1), 0x06090032u);
  EXPECT_EQ(write(0x2000, 0, 128, 1), 0x06090031u);
}

TEST_F(DsvTest, C25_StopWhileActive) {
  ASSERT_EQ(write(0x1017, 0, 100, 2), 0u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  h->run_ms(2);
  h->take();
  h->nmt(0x02, 1);
  h->run_ms(100);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x04})});
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  h->send(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(h->take().empty());
  h->nmt(0x01, 1);
  h->take();
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(read(0x1001), 0x11);
  make();
  h->nmt(0x02, 1);
  h->nmt(0x80, 1);
  EXPECT_EQ(status(), 0x0008);
}

TEST_F(DsvTest, C26_C27_FaultResetPaths) {
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  dev->inject_fault("general_error", true);
  h->run_ms(1);
  dev->inject_fault("general_error", false);
  h->run_ms(1);
  h->take();
  h->send(0x601, {0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0, 0});  // R edge with H = 1
  EXPECT_EQ(h->take(), (Frames{Frame(0x081, {0, 0, 0, 0, 0, 0, 0, 0}), resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})}));
  EXPECT_EQ(status(), 0x000F);
  ASSERT_EQ(write(0x6040, 0, 0x000F, 2), 0u);  // no new edge
  EXPECT_EQ(status(), 0x000F);
  dev->inject_fault("general_error", true);
  h->run_ms(1);
  dev->inject_fault("general_error", false);
  h->run_ms(1);
  h->take();
  ASSERT_EQ(write(0x6040, 0, 0x0000, 2), 0u);
  h->send(0x601, {0x2B, 0x40, 0x60, 0x00, 0x08, 0x00, 0, 0});
  EXPECT_EQ(h->take(), (Frames{Frame(0x081, {0, 0, 0, 0, 0, 0, 0, 0}), resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})}));
  EXPECT_EQ(status(), 0x0008);
  EXPECT_EQ(read(0x1001), 0);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  EXPECT_EQ(status(), 0x000F);
}

TEST_F(DsvTest, C28_ErrorHistory) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x00});
  h->nmt(0x02, 1);
  h->nmt(0x80, 1);
  h->take();
  EXPECT_EQ(sdo({0x40, 0x03, 0x10, 0x00}), Frames{resp({0x4F, 0x03, 0x10, 0x00, 0x01, 0x00, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x40, 0x03, 0x10, 0x01}), Frames{resp({0x43, 0x03, 0x10, 0x01, 0x00, 0x81, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x2F, 0x03, 0x10, 0x00, 0x00}), Frames{resp({0x60, 0x03, 0x10, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(read(0x1003), 0);
  EXPECT_EQ(sdo({0x2F, 0x03, 0x10, 0x00, 0x01}), Frames{resp({0x80, 0x03, 0x10, 0x00, 0x43, 0x00, 0x04, 0x06})});
}

TEST_F(DsvTest, C29_SolenoidAOpen) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  h->run_ms(2);
  h->take();
  ASSERT_GT(dev->solenoid_a(), 0.0);
  dev->inject_fault("solenoid_a_open", true);
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x11, 0x54, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(status(), 0x0001);
  h->run_ms(200);
  EXPECT_TRUE(h->take().empty());
  h->send(0x201, {0x00, 0x00, 0x00, 0x00});
  h->send(0x201, {0x08, 0x00, 0x00, 0x00});  // reset edge while still open: ignored
  EXPECT_EQ(h->take(), (Frames{Frame(0x181, {0x01, 0x00}), Frame(0x181, {0x01, 0x00})}));
}

TEST_F(DsvTest, C30_ErrorHandlingKeepsSolenoidAOn) {
  ASSERT_EQ(write(0x2043, 0, 1, 1), 0u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0xE0});  // −50 %: solenoid B driven
  h->run_ms(2);
  h->take();
  ASSERT_GT(dev->solenoid_b(), 0.0);
  dev->inject_fault("solenoid_b_open", true);
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x12, 0x54, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_NEAR(dev->solenoid_a(), 8192 * 1.536 / 16384, 1e-9);  // Imax A, no dither
  EXPECT_EQ(dev->solenoid_b(), 0.0);
}

TEST_F(DsvTest, C31_IminImaxCrossChecks) {
  EXPECT_EQ(write(0x6343, 1, 9000, 2), 0x06090031u);
  EXPECT_EQ(write(0x2340, 1, 100, 2), 0x06090032u);
}

TEST_F(DsvTest, C32_ModeOfOperationHardwareAndState) {
  make(bus_mode({{"solenoids", "1"}, {"mode_of_operation", "0"}}));
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  EXPECT_EQ(write(0x2042, 0, 2, 1), 0x06090032u);
  make();
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  EXPECT_EQ(write(0x2042, 0, 0, 1), 0x08000022u);
}

TEST_F(DsvTest, C33_ModeOfOperation3UsesRpdo2AndReleaseBits) {
  make(bus_mode({{"dither_amplitude", "0"}}), "", 0, temp_store("c33"));
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  ASSERT_EQ(write(0x2042, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x1010, 1, 0x65766173, 4), 0u);
  h->nmt(0x81, 1);
  h->run_ticks(1);
  h->take();
  start();
  h->send(0x301, {0x07, 0x60, 0x00, 0x20, 0x00, 0x10});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x60})});
  h->run_ms(1);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);
  EXPECT_NEAR(dev->solenoid_b(), amps(0.25), 1e-9);
  h->send(0x201, {0x00, 0x00, 0x00, 0x00});  // RPDO1 is not active
  EXPECT_TRUE(h->take().empty());
  h->send(0x301, {0x07, 0x20, 0x00, 0x20, 0x00, 0x10});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x20})});
  h->run_ms(1);
  EXPECT_EQ(dev->solenoid_b(), 0.0);
}

TEST_F(DsvTest, C34_RampRunningBitAndTimes) {
  ASSERT_EQ(write(0x6330, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x6332, 1, 1000, 2), 0u);
  ASSERT_EQ(write(0x6335, 1, 2000, 2), 0u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x40});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x02})});
  h->run_ms(500);
  h->send(0x201, {0x07, 0x00, 0x00, 0x40});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x02})});
  h->run_ms(499);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
  ASSERT_EQ(write(0x6300, 1, 0, 2), 0u);
  h->run_ms(1999);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
}

TEST_F(DsvTest, C35_SynchronousPdosAndTransmissionTypeRange) {
  ASSERT_EQ(write(0x1800, 2, 1, 1), 0u);
  ASSERT_EQ(write(0x1400, 2, 1, 1), 0u);
  EXPECT_EQ(write(0x1400, 2, 245, 1), 0x06040043u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(status(), 0x0008);
  h->send(0x080, {});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
  EXPECT_EQ(read(0x6300, 1), 0x2000);
  h->send(0x080, {});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
}

TEST_F(DsvTest, C36_RemoteRequests) {
  h->send(Frame::remote(0x181, 2));
  EXPECT_TRUE(h->take().empty());
  start();
  h->send(Frame::remote(0x181, 2));
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x08, 0x00})});
  h->send(Frame::remote(0x181, 0));
  EXPECT_EQ(h->take(), Frames{Frame(0x181, std::vector<std::uint8_t>{})});
}

TEST_F(DsvTest, C37_LocalOperation) {
  EXPECT_EQ(write(0x604F, 0, 1, 1), 0u);
  EXPECT_EQ(status(), 0x0018);
  EXPECT_EQ(sdo({0x2B, 0x00, 0x63, 0x01, 0x00, 0x00}), Frames{resp({0x80, 0x00, 0x63, 0x01, 0x21, 0x00, 0x00, 0x08})});
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x00});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x18, 0x00})});
}

TEST_F(DsvTest, C38_DitherParameterChecks) {
  EXPECT_EQ(write(0x6362, 1, 22, 2), 0x06040043u);
  EXPECT_EQ(write(0x6362, 1, 100, 2), 0u);
  EXPECT_EQ(write(0x6361, 1, 4267, 2), 0x06090031u);
}

TEST_F(DsvTest, C39_EnableInput) {
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(write(0x6300, 1, 8192, 2), 0u);
  h->run_ms(2);
  ASSERT_GT(dev->solenoid_a(), 0.0);
  dev->set_input("enable_input", 0);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x0008);
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  dev->set_input("enable_input", 1);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
}

TEST_F(DsvTest, C40_UnknownCommandSpecifiers) {
  EXPECT_EQ(sdo({0xE0, 0x00, 0x10, 0x00}), Frames{resp({0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x08})});
  EXPECT_EQ(sdo({0xA0, 0x00, 0x10, 0x00}), Frames{resp({0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x08})});
}

}  // namespace dsvtest
