// The MD2 digest's "Emulator test checklist" (§8), item by item, frame level. Node 1, 20 kbit/s,
// amplifier, delivery state (0x6043 = 1) unless the item says otherwise.
#include <cstdio>
#include <memory>
#include <vector>

#include "tests/devices/md2/md2_fixture.h"
#include "tests/support/temp_path.h"

namespace md2test {

namespace {
// Removed when the test program exits (ctest runs each case as its own process).
std::string temp_store(const char* name) {
  static std::vector<std::unique_ptr<vtest::TempPath>> paths;
  paths.push_back(std::make_unique<vtest::TempPath>(std::string("md2_") + name, ".store"));
  return paths.back()->str();
}
}  // namespace

TEST_F(Md2Test, C01_PowerOnSendsOneBootUpThenSilence) {
  EXPECT_EQ(boot, Frames{Frame(0x701, {0x00})});
  h->run_ms(2000);
  EXPECT_TRUE(h->take().empty());
}

TEST_F(Md2Test, C02_DeviceType) {
  EXPECT_EQ(sdo({0x40, 0x00, 0x10, 0x00}), Frames{resp({0x43, 0x00, 0x10, 0x00, 0x98, 0x01, 0x00, 0x10})});
}

TEST_F(Md2Test, C03_Identity) {
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x01}), Frames{resp({0x43, 0x18, 0x10, 0x01, 0x4D, 0x01, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x00}), Frames{resp({0x4F, 0x18, 0x10, 0x00, 0x01, 0x00, 0x00, 0x00})});
}

TEST_F(Md2Test, C04_VendorNameSegmented) {
  EXPECT_EQ(sdo({0x40, 0x57, 0x60, 0x00}), Frames{resp({0x41, 0x57, 0x60, 0x00, 0x0B, 0x00, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x60}), Frames{resp({0x00, 0x57, 0x61, 0x6E, 0x64, 0x66, 0x6C, 0x75})});
  EXPECT_EQ(sdo({0x70}), Frames{resp({0x17, 0x68, 0x20, 0x41, 0x47, 0x00, 0x00, 0x00})});
}

TEST_F(Md2Test, C05_FirstSegmentWithToggle1Aborts) {
  sdo({0x40, 0x57, 0x60, 0x00});
  EXPECT_EQ(sdo({0x70}), Frames{resp({0x80, 0x57, 0x60, 0x00, 0x00, 0x00, 0x03, 0x05})});
}

TEST_F(Md2Test, C06_MissingObjectAndSubIndex) {
  EXPECT_EQ(sdo({0x40, 0x08, 0x10, 0x00}), Frames{resp({0x80, 0x08, 0x10, 0x00, 0x00, 0x00, 0x02, 0x06})});
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x05}), Frames{resp({0x80, 0x18, 0x10, 0x05, 0x11, 0x00, 0x09, 0x06})});
}

TEST_F(Md2Test, C07_StatusWordIsReadOnly) {
  EXPECT_EQ(sdo({0x2B, 0x41, 0x60, 0x00, 0x0F, 0x00}), Frames{resp({0x80, 0x41, 0x60, 0x00, 0x00, 0x00, 0x01, 0x06})});
}

TEST_F(Md2Test, C08_ControlWordWithOneByteIsTooShort) {
  EXPECT_EQ(sdo({0x2F, 0x40, 0x60, 0x00, 0x07}), Frames{resp({0x80, 0x40, 0x60, 0x00, 0x13, 0x00, 0x07, 0x06})});
  EXPECT_EQ(status(), 0x0008);
}

TEST_F(Md2Test, C09_RpdoInPreOperationalIsIgnored) {
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(read(0x6040), 0u);
  EXPECT_EQ(status(), 0x0008);
}

TEST_F(Md2Test, C10_SyncInPreOperationalIsIgnored) {
  h->send(0x080, {});
  h->run_ms(10);
  EXPECT_TRUE(h->take().empty());
}

