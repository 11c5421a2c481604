// The control cycle against the bus: every channel publishes into its 6041h (what change-driven
// TPDOs send) the status word status_word() computes from scratch, idle channels included, and
// a channel that goes back to rest starts its functions from rest again. 6041h is looked at in
// the dictionary directly: an SDO read would rebuild it.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "tests/devices/md2/md2_fixture.h"

namespace md2test {

namespace {
class Md2CycleTest : public Md2Test {
 protected:
  void SetUp() override { make({{"dither_level", "0"}, {"ramp_up_ms", "100"}, {"ramp_down_ms", "50"}}); }
  static std::uint16_t at(std::uint16_t index, int c) { return static_cast<std::uint16_t>(index + 0x800 * (c - 1)); }
  void control(int c, std::uint16_t cw) { ASSERT_EQ(write(at(0x6040, c), 0, cw, 2), 0u); }
  void command(int c, std::int16_t v) { ASSERT_EQ(write(at(0x6300, c), 1, static_cast<std::uint16_t>(v), 2), 0u); }
  std::uint16_t published(int c) { return dev->node().od().get<std::uint16_t>(at(0x6041, c), 0); }
  /// `n` cycles, each checked on every channel: the word published is the word computed.
  void cycles(int n) {
    for (int i = 0; i < n; ++i) {
      h->run_ms(1);
      for (int c = 1; c <= dev->options().channels; ++c) {
        ASSERT_EQ(published(c), ch(c).control().status_word()) << "channel " << c << ", cycle " << i << " of " << n;
        words.push_back(published(c));
      }
    }
  }
  bool seen(std::uint16_t w) const { return std::find(words.begin(), words.end(), w) != words.end(); }
  std::vector<std::uint16_t> words;
};
}  // namespace

TEST_F(Md2CycleTest, PublishedStatusWordsOfBusyAndIdleChannels) {
  cycles(3);
  control(1, 0x0007);
  command(1, 16384);
  cycles(50);
  command(1, -8192);  // through zero: ramp running again
  cycles(30);
  control(1, 0x0003);  // HOLD mid-ramp
  cycles(5);
  control(1, 0x0007);
  cycles(120);
  control(2, 0x0001);  // channel 2 DISABLED, then under local control (bit 4 while idle)
  cycles(2);
  ASSERT_EQ(write(at(0x604F, 2), 0, 1, 1), 0u);
  cycles(3);
  ASSERT_EQ(write(at(0x604F, 2), 0, 0, 1), 0u);
  control(3, 0x0007);
  command(3, 4000);
  cycles(120);
  control(1, 0x0001);
  cycles(3);
  EXPECT_TRUE(seen(0x020F));  // ramp running
  EXPECT_TRUE(seen(0x000F));
  EXPECT_TRUE(seen(0x000B));
  EXPECT_TRUE(seen(0x0019));  // DISABLED under local control
}

TEST_F(Md2CycleTest, PublishedStatusWordOfTheClosedLoopWindow) {
  make({{"dither_level", "0"}, {"kp", "4"}, {"ki", "20"}, {"p_range", "20000000"}}, "controller");
  ASSERT_EQ(write(0x6043, 0, 4, 1), 0u);
  ASSERT_EQ(write(0x6380, 1, 8192, 2), 0u);
  ASSERT_EQ(dev->set_input("actual", 60e5), "");
  control(1, 0x0007);
  cycles(3);
  ASSERT_EQ(dev->set_input("actual", 100e5), "");
  cycles(3);
  control(1, 0x0003);
  cycles(3);
  ASSERT_EQ(write(0x6380, 1, 16000, 2), 0u);  // HOLD keeps its set point: out of the window?
  cycles(3);
  control(1, 0x0007);
  cycles(3);
  EXPECT_TRUE(seen(0x100F));
  EXPECT_TRUE(seen(0x100B));
  EXPECT_TRUE(seen(0x000F));
}

TEST_F(Md2CycleTest, ARestedChannelRampsFromZeroAgain) {
  control(1, 0x0007);
  command(1, 16384);
  h->run_ms(1);
  const double first = ch().solenoid_a;
  h->run_ms(40);
  EXPECT_GT(ch().solenoid_a, first);
  control(1, 0x0001);  // DISABLED: the ramp goes back to 0
  h->run_ms(3);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  control(1, 0x0007);
  h->run_ms(1);
  EXPECT_DOUBLE_EQ(ch().solenoid_a, first);
  command(1, 0);  // a set point written between two cycles acts in the next one
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
}

TEST_F(Md2CycleTest, AConditionStillPresentAfterAResetNodeRaisesItsEmcyAgain) {
  auto general_emcys = [](const Frames& frames) {
    return std::count_if(frames.begin(), frames.end(), [](const Frame& f) {
      return f.id == 0x081 && f.data.size() >= 2 && f.data[0] == 0x00 && f.data[1] == 0x10;
    });
  };
  dev->inject_fault("general_error", true);
  h->run_ms(5);
  EXPECT_EQ(general_emcys(h->take()), 1);  // once: the condition persists without a new edge
  h->nmt(0x81, 1);  // reset node: the errors are forgotten and detected afresh
  h->run_ms(5);
  EXPECT_EQ(general_emcys(h->take()), 1);
  dev->inject_fault("general_error", false);
  h->run_ms(2);
  dev->inject_fault("general_error", true);  // a new edge
  h->run_ms(2);
  EXPECT_EQ(general_emcys(h->take()), 0);  // still latched: no repeated EMCY (§4.4.1)
}

}  // namespace md2test
