// The length of a classic CAN frame on the wire, in bits (ISO 11898-1): SOF, arbitration field,
// control field, data, CRC-15 computed over the frame's actual bits, the stuff bits those bits
// need (SOF..CRC sequence, after five equal bits one of the other level), CRC delimiter, ACK slot
// and delimiter, EOF and the 3-bit intermission. Pure functions; the bus times frames with them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "sim/can_frame.h"

namespace sim {

/// ACK delimiter + EOF + intermission: the 11 recessive bits that end every frame.
inline constexpr unsigned kFrameTailBits = 1 + 7 + 3;
/// An error frame as this model puts it on the wire: a 6-bit error flag, up to 6 bits of other
/// nodes' flags superposed on it (counted in full), the 8-bit error delimiter and intermission.
inline constexpr unsigned kErrorFrameBits = 6 + 6 + 8 + 3;

struct FrameBits {
  unsigned stuffed_region = 0;  ///< SOF..CRC sequence before stuffing
  unsigned stuff_bits = 0;
  std::uint16_t crc = 0;        ///< the CRC-15 sequence
  /// Everything, intermission included: the time the frame keeps the bus from the next SOF.
  unsigned total() const { return stuffed_region + stuff_bits + 1 /*CRC delim*/ + 2 /*ACK*/ + 7 /*EOF*/ + 3; }
  /// Up to the end of EOF (the instant receivers accept the frame).
  unsigned until_eof() const { return total() - 3; }
};

/// CRC-15/CAN (polynomial 0x4599) over `count` bits given MSB-first in `bits`.
std::uint16_t can_crc15(const std::uint8_t* bits, unsigned count);

/// The frame's exact bit count and where they come from.
FrameBits frame_bits(const CanFrame& frame);

/// The part of frame_bits() that depends only on the identifier, format, RTR and DLC: the CRC
/// register and the stuffing after the header (SOF .. DLC).
struct FrameHeaderBits {
  std::uint16_t crc = 0;
  std::uint8_t stuff_state = 0;  ///< level of the last bit and its run (can_bit_timing.cpp)
  std::uint8_t stuff_bits = 0;   ///< stuff bits in the header
  std::uint8_t header_bits = 0;  ///< SOF .. DLC: 19 standard, 39 extended
  std::uint8_t data_bytes = 0;   ///< bytes in the data field (0 for a remote frame)
};
FrameHeaderBits frame_header_bits(const CanFrame& frame);
/// frame_bits() of a frame whose header gave `header`: only its data and CRC are worked through.
FrameBits frame_bits(const FrameHeaderBits& header, const CanFrame& frame);

/// frame_bits() of recently seen frames: the bus times every frame, and most repeat exactly
/// (SYNC, heartbeats, PDOs whose values did not change). Direct-mapped by identifier; an entry
/// answers only for a frame equal in identifier, format, DLC and all eight data bytes. A frame
/// that differs only in its data (a PDO whose values changed) starts from the entry's header.
class FrameBitsCache {
 public:
  FrameBits get(const CanFrame& frame) {
    const std::uint64_t meta = std::uint64_t{frame.id} | std::uint64_t{frame.dlc} << 32 |
                               std::uint64_t{frame.extended} << 40 | std::uint64_t{frame.rtr} << 41 | kValid;
    std::uint64_t data;
    std::memcpy(&data, frame.data.data(), sizeof data);
    Entry& e = entries_[(frame.id ^ (frame.id >> 7) ^ (frame.id >> 14)) % kEntries];
    if (e.meta != meta) {
      e.meta = meta;
      e.header = frame_header_bits(frame);
    } else if (e.data == data) {
      return e.bits;
    }
    e.data = data;
    e.bits = frame_bits(e.header, frame);
    return e.bits;
  }

 private:
  static constexpr std::uint64_t kValid = 1ull << 42;
  static constexpr std::size_t kEntries = 64;
  struct Entry {
    std::uint64_t meta = 0;  // identifier, DLC, format; 0: empty
    std::uint64_t data = 0;
    FrameHeaderBits header;
    FrameBits bits;
  };
  std::array<Entry, kEntries> entries_{};
};

/// The arbitration order key: the arbitration field's bits (ID, RTR/SRR, IDE, extended ID,
/// RTR) as one number; the lower key wins arbitration, since dominant is 0.
inline std::uint64_t arbitration_key(const CanFrame& frame) {
  // 11 base bits, RTR|SRR, IDE, 18 extension bits, RTR (extended only): 32 bits, MSB first.
  if (!frame.extended)
    return (static_cast<std::uint64_t>(frame.id & 0x7FF) << 21) | (static_cast<std::uint64_t>(frame.rtr) << 20);
  return (static_cast<std::uint64_t>((frame.id >> 18) & 0x7FF) << 21) | (1ull << 20) | (1ull << 19) |
         (static_cast<std::uint64_t>(frame.id & 0x3FFFF) << 1) | static_cast<std::uint64_t>(frame.rtr);
}

}  // namespace sim