TEST_F(Md2Test, C11_RpdoInOperationalAnsweredByTpdo) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
  EXPECT_EQ(read(0x6300, 1), 0x2000u);
}

TEST_F(Md2Test, C12_RemoteRequestForTpdo1) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x00});
  h->take();
  h->send(Frame::remote(0x181, 2));
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
  h->send(Frame::remote(0x181, 0));
  EXPECT_EQ(h->take(), Frames{Frame(0x181, std::vector<std::uint8_t>{})});
}

TEST_F(Md2Test, C13_ControlWordsByRpdoChainDownAndUp) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x00});
  h->take();
  h->send(0x201, {0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x08, 0x00})});
  h->send(0x201, {0x01, 0x00, 0x00, 0x00});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x09, 0x00})});
  h->send(0x201, {0x03, 0x00, 0x00, 0x00});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0B, 0x00})});
}

TEST_F(Md2Test, C14_ControlModeLockedOutsideInitAndDisabled) {
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x03}), Frames{resp({0x80, 0x43, 0x60, 0x00, 0x22, 0x00, 0x00, 0x08})});
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x03}), Frames{resp({0x60, 0x43, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00})});
}

TEST_F(Md2Test, C15_ControlModeSupportedByVariant) {
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x07}), Frames{resp({0x80, 0x43, 0x60, 0x00, 0x43, 0x00, 0x04, 0x06})});
  make({}, "controller");
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x07}), Frames{resp({0x60, 0x43, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(read(0x6043), 7u);
}

TEST_F(Md2Test, C16_CommandValueLimits) {
  EXPECT_EQ(sdo({0x2B, 0x00, 0x63, 0x01, 0x01, 0x40}), Frames{resp({0x80, 0x00, 0x63, 0x01, 0x31, 0x00, 0x09, 0x06})});
  EXPECT_EQ(sdo({0x2B, 0x00, 0x63, 0x01, 0xFF, 0xBF}), Frames{resp({0x80, 0x00, 0x63, 0x01, 0x32, 0x00, 0x09, 0x06})});
  EXPECT_EQ(write(0x6300, 1, 0x4000, 2), 0u);
  EXPECT_EQ(write(0x6300, 1, 0xC000, 2), 0u);
}

TEST_F(Md2Test, C17_PdoParametersOnlyInPreOperational) {
  start();
  EXPECT_EQ(sdo({0x2F, 0x00, 0x18, 0x02, 0x01}), Frames{resp({0x80, 0x00, 0x18, 0x02, 0x22, 0x00, 0x00, 0x08})});
  h->nmt(0x80, 1);
  EXPECT_EQ(sdo({0x2F, 0x00, 0x18, 0x02, 0x01}), Frames{resp({0x60, 0x00, 0x18, 0x02, 0x00, 0x00, 0x00, 0x00})});
}

TEST_F(Md2Test, C18_RemapOnlyAfterDisablingAndClearingTheCount) {
  EXPECT_EQ(sdo({0x23, 0x00, 0x16, 0x01, 0x10, 0x00, 0x40, 0x60}),
            Frames{resp({0x80, 0x00, 0x16, 0x01, 0x22, 0x00, 0x00, 0x08})});
  ASSERT_EQ(write(0x1400, 1, 0x80000201, 4), 0u);
  EXPECT_EQ(sdo({0x23, 0x00, 0x16, 0x01, 0x10, 0x00, 0x40, 0x60}),
            Frames{resp({0x80, 0x00, 0x16, 0x01, 0x22, 0x00, 0x00, 0x08})});  // sub 0 still 2
  ASSERT_EQ(write(0x1600, 0, 0, 1), 0u);
  EXPECT_EQ(sdo({0x23, 0x00, 0x16, 0x01, 0x10, 0x00, 0x40, 0x60}),
            Frames{resp({0x60, 0x00, 0x16, 0x01, 0x00, 0x00, 0x00, 0x00})});
}

TEST_F(Md2Test, C19_MappingLengthAndMappability) {
  ASSERT_EQ(write(0x1400, 1, 0x80000201, 4), 0u);
  ASSERT_EQ(write(0x1600, 0, 0, 1), 0u);
  for (std::uint8_t sub = 1; sub <= 3; ++sub) ASSERT_EQ(write(0x1600, sub, 0x00070020, 4), 0u);
  EXPECT_EQ(sdo({0x2F, 0x00, 0x16, 0x00, 0x03}), Frames{resp({0x80, 0x00, 0x16, 0x00, 0x42, 0x00, 0x04, 0x06})});
  EXPECT_EQ(sdo({0x23, 0x00, 0x16, 0x01, 0x20, 0x00, 0x00, 0x10}),
            Frames{resp({0x80, 0x00, 0x16, 0x01, 0x41, 0x00, 0x04, 0x06})});
}

TEST_F(Md2Test, C20_SynchronousPdos) {
  ASSERT_EQ(write(0x1400, 2, 0, 1), 0u);
  ASSERT_EQ(write(0x1800, 2, 2, 1), 0u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(dev->node().od().get<std::uint16_t>(0x6040), 0u);
  h->send(0x080, {});
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(dev->node().od().get<std::uint16_t>(0x6040), 7u);  // applied at the 1st SYNC
  h->send(0x080, {});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
  h->send(0x080, {});
  EXPECT_TRUE(h->take().empty());
  h->send(0x080, {});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
}

TEST_F(Md2Test, C21_Heartbeat) {
  ASSERT_EQ(write(0x1017, 0, 100, 2), 0u);
  h->run_ms(1001);  // the first heartbeat one period after the write, the 10th at 1000 ms
  const auto frames = h->take();
  EXPECT_EQ(frames.size(), 10u);
  for (const auto& f : frames) EXPECT_EQ(f, Frame(0x701, {0x7F}));
  start();
  h->run_ms(100);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x05})});
  h->nmt(0x02, 1);
  h->run_ms(100);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x04})});
  h->nmt(0x80, 1);
  ASSERT_EQ(write(0x1017, 0, 0, 2), 0u);
  h->run_ms(500);
  EXPECT_TRUE(h->take().empty());
}

