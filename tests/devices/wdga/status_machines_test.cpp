// The WDGA's CiA 406 machines (devices/profiles/cia406/status_machines.h) in its transition log:
// the named bits of 6503h (alarms) and 6505h (warnings) recorded as they set and clear, with the
// word as evidence.
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

/// The same device sampling its temperature every second (warnings come from the samples).
class StatusMachines : public WdgaTest {
 protected:
  StatusMachines() : WdgaTest({{"temperature_period_s", "1"}}) {}
  std::vector<devices::Transition> of(std::string_view machine, std::uint64_t after) {
    std::vector<devices::Transition> out;
    device().transition_log().for_each_after(after, [&](const devices::Transition& t) {
      if (t.machine == machine) out.push_back(t);
    });
    return out;
  }
};

TEST_F(StatusMachines, PositionErrorIsANamedAlarmBit) {
  const auto seq = device().transition_log().last_seq();
  device().inject_fault("position_error", true);
  h().run_ms(5);
  device().inject_fault("position_error", false);
  h().run_ms(5);
  const auto a = of("cia406.alarms", seq);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].from, "none");
  EXPECT_EQ(a[0].to, "position error");
  EXPECT_EQ(a[0].transition, "set");
  EXPECT_EQ(a[0].cause, devices::TransitionCause::DeviceFault);
  EXPECT_EQ(a[0].value, 0x0000u);  // the manual documents no EMCY code for it (position_error_emcy 0)
  EXPECT_EQ(a[0].detail, "position error");
  EXPECT_EQ(a[1].to, "none");
  EXPECT_EQ(a[1].transition, "cleared");
  EXPECT_EQ(a[1].value, 0x0000u);
  EXPECT_TRUE(of("cia406.warnings", seq).empty());
}

TEST_F(StatusMachines, OverTemperatureIsANamedWarningBit) {
  const auto seq = device().transition_log().last_seq();
  device().set_input("temperature", 105);
  h().run_ms(1001);
  device().set_input("temperature", 25);
  h().run_ms(1001);
  const auto w = of("cia406.warnings", seq);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].from, "none");
  EXPECT_EQ(w[0].to, "over-temperature");
  EXPECT_EQ(w[0].cause, devices::TransitionCause::DeviceFault);
  EXPECT_EQ(w[0].value, 0x4200u);  // the temperature EMCY it sent
  EXPECT_EQ(w[0].detail, "over-temperature");
  EXPECT_EQ(w[1].from, "over-temperature");
  EXPECT_EQ(w[1].to, "none");
  EXPECT_TRUE(of("cia406.alarms", seq).empty());
}

}  // namespace
}  // namespace wdga::test
