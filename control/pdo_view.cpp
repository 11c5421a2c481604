#include "control/pdo_view.h"

#include <charconv>
#include <cstdio>

namespace control {

namespace {
constexpr int kMaxPdoNumber = 512;  // CiA 301: 1400h..15FFh, 1800h..19FFh

std::optional<std::uint32_t> parse_hex_field(std::string_view text, std::size_t max_digits) {
  if (text.empty() || text.size() > max_digits) return std::nullopt;
  std::uint32_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, 16);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}
}  // namespace

std::vector<PdoConfig> read_pdo_configs(const canopen::ObjectDictionary& od) {
  std::vector<PdoConfig> out;
  for (const bool transmit : {false, true}) {
    for (int n = 0; n < kMaxPdoNumber; ++n) {
      const auto comm = static_cast<std::uint16_t>((transmit ? 0x1800 : 0x1400) + n);
      const auto* cob = od.entry(comm, 1);
      if (!cob) continue;
      PdoConfig p;
      p.transmit = transmit;
      p.number = static_cast<std::uint16_t>(n + 1);
      p.cob_raw = cob->as<std::uint32_t>();
      if (const auto* t = od.entry(comm, 2)) p.transmission_type = t->as<std::uint8_t>();
      const auto mapping = static_cast<std::uint16_t>((transmit ? 0x1A00 : 0x1600) + n);
      if (const auto* count = od.entry(mapping, 0)) {
        for (unsigned s = 1; s <= count->as<std::uint8_t>(); ++s)
          if (const auto* e = od.entry(mapping, static_cast<std::uint8_t>(s))) p.entries.push_back(e->as<std::uint32_t>());
      }
      out.push_back(std::move(p));
    }
  }
  return out;
}

std::string object_key(std::uint16_t index, std::uint8_t sub) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04X:%02X", index, sub);
  return buf;
}

std::optional<std::pair<std::uint16_t, std::uint8_t>> parse_object_key(std::string_view text) {
  if (text.rfind("0x", 0) == 0 || text.rfind("0X", 0) == 0) text.remove_prefix(2);
  const auto colon = text.find(':');
  const auto index = parse_hex_field(text.substr(0, colon), 4);
  std::optional<std::uint32_t> sub = 0;
  if (colon != std::string_view::npos) sub = parse_hex_field(text.substr(colon + 1), 2);
  if (!index || !sub) return std::nullopt;
  return std::make_pair(static_cast<std::uint16_t>(*index), static_cast<std::uint8_t>(*sub));
}

nlohmann::json pdos_json(const std::vector<PdoConfig>& pdos, const DictionaryCatalog& catalog, std::size_t node) {
  auto out = nlohmann::json::array();
  for (const auto& p : pdos) {
    const bool extended = (p.cob_raw & 0x20000000u) != 0;
    auto entries = nlohmann::json::array();
    for (const auto raw : p.entries) {
      const auto index = static_cast<std::uint16_t>(raw >> 16);
      const auto sub = static_cast<std::uint8_t>(raw >> 8);
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%08X", raw);
      const auto* e = catalog.find(node, index, sub);
      // 0001h..0007h: dummy entries (CiA 301 7.4.7.1), padding the node ignores.
      const std::string name = e ? e->name : index < 0x20 ? "dummy" : "(not in the dictionary)";
      entries.push_back({{"object", object_key(index, sub)}, {"name", name}, {"bits", raw & 0xFF}, {"raw", hex}});
    }
    nlohmann::json j = {{"kind", p.transmit ? "tpdo" : "rpdo"},
                        {"number", p.number},
                        {"cob_id", p.cob_raw & (extended ? 0x1FFFFFFFu : 0x7FFu)},
                        {"extended", extended},
                        {"valid", (p.cob_raw & 0x80000000u) == 0},
                        {"transmission_type", nullptr},
                        {"entries", std::move(entries)}};
    if (p.transmission_type) j["transmission_type"] = *p.transmission_type;
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace control
