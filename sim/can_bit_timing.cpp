#include "sim/can_bit_timing.h"

#include <array>

namespace sim {

namespace {

// The frame's bits SOF .. CRC sequence are packed MSB-first into bytes, so the CRC and the stuff
// bits are found a byte at a time through tables (the bus times every frame with frame_bits()).
// tests/sim/can_bit_timing_test.cpp checks both against a bit-by-bit reference.

// SOF .. CRC sequence of the longest frame: 1 + 32 + 6 + 64 + 15 = 118 bits, 15 bytes.
constexpr unsigned kMaxRegionBytes = (1 + 32 + 6 + 64 + 15 + 7) / 8;
constexpr std::uint16_t kCrcPoly = 0x4599;

// One bit through the CRC-15 register (ISO 11898-1: the next bit XOR the register's top bit).
constexpr std::uint16_t crc_bit(std::uint16_t crc, unsigned bit) {
  const bool next = ((bit ^ (crc >> 14)) & 1u) != 0;
  crc = static_cast<std::uint16_t>((crc << 1) & 0x7FFF);
  return next ? static_cast<std::uint16_t>(crc ^ kCrcPoly) : crc;
}

// The register after eight zero bits, starting from the byte in its top eight bits: feeding a
// byte b to register r is then (r << 8) ^ table[(r >> 7) ^ b] (the classic table-driven CRC).
constexpr std::array<std::uint16_t, 256> make_crc_table() {
  std::array<std::uint16_t, 256> t{};
  for (unsigned b = 0; b < 256; ++b) {
    auto crc = static_cast<std::uint16_t>(b << 7);
    for (int i = 0; i < 8; ++i) crc = crc_bit(crc, 0);
    t[b] = crc;
  }
  return t;
}
constexpr auto kCrcTable = make_crc_table();

// The stuffing state between two bits: the level of the last bit on the wire (stuff bits count)
// and how many bits of that level end the stream (1..4; a fifth is followed by a stuff bit, which
// starts a run of one). state = level * 4 + run - 1. Before SOF the state is "recessive, run 1":
// SOF is dominant, so it starts a run of its own exactly as on an idle bus.
constexpr unsigned kStuffStart = 1 * 4 + 0;

struct StuffStep {
  unsigned state;
  unsigned stuffed;  // 0 or 1
};

constexpr StuffStep stuff_bit(unsigned state, unsigned bit) {
  const unsigned level = state >> 2;
  unsigned run = (state & 3u) + 1;
  if (bit == level) {
    ++run;
  } else {
    run = 1;
  }
  if (run == 5) return {(level ^ 1u) * 4, 1};  // the stuff bit: the other level, a run of one
  return {bit * 4 + run - 1, 0};
}

// Per state and byte: the state after the byte's eight bits (low 3 bits) and the stuff bits they
// need (above).
constexpr std::array<std::array<std::uint8_t, 256>, 8> make_stuff_table() {
  std::array<std::array<std::uint8_t, 256>, 8> t{};
  for (unsigned s = 0; s < 8; ++s) {
    for (unsigned b = 0; b < 256; ++b) {
      unsigned state = s;
      unsigned stuffed = 0;
      for (unsigned i = 8; i-- > 0;) {
        const auto step = stuff_bit(state, (b >> i) & 1u);
        state = step.state;
        stuffed += step.stuffed;
      }
      t[s][b] = static_cast<std::uint8_t>(stuffed << 3 | state);
    }
  }
  return t;
}
constexpr auto kStuffTable = make_stuff_table();

// Packs bit fields MSB-first into whole bytes; up to 7 bits wait in `pending`.
struct BitPacker {
  std::array<std::uint8_t, kMaxRegionBytes + 1> bytes{};
  unsigned full = 0;      // whole bytes written
  std::uint64_t acc = 0;  // the low `pending` bits are the ones not yet in a byte
  unsigned pending = 0;
  // width + 7 pending bits must fit in acc: width <= 57.
  void put(std::uint64_t value, unsigned width) {
    acc = (acc << width) | value;
    pending += width;
    while (pending >= 8) {
      pending -= 8;
      bytes[full++] = static_cast<std::uint8_t>(acc >> pending);
    }
  }
  unsigned tail() const { return static_cast<unsigned>(acc) & ((1u << pending) - 1u); }
};

}  // namespace

std::uint16_t can_crc15(const std::uint8_t* bits, unsigned count) {
  std::uint16_t crc = 0;
  for (unsigned i = 0; i < count; ++i) crc = crc_bit(crc, bits[i]);
  return crc;
}

FrameBits frame_bits(const CanFrame& frame) {
  BitPacker w;
  const unsigned dlc = frame.dlc > 8 ? 8u : frame.dlc;
  const std::uint64_t rtr = frame.rtr ? 1 : 0;
  if (!frame.extended) {
    // SOF, 11-bit identifier, RTR, IDE, r0, DLC: 19 bits.
    w.put((std::uint64_t{frame.id & 0x7FF} << 7) | (rtr << 6) | dlc, 19);
  } else {
    // SOF, base identifier, SRR, IDE, 18-bit extension, RTR, r1, r0, DLC: 39 bits.
    w.put((std::uint64_t{(frame.id >> 18) & 0x7FF} << 27) | (std::uint64_t{3} << 25) |
              (std::uint64_t{frame.id & 0x3FFFF} << 7) | (rtr << 6) | dlc,
          39);
  }
  if (!frame.rtr)
    for (unsigned i = 0; i < dlc; ++i) w.put(frame.data[i], 8);

  FrameBits out;
  std::uint16_t crc = 0;
  for (unsigned i = 0; i < w.full; ++i)
    crc = static_cast<std::uint16_t>(((crc << 8) & 0x7FFF) ^ kCrcTable[((crc >> 7) ^ w.bytes[i]) & 0xFFu]);
  const unsigned tail = w.tail();
  for (unsigned i = w.pending; i-- > 0;) crc = crc_bit(crc, (tail >> i) & 1u);
  out.crc = crc;
  out.stuffed_region = w.full * 8 + w.pending + 15;
  w.put(crc, 15);

  // After five equal bits the transmitter inserts one of the other level; it counts as the
  // first bit of the next run.
  unsigned state = kStuffStart;
  unsigned stuffed = 0;
  for (unsigned i = 0; i < w.full; ++i) {
    const std::uint8_t e = kStuffTable[state][w.bytes[i]];
    stuffed += e >> 3;
    state = e & 7u;
  }
  const unsigned last = w.tail();
  for (unsigned i = w.pending; i-- > 0;) {
    const auto step = stuff_bit(state, (last >> i) & 1u);
    state = step.state;
    stuffed += step.stuffed;
  }
  out.stuff_bits = stuffed;
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
