// WDGA errors: temperature (4200h), EEPROM (5000h), CAN controller (8100h, 8110h, 8120h, 8140h with the
// bus-off auto-reset 2103h), position error (6503h, 1002h, 1029h:02), EMCY disable and inhibit
// time, and the histories 1003h, 2502h-2504h (digest checklist 35, 37; vectors §5.5).
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

class Faults : public WdgaTest {};

/// The same device sampling its temperature every second (the 60 s period is tested above).
class FastTemperature : public WdgaTest {
 protected:
  FastTemperature() : WdgaTest({{"temperature_period_s", "1"}}) {}
};

TEST_F(Faults, OverTemperatureOnceThenErrorReset) {
  device().set_input("temperature", 105);
  h().run_ms(60001);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x42, 0x08, 0x10})});
  EXPECT_EQ(u(0x1001), 0x08u);
  EXPECT_EQ(u(0x6505), 0x1000u);
  EXPECT_EQ(static_cast<std::int16_t>(u(0x2500, 4)), 105);
  EXPECT_EQ(static_cast<std::int16_t>(u(0x2500, 1)), 105);
  h().run_ms(60000);
  EXPECT_TRUE(h().take().empty());  // one EMCY per excursion
  device().set_input("temperature", 25);
  h().run_ms(60000);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  EXPECT_EQ(u(0x1001), 0x00u);
  EXPECT_EQ(u(0x6505), 0x0000u);
  EXPECT_EQ(static_cast<std::int16_t>(u(0x2500, 5)), 25);
  EXPECT_EQ(u(0x1003, 0), 1u);
  EXPECT_EQ(u(0x1003, 1), 0x00104200u);
  EXPECT_EQ(u(0x2502, 1), 0x00104200u);
  EXPECT_EQ(u(0x2504, 1), 0x1000u);
}

TEST_F(FastTemperature, UnderTemperatureReadFailureAndLimitRule) {
  EXPECT_EQ(h().write(0x2500, 2, static_cast<std::uint16_t>(-40), 2), 0x06090036u);
  EXPECT_EQ(h().write(0x2500, 3, 100, 2), 0x06090036u);
  ASSERT_EQ(h().write(0x2500, 3, 30, 2), 0u);
  h().run_ms(1001);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x42, 0x08, 0x20})});
  EXPECT_EQ(u(0x6505), 0x2000u);
  ASSERT_EQ(h().write(0x2500, 3, static_cast<std::uint16_t>(-40), 2), 0u);
  h().run_ms(1000);
  h().take();
  device().inject_fault("temperature_sensor_failure", true);
  h().run_ms(1000);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x42, 0x08, 0x40})});
  EXPECT_EQ(u(0x6505), 0x4000u);
}

TEST_F(FastTemperature, EmcyDisabledByBit31AndSpacedByInhibitTime) {
  ASSERT_EQ(h().write(0x1014, 0, 0x800000FF, 4), 0u);
  device().inject_fault("over_temperature", true);
  h().run_ms(1001);
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(u(0x1001), 0x08u);  // recorded all the same
  ASSERT_EQ(h().write(0x1014, 0, 0xFF, 4), 0u);
  ASSERT_EQ(h().write(0x1015, 0, 10000, 2), 0u);  // 1 s
  device().inject_fault("can_overrun", true);
  device().inject_fault("can_overrun", true);
  h().run_ticks(1);
  auto times = h().take_times();
  ASSERT_EQ(times.size(), 1u);
  h().run_ms(1001);
  const auto later = h().take_times();
  ASSERT_EQ(later.size(), 1u);
  EXPECT_GE(later[0] - times[0], sim::milliseconds(1000));
}

