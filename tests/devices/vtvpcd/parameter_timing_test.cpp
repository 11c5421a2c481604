// A parameter written by SDO while the card runs acts in the first control cycle after the write
// (the cycle reads every object it uses anew), also when the same value is written again or a
// value goes back to one used before; nothing of it shows before that cycle.
#include <gtest/gtest.h>

#include <cstdint>

#include "devices/vtvpcd/parameter_conversion.h"
#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using namespace vtvpcd;

namespace {

/// Writes by SDO between two ticks, checks that `readout` still shows `before`, runs one tick
/// (one control cycle) and returns what it shows then.
std::int64_t write_then_cycle(vtest::Vtvpcd& n, std::uint16_t index, std::int64_t raw, int size,
                              std::uint16_t readout, std::int64_t before) {
  const std::uint32_t abort = size == 4 ? n.write4(index, raw) : n.write2(index, raw);
  EXPECT_EQ(abort, 0u) << std::hex << index;
  EXPECT_EQ(n.raw(readout), before) << "no cycle has run since the write of 0x" << std::hex << index;
  n->run_ticks(1);
  return n.raw(readout);
}

TEST(VtvpcdParameterTiming, EveryParameterActsInTheFirstCycleAfterItsWrite) {
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  ASSERT_EQ(n.dev().settings().control_period_ms, 1);
  n.set("swivel_angle", 0.2);
  n.set("pressure_b", 315e5);  // 10 % of p_ref below the 350 bar start-up command
  n->run_ticks(5);

  // Direct mode, bus commands: Angle CMD (BUS) -> Angle CMD 0x2F33.
  std::int64_t angle = n.raw(0x2F33);
  for (double pct : {30.0, 30.0, 55.0, 30.0}) {
    const std::int64_t raw = to_raw(pct, kScalePercent);
    EXPECT_EQ(write_then_cycle(n, 0x2C72, raw, 4, 0x2F33, angle), raw) << pct;
    angle = raw;
  }
  // Power CMD (BUS) -> Power CMD 0x2F18; Pressure CMD (BUS) -> Press CMD 0x2F0E.
  EXPECT_EQ(write_then_cycle(n, 0x2C76, to_raw(40.0, kScalePercent), 4, 0x2F18, n.raw(0x2F18)),
            to_raw(40.0, kScalePercent));
  EXPECT_EQ(write_then_cycle(n, 0x2C74, to_raw(300.0, kScalePercent), 4, 0x2F0E, n.raw(0x2F0E)),
            to_raw(300.0, kScalePercent));
  EXPECT_EQ(write_then_cycle(n, 0x2C74, to_raw(350.0, kScalePercent), 4, 0x2F0E, n.raw(0x2F0E)),
            to_raw(350.0, kScalePercent));

  // Gain LVDT pump and Zeropoint pump -> act. Angle 0x2F07 = gain * 20 % + zero point.
  auto act_angle = [](std::int64_t gain_raw, std::int64_t zero_raw) {
    return to_raw(to_eu(gain_raw, kScaleLvdtGain) / 100.0 * 20.0 + to_eu(zero_raw, kScaleTable), kScalePercent);
  };
  const std::int64_t zero5 = to_raw(5.0, kScaleTable);
  EXPECT_EQ(write_then_cycle(n, 0x2F2C, 630, 2, 0x2F07, act_angle(1260, 0)), act_angle(630, 0));
  EXPECT_EQ(write_then_cycle(n, 0x2C69, zero5, 4, 0x2F07, act_angle(630, 0)), act_angle(630, zero5));
  EXPECT_EQ(write_then_cycle(n, 0x2F2C, 1260, 2, 0x2F07, act_angle(630, zero5)), act_angle(1260, zero5));

  // Zeropoint valve -> valve CMD = k_pos * (res. angle - act. angle) + zero point, in that cycle.
  write_then_cycle(n, 0x2F2A, to_raw(-1.5, kScaleValveZero), 2, 0x2F1F, n.raw(0x2F1F));
  const auto& c = n.dev().control();
  const double alpha_meas = to_eu(act_angle(1260, zero5), kScalePercent);
  EXPECT_NEAR(c.valve_cmd - n.dev().settings().k_pos * (c.alpha_res - alpha_meas), -1.5, 0.01);

  // Contr P of group 0 -> pressure stroke 0x2F32 = Kp * e + I with e = 10 %: doubling Kp adds
  // 10 % (and I its usual Kp * e * dt / Ti = 0.1 % of the cycle before).
  const double stroke = to_eu(n.raw(0x2F32), kScaleTable);
  const double stroke_after = to_eu(write_then_cycle(n, 0x2323, 256, 2, 0x2F32, n.raw(0x2F32)), kScaleTable);
  EXPECT_NEAR(stroke_after - stroke, 10.1, 0.01);

  // Trigger -> binary set 2 in the next cycle, its table values at once (no ramp).
  ASSERT_EQ(n.write4(0x2003, to_raw(60.0, kScalePercent)), 0u);
  EXPECT_EQ(write_then_cycle(n, 0x2C67, 0x04, 4, 0x2F33, angle), to_raw(60.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F2F), to_raw(60.0, kScalePercent));
  // A table entry of the set in use -> Angle CMD and the "binary" readout.
  EXPECT_EQ(write_then_cycle(n, 0x2003, to_raw(65.0, kScalePercent), 4, 0x2F33, to_raw(60.0, kScalePercent)),
            to_raw(65.0, kScalePercent));
  EXPECT_EQ(n.raw(0x2F2F), to_raw(65.0, kScalePercent));
  // Its ramp: 2 s full scale = 0.05 % per cycle from the next cycle on.
  ASSERT_EQ(n.write2(0x2103, 250), 0u);
  EXPECT_EQ(write_then_cycle(n, 0x2003, to_raw(20.0, kScalePercent), 4, 0x2F33, to_raw(65.0, kScalePercent)),
            to_raw(to_eu(to_raw(65.0, kScalePercent), kScalePercent) - 0.05, kScalePercent));
}

}  // namespace
