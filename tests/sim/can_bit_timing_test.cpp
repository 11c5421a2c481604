// Frame lengths against hand-computed bit counts (ISO 11898-1 framing, CRC-15, bit stuffing).
#include "sim/can_bit_timing.h"

#include <gtest/gtest.h>

namespace {

using sim::CanFrame;
using sim::frame_bits;

CanFrame ext_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  auto f = CanFrame::data_frame(id, bytes);
  f.extended = true;
  return f;
}

}  // namespace

TEST(CanBitTiming, Crc15OfZerosIsZero) {
  const std::uint8_t zeros[19] = {};
  EXPECT_EQ(sim::can_crc15(zeros, 19), 0u);
}

// Standard, DLC 0, identifier 0: SOF, 11 identifier bits, RTR, IDE, r0 and DLC are 19 dominant
// bits, the CRC of all-zero bits is zero: 34 dominant bits in a row. A stuff bit follows every
// fifth (it starts the next run): 6 stuff bits. 34 + 6 + CRC delimiter 1 + ACK 2 + EOF 7 +
// intermission 3 = 53.
TEST(CanBitTiming, StandardDlc0WithStuffing) {
  const auto b = frame_bits(CanFrame::data_frame(0x000, {}));
  EXPECT_EQ(b.stuffed_region, 34u);
  EXPECT_EQ(b.crc, 0u);
  EXPECT_EQ(b.stuff_bits, 6u);
  EXPECT_EQ(b.total(), 53u);
  EXPECT_EQ(b.until_eof(), 50u);
}

// Standard, DLC 8, no stuff bit at all: 1 + 11 + 3 + 4 + 64 + 15 = 98, + 13 = 111 bits, the
// nominal length of a standard 8-byte frame. (0x086 with 0x55 bytes: CRC 0x3D85.)
TEST(CanBitTiming, StandardDlc8WithoutStuffing) {
  const auto b = frame_bits(CanFrame::data_frame(0x086, {0x55, 0x55, 0x55, 0x55, 0x55, 0x55, 0x55, 0x55}));
  EXPECT_EQ(b.stuffed_region, 98u);
  EXPECT_EQ(b.crc, 0x3D85u);
  EXPECT_EQ(b.stuff_bits, 0u);
  EXPECT_EQ(b.total(), 111u);
}

TEST(CanBitTiming, StandardDlc8AllZeroData) {
  // SOF, identifier, RTR, IDE, r0: 15 dominant bits, 3 stuff bits. DLC 1000. Then 3 + 64 = 67
  // dominant bits: 13 stuff bits. The CRC 0x145B (001010001011011) adds no fifth equal bit.
  const auto b = frame_bits(CanFrame::data_frame(0x000, {0, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(b.crc, 0x145Bu);
  EXPECT_EQ(b.stuff_bits, 16u);
  EXPECT_EQ(b.total(), 127u);
}

TEST(CanBitTiming, StandardDlc0AllRecessiveIdentifier) {
  const auto b = frame_bits(CanFrame::data_frame(0x7FF, {}));
  EXPECT_EQ(b.stuffed_region, 34u);
  EXPECT_EQ(b.stuff_bits, 3u);  // two in the identifier, one in RTR..DLC (7 dominant bits)
  EXPECT_EQ(b.total(), 50u);
}

TEST(CanBitTiming, ExtendedDlc0) {
  // 1 + 11 + SRR + IDE + 18 + RTR + r1 + r0 + 4 + 15 = 54, nominal 67; CRC 0x6C97.
  const auto b = frame_bits(ext_frame(0x12345678 & 0x1FFFFFFF, {}));
  EXPECT_EQ(b.stuffed_region, 54u);
  EXPECT_EQ(b.crc, 0x6C97u);
  EXPECT_EQ(b.stuff_bits, 2u);
  EXPECT_EQ(b.total(), 69u);
}

TEST(CanBitTiming, ExtendedDlc8AllRecessive) {
  // Nominal 131 bits; 18 stuff bits in the long recessive runs.
  const auto b = frame_bits(ext_frame(0x1FFFFFFF, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(b.stuffed_region, 118u);
  EXPECT_EQ(b.stuff_bits, 18u);
  EXPECT_EQ(b.total(), 149u);
}

TEST(CanBitTiming, RemoteFrameHasNoDataField) {
  const auto b = frame_bits(CanFrame::remote_frame(0x701, 1));
  EXPECT_EQ(b.stuffed_region, 34u);
  EXPECT_EQ(b.total(), 51u);
}

TEST(CanBitTiming, ArbitrationOrder) {
  using sim::arbitration_key;
  const auto data100 = CanFrame::data_frame(0x100, {1});
  const auto rtr100 = CanFrame::remote_frame(0x100, 1);
  auto ext100 = ext_frame(0x100u << 18, {1});
  EXPECT_LT(arbitration_key(CanFrame::data_frame(0x080, {})), arbitration_key(data100));
  EXPECT_LT(arbitration_key(data100), arbitration_key(rtr100));  // RTR is recessive
  EXPECT_LT(arbitration_key(rtr100), arbitration_key(ext100));   // IDE decides after RTR = SRR
  EXPECT_LT(arbitration_key(data100), arbitration_key(ext100));  // SRR is recessive
  auto ext_rtr = ext100;
  ext_rtr.rtr = true;
  EXPECT_LT(arbitration_key(ext100), arbitration_key(ext_rtr));
  EXPECT_LT(arbitration_key(ext_rtr), arbitration_key(CanFrame::data_frame(0x101, {})));
}