TEST_F(Faults, EepromFaultAtBootAndOnStore) {
  device().inject_fault("eeprom_error", true);
  device().power_off();
  device().power_on(h().now());
  h().run_ticks(1);
  h().send(Frame(0x080, eight({})));
  h().run_ticks(1);
  EXPECT_EQ(h().take(), (Frames{Frame(0x77F, {0x00}), emcy({0x00, 0x50, 0x01, 0x00, 0x01})}));
  EXPECT_EQ(u(0x1002), 0x04u);
  EXPECT_EQ(h().write(0x1010, 1, kSave, 4), 0x06060000u);  // 5000h already active: no second EMCY
  device().inject_fault("eeprom_error", false);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  EXPECT_EQ(u(0x1002), 0u);
}

TEST_F(Faults, EepromErrorFollowsTheEncoderErrorBehaviour) {
  start();
  h().take();
  device().inject_fault("eeprom_error", true);
  h().send(0x67F, {0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65});
  EXPECT_EQ(h().take(), (Frames{emcy({0x00, 0x50, 0x01, 0x00, 0x08}), resp({0x80, 0x10, 0x10, 0x01, 0x00, 0x00, 0x06, 0x06})}));
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST_F(Faults, ErrorPassiveAndOverrun) {
  device().inject_fault("can_error_passive", true);
  EXPECT_EQ(h().take(), Frames{emcy({0x20, 0x81, 0x10, 0x47})});
  EXPECT_EQ(u(0x1001), 0x10u);
  device().inject_fault("can_error_passive", false);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  device().inject_fault("can_overrun", true);
  EXPECT_EQ(h().take(), Frames{emcy({0x10, 0x81, 0x10, 0x01})});
  EXPECT_EQ(u(0x1001), 0x00u);  // an event, not a lasting condition
  start();
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);  // no state change
}

TEST_F(Faults, BusWarningSends8100AndBackToErrorActive) {
  // 8100h info1 46h (CRC errors, bus warning), then 8100h info1 01h (error-active) and the
  // error reset.
  ASSERT_EQ(device().inject_fault("can_bus_warning", true), "");
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x81, 0x10, 0x46})});
  EXPECT_EQ(u(0x1001), 0x10u);
  EXPECT_EQ(u(0x1003, 1), 0x00468100u);
  EXPECT_EQ(u(0x2502, 1), 0x00468100u);
  device().inject_fault("can_bus_warning", true);
  EXPECT_TRUE(h().take().empty());
  ASSERT_EQ(device().inject_fault("can_bus_warning", false), "");
  EXPECT_EQ(h().take(), (Frames{emcy({0x00, 0x81, 0x00, 0x01}), emcy({0x00, 0x00, 0x00})}));
  EXPECT_EQ(u(0x1001), 0u);
  EXPECT_EQ(u(0x1003, 0), 1u);  // back to error-active is no error entry
}

TEST_F(Faults, BusWarningEndingWhileErrorPassiveIsNotErrorActive) {
  device().inject_fault("can_bus_warning", true);
  device().inject_fault("can_error_passive", true);
  EXPECT_EQ(h().take(), (Frames{emcy({0x00, 0x81, 0x10, 0x46}), emcy({0x20, 0x81, 0x10, 0x47})}));
  device().inject_fault("can_bus_warning", false);
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(u(0x1001), 0x10u);
  device().inject_fault("can_error_passive", false);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
}

class NoBusWarningEmcy : public WdgaTest {
 protected:
  NoBusWarningEmcy() : WdgaTest({{"bus_warning_emcy", "off"}}) {}
};

TEST_F(NoBusWarningEmcy, BusWarningIsSilent) {
  ASSERT_EQ(device().inject_fault("can_bus_warning", true), "");
  h().run_ms(2);
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(u(0x1001), 0u);
  ASSERT_EQ(device().inject_fault("can_bus_warning", false), "");
  h().run_ms(2);
  EXPECT_TRUE(h().take().empty());
}

