// The card's control (digest §4): binary sets by inputs or Trigger, ramps, pressure controller
// taking over by minimum selection, power limit, position loop, enable and slave mode
// (checklist 29-36, 38), with the built-in pump model as the plant.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "devices/vtvpcd/parameter_conversion.h"
#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using vtest::Frame;
using vtest::Frames;
using namespace vtvpcd;

namespace {
double angle(vtest::Vtvpcd& n) { return to_eu(n.raw(0x2F07), kScalePercent); }
double pressure_b(vtest::Vtvpcd& n) { return to_eu(n.raw(0x2F0F), kScalePercent); }
}  // namespace

TEST(VtvpcdControl, DiscreteInputsSelectTheBinarySet) {  // checklist 29, TV22
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2006, 11111), 0u);
  ASSERT_EQ(n.write4(0x2028, 22222), 0u);
  ASSERT_EQ(n.write4(0x204A, 3333), 0u);
  for (const char* in : {"di6", "di1", "di3"}) n.set(in, 1);
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F27), 0x0125);
  EXPECT_EQ(n.raw(0x2F2F), 11111);
  EXPECT_EQ(n.raw(0x2F30), 22222);
  EXPECT_EQ(n.raw(0x2F31), 3333);
  EXPECT_EQ(n.raw(0x2F26) & 0x80, 0x80);  // DO7: a binary set is in use
  // Without DI6 the readouts still follow DI1..DI4, but the bus commands are used.
  n.set("di6", 0);
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F2F), 11111);
  EXPECT_EQ(n.raw(0x2F26) & 0x80, 0);
  EXPECT_EQ(n.raw(0x2F33), 0);
}

TEST(VtvpcdControl, TriggerWinsOverInputsAndSelectsTheControllerGroup) {  // checklist 30, 31, TV19
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  ASSERT_EQ(n.write2(0x2323, 256), 0u);  // group 0 (sets 0-3): Kp 2.0
  ASSERT_EQ(n.write2(0x2327, 384), 0u);  // group 1 (sets 4-7): Kp 3.0
  ASSERT_EQ(n.write2(0x2423, 2000), 0u);   // group 0: Ti 2 s
  ASSERT_EQ(n.write2(0x2427, 10000), 0u);  // group 1: Ti 10 s
  for (int k = 0; k < 16; ++k) ASSERT_EQ(n.write4(static_cast<std::uint16_t>(0x2001 + k), 32767), 0u);
  ASSERT_EQ(n.write4(0x2004, 4444), 0u);
  n.set("pressure_b", 315e5);  // 10 % of p_ref below the 350 bar command
  for (const char* in : {"di6", "di1", "di3"}) n.set(in, 1);  // set 5: group 1
  n->run_ms(1);
  EXPECT_NEAR(to_eu(n.raw(0x2F32), kScaleTable), 30.0, 0.05);
  ASSERT_EQ(n.write4(0x2C67, 0x00000008), 0u);  // set 3 by the bus: group 0, at once
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F2F), 4444);
  EXPECT_NEAR(to_eu(n.raw(0x2F32), kScaleTable), 20.0, 0.05);
  // The integral time is the group's too: I grows by Kp·e·t/Ti, e = 10 % constant (no plant).
  // Group 0 over 100 ms: 2.0 · 10 · 0.1 / 2 = 1.0 % (group 1's Ti would give 0.2 %).
  const double g0 = to_eu(n.raw(0x2F32), kScaleTable);
  n->run_ms(100);
  EXPECT_NEAR(to_eu(n.raw(0x2F32), kScaleTable) - g0, 1.0, 0.02);
  // Back to set 5 (group 1, I kept): 3.0 · 10 · 0.1 / 10 = 0.3 % per 100 ms (group 0's: 1.5 %).
  ASSERT_EQ(n.write4(0x2C67, 0x00000020), 0u);
  n->run_ms(1);
  const double g1 = to_eu(n.raw(0x2F32), kScaleTable);
  EXPECT_NEAR(g1, 30.0 + 1.0, 0.05);  // bumpless: Kp·e of group 1 plus the kept I
  n->run_ms(100);
  EXPECT_NEAR(to_eu(n.raw(0x2F32), kScaleTable) - g1, 0.3, 0.02);
  ASSERT_EQ(n.write4(0x2C67, 0x00000101), 0u);  // two sets: the lowest (0), no fault by default
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F2F), 32767);
  EXPECT_EQ(n.raw(0x2C68), 0);
  EXPECT_TRUE(n->take().empty());
}

