#include "sim/can_bit_timing.h"

#include <array>

namespace sim {

namespace {

// SOF .. CRC sequence of the longest frame: 1 + 32 + 6 + 64 + 15 bits.
constexpr unsigned kMaxRegion = 1 + 32 + 6 + 64 + 15;

struct BitWriter {
  std::array<std::uint8_t, kMaxRegion> bits{};
  unsigned n = 0;
  void put(std::uint32_t value, unsigned width) {
    for (unsigned i = width; i-- > 0;) bits[n++] = static_cast<std::uint8_t>((value >> i) & 1u);
  }
};

}  // namespace

std::uint16_t can_crc15(const std::uint8_t* bits, unsigned count) {
  std::uint16_t crc = 0;
  for (unsigned i = 0; i < count; ++i) {
    const bool next = (bits[i] ^ (crc >> 14)) & 1u;
    crc = static_cast<std::uint16_t>((crc << 1) & 0x7FFF);
    if (next) crc ^= 0x4599;
  }
  return crc;
}

FrameBits frame_bits(const CanFrame& frame) {
  BitWriter w;
  w.put(0, 1);  // SOF
  const unsigned dlc = frame.dlc > 8 ? 8u : frame.dlc;
  if (!frame.extended) {
    w.put(frame.id & 0x7FF, 11);
    w.put(frame.rtr ? 1 : 0, 1);  // RTR
    w.put(0, 1);                  // IDE
    w.put(0, 1);                  // r0
  } else {
    w.put((frame.id >> 18) & 0x7FF, 11);
    w.put(1, 1);  // SRR
    w.put(1, 1);  // IDE
    w.put(frame.id & 0x3FFFF, 18);
    w.put(frame.rtr ? 1 : 0, 1);  // RTR
    w.put(0, 2);                  // r1, r0
  }
  w.put(dlc, 4);
  if (!frame.rtr)
    for (unsigned i = 0; i < dlc; ++i) w.put(frame.data[i], 8);
  FrameBits out;
  out.crc = can_crc15(w.bits.data(), w.n);
  w.put(out.crc, 15);
  out.stuffed_region = w.n;
  // After five equal bits the transmitter inserts one of the other level; it counts as the
  // first bit of the next run.
  unsigned run = 0;
  std::uint8_t last = 2;
  for (unsigned i = 0; i < w.n; ++i) {
    if (w.bits[i] == last) {
      ++run;
    } else {
      last = w.bits[i];
      run = 1;
    }
    if (run == 5) {
      ++out.stuff_bits;
      last = static_cast<std::uint8_t>(last ^ 1u);
      run = 1;
    }
  }
  return out;
}

std::uint64_t arbitration_key(const CanFrame& frame) {
  // 11 base bits, RTR|SRR, IDE, 18 extension bits, RTR (extended only): 32 bits, MSB first.
  std::uint64_t key;
  if (!frame.extended) {
    key = (static_cast<std::uint64_t>(frame.id & 0x7FF) << 21) | (static_cast<std::uint64_t>(frame.rtr) << 20);
  } else {
    key = (static_cast<std::uint64_t>((frame.id >> 18) & 0x7FF) << 21) | (1ull << 20) | (1ull << 19) |
          (static_cast<std::uint64_t>(frame.id & 0x3FFFF) << 1) | static_cast<std::uint64_t>(frame.rtr);
  }
  return key;
}

}  // namespace sim
