#include "sim/can_bit_timing.h"

#include <array>

namespace sim {

namespace {

// The bus times every frame with frame_bits(), so it works a byte at a time through tables
// instead of bit by bit. The bits before the CRC sequence are laid out as whole bytes: zero bits
// put in front of SOF leave the CRC unchanged (the register stays 0), so the header (SOF ..
// DLC: 19 bits standard, 39 extended) is padded to 3 or 5 bytes and the data bytes follow as
// they are. Stuff counting starts at SOF, inside the first byte, and ends 7 bits into the
// CRC's second byte. tests/sim/can_bit_timing_test.cpp holds both to the bit-by-bit definition.

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

constexpr std::uint16_t crc_byte(std::uint16_t crc, std::uint8_t byte) {
  return static_cast<std::uint16_t>(((crc << 8) & 0x7FFF) ^ kCrcTable[((crc >> 7) ^ byte) & 0xFFu]);
}

// The stuffing state between two bits: the level of the last bit on the wire (stuff bits count)
// and how many bits of that level end the stream (1..4; a fifth is followed by a stuff bit, which
// starts a run of one). state = level * 4 + run - 1. Before SOF the state is "recessive, run 1":
// SOF is dominant, so it starts a run of its own exactly as on an idle bus.
constexpr unsigned kStuffStart = 1 * 4 + 0;

constexpr unsigned stuff_bit(unsigned state, unsigned bit, unsigned& stuffed) {
  const unsigned level = state >> 2;
  const unsigned run = bit == level ? (state & 3u) + 2 : 1;
  if (run == 5) {  // the stuff bit: the other level, a run of one
    ++stuffed;
    return (level ^ 1u) * 4;
  }
  return bit * 4 + run - 1;
}

// An entry: the state after the bits (low 3 bits) and the stuff bits they need (above).
using StuffTable = std::array<std::array<std::uint8_t, 256>, 8>;

// Per state, the last `width` bits of the index, MSB first.
constexpr StuffTable make_stuff_table(unsigned width) {
  StuffTable t{};
  for (unsigned s = 0; s < 8; ++s) {
    for (unsigned v = 0; v < 256; ++v) {
      unsigned state = s;
      unsigned stuffed = 0;
      for (unsigned i = width; i-- > 0;) state = stuff_bit(state, (v >> i) & 1u, stuffed);
      t[s][v] = static_cast<std::uint8_t>(stuffed << 3 | state);
    }
  }
  return t;
}
constexpr StuffTable kStuff8 = make_stuff_table(8);
constexpr StuffTable kStuff7 = make_stuff_table(7);  // the CRC's last 7 bits; the extended first byte
constexpr StuffTable kStuff3 = make_stuff_table(3);  // the standard first byte: SOF, ID10, ID9

struct Stuffing {
  unsigned state = kStuffStart;
  unsigned bits = 0;
  void add(const StuffTable& table, unsigned value) {
    const std::uint8_t e = table[state][value & 0xFFu];
    bits += e >> 3;
    state = e & 7u;
  }
};

}  // namespace

std::uint16_t can_crc15(const std::uint8_t* bits, unsigned count) {
  std::uint16_t crc = 0;
  for (unsigned i = 0; i < count; ++i) crc = crc_bit(crc, bits[i]);
  return crc;
}

FrameHeaderBits frame_header_bits(const CanFrame& frame) {
  const unsigned dlc = frame.dlc > 8 ? 8u : frame.dlc;
  const std::uint64_t rtr = frame.rtr ? 1 : 0;
  // SOF .. DLC, right-aligned in whole bytes (the zero bits in front are padding).
  std::uint64_t header;
  unsigned header_bytes;
  FrameHeaderBits out;
  out.data_bytes = static_cast<std::uint8_t>(frame.rtr ? 0u : dlc);
  if (!frame.extended) {
    // SOF, 11-bit identifier, RTR, IDE, r0, DLC.
    header = (std::uint64_t{frame.id & 0x7FF} << 7) | (rtr << 6) | dlc;
    header_bytes = 3;
    out.header_bits = 19;
  } else {
    // SOF, base identifier, SRR, IDE, 18-bit extension, RTR, r1, r0, DLC.
    header = (std::uint64_t{(frame.id >> 18) & 0x7FF} << 27) | (std::uint64_t{3} << 25) |
             (std::uint64_t{frame.id & 0x3FFFF} << 7) | (rtr << 6) | dlc;
    header_bytes = 5;
    out.header_bits = 39;
  }
  std::uint16_t crc = 0;
  for (unsigned i = header_bytes; i-- > 0;) crc = crc_byte(crc, static_cast<std::uint8_t>(header >> (8 * i)));
  // After five equal bits the transmitter inserts one of the other level; it counts as the
  // first bit of the next run.
  Stuffing st;
  const unsigned top = header_bytes - 1;
  st.add(frame.extended ? kStuff7 : kStuff3, static_cast<unsigned>(header >> (8 * top)));
  for (unsigned i = top; i-- > 0;) st.add(kStuff8, static_cast<unsigned>(header >> (8 * i)));
  out.crc = crc;
  out.stuff_state = static_cast<std::uint8_t>(st.state);
  out.stuff_bits = static_cast<std::uint8_t>(st.bits);
  return out;
}

FrameBits frame_bits(const FrameHeaderBits& header, const CanFrame& frame) {
  std::uint16_t crc = header.crc;
  Stuffing st{header.stuff_state, header.stuff_bits};
  for (unsigned i = 0; i < header.data_bytes; ++i) {
    crc = crc_byte(crc, frame.data[i]);
    st.add(kStuff8, frame.data[i]);
  }
  st.add(kStuff8, crc >> 7);
  st.add(kStuff7, crc & 0x7Fu);

  FrameBits out;
  out.stuffed_region = header.header_bits + 8u * header.data_bytes + 15;
  out.stuff_bits = st.bits;
  out.crc = crc;
  return out;
}

FrameBits frame_bits(const CanFrame& frame) { return frame_bits(frame_header_bits(frame), frame); }

}  // namespace sim
