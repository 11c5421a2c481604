#include "devices/canopen/pdo_mapping.h"

#include <algorithm>

namespace canopen {

SdoAbort resolve_mapping_entry(ObjectDictionary& od, std::uint32_t value, PdoDirection dir, const MappingRules& rules,
                               MappedObject& out) {
  const auto index = static_cast<std::uint16_t>(value >> 16);
  const auto sub = static_cast<std::uint8_t>(value >> 8);
  const auto bits = static_cast<std::uint8_t>(value);
  if (bits == 0 || bits % 8 != 0 || bits > 64) return SdoAbort::NotMappable;  // byte granularity only
  out.bytes = bits / 8;
  if (index >= 0x0001 && index <= 0x0007 && sub == 0) {
    // Dummy entry: the index is a basic data type code; only receive PDOs may skip bytes.
    if (dir != PdoDirection::Receive || !rules.dummy_mapping) return SdoAbort::NotMappable;
    if (type_size(static_cast<DataType>(index)) * 8 != bits) return rules.length_mismatch;
    out.entry = nullptr;
    out.sign_extend = false;
    return SdoAbort::None;
  }
  OdEntry* e = od.entry(index, sub);
  if (!e || !e->pdo_mappable) return SdoAbort::NotMappable;
  if (dir == PdoDirection::Receive && !e->writable()) return SdoAbort::NotMappable;
  if (dir == PdoDirection::Transmit && !e->readable()) return SdoAbort::NotMappable;
  if (e->bit_length() != bits && !rules.width_conversion) return rules.length_mismatch;
  out.entry = e;
  out.sign_extend = is_signed_integer(e->type);
  return SdoAbort::None;
}

SdoAbort resolve_mapping(ObjectDictionary& od, std::uint16_t mapping_index, std::uint8_t count, PdoDirection dir,
                         const MappingRules& rules, PdoMapping& out) {
  out.objects.clear();
  out.length = 0;
  if (count > 0 && !od.entry(mapping_index, count)) return SdoAbort::ValueTooHigh;  // more than it has
  unsigned total = 0;
  for (std::uint8_t sub = 1; sub <= count; ++sub) {
    const OdEntry* raw = od.entry(mapping_index, sub);
    if (!raw) return SdoAbort::ValueTooHigh;  // more entries requested than the object has
    MappedObject m;
    if (auto a = resolve_mapping_entry(od, raw->as<std::uint32_t>(), dir, rules, m); a != SdoAbort::None) return a;
    total += m.bytes;
    if (total > 8) return SdoAbort::PdoLengthExceeded;
    out.objects.push_back(m);
  }
  out.length = static_cast<std::uint8_t>(total);
  return SdoAbort::None;
}

}  // namespace canopen
