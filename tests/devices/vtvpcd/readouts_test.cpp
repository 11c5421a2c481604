// The read-only readouts the control cycle publishes (0x2F03 and the others): a changed input is
// in the object in the cycle that read it, an unchanged one keeps its converted value, and the
// bytes are rewritten every cycle (a reset that put the start value there is overwritten).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "devices/vtvpcd/parameter_conversion.h"
#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using namespace vtvpcd;

namespace {

std::int64_t sdo_raw32(vtest::Vtvpcd& n, std::uint16_t index) {
  const auto bytes = n->read(index, 0);
  if (!bytes || bytes->size() != 4) return std::numeric_limits<std::int64_t>::min();
  return static_cast<std::int32_t>(static_cast<std::uint32_t>((*bytes)[0]) | static_cast<std::uint32_t>((*bytes)[1]) << 8 |
                                   static_cast<std::uint32_t>((*bytes)[2]) << 16 | static_cast<std::uint32_t>((*bytes)[3]) << 24);
}

TEST(VtvpcdReadouts, AChangedInputIsPublishedInTheCycleThatReadsIt) {
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  const int period = n.dev().settings().control_period_ms;
  n.set("angle_cmd_b14_b16", 0.5);
  n->run_ms(period);
  EXPECT_EQ(n.raw(0x2F03), to_raw(50.0, kScalePercent));
  EXPECT_EQ(sdo_raw32(n, 0x2F03), 16384);  // 50 % * 327.67 = 16383.5, rounded away from zero
  n.set("angle_cmd_b14_b16", 0.25);
  n->run_ms(period);
  EXPECT_EQ(n.raw(0x2F03), to_raw(25.0, kScalePercent));
  EXPECT_EQ(sdo_raw32(n, 0x2F03), to_raw(25.0, kScalePercent));
  n.set("angle_cmd_b14_b16", 0.5);  // back to the value converted two cycles ago
  n->run_ms(period);
  EXPECT_EQ(n.raw(0x2F03), 16384);
  // Unchanged over many cycles: the same value.
  n->run_ms(20 * period);
  EXPECT_EQ(sdo_raw32(n, 0x2F03), 16384);
}

TEST(VtvpcdReadouts, AnUnchangedInputIsRewrittenOverAReset) {
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  const int period = n.dev().settings().control_period_ms;
  n.set("pressure_cmd_b18_b20", 300e5);
  n->run_ms(period);
  ASSERT_EQ(n.raw(0x2F0D), to_raw(300.0, kScalePercent));
  n.od().entry(0x2F0D, 0)->reset_to_default(n.id());  // as a reset of the objects would
  ASSERT_EQ(n.raw(0x2F0D), 0);
  n->run_ms(period);
  EXPECT_EQ(n.raw(0x2F0D), to_raw(300.0, kScalePercent));
}

TEST(VtvpcdReadouts, NotANumberReadsZeroEveryTime) {
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  const int period = n.dev().settings().control_period_ms;
  n.set("angle_cmd_b14_b16", 0.5);
  n->run_ms(period);
  ASSERT_EQ(n.raw(0x2F03), 16384);
  n.set("angle_cmd_b14_b16", std::nan(""));
  n->run_ms(period);
  EXPECT_EQ(n.raw(0x2F03), 0);
  n->run_ms(period);
  EXPECT_EQ(n.raw(0x2F03), 0);
  n.set("angle_cmd_b14_b16", 0.5);
  n->run_ms(period);
  EXPECT_EQ(n.raw(0x2F03), 16384);
}

TEST(VtvpcdReadouts, PressCmdUsesTheConfiguredScale) {
  for (const bool printed : {false, true}) {
    vtest::Vtvpcd n({{"builtin_plant", "false"}, {"cmd_source", "analog"}, {"scale_0x2F0E", printed ? "324.7" : "327.67"}});
    n.set("pressure_cmd_b18_b20", 300e5);
    n->run_ms(100);
    EXPECT_EQ(n.raw(0x2F0E), to_raw(300.0, printed ? kScalePressCmdPrinted : kScalePercent)) << printed;
    EXPECT_EQ(n.raw(0x2F0D), to_raw(300.0, kScalePercent)) << printed;  // the input readout keeps 327.67
  }
}

}  // namespace
