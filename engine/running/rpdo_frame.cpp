#include "engine/running/rpdo_frame.h"

#include <cstdio>
#include <vector>

#include "engine/loading/value_codec.h"

namespace scenario {

namespace {

RpdoFrame refused(std::string expected, std::string actual, std::optional<std::size_t> value = std::nullopt) {
  return RpdoFrame{std::nullopt, std::move(expected), std::move(actual), value};
}

}  // namespace

RpdoFrame build_rpdo(const canopen::ObjectDictionary& od, std::string_view node, int pdo,
                     std::span<const ParameterOverride> values) {
  if (pdo < 1 || pdo > 512) return refused("an RPDO number 1..512", std::to_string(pdo));
  const auto comm = static_cast<std::uint16_t>(0x1400 + pdo - 1), map = static_cast<std::uint16_t>(0x1600 + pdo - 1);
  const auto* cob = od.entry(comm, 1);
  const auto* count = od.entry(map, 0);
  if (!cob || !count) return refused("RPDO " + std::to_string(pdo) + " of " + std::string(node), "the node has no such RPDO");
  const auto cob_id = cob->as<std::uint32_t>();
  if (cob_id & 0x80000000u) return refused("a valid RPDO " + std::to_string(pdo), "COB-ID " + hex32(cob_id) + " (invalid)");
  std::uint8_t payload[8] = {};
  std::size_t bits = 0;
  std::vector<bool> used(values.size(), false);
  for (unsigned i = 1; i <= count->as<unsigned>(); ++i) {
    const auto* m = od.entry(map, static_cast<std::uint8_t>(i));
    if (!m) continue;
    const auto entry = m->as<std::uint32_t>();
    const auto index = static_cast<std::uint16_t>(entry >> 16);
    const auto sub = static_cast<std::uint8_t>(entry >> 8);
    const std::size_t len = entry & 0xFF;
    if (bits + len > 64 || len % 8 != 0)
      return refused("a byte-aligned mapping of at most 64 bits", "mapping entry " + hex32(entry));
    std::vector<std::uint8_t> bytes(len / 8, 0);
    if (index >= 0x20) {  // not a dummy entry
      std::size_t k = 0;
      while (k < values.size() && !(values[k].index == index && values[k].sub == sub)) ++k;
      const auto* obj = od.entry(index, sub);
      if (k == values.size() || !obj) return refused("a value for every mapped object", object_address(index, sub) + " is mapped but not given");
      used[k] = true;
      std::vector<std::uint8_t> encoded;
      if (auto err = encode_literal(obj->type, values[k].value, encoded); !err.empty())
        return refused(object_address(index, sub) + " value", err, k);
      bytes = canopen::resize_value(obj->type, encoded, len / 8);
    }
    for (std::size_t j = 0; j < bytes.size(); ++j) payload[bits / 8 + j] = bytes[j];
    bits += len;
  }
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!used[k])
      return refused("objects mapped into RPDO " + std::to_string(pdo), object_address(values[k].index, values[k].sub) + " is not mapped", k);
  sim::CanFrame f = sim::CanFrame::data_frame(cob_id & 0x1FFFFFFFu, std::span<const std::uint8_t>(payload, bits / 8));
  f.extended = (cob_id & 0x20000000u) != 0;
  if (!f.extended) f.id &= 0x7FF;
  return RpdoFrame{f, {}, {}, std::nullopt};
}

}  // namespace scenario