TEST_F(Md2Test, C22_GuardingObjectsLockedWhileHeartbeatRuns) {
  ASSERT_EQ(write(0x1017, 0, 1000, 2), 0u);
  EXPECT_EQ(sdo({0x2B, 0x0C, 0x10, 0x00, 0x64, 0x00}), Frames{resp({0x80, 0x0C, 0x10, 0x00, 0x23, 0x00, 0x0A, 0x06})});
  EXPECT_EQ(sdo({0x2F, 0x0D, 0x10, 0x00, 0x03}), Frames{resp({0x80, 0x0D, 0x10, 0x00, 0x23, 0x00, 0x0A, 0x06})});
  ASSERT_EQ(write(0x1017, 0, 0, 2), 0u);
  EXPECT_EQ(write(0x100C, 0, 100, 2), 0u);
}

TEST_F(Md2Test, C23_NodeGuardingToggle) {
  for (std::uint8_t expected : {0x7F, 0xFF, 0x7F}) {
    h->send(Frame::remote(0x701, 1));
    EXPECT_EQ(h->take(), Frames{Frame(0x701, {expected})});
  }
  h->nmt(0x82, 1);
  h->run_ticks(1);
  h->take();
  h->send(Frame::remote(0x701, 1));
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x7F})});
}

TEST_F(Md2Test, C24_LifeGuardingTimeoutFaultsWithOneEmcy) {
  ASSERT_EQ(write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(write(0x100D, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);  // DISABLED
  h->send(Frame::remote(0x701, 1));
  h->take();
  const auto t0 = h->now();
  h->run_ms(280);
  EXPECT_TRUE(h->take().empty());
  h->run_ms(40);
  const auto times = h->take_times();
  ASSERT_EQ(times.size(), 1u);
  EXPECT_NEAR(sim::seconds(times[0] - t0), 0.300, 0.020);
  h->run_ms(1000);
  EXPECT_TRUE(h->take().empty());  // exactly one
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(read(0x1001), 0x11u);
  EXPECT_EQ(read(0x1003, 1), 0x8100u);
}

TEST_F(Md2Test, C24b_LifeGuardingEmcyFrame) {
  ASSERT_EQ(write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(write(0x100D, 0, 3, 1), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  h->send(Frame::remote(0x701, 1));
  h->take();
  h->run_ms(400);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x00, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00})});
}

