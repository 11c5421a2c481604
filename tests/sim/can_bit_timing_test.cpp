// Frame lengths against hand-computed bit counts (ISO 11898-1 framing, CRC-15, bit stuffing) and
// against a bit-by-bit reference implementation kept here.
#include "sim/can_bit_timing.h"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

namespace {

using sim::CanFrame;
using sim::frame_bits;

CanFrame ext_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  auto f = CanFrame::data_frame(id, bytes);
  f.extended = true;
  return f;
}

// The straightforward definition frame_bits() must agree with: every bit SOF .. CRC sequence
// written out one by one, the CRC-15 computed bit by bit, stuff bits counted bit by bit.
sim::FrameBits reference_frame_bits(const CanFrame& frame) {
  std::array<std::uint8_t, 1 + 32 + 6 + 64 + 15> bits{};
  unsigned n = 0;
  auto put = [&](std::uint32_t value, unsigned width) {
    for (unsigned i = width; i-- > 0;) bits[n++] = static_cast<std::uint8_t>((value >> i) & 1u);
  };
  put(0, 1);  // SOF
  const unsigned dlc = frame.dlc > 8 ? 8u : frame.dlc;
  if (!frame.extended) {
    put(frame.id & 0x7FF, 11);
    put(frame.rtr ? 1 : 0, 1);  // RTR
    put(0, 1);                  // IDE
    put(0, 1);                  // r0
  } else {
    put((frame.id >> 18) & 0x7FF, 11);
    put(1, 1);  // SRR
    put(1, 1);  // IDE
    put(frame.id & 0x3FFFF, 18);
    put(frame.rtr ? 1 : 0, 1);  // RTR
    put(0, 2);                  // r1, r0
  }
  put(dlc, 4);
  if (!frame.rtr)
    for (unsigned i = 0; i < dlc; ++i) put(frame.data[i], 8);
  sim::FrameBits out;
  std::uint16_t crc = 0;
  for (unsigned i = 0; i < n; ++i) {
    const bool next = (bits[i] ^ (crc >> 14)) & 1u;
    crc = static_cast<std::uint16_t>((crc << 1) & 0x7FFF);
    if (next) crc ^= 0x4599;
  }
  out.crc = crc;
  put(crc, 15);
  out.stuffed_region = n;
  unsigned run = 0;
  std::uint8_t last = 2;
  for (unsigned i = 0; i < n; ++i) {
    if (bits[i] == last) {
      ++run;
    } else {
      last = bits[i];
      run = 1;
    }
    if (run == 5) {  // the stuff bit has the other level and starts the next run
      ++out.stuff_bits;
      last = static_cast<std::uint8_t>(last ^ 1u);
      run = 1;
    }
  }
  return out;
}