TEST_F(Faults, BusOffStaysUntilPowerCycleWithoutAutoReset) {
  start();
  h().take();
  device().inject_fault("bus_off", true);
  EXPECT_EQ(device().led(), Led::Red);
  h().send(0x67F, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  h().run_ms(5000);
  EXPECT_TRUE(h().take().empty());
  power_cycle();
  EXPECT_EQ(u(0x1000), 0x00020196u);
}

TEST_F(Faults, BusOffAutoResetSends8140AndAppliesTheCommunicationErrorBehaviour) {
  ASSERT_EQ(h().write(0x2103, 0, 2, 1), 0u);
  start();
  h().take();
  device().inject_fault("bus_off", true);
  h().run_ms(1990);
  EXPECT_TRUE(h().take().empty());
  h().run_ms(20);
  EXPECT_EQ(h().take(), Frames{emcy({0x40, 0x81, 0x10, 0x01})});
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST_F(Faults, BusOffMadeOnTheWireAlsoSends8140) {
  // A scenario's wire fault: the controller never knew, the stack reports the recovery.
  start();
  h().take();
  device().node().communication_error(canopen::CommError::BusOffRecovered);
  h().run_ms(2);
  EXPECT_EQ(h().take(), Frames{emcy({0x40, 0x81, 0x10, 0x01})});
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST_F(Faults, PositionErrorHasNoEmcyButRegisterStatusAndHistory) {
  start();
  h().take();
  device().inject_fault("position_error", true);
  h().run_ms(2);
  for (const auto& f : h().take()) EXPECT_NE(f.id, 0xFFu);
  EXPECT_EQ(u(0x6503), 1u);
  EXPECT_EQ(u(0x1001), 0x01u);
  EXPECT_EQ(u(0x1002), 0x02u);  // multiturn error bit
  EXPECT_EQ(u(0x2503, 0), 1u);
  EXPECT_EQ(u(0x2503, 1), 1u);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);  // 1029h:02 = 0
  device().inject_fault("position_error", false);
  EXPECT_EQ(u(0x6503), 0u);
  EXPECT_EQ(u(0x1001), 0u);
}

class PositionErrorEmcy : public WdgaTest {
 protected:
  PositionErrorEmcy() : WdgaTest({{"position_error_emcy", "0x1000"}}) {}
};

TEST_F(PositionErrorEmcy, KnobSendsAnEmcy) {
  ASSERT_EQ(h().write(0x1029, 2, 1, 1), 0u);
  start();
  h().take();
  device().inject_fault("position_error", true);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x10, 0x01})});
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);  // 1029h:02 = 1
}

TEST_F(Faults, ErrorListNewestFirstKeptOverPowerCycles) {
  device().inject_fault("can_overrun", true);
  device().inject_fault("can_error_passive", true);
  h().take();
  EXPECT_EQ(u(0x1003, 0), 2u);
  EXPECT_EQ(u(0x1003, 1), 0x00478120u);
  EXPECT_EQ(u(0x1003, 2), 0x00018110u);
  EXPECT_EQ(abort_of_read(0x1003, 3), 0x08000024u);
  power_cycle();
  EXPECT_EQ(u(0x1003, 0), 2u);
  EXPECT_EQ(u(0x2502, 0), 2u);
  EXPECT_EQ(h().write(0x1003, 0, 1, 1), 0x06090030u);
  ASSERT_EQ(h().write(0x1003, 0, 0, 1), 0u);
  EXPECT_EQ(u(0x1003, 0), 0u);
  EXPECT_EQ(u(0x2502, 0), 2u);  // the manufacturer history stays
  for (int i = 0; i < 7; ++i) device().inject_fault("can_overrun", true);
  EXPECT_EQ(u(0x1003, 0), 5u);
  EXPECT_EQ(u(0x2502, 0), 5u);
  EXPECT_EQ(h().write(0x2504, 0, 1, 1), 0x06090030u);
  EXPECT_EQ(h().write(0x2504, 0, 0, 1), 0u);
}

}  // namespace
}  // namespace wdga::test