TEST_F(Md2Test, C25_SolenoidOpenFaultsOnceWithCurrentsOff) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  h->run_ms(5);
  h->take();
  EXPECT_GT(ch().solenoid_a, 0.0);
  ASSERT_EQ(dev->inject_fault("solenoid_a_open", true), "");
  h->run_ms(20);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x11, 0x23, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_EQ(ch().solenoid_b, 0.0);
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(read(0x1003, 1), 0x00002311u);
  h->run_ms(500);
  EXPECT_TRUE(h->take().empty());
}

TEST_F(Md2Test, C26_FaultResetOnlyWhenTheFaultIsGone) {
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  dev->inject_fault("solenoid_a_open", true);
  h->run_ms(2);
  h->take();
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0009, 2), 0u);
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(status(), 0x0001);
  dev->inject_fault("solenoid_a_open", false);
  h->run_ms(2);
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  h->take();
  h->send(0x601, {0x2B, 0x40, 0x60, 0x00, 0x09, 0x00, 0x00, 0x00});
  EXPECT_EQ(h->take(), (Frames{Frame(0x081, {0, 0, 0, 0, 0, 0, 0, 0}), resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})}));
  EXPECT_EQ(status(), 0x0009);
  EXPECT_EQ(read(0x1001), 0u);
}

TEST_F(Md2Test, C27_SupplyAndAnalogSignalErrors) {
  // Each error drives the DSM to FAULT (status word 0x0001, digest §4.5 "hardware errors in
  // INIT"), from INIT as well as from DEVICE_MODE_ACTIVE.
  dev->inject_fault("supply_low", true);
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x12, 0x34, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(read(0x1001), 0x05u);
  make();
  // Analog loss matters only while the analog input is in use.
  dev->inject_fault("analog_signal_lost", true);
  h->run_ms(5);
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(status(), 0x0008);
  make();
  ASSERT_EQ(write(0x6042, 0, 2, 1), 0u);
  dev->inject_fault("analog_signal_lost", true);
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x22, 0x34, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(status(), 0x0001);
  // The supply voltage input below u_supply_min has the same effect as the injection.
  make();
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(status(), 0x000F);
  ASSERT_EQ(dev->set_input("supply_voltage", 17.0), "");
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x12, 0x34, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(status(), 0x0001);
  // Analog loss while ACTIVE on the analog command.
  make();
  ASSERT_EQ(write(0x6042, 0, 2, 1), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(status(), 0x000F);
  dev->inject_fault("analog_signal_lost", true);
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x22, 0x34, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  EXPECT_EQ(ch().solenoid_b, 0.0);
}

TEST_F(Md2Test, C28_ResetCommunicationWhileActiveFaultsAfterBootUp) {
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->nmt(0x82, 1);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), (Frames{Frame(0x701, {0x00}), Frame(0x081, {0x00, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00})}));
  EXPECT_EQ(status(), 0x0001);
  make();
  h->nmt(0x82, 1);
  h->run_ms(10);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  EXPECT_EQ(status(), 0x0008);
}

TEST_F(Md2Test, C29_StopWhileActiveFaultsSilently) {
  ASSERT_EQ(write(0x1017, 0, 100, 2), 0u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  h->run_ms(5);
  h->take();
  EXPECT_GT(ch().solenoid_a, 0.0);
  h->nmt(0x02, 1);
  h->run_ms(100);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x04})});
  EXPECT_EQ(ch().solenoid_a, 0.0);
  h->send(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(h->take().empty());
  h->nmt(0x80, 1);
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(read(0x1001), 0x11u);
  EXPECT_EQ(read(0x1003, 1), 0x8100u);
}