void expect_same_bits(const CanFrame& f) {
  const auto fast = frame_bits(f);
  const auto ref = reference_frame_bits(f);
  ASSERT_EQ(fast.stuffed_region, ref.stuffed_region) << sim::to_candump(f) << " ext " << f.extended;
  ASSERT_EQ(fast.crc, ref.crc) << sim::to_candump(f) << " ext " << f.extended;
  ASSERT_EQ(fast.stuff_bits, ref.stuff_bits) << sim::to_candump(f) << " ext " << f.extended;
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

// frame_bits() works a byte at a time through tables; it must not drift from the bit-by-bit
// definition. Random frames, half of them with runs of equal bytes (the stuffing cases), every
// DLC (above 8 the data field stays 8 bytes), 11- and 29-bit identifiers, data and remote.
TEST(CanBitTiming, MatchesBitByBitReferenceOnRandomFrames) {
  std::mt19937 rng(20261125);
  for (int i = 0; i < 200000; ++i) {
    CanFrame f;
    f.extended = (rng() & 1u) != 0;
    f.id = f.extended ? rng() & CanFrame::kMaxExtId : rng() & CanFrame::kMaxStdId;
    if (rng() % 8 == 0) f.id = f.extended ? (rng() % 2 ? CanFrame::kMaxExtId : 0) : (rng() % 2 ? CanFrame::kMaxStdId : 0);
    f.rtr = rng() % 4 == 0;
    f.dlc = static_cast<std::uint8_t>(rng() % 10 == 0 ? 9 + rng() % 7 : rng() % 9);
    const bool runs = (rng() & 1u) != 0;
    for (auto& b : f.data) {
      const auto r = rng();
      b = static_cast<std::uint8_t>(runs ? ((r & 3u) == 0 ? r >> 8 : ((r & 4u) ? 0xFF : 0x00)) : r >> 8);
    }
    expect_same_bits(f);
  }
}

TEST(CanBitTiming, MatchesBitByBitReferenceOnEveryStandardIdentifier) {
  for (std::uint32_t id = 0; id <= CanFrame::kMaxStdId; ++id) {
    for (std::uint8_t dlc = 0; dlc <= 8; ++dlc) {
      auto f = CanFrame::data_frame(id, {});
      f.dlc = dlc;
      f.data = {0x00, 0xFF, 0x0F, 0xF0, 0x83, 0x7C, 0x00, 0x00};
      expect_same_bits(f);
      f.rtr = true;
      expect_same_bits(f);
    }
  }
}

TEST(CanBitTiming, Crc15MatchesFrameCrc) {
  // can_crc15() over the frame's bits gives the CRC frame_bits() reports.
  const auto f = CanFrame::data_frame(0x181, {1, 2, 3, 4, 5, 6, 7, 8});
  std::array<std::uint8_t, 19 + 64> bits{};
  unsigned n = 0;
  auto put = [&](std::uint32_t value, unsigned width) {
    for (unsigned i = width; i-- > 0;) bits[n++] = static_cast<std::uint8_t>((value >> i) & 1u);
  };
  put(0, 1);
  put(0x181, 11);
  put(0, 3);
  put(8, 4);
  for (auto b : f.data) put(b, 8);
  EXPECT_EQ(sim::can_crc15(bits.data(), n), frame_bits(f).crc);
}

// The bus's cache of frame lengths answers what frame_bits() would, also for frames that differ
// from a cached one only in a data byte, the DLC, the format or RTR, and for colliding slots.
TEST(CanBitTiming, CacheAgreesWithFrameBits) {
  std::mt19937 rng(7);
  sim::FrameBitsCache cache;
  std::vector<CanFrame> seen;
  for (int i = 0; i < 50000; ++i) {
    CanFrame f;
    if (!seen.empty() && rng() % 2 == 0) {
      f = seen[rng() % seen.size()];
      switch (rng() % 6) {
        case 0: f.data[rng() % 8] ^= static_cast<std::uint8_t>(1u << (rng() % 8)); break;
        case 1: f.dlc = static_cast<std::uint8_t>(rng() % 9); break;
        case 2: f.extended = !f.extended; break;
        case 3: f.rtr = !f.rtr; break;
        case 4: f.id ^= 64u << (rng() % 4); break;  // another identifier, maybe the same slot
        default: break;                             // the same frame again
      }
    } else {
      f.extended = rng() % 4 == 0;
      f.id = f.extended ? rng() & CanFrame::kMaxExtId : rng() & CanFrame::kMaxStdId;
      f.rtr = rng() % 8 == 0;
      f.dlc = static_cast<std::uint8_t>(rng() % 9);
      for (auto& b : f.data) b = static_cast<std::uint8_t>(rng() % 3 == 0 ? 0 : rng());
      if (seen.size() < 64) seen.push_back(f);
    }
    const auto cached = cache.get(f);
    const auto direct = frame_bits(f);
    ASSERT_EQ(cached.stuffed_region, direct.stuffed_region) << i;
    ASSERT_EQ(cached.stuff_bits, direct.stuff_bits) << i;
    ASSERT_EQ(cached.crc, direct.crc) << i;
  }
}
