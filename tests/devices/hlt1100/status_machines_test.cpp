// The HLT 1100's CiA 406 machines (devices/profiles/cia406/status_machines.h) in its transition
// log: each named bit of 6503h recorded as it sets (raised by a device fault: the fault with its
// EMCY code) and clears (the word as evidence).
#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

std::vector<devices::Transition> of(const devices::TransitionLog& log, std::string_view machine, std::uint64_t after) {
  std::vector<devices::Transition> out;
  log.for_each_after(after, [&](const devices::Transition& t) {
    if (t.machine == machine) out.push_back(t);
  });
  return out;
}

TEST_F(Hlt1100Test, MagnetLostSetsAndClearsTheNamedAlarmBit) {
  start();
  const auto seq = device().transition_log().last_seq();
  device().inject_fault("magnet_lost", true);
  h().run_ms(5);
  device().inject_fault("magnet_lost", false);
  h().run_ms(5);
  const auto a = of(device().transition_log(), "cia406.alarms", seq);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].from, "none");
  EXPECT_EQ(a[0].to, "position error");
  EXPECT_EQ(a[0].transition, "set");
  EXPECT_EQ(a[0].cause, devices::TransitionCause::DeviceFault);  // not `internal`
  EXPECT_EQ(a[0].value, 0xFF00u);  // the EMCY the alarm sent (position_emcy_code)
  EXPECT_EQ(a[0].detail, "position error");
  EXPECT_EQ(a[1].from, "position error");
  EXPECT_EQ(a[1].to, "none");
  EXPECT_EQ(a[1].transition, "cleared");
  EXPECT_EQ(a[1].cause, devices::TransitionCause::Internal);
  EXPECT_EQ(a[1].value, 0x0000u);  // 6503h as it became
  EXPECT_EQ(a[1].detail, "Alarms 6503h (CiA 406)");
  EXPECT_GT(a[1].t_us, a[0].t_us);
  // Nothing else changed: no status or warning entries.
  EXPECT_TRUE(of(device().transition_log(), "cia406.status", seq).empty());
  EXPECT_TRUE(of(device().transition_log(), "cia406.warnings", seq).empty());
}

TEST_F(Hlt1100Test, AnAlarmFromAnSdoWriteNamesItsEmcyCode) {
  start();
  const auto seq = device().transition_log().last_seq();
  // A preset beyond the range is confirmed, not applied: "parameter error" (EMCY 6300h).
  EXPECT_EQ(h().write(0x6010, 1, 5000, 4), 0u);
  h().run_ms(5);
  const auto a = of(device().transition_log(), "cia406.alarms", seq);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].to, "parameter error");
  EXPECT_EQ(a[0].cause, devices::TransitionCause::DeviceFault);
  EXPECT_EQ(a[0].value, 0x6300u);
  EXPECT_EQ(a[0].detail, "parameter error");
}

}  // namespace
}  // namespace hlt1100::test