TEST(VtvpcdControl, AngleCommandFollowsTheSelectedRamp) {  // checklist 32
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write2(0x2104, 250), 0u);  // Angle Ramp binary 3 = 2.0 s
  ASSERT_EQ(n.write4(0x2003, 0), 0u);
  ASSERT_EQ(n.write4(0x2004, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C67, 0x04), 0u);
  n->run_ms(100);
  EXPECT_EQ(n.raw(0x2F33), 0);
  ASSERT_EQ(n.write4(0x2C67, 0x08), 0u);
  n->run_ms(1000);
  EXPECT_NEAR(static_cast<double>(n.raw(0x2F33)), 16384.0, 17.0);  // 50 %/s, +-1 cycle
  n->run_ms(999);
  EXPECT_LT(n.raw(0x2F33), 32767);
  EXPECT_GT(n.raw(0x2F33), 32767 - 34);
  n->run_ms(2);
  EXPECT_EQ(n.raw(0x2F33), 32767);
  // Down with the ramp of the set selected now (set 2: no ramp).
  ASSERT_EQ(n.write4(0x2C67, 0x04), 0u);
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F33), 0);
}

TEST(VtvpcdControl, ZeroRampJumpsInTheNextCycle) {  // checklist 33
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2004, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C67, 0x04), 0u);
  n->run_ms(10);
  ASSERT_EQ(n.write4(0x2C67, 0x08), 0u);
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F33), 32767);
}

TEST(VtvpcdControl, SwitchingTheSetChangesTheCommandsAtOnce) {
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2002, to_raw(30.0, kScalePercent)), 0u);
  ASSERT_EQ(n.write4(0x2003, to_raw(60.0, kScalePercent)), 0u);
  ASSERT_EQ(n.write4(0x2024, to_raw(100.0, kScaleTable)), 0u);
  ASSERT_EQ(n.write4(0x2025, to_raw(200.0, kScaleTable)), 0u);
  ASSERT_EQ(n.write4(0x2046, to_raw(40.0, kScaleTable)), 0u);
  ASSERT_EQ(n.write4(0x2047, to_raw(80.0, kScaleTable)), 0u);
  n.set("di6", 1);
  n.set("di1", 1);  // set 1
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F33), to_raw(30.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F0E), to_raw(100.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F18), to_raw(40.0, kScalePercent));
  n.set("di1", 0);
  n.set("di2", 1);  // set 2
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F33), to_raw(60.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F0E), to_raw(200.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F18), to_raw(80.0, kScalePercent));
}

TEST(VtvpcdControl, PressureControllerTakesOverByMinimumSelection) {  // checklist 34
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  n->run_ms(3000);
  EXPECT_NEAR(pressure_b(n), 150.0, 1.0);
  EXPECT_NEAR(angle(n), 66.9, 1.0);
  EXPECT_NEAR(to_eu(n.raw(0x2F32), kScaleTable), to_eu(n.raw(0x2F20), kScaleTable), 0.01);
  EXPECT_EQ(n.dev().control().branch, Branch::Pressure);
  EXPECT_EQ(n.raw(0x2F26) & 0x08, 0x08);  // DO3
  EXPECT_EQ(n.raw(0x2F26) & 0x10, 0x00);
  EXPECT_EQ(n.raw(0x2F26) & 0x20, 0x20);  // DO5: pressure in window
}

TEST(VtvpcdControl, PressureStepReachesItsCommandWithoutOvershoot) {  // digest §4.8 sanity point
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  double peak = 0;
  double t95 = -1;
  for (int ms = 1; ms <= 2000; ++ms) {
    n->run_ms(1);
    const double p = n.dev().builtin_plant()->p_b_bar();
    peak = std::max(peak, p);
    if (t95 < 0 && p >= 0.95 * 150.0) t95 = ms / 1000.0;
  }
  EXPECT_GT(t95, 0.3);
  EXPECT_LT(t95, 0.7);
  EXPECT_LT(peak, 151.0);
}