TEST_F(Md2Test, C30_ResetNodeRevertsUnsavedChanges) {
  ASSERT_EQ(write(0x1017, 0, 100, 2), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  dev->inject_fault("general_error", true);
  h->run_ms(2);
  dev->inject_fault("general_error", false);
  h->take();
  h->nmt(0x81, 1);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  EXPECT_EQ(read(0x6040), 0u);
  EXPECT_EQ(status(), 0x0008);
  EXPECT_EQ(read(0x1003), 0u);
  EXPECT_EQ(read(0x1017), 0u);
}

TEST_F(Md2Test, C31_SavedHeartbeatSurvivesAPowerCycle) {
  make({}, "", 0, temp_store("c31"));
  ASSERT_EQ(write(0x1017, 0, 500, 2), 0u);
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x02, 0x73, 0x61, 0x76, 0x65}),
            Frames{resp({0x60, 0x10, 0x10, 0x02, 0x00, 0x00, 0x00, 0x00})});
  dev->power_off();
  h->run_ms(10);
  dev->power_on(h->now());
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  h->run_ms(1000);
  EXPECT_EQ(h->take(), (Frames{Frame(0x701, {0x7F}), Frame(0x701, {0x7F})}));
}

TEST_F(Md2Test, C32_WrongSaveSignatureStoresNothing) {
  make({}, "", 0, temp_store("c32"));
  ASSERT_EQ(write(0x1017, 0, 500, 2), 0u);
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x66}),
            Frames{resp({0x80, 0x10, 0x10, 0x01, 0x20, 0x00, 0x00, 0x08})});
  dev->power_off();
  dev->power_on(h->now());
  h->run_ticks(1);
  h->take();
  EXPECT_EQ(read(0x1017), 0u);
}

