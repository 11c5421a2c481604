// HLT 1100 robustness: malformed SDO and LSS frames (and a seeded stream of random ones) never
// crash the node and never change what they must not: object values, node-ID, bit rate, LSS
// and NMT state.
#include <random>

#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

using Snapshot = std::map<std::pair<std::uint16_t, std::uint8_t>, canopen::Bytes>;

class BadInput : public Hlt1100Test {
 protected:
  Snapshot snapshot() {
    Snapshot s;
    for (const auto& [index, object] : od().objects())
      for (const auto& [sub, e] : object.entries) s[{index, sub}] = e.value.bytes();
    return s;
  }
  struct State {
    std::uint8_t node_id, pending_id, bit_rate, pending_rate;
    canopen::NmtState nmt;
    canopen::LssSlave::State lss;
    bool operator==(const State&) const = default;
  };
  State state() {
    auto& n = device().node();
    return {n.node_id(), n.pending_node_id(), n.lss()->active_bit_rate(), n.lss()->pending_bit_rate(), n.nmt_state(),
            n.lss()->state()};
  }
};

TEST_F(BadInput, MalformedSdoRequestsAbortOrAreIgnored) {
  const auto before = snapshot();
  // Block transfer, reserved specifiers, segments without a transfer, wrong sizes, no object.
  EXPECT_EQ(sdo({0xC0, 0x00, 0x60, 0x00})->data[0], 0x80);
  EXPECT_EQ(sdo({0xE0, 0x00, 0x60, 0x00})->data[0], 0x80);
  EXPECT_EQ(sdo({0x00, 1, 2, 3, 4, 5, 6, 7})->data[0], 0x80);
  EXPECT_EQ(sdo({0x60, 1, 2, 3, 4, 5, 6, 7})->data[0], 0x80);
  EXPECT_EQ(h().write(0x6000, 0, 8, 4), 0x06070010u);
  EXPECT_EQ(h().write(0x6000, 0, 8, 1), 0x06070010u);
  EXPECT_EQ(h().write(0x6010, 1, 7, 2), 0x06070010u);
  EXPECT_EQ(h().write(0x1F80, 0, 0x08, 2), 0x06070010u);
  EXPECT_EQ(h().write(0x1003, 0, 0, 4), 0x06070010u);
  EXPECT_EQ(h().write(0x6002, 0, 0, 4), 0x06020000u);
  EXPECT_EQ(h().write(0x6010, 2, 0, 4), 0x06090011u);
  EXPECT_EQ(h().write(0x1005, 0, 0x40000080, 4), 0x06090030u);  // SYNC producer: never
  EXPECT_EQ(h().write(0x1005, 0, 0x80000880, 4), 0x06090030u);  // not an 11-bit ID
  // A segmented download of a numeric object with the wrong total.
  EXPECT_EQ(h().download(0x6200, 0, {1, 2, 3}), 0x06070010u);
  EXPECT_EQ(h().download(0x1008, 0, {'x'}), 0x06010000u);
  // An SDO frame with DLC 0 is ignored.
  h().send(Frame(0x605, std::vector<std::uint8_t>{}));
  EXPECT_TRUE(h().take().empty());
  h().run_ms(5);
  EXPECT_EQ(snapshot(), before);
}

TEST_F(BadInput, MalformedLssFramesChangeNothing) {
  const auto before = snapshot();
  const auto st = state();
  auto lss = [&](std::vector<std::uint8_t> d) {
    h().send(Frame(0x7E5, std::move(d)));
    return h().take();
  };
  EXPECT_TRUE(lss({}).empty());                     // DLC 0
  EXPECT_TRUE(lss({0x04, 0x02}).empty());           // unknown mode
  EXPECT_TRUE(lss({0x04, 0xFF}).empty());
  EXPECT_TRUE(lss({0x11, 0x0C}).empty());           // configure while waiting
  EXPECT_TRUE(lss({0x43, 0x01, 0, 0, 0}).empty());  // selective out of order
  EXPECT_TRUE(lss({0x41, 0x00, 0x11, 0, 0}).empty());
  EXPECT_TRUE(lss({0x51, 0, 0, 0, 0, 40, 0, 0}).empty());  // fastscan, configured node
  for (std::uint8_t cs : {0x00, 0x01, 0x12, 0x14, 0x16, 0x18, 0x44, 0x4D, 0x4E, 0x4F, 0x50, 0x59, 0x5F, 0xFF}) {
    EXPECT_TRUE(lss(eight({cs, 1, 2, 3, 4, 5, 6, 7})).empty()) << int(cs);
  }
  h().send(Frame::remote(0x7E5, 8));
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(state(), st);
  // In configuration: invalid values are answered with an error and change nothing.
  lss(eight({0x04, 0x01}));
  EXPECT_EQ(lss(eight({0x11, 0x00})), Frames{Frame(0x7E4, eight({0x11, 0x01}))});
  EXPECT_EQ(lss(eight({0x13, 0x02, 0x00})), Frames{Frame(0x7E4, eight({0x13, 0x01}))});
  lss(eight({0x04, 0x00}));
  EXPECT_EQ(state(), st);
  EXPECT_EQ(snapshot(), before);
}

TEST_F(BadInput, RandomFramesNeverCrashAndTheNodeStillAnswers) {
  std::mt19937 rng(20240506);
  std::uniform_int_distribution<int> byte(0, 255), dlc(0, 8);
  const std::uint32_t ids[] = {0x000, 0x080, 0x185, 0x285, 0x605, 0x705, 0x7E5, 0x7E4, 0x585};
  for (int i = 0; i < 20000; ++i) {
    Frame f;
    f.id = ids[static_cast<std::size_t>(byte(rng)) % std::size(ids)];
    if (f.id == 0x000) continue;  // random NMT commands legitimately reset or stop the node
    if (byte(rng) < 16) {
      f = Frame::remote(f.id, static_cast<std::uint8_t>(dlc(rng)));
    } else {
      f.data.resize(static_cast<std::size_t>(dlc(rng)));
      for (auto& b : f.data) b = static_cast<std::uint8_t>(byte(rng));
    }
    h().send(f);
    if (i % 64 == 0) h().run_ticks(1);
  }
  h().run_ms(3100);  // a random "save" may have silenced the node
  h().nmt(0x82, 0);  // whatever LSS did, a communication reset brings a known node back
  h().run_ms(10);
  h().take();
  const auto id = device().node().node_id();
  ASSERT_TRUE(id >= 1 && id <= 127);
  h().send(Frame(0x600u + id, eight({0x40, 0x00, 0x10, 0x00})));
  const auto got = h().take();
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0], Frame(0x580u + id, eight({0x43, 0x00, 0x10, 0x00, 0x96, 0x01, 0x0A, 0x00})));
}

}  // namespace
}  // namespace hlt1100::test