TEST(VtvpcdControl, PowerLimitCapsAngleTimesPressure) {  // checklist 35
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  n->run_ms(2000);
  ASSERT_EQ(n.write4(0x2C76, to_raw(50.0, kScalePercent)), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(350.0, kScalePercent)), 0u);
  n->run_ms(3000);
  EXPECT_NEAR(pressure_b(n), 216.6, 1.5);
  EXPECT_NEAR(angle(n), 80.8, 1.0);
  EXPECT_LE(angle(n) * pressure_b(n), 50.0 * 350.0 * 1.005);
  EXPECT_EQ(n.dev().control().branch, Branch::Power);
  EXPECT_EQ(n.raw(0x2F26) & 0x18, 0x10);  // DO4, not DO3
}

TEST(VtvpcdControl, FullCommandIsLoadLimited) {  // digest §4.8: 100 % -> ~327 bar
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  n->run_ms(3000);
  EXPECT_NEAR(angle(n), 100.0, 0.1);
  EXPECT_NEAR(pressure_b(n), 327.4, 1.0);
  EXPECT_EQ(n.dev().control().branch, Branch::Angle);
}

TEST(VtvpcdControl, DeadHeadedPumpMakesUpLeakage) {  // digest §4.8: K_L = 0 -> ~3.7 %
  vtest::Vtvpcd n({{"k_load", "0"}});
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  n->run_ms(4000);
  EXPECT_NEAR(pressure_b(n), 350.0, 1.0);
  EXPECT_NEAR(angle(n), 3.73, 0.2);
}

TEST(VtvpcdControl, PositionLoopFollowsAnAngleStep) {  // digest §4.8: 0 -> 50 % within 1 % after ~0.1 s
  vtest::Vtvpcd n;
  n->run_ms(100);
  ASSERT_EQ(n.write4(0x2C72, 16384), 0u);
  n->run_ms(60);
  EXPECT_LT(angle(n), 49.5);
  n->run_ms(60);
  EXPECT_NEAR(angle(n), 50.0, 0.5);
  EXPECT_EQ(n.raw(0x2F26) & 0x04, 0x04);  // DO2: angle in window
  n->run_ms(300);
  EXPECT_NEAR(to_eu(n.raw(0x2F1F), kScaleTable), 0.0, 0.05);  // valve centred at steady state
  EXPECT_NEAR(to_eu(n.raw(0x2F19), kScaleTable), 0.0, 0.05);
}

TEST(VtvpcdControl, EnableOffDeEnergisesTheValve) {  // checklist 36
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  n->run_ms(2000);
  n->take();
  n.set("enable", 0);
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F1F), 0);
  EXPECT_DOUBLE_EQ(n.dev().ports()[0].value[0], -0.25);  // pilot_command: spring offset
  EXPECT_EQ(n.raw(0x2F27) & 0x0100, 0);
  EXPECT_EQ(n.raw(0x2F26) & 0x03, 0x02);  // DO1 off, OK stays
  n->run_ms(500);
  EXPECT_LT(angle(n), 0.5);
  EXPECT_LT(pressure_b(n), 10.0);
  EXPECT_TRUE(n->take().empty());  // not a fault: no EMCY
  EXPECT_EQ(n.raw(0x2C68), 0);
  // Enabled again: bumpless start, the pressure comes back.
  n.set("enable", 1);
  n->run_ms(2000);
  EXPECT_NEAR(pressure_b(n), 150.0, 1.5);
}

TEST(VtvpcdControl, SlaveModeFollowsTheResultingAngleCommand) {  // checklist 38
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C99, to_raw(40.0, kScalePercent)), 0u);
  ASSERT_EQ(n.write4(0x2C67, 0x00010000), 0u);
  n->run_ms(1000);
  EXPECT_EQ(n.raw(0x2F20), 13108);
  EXPECT_NEAR(angle(n), 40.0, 0.3);
  EXPECT_EQ(n.raw(0x2F26) & 0x40, 0x40);  // DO6
  EXPECT_EQ(n.dev().control().branch, Branch::Slave);
}

