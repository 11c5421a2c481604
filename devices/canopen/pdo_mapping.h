// PDO mapping (CiA 301 §7.4.2): entries `index<<16 | sub<<8 | bits`, resolved to object
// dictionary entries once, so packing and unpacking a PDO touches no map and allocates nothing.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "devices/canopen/object_dictionary.h"

namespace canopen {

struct MappedObject {
  OdEntry* entry = nullptr;    ///< nullptr for a dummy entry (RPDO only: bytes skipped)
  std::uint8_t bytes = 0;      ///< length in the PDO
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

/// Packs the mapped objects' current values into `out` (length bytes).
void pack_pdo(const PdoMapping& m, std::span<std::uint8_t, 8> out);

}  // namespace canopen