TEST_F(Md2Test, C33_RestoreWaitsForResetAndPowerCycleBringsStoredValuesBack) {
  make({}, "", 0, temp_store("c33"));
  ASSERT_EQ(write(0x1017, 0, 500, 2), 0u);
  ASSERT_EQ(write(0x1010, 1, 0x65766173, 4), 0u);
  EXPECT_EQ(sdo({0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64}),
            Frames{resp({0x60, 0x11, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(read(0x1017), 500u);
  h->nmt(0x82, 1);
  h->run_ticks(1);
  h->take();
  EXPECT_EQ(read(0x1017), 0u);
  dev->power_off();
  dev->power_on(h->now());
  h->run_ticks(1);
  h->take();
  EXPECT_EQ(read(0x1017), 500u);
}

TEST_F(Md2Test, C34_NodeIdChangeTakesEffectAtResetCommunication) {
  make({}, "", 0, temp_store("c34"));
  ASSERT_EQ(write(0x2000, 0, 5, 1), 0u);
  h->nmt(0x82, 1);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x00})});
  h->send(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(h->take(), Frames{Frame(0x585, {0x43, 0x00, 0x10, 0x00, 0x98, 0x01, 0x00, 0x10})});
  h->nmt(0x01, 5);
  h->send(0x205, {0x01, 0x00, 0x00, 0x00});
  EXPECT_EQ(h->take(), Frames{Frame(0x185, {0x09, 0x00})});
  dev->power_off();
  dev->power_on(h->now());
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
}

TEST_F(Md2Test, C35_BitRateChange) {
  EXPECT_EQ(sdo({0x2B, 0x01, 0x20, 0x00, 0x7D, 0x00}), Frames{resp({0x60, 0x01, 0x20, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(dev->active_bit_rate_kbit(), 20);
  h->nmt(0x82, 1);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});
  EXPECT_EQ(dev->active_bit_rate_kbit(), 125);
  EXPECT_EQ(sdo({0x2B, 0x01, 0x20, 0x00, 0x1E, 0x00}), Frames{resp({0x80, 0x01, 0x20, 0x00, 0x43, 0x00, 0x04, 0x06})});
}

TEST_F(Md2Test, C36_LocalOperation) {
  ASSERT_EQ(write(0x6040, 0, 0x0001, 2), 0u);
  EXPECT_EQ(sdo({0x2F, 0x4F, 0x60, 0x00, 0x01}), Frames{resp({0x60, 0x4F, 0x60, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), Frames{resp({0x80, 0x40, 0x60, 0x00, 0x21, 0x00, 0x00, 0x08})});
  EXPECT_EQ(status(), 0x0019);
  dev->set_input("enable_input", 0);
  h->run_ms(2);
  dev->set_input("enable_input", 1);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x001F);
  dev->set_input("enable_input", 0);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x0019);
  EXPECT_EQ(write(0x604F, 0, 0, 1), 0u);
  EXPECT_EQ(status(), 0x0009);
}

TEST_F(Md2Test, C37_RampRunsForTheRampTimeWithTheCurrentRisingLinearly) {
  make({{"ramp_up_ms", "1000"}, {"dither_level", "0"}});
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(write(0x6300, 1, 16384, 2), 0u);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(250);
  EXPECT_NEAR(ch().solenoid_a, 0.2 + 0.8 * 0.25, 0.8 * 0.002);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(500);
  EXPECT_NEAR(ch().solenoid_a, 0.2 + 0.8 * 0.75, 0.8 * 0.002);
  h->run_ms(249);
  EXPECT_EQ(status(), 0x020F);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
  EXPECT_DOUBLE_EQ(ch().solenoid_a, 1.0);
}

TEST_F(Md2Test, C38_PositionControlWithActualValueViaCan) {
  // u = 1000 / 2000000 is inside the default dead band (1 %, applied in every mode): the
  // open-loop-only dead band lets the small demand through.
  make({{"deadband_modes", "open_loop"}}, "controller");
  ASSERT_EQ(write(0x6043, 0, 9, 1), 0u);
  ASSERT_EQ(write(0x2200, 0, 1, 1), 0u);
  ASSERT_EQ(write(0x6600, 1, 100000, 4), 0u);
  ASSERT_EQ(write(0x2202, 0, 99000, 4), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(2);
  EXPECT_EQ(read(0x6650, 1), 1000u);
  EXPECT_EQ(read(0x6601, 1), 99000u);
  EXPECT_EQ(status(), 0x100F);  // window 1 % of 2000000 ≥ 1000
  EXPECT_GT(ch().solenoid_a, 0.0);
  EXPECT_EQ(ch().solenoid_b, 0.0);
  make({{"window_scaled", "500"}}, "controller");
  ASSERT_EQ(write(0x6043, 0, 9, 1), 0u);
  ASSERT_EQ(write(0x2200, 0, 1, 1), 0u);
  ASSERT_EQ(write(0x6600, 1, 100000, 4), 0u);
  ASSERT_EQ(write(0x2202, 0, 99000, 4), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(2);
  EXPECT_EQ(status(), 0x000F);
}

TEST_F(Md2Test, C39_ControllerObjectsDoNotExistOnTheAmplifier) {
  EXPECT_EQ(sdo({0x40, 0x81, 0x63, 0x01}), Frames{resp({0x80, 0x81, 0x63, 0x01, 0x00, 0x00, 0x02, 0x06})});
  EXPECT_EQ(sdo({0x40, 0x00, 0x22, 0x00}), Frames{resp({0x80, 0x00, 0x22, 0x00, 0x00, 0x00, 0x02, 0x06})});
}

TEST_F(Md2Test, C40_DeviceVersionString) {
  EXPECT_EQ(sdo({0x40, 0x50, 0x60, 0x00}), Frames{resp({0x41, 0x50, 0x60, 0x00, 0x08, 0x00, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x60}), Frames{resp({0x00, 0x56, 0x31, 0x2E, 0x30, 0x2E, 0x30, 0x2E})});
  EXPECT_EQ(sdo({0x70}), Frames{resp({0x1D, 0x30, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00})});
}

}  // namespace md2test