TEST(VtvpcdControl, LvdtGainAndZeroPoints) {
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  n.set("swivel_angle", 0.5);
  ASSERT_EQ(n.write2(0x2F2C, 630), 0u);                       // gain 50
  ASSERT_EQ(n.write4(0x2C69, to_raw(10.0, kScaleTable)), 0u);  // zero point pump +10 %
  ASSERT_EQ(n.write2(0x2F2A, static_cast<std::uint16_t>(to_raw(-1.5, kScaleValveZero))), 0u);
  ASSERT_EQ(n.write4(0x2C72, to_raw(35.0, kScalePercent)), 0u);
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F07), to_raw(35.0, kScalePercent));  // 0.5 * 50 + 10
  EXPECT_NEAR(static_cast<double>(n.raw(0x2F1F)), static_cast<double>(to_raw(-1.5, kScaleTable)), 2.0);  // only the valve zero point
}

TEST(VtvpcdControl, KpZeroFreezesThePressureController) {
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  ASSERT_EQ(n.write2(0x2323, 0), 0u);
  n.set("pressure_b", 100e5);
  n->run_ms(100);
  EXPECT_EQ(n.raw(0x2F32), 0);
}

TEST(VtvpcdControl, AnalogCommandSource) {  // cmd_source = analog
  vtest::Vtvpcd n({{"cmd_source", "analog"}});
  n.set("angle_cmd_b14_b16", 0.3);
  n.set("pressure_cmd_b18_b20", 300e5);
  n.set("power_cmd_f8_f10", 1.0);
  n->run_ms(1000);
  EXPECT_EQ(n.raw(0x2F03), to_raw(30.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F0D), to_raw(300.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F17), to_raw(100.0, kScalePercent));
  EXPECT_NEAR(angle(n), 30.0, 0.3);
  // Slave mode takes the analog resulting-angle input b2/b4.
  n.set("angle_cmd_b2_b4", 0.2);
  ASSERT_EQ(n.write4(0x2C67, 0x00010000), 0u);
  n->run_ms(1000);
  EXPECT_NEAR(angle(n), 20.0, 0.3);
}

TEST(VtvpcdControl, PressureBusUnitPercentOfReference) {  // pressure_bus_unit = percent (A8)
  vtest::Vtvpcd n({{"pressure_bus_unit", "percent"}});
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(50.0, kScalePercent)), 0u);  // 50 % of 350 bar
  n->run_ms(3000);
  EXPECT_NEAR(pressure_b(n), 175.0, 1.0);
}

TEST(VtvpcdControl, PressCmdScaleAsPrinted) {  // scale_0x2F0E = 324.7 (A7)
  vtest::Vtvpcd n({{"scale_0x2F0E", "324.7"}});
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F0E), to_raw(350.0, Scale{3247, 10}));
  vtest::Vtvpcd m;
  m->run_ms(1);
  EXPECT_EQ(m.raw(0x2F0E), 114685);
}

TEST(VtvpcdControl, DirectModeRampsFromSetZero) {  // direct_mode_ramps = set0
  vtest::Vtvpcd n({{"direct_mode_ramps", "set0"}});
  ASSERT_EQ(n.write2(0x2101, 125), 0u);  // 1 s
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  n->run_ms(500);
  EXPECT_NEAR(static_cast<double>(n.raw(0x2F33)), 16384.0, 40.0);
}

