// The nodes' object dictionaries as the server threads may read them: names, types, access and
// PDO-mappability copied once before the run (the live dictionaries belong to the scheduler's
// thread), and, per bus, a frame-decoder context that adds the node-IDs and PDO mappings the
// scheduler last published.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "control/live_state.h"
#include "devices/canopen/frame_decoder.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/device.h"

namespace control {

struct CatalogEntry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::string name;  ///< "Device control word" (object name + sub name for records/arrays)
  canopen::DataType type = canopen::DataType::Unsigned8;
  canopen::Access access = canopen::Access::ReadWrite;
  bool pdo_mappable = false;
  canopen::ValueScaling scaling;  ///< the product's documented scaling when the run began
};

class DictionaryCatalog {
 public:
  /// Copies one node's dictionary, its product's scalings and EMCY codes (before the run: the
  /// caller owns the node's thread).
  void add_node(devices::Device& device);
  std::size_t size() const { return nodes_.size(); }
  const std::vector<CatalogEntry>& entries(std::size_t node) const { return nodes_[node].entries; }
  const CatalogEntry* find(std::size_t node, std::uint16_t index, std::uint8_t sub) const;
  /// The product's text for EMCY `code` of node `node`, or "".
  std::string_view emcy_text(std::size_t node, std::uint16_t code) const;

 private:
  struct Node {
    std::vector<CatalogEntry> entries;  ///< by index, then sub
    std::map<std::uint32_t, std::size_t> by_key;
    std::span<const devices::EmcyCode> emcy_codes;  ///< the product's table (static storage)
  };
  std::vector<Node> nodes_;
};

/// What the frame decoder knows of one bus: node-ID → node, and the PDOs configured on it.
class BusDecoderContext final : public canopen::DecoderContext {
 public:
  BusDecoderContext(const DictionaryCatalog& catalog, int bus) : catalog_(catalog), bus_(bus) {}
  /// `node_bus[i]` / `status[i]` / `maps[i]` for node i of the scenario.
  void update(const std::vector<int>& node_bus, const std::vector<NodeStatus>& status,
              const std::vector<std::vector<PdoMap>>& maps);

  const ObjectInfo* object(std::uint8_t node, std::uint16_t index, std::uint8_t sub) const override;
  const PdoInfo* pdo(std::uint32_t cob_id) const override;
  std::string_view emcy_text(std::uint8_t node, std::uint16_t code) const override;
  /// Scenario index of the node with this node-ID on the bus, or -1.
  int node_index(std::uint8_t node_id) const { return node_id < 128 ? by_id_[node_id] : -1; }

 private:
  const DictionaryCatalog& catalog_;
  int bus_;
  std::array<int, 128> by_id_{};
  std::map<std::uint32_t, PdoInfo> pdos_;
  mutable ObjectInfo scratch_;
};

}  // namespace control
