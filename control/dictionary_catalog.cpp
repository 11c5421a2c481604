#include "control/dictionary_catalog.h"

namespace control {

void DictionaryCatalog::add_node(devices::Device& device) {
  const auto& od = device.node().od();
  Node n;
  n.emcy_codes = device.emcy_codes();
  for (const auto& [index, object] : od.objects()) {
    for (const auto& [sub, e] : object.entries) {
      CatalogEntry c;
      c.index = index;
      c.sub = sub;
      c.name = object.entries.size() > 1 && e.name != object.name ? object.name + ": " + e.name : e.name;
      c.type = e.type;
      c.access = e.access;
      c.pdo_mappable = e.pdo_mappable;
      c.scaling = device.value_scaling(index, sub);
      n.by_key[static_cast<std::uint32_t>(index) << 8 | sub] = n.entries.size();
      n.entries.push_back(std::move(c));
    }
  }
  nodes_.push_back(std::move(n));
}

const CatalogEntry* DictionaryCatalog::find(std::size_t node, std::uint16_t index, std::uint8_t sub) const {
  if (node >= nodes_.size()) return nullptr;
  const auto& n = nodes_[node];
  const auto it = n.by_key.find(static_cast<std::uint32_t>(index) << 8 | sub);
  return it == n.by_key.end() ? nullptr : &n.entries[it->second];
}

std::string_view DictionaryCatalog::emcy_text(std::size_t node, std::uint16_t code) const {
  if (node >= nodes_.size()) return {};
  for (const auto& c : nodes_[node].emcy_codes)
    if (c.code == code) return c.text;
  return {};
}

void BusDecoderContext::update(const std::vector<int>& node_bus, const std::vector<NodeStatus>& status,
                               const std::vector<std::vector<PdoMap>>& maps) {
  by_id_.fill(-1);
  pdos_.clear();
  for (std::size_t i = 0; i < node_bus.size() && i < status.size(); ++i) {
    if (node_bus[i] != bus_) continue;
    const auto id = status[i].node_id;
    if (id >= 1 && id <= 127) by_id_[id] = static_cast<int>(i);
    if (i >= maps.size()) continue;
    for (const auto& m : maps[i]) {
      if (!m.valid || m.cob_id == 0) continue;
      PdoInfo info;
      info.node = id;
      info.transmit = m.transmit;
      info.number = m.number;
      for (std::size_t k = 0; k < m.count; ++k) {
        const auto v = m.entries[k];
        info.entries.push_back({static_cast<std::uint16_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
                                static_cast<std::uint8_t>(v)});
      }
      // A COB-ID both sent (TPDO) and received (another node's RPDO): the sender explains it.
      auto [it, inserted] = pdos_.emplace(m.cob_id, info);
      if (!inserted && m.transmit && !it->second.transmit) it->second = std::move(info);
    }
  }
}

const canopen::DecoderContext::ObjectInfo* BusDecoderContext::object(std::uint8_t node, std::uint16_t index,
                                                                     std::uint8_t sub) const {
  const int i = node_index(node);
  if (i < 0) return nullptr;
  const auto* e = catalog_.find(static_cast<std::size_t>(i), index, sub);
  if (!e) return nullptr;
  scratch_.name = e->name;
  scratch_.type = e->type;
  scratch_.scaling = e->scaling;
  return &scratch_;
}

std::string_view BusDecoderContext::emcy_text(std::uint8_t node, std::uint16_t code) const {
  const int i = node_index(node);
  return i < 0 ? std::string_view{} : catalog_.emcy_text(static_cast<std::size_t>(i), code);
}

const canopen::DecoderContext::PdoInfo* BusDecoderContext::pdo(std::uint32_t cob_id) const {
  const auto it = pdos_.find(cob_id);
  return it == pdos_.end() ? nullptr : &it->second;
}

}  // namespace control
