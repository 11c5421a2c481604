// A node's PDOs as the API shows them (GET /api/nodes/{name}/pdos) and the object keys the API's
// RPDO sender takes ("6040:00"). The configuration is copied from the live dictionary between
// ticks (read_pdo_configs, scheduler thread); the JSON is made on a server thread, with the names
// from the catalog (the node's EDS / C++ dictionary).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "control/dictionary_catalog.h"
#include "devices/canopen/object_dictionary.h"

namespace control {

struct PdoConfig {
  bool transmit = false;
  std::uint16_t number = 0;  ///< 1-based
  std::uint32_t cob_raw = 0;  ///< 1400h/1800h sub 1 as held
  std::optional<std::uint8_t> transmission_type;  ///< sub 2, when the node has it
  std::vector<std::uint32_t> entries;  ///< 1600h/1A00h sub 1..count: index << 16 | sub << 8 | bits
};

/// Every RPDO then every TPDO the node's dictionary holds (communication object present).
std::vector<PdoConfig> read_pdo_configs(const canopen::ObjectDictionary& od);
/// [{"kind","number","cob_id","valid","transmission_type","entries":[{"object","name","bits","raw"}]}].
nlohmann::json pdos_json(const std::vector<PdoConfig>& pdos, const DictionaryCatalog& catalog, std::size_t node);
/// "6040:00".
std::string object_key(std::uint16_t index, std::uint8_t sub);
/// "6040:00", "0x6040:00", "6040" (sub 0); nullopt when it is not an object address.
std::optional<std::pair<std::uint16_t, std::uint8_t>> parse_object_key(std::string_view text);

}  // namespace control