TEST(VtvpcdControl, OverCentrePumpControlsPressureAOnTheNegativeSide) {  // pump_type = A4VSG
  vtest::Vtvpcd n({{"pump_type", "A4VSG"}});
  n->run_ms(10);
  ASSERT_EQ(n.write4(0x2C72, -32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  n->run_ms(3000);
  EXPECT_NEAR(to_eu(n.raw(0x2F10), kScalePercent), 150.0, 1.5);  // act. pressure A
  EXPECT_NEAR(angle(n), -66.9, 1.0);
  EXPECT_EQ(n.dev().control().branch, Branch::Pressure);
  // De-energised, the A4VSG swivels to -100 % (x_off = -25 %).
  n.set("enable", 0);
  n->run_ms(1000);
  EXPECT_NEAR(angle(n), -100.0, 0.1);
}

// controlled_pressure (A31): which transducer the pressure controller (and the power limit) uses.
// External plant, LVDT at 0: angle 100 %, pressure 150 bar, one transducer at 100 bar and the other
// at 200 bar. The pressure branch limits (pressure stroke 0x2F32 -> 0) only if the controlled
// pressure is the 200 bar one; otherwise it winds up to 100 % and the angle command wins.
namespace {
Branch limiting_branch(const std::string& controlled, const std::string& pump, double p_a_bar, double p_b_bar) {
  vtest::Vtvpcd n({{"builtin_plant", "false"}, {"pump_type", pump}, {"controlled_pressure", controlled}});
  n.set("pressure_a", p_a_bar * 1e5);
  n.set("pressure_b", p_b_bar * 1e5);
  EXPECT_EQ(n.write4(0x2C72, 32767), 0u);
  EXPECT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  n->run_ms(3000);
  const double stroke = to_eu(n.raw(0x2F32), kScaleTable);
  const Branch b = n.dev().control().branch;
  if (b == Branch::Pressure) {
    EXPECT_LT(stroke, 0.5) << controlled;  // down to the swivel range's low end (A4VSG: -100 %)
    EXPECT_LT(to_eu(n.raw(0x2F20), kScaleTable), 0.5) << controlled;  // res. Angle CMD
  } else {
    EXPECT_NEAR(stroke, 100.0, 0.5) << controlled;
    EXPECT_NEAR(to_eu(n.raw(0x2F20), kScaleTable), 100.0, 0.5) << controlled;
  }
  return b;
}
}  // namespace

TEST(VtvpcdControl, ControlledPressureIsConfigurable) {  // controlled_pressure (A31)
  // Pressure B above A.
  EXPECT_EQ(limiting_branch("flow_side", "A4VSO", 100.0, 200.0), Branch::Pressure);  // default: B
  EXPECT_EQ(limiting_branch("B", "A4VSO", 100.0, 200.0), Branch::Pressure);
  EXPECT_EQ(limiting_branch("A", "A4VSO", 100.0, 200.0), Branch::Angle);
  EXPECT_EQ(limiting_branch("max", "A4VSO", 100.0, 200.0), Branch::Pressure);
  // Pressure A above B.
  EXPECT_EQ(limiting_branch("flow_side", "A4VSO", 200.0, 100.0), Branch::Angle);
  EXPECT_EQ(limiting_branch("B", "A4VSO", 200.0, 100.0), Branch::Angle);
  EXPECT_EQ(limiting_branch("A", "A4VSO", 200.0, 100.0), Branch::Pressure);
  EXPECT_EQ(limiting_branch("max", "A4VSO", 200.0, 100.0), Branch::Pressure);
  // The default is the flow side: an A4VSG with a positive angle command controls B, too.
  EXPECT_EQ(limiting_branch("flow_side", "A4VSG", 200.0, 100.0), Branch::Angle);
  EXPECT_EQ(limiting_branch("flow_side", "A4VSG", 100.0, 200.0), Branch::Pressure);
  // DO5 (|Press CMD - controlled pressure| <= 5 % of p_ref) follows the same choice.
  for (const auto& [controlled, do5] : std::vector<std::pair<std::string, std::int64_t>>{
           {"flow_side", 0x00}, {"B", 0x00}, {"A", 0x20}, {"max", 0x20}}) {
    vtest::Vtvpcd n({{"builtin_plant", "false"}, {"controlled_pressure", controlled}});
    n.set("pressure_a", 150.0 * 1e5);  // in the window
    n.set("pressure_b", 100.0 * 1e5);  // outside it
    ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
    n->run_ms(10);
    EXPECT_EQ(n.raw(0x2F26) & 0x20, do5) << controlled;
  }
}

TEST(VtvpcdControl, OverCentrePumpWithPressureBControlledOnTheNegativeSide) {  // A4VSG, controlled_pressure = B
  // The flow goes to A; B only sees the boost pressure, so the pressure controller never limits.
  vtest::Vtvpcd n({{"pump_type", "A4VSG"}, {"controlled_pressure", "B"}});
  n->run_ms(10);
  ASSERT_EQ(n.write4(0x2C72, -32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  n->run_ms(3000);
  EXPECT_NEAR(angle(n), -100.0, 0.1);
  EXPECT_GT(to_eu(n.raw(0x2F10), kScalePercent), 300.0);  // act. pressure A: load-limited
  EXPECT_EQ(n.dev().control().branch, Branch::Angle);
}

TEST(VtvpcdControl, CounterClockwiseOverCentrePumpFailsToThePositiveEnd) {  // A4VSG, x_off_pct > 0
  // The digest's end position (-100 %) holds for clockwise rotation; a counter-clockwise A4VSG is
  // configured through the sign of the spring offset.
  vtest::Vtvpcd n({{"pump_type", "A4VSG"}, {"x_off_pct", "25"}});
  n.set("enable", 0);
  n->run_ms(1000);
  EXPECT_DOUBLE_EQ(n.dev().ports()[0].value[0], 0.25);  // pilot_command
  EXPECT_EQ(n.raw(0x2F1F), 0);                          // valve CMD reads 0
  EXPECT_NEAR(to_eu(n.raw(0x2F19), kScaleTable), 25.0, 0.1);  // act. valve
  EXPECT_NEAR(angle(n), 100.0, 0.1);
}

TEST(VtvpcdControl, FollowingErrorMonitoring) {  // monitor_enable = true: fault 19
  vtest::Vtvpcd n({{"monitor_enable", "true"}, {"builtin_plant", "false"}});
  ASSERT_EQ(n.write4(0x2C72, 16384), 0u);  // the LVDT input stays at 0: the loop cannot follow
  n->run_ms(1000);
  EXPECT_TRUE(n->take().empty());
  n->run_ms(3);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0x01, 0x83, 0x81, 0, 0, 0, 0, 0})});
  EXPECT_EQ(n.raw(0x2C68), 0x8113);
  EXPECT_FALSE(n.dev().control().energised);
  // Without monitoring nothing happens.
  vtest::Vtvpcd m({{"builtin_plant", "false"}});
  ASSERT_EQ(m.write4(0x2C72, 16384), 0u);
  m->run_ms(3000);
  EXPECT_TRUE(m->take().empty());
}

