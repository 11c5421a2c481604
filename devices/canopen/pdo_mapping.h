// PDO mapping (CiA 301 §7.4.2): entries `index<<16 | sub<<8 | bits`, resolved to object
// dictionary entries once, so packing and unpacking a PDO touches no map and allocates nothing.
#pragma once

#include <array>
#include <bit>
#include <cstring>
#include <cstdint>
#include <span>
#include <vector>

#include "devices/canopen/object_dictionary.h"

namespace canopen {

struct MappedObject {
  OdEntry* entry = nullptr;    ///< nullptr for a dummy entry (RPDO only: bytes skipped)
  std::uint8_t bytes = 0;      ///< length in the PDO
  bool sign_extend = false;    ///< a signed integer: a narrow value in a wider slot is sign-extended
};

struct PdoMapping {
  std::vector<MappedObject> objects;
  std::uint8_t length = 0;     ///< total bytes (≤ 8)
};

enum class PdoDirection : std::uint8_t { Receive, Transmit };

struct MappingRules {
  bool dummy_mapping = true;
  bool width_conversion = false;
  SdoAbort length_mismatch = SdoAbort::NotMappable;
};

/// Checks one mapping entry value for a PDO direction; resolves it into `out` on success.
SdoAbort resolve_mapping_entry(ObjectDictionary& od, std::uint32_t value, PdoDirection dir, const MappingRules& rules,
                               MappedObject& out);
/// Resolves entries 1..count of mapping object `mapping_index`.
SdoAbort resolve_mapping(ObjectDictionary& od, std::uint16_t mapping_index, std::uint8_t count, PdoDirection dir,
                         const MappingRules& rules, PdoMapping& out);

/// Packs the mapped objects' current values into `out` (length bytes, the rest zero). Inline:
/// every TPDO on every SYNC. Each value is loaded as one little-endian integer (at most 8 bytes),
/// widened (sign- or zero-extended) to its slot and or-ed into one 64-bit word at its offset.
inline void pack_pdo(const PdoMapping& m, std::span<std::uint8_t, 8> out) {
  std::uint64_t word = 0;
  unsigned shift = 0;  // < 64 for every object: a mapping holds at most 8 bytes of whole bytes
  for (const auto& o : m.objects) {
    if (o.entry) {
      const StoredValue& v = o.entry->value;
      const std::size_t n = o.bytes < v.size() ? o.bytes : v.size();
      std::uint64_t x = decode_unsigned(std::span<const std::uint8_t>(v.data(), n));
      if (n < o.bytes && n > 0 && o.sign_extend && (v[n - 1] & 0x80)) {
        const std::uint64_t slot = o.bytes >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * o.bytes)) - 1;
        x |= (~std::uint64_t{0} << (8 * n)) & slot;
      }
      word |= x << shift;
    }
    shift += 8u * o.bytes;
  }
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(out.data(), &word, 8);
  } else {
    for (std::size_t i = 0; i < 8; ++i) out[i] = static_cast<std::uint8_t>(word >> (8 * i));
  }
}

}  // namespace canopen
