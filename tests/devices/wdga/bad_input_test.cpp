// WDGA robustness: malformed SDO and LSS frames (and a seeded stream of random ones) never crash
// the node and never change what they must not.
#include <random>

#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

using Snapshot = std::map<std::pair<std::uint16_t, std::uint8_t>, canopen::Bytes>;

class BadInput : public WdgaTest {
 protected:
  Snapshot snapshot() {
    Snapshot s;
    for (const auto& [index, object] : od().objects())
      for (const auto& [sub, e] : object.entries) s[{index, sub}] = e.value.bytes();
    return s;
  }
};

TEST_F(BadInput, MalformedSdoRequestsChangeNothing) {
  h().run_ms(2);
  const auto before = snapshot();
  EXPECT_EQ(sdo({0xC0, 0x00, 0x60, 0x00})->data[0], 0x80);
  EXPECT_EQ(sdo({0xE0})->data[0], 0x80);
  EXPECT_EQ(sdo({0x00, 1, 2, 3, 4, 5, 6, 7})->data[0], 0x80);   // segment without a transfer
  EXPECT_EQ(sdo({0x70, 1, 2, 3, 4, 5, 6, 7})->data[0], 0x80);
  EXPECT_EQ(h().write(0x6000, 0, 0x00010004, 4), 0x06070012u);  // excess bytes not zero
  EXPECT_EQ(h().write(0x6301, 1, 0x0107, 4), 0x06070012u);
  EXPECT_EQ(h().write(0x6310, 1, 0, 4), 0u);                      // unchanged value: accepted
  EXPECT_EQ(h().download(0x6001, 0, {1, 2, 3}), 0x06070010u);     // segmented, wrong total
  EXPECT_EQ(h().download(0x6009, 0, {1, 2, 3, 4, 5, 6, 7, 8, 9}), 0x06070010u);
  EXPECT_EQ(h().write(0x1005, 0, 0x40000080, 4), 0x06090030u);
  EXPECT_EQ(h().write(0x1010, 5, kSave, 4), 0x06090011u);
  EXPECT_EQ(h().write(0x1800, 3, 10, 2), 0x06090011u);
  h().send(Frame(0x67F, std::vector<std::uint8_t>{}));
  EXPECT_TRUE(h().take().empty());
  h().run_ms(2);
  EXPECT_EQ(snapshot(), before);
}

TEST_F(BadInput, MalformedLssFramesChangeNothing) {
  const auto node_id = id();
  const auto rate = device().node().lss()->pending_bit_rate();
  auto lss = [&](std::vector<std::uint8_t> d) {
    h().send(Frame(0x7E5, std::move(d)));
    return h().take();
  };
  EXPECT_TRUE(lss({}).empty());
  EXPECT_TRUE(lss({0x04, 0x07}).empty());
  EXPECT_TRUE(lss(eight({0x11, 0x05})).empty());  // waiting
  EXPECT_TRUE(lss(eight({0x43, 0x38, 0x61, 0xBC, 0x00})).empty());
  for (std::uint8_t cs : {0x00, 0x12, 0x15, 0x16, 0x44, 0x4C, 0x4F, 0x50, 0x51, 0x59, 0x5F, 0xFF}) {
    EXPECT_TRUE(lss(eight({cs, 1, 2, 3, 4, 5, 6, 7})).empty()) << int(cs);
  }
  lss(eight({0x04, 0x01}));
  EXPECT_EQ(lss(eight({0x13, 0x01, 0x03})), Frames{Frame(0x7E4, eight({0x13, 0x01}))});
  EXPECT_EQ(lss(eight({0x11, 0x00})), Frames{Frame(0x7E4, eight({0x11, 0x01}))});
  lss(eight({0x04, 0x00}));
  EXPECT_EQ(device().node().lss()->pending_node_id(), node_id);
  EXPECT_EQ(device().node().lss()->pending_bit_rate(), rate);
  power_cycle();
  EXPECT_EQ(id(), node_id);
}

TEST_F(BadInput, RandomFramesNeverCrashAndTheNodeStillAnswers) {
  std::mt19937 rng(5150);
  std::uniform_int_distribution<int> byte(0, 255), dlc(0, 8);
  const std::uint32_t ids[] = {0x080, 0x1FF, 0x2FF, 0x67F, 0x77F, 0x7E5, 0x5FF, 0x77E};
  for (int i = 0; i < 20000; ++i) {
    Frame f;
    f.id = ids[static_cast<std::size_t>(byte(rng)) % std::size(ids)];
    if (byte(rng) < 16) {
      f = Frame::remote(f.id, static_cast<std::uint8_t>(dlc(rng)));
    } else {
      f.data.resize(static_cast<std::size_t>(dlc(rng)));
      for (auto& b : f.data) b = static_cast<std::uint8_t>(byte(rng));
    }
    h().send(f);
    if (i % 64 == 0) h().run_ticks(1);
  }
  h().nmt(0x80, 0);
  h().take();
  EXPECT_EQ(h().read_u(0x1000, 0), 0x00020196u);
}

}  // namespace
}  // namespace wdga::test