TEST(VtvpcdControl, PressureFollowingErrorMonitoring) {
  vtest::Vtvpcd n({{"monitor_enable", "true"}, {"builtin_plant", "false"}});
  ASSERT_EQ(n.write2(0x2423, 30000), 0u);  // slow integrator: the pressure branch stays below 100 %
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  ASSERT_EQ(n.write4(0x2C74, to_raw(150.0, kScalePercent)), 0u);
  n.set("swivel_angle", 0.44);  // the angle follows, but no pressure builds
  n->run_ms(1500);
  EXPECT_EQ(n.dev().control().branch, Branch::Pressure);
  EXPECT_TRUE(n->take().empty());
  n->run_ms(600);
  const auto frames = n->take();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0], Frame(0x0BF, {0x02, 0x83, 0x81, 0, 0, 0, 0, 0}));
}

TEST(VtvpcdControl, DigitalOutputFunctionsAreConfigurable) {
  vtest::Vtvpcd n({{"do_functions", "off,off,off,off,off,off,controller_active"}});
  n->run_ms(1);
  EXPECT_EQ(n.raw(0x2F26), 0x82);  // OK + DO7 (controller active)
}

TEST(VtvpcdControl, ControlPeriodSetting) {
  vtest::Vtvpcd n({{"control_period_ms", "5"}, {"direct_mode_ramps", "set0"}});
  ASSERT_EQ(n.write2(0x2101, 125), 0u);  // 1 s: 0.5 % per 5 ms cycle
  ASSERT_EQ(n.write4(0x2C72, 32767), 0u);
  int changes = 0;
  std::int64_t last = n.raw(0x2F33);
  for (int ms = 0; ms < 50; ++ms) {
    n->run_ms(1);
    if (n.raw(0x2F33) != last) {
      ++changes;
      EXPECT_NEAR(static_cast<double>(n.raw(0x2F33) - last), 0.5 * 327.67, 1.0);
    }
    last = n.raw(0x2F33);
  }
  EXPECT_EQ(changes, 10);
}
