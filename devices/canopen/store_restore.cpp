#include "devices/canopen/store_restore.h"

#include "devices/canopen/node.h"
#include "sim/log.h"

namespace canopen {

namespace {
constexpr std::uint16_t kStore = 0x1010;
constexpr std::uint16_t kRestore = 0x1011;
}  // namespace

StoreRestore::StoreRestore(Node& node) : node_(node), store_(node.policy().store.path) {}

StoreRestore::Ranges StoreRestore::group_ranges(std::uint8_t sub) const {
  for (const auto& g : node_.policy().store.groups)
    if (g.sub == sub) return g.ranges;
  if (!node_.policy().store.groups.empty()) return {};
  switch (sub) {
    case 1: return {{0x1000, 0xFFFF}};
    case 2: return {{0x1000, 0x1FFF}};
    case 3: return {{0x6000, 0x9FFF}};
    case 4: return {{0x2000, 0x5FFF}};
    default: return {};
  }
}

bool StoreRestore::storable(const OdEntry& e) {
  if (!e.persistent || !e.writable()) return false;
  return e.index != kStore && e.index != kRestore && e.index != 0x1003;
}

void StoreRestore::bind_objects() {
  auto& od = node_.od();
  for (std::uint16_t idx : {kStore, kRestore}) {
    auto* obj = od.object(idx);
    if (!obj) continue;
    for (auto& [sub, e] : obj->entries) {
      if (sub == 0 || !e.writable()) continue;
      od.add_check(idx, sub, [this, idx, s = sub](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        if (origin != Origin::Sdo) return SdoAbort::None;
        const auto v = static_cast<std::uint32_t>(decode_unsigned(data));
        if (v != (idx == kStore ? kSaveSignature : kLoadSignature)) return node_.policy().store.wrong_signature;
        return idx == kStore ? save_group(s) : restore_group(s);
      });
      // Reading back shows the capability (default 1), never the signature.
      od.add_observer(idx, sub, [this](OdEntry& entry, Origin) { entry.reset_to_default(node_.node_id()); });
    }
  }
}

bool StoreRestore::power_on(std::string& error) {
  pending_restore_.clear();
  store_.set_path(node_.policy().store.path);
  const bool ok = store_.load(error);
  for (const auto& p : node_.policy().store.preset) store_.put(p.index, p.sub, ParameterStore::Value{false, p.bytes});
  return ok;
}

bool StoreRestore::in_pending_restore(std::uint16_t index) const {
  for (auto sub : pending_restore_)
    for (const auto& [first, last] : group_ranges(sub))
      if (index >= first && index <= last) return true;
  return false;
}

void StoreRestore::load_area(std::uint16_t first, std::uint16_t last) {
  auto& od = node_.od();
  od.reset_range(first, last, node_.node_id());
  for (const auto& [key, v] : store_.values()) {
    if (key.first < first || key.first > last || in_pending_restore(key.first)) continue;
    OdEntry* e = od.entry(key.first, key.second);
    if (!e) continue;
    const std::size_t fixed = type_size(e->type);
    if (fixed != 0 && v.bytes.size() != fixed) continue;  // stale store from another OD layout
    e->value = v.bytes;
    if (v.node_relative) encode_unsigned(decode_unsigned(e->value) + node_.node_id(), e->value);
  }
}

SdoAbort StoreRestore::save_group(std::uint8_t sub) {
  const auto ranges = group_ranges(sub);
  if (ranges.empty()) return SdoAbort::DataTransfer;
  if (failing_) return node_.policy().store.hardware_error;
  const bool freeze = node_.policy().store.freeze_node_relative;
  for (const auto& [first, last] : ranges) {
    for (auto it = node_.od().objects().lower_bound(first); it != node_.od().objects().end() && it->first <= last; ++it) {
      for (const auto& [s, e] : it->second.entries) {
        if (!storable(e)) continue;
        ParameterStore::Value v;
        if (!freeze && e.node_id_relative && e.value == e.default_for_node(node_.node_id())) {
          v.node_relative = true;
          v.bytes = e.default_value;
        } else {
          v.bytes = e.value;
        }
        store_.put(e.index, e.sub, std::move(v));
      }
    }
    // A saved group is no longer waiting for its defaults.
    for (auto p = pending_restore_.begin(); p != pending_restore_.end();) {
      p = (*p == sub || sub == 1) ? pending_restore_.erase(p) : std::next(p);
    }
  }
  std::string error;
  if (!store_.save(error)) {
    sim::log(sim::LogLevel::Error, "node {}: {}", node_.name(), error);
    return node_.policy().store.hardware_error;
  }
  const auto busy = node_.policy().store.busy_time;
  if (busy.count() > 0) node_.go_silent_until(node_.now() + busy);
  return SdoAbort::None;
}

SdoAbort StoreRestore::save_entry(std::uint16_t index, std::uint8_t sub) {
  const OdEntry* e = node_.od().entry(index, sub);
  if (!e) return SdoAbort::NoObject;
  if (failing_) return node_.policy().store.hardware_error;
  store_.put(index, sub, ParameterStore::Value{false, e->value});
  std::string error;
  return store_.save(error) ? SdoAbort::None : node_.policy().store.hardware_error;
}

SdoAbort StoreRestore::restore_group(std::uint8_t sub) {
  const auto ranges = group_ranges(sub);
  if (ranges.empty()) return SdoAbort::DataTransfer;
  if (failing_) return node_.policy().store.hardware_error;
  if (node_.policy().store.restore == StorePolicy::Restore::PendingUntilReset) {
    pending_restore_.insert(sub);
  } else {
    for (const auto& [first, last] : ranges) store_.erase_range(first, last);
    std::string error;
    if (!store_.save(error)) return node_.policy().store.hardware_error;
  }
  const auto busy = node_.policy().store.restore_busy_time;
  if (busy.count() > 0) node_.go_silent_until(node_.now() + busy);
  return SdoAbort::None;
}

}  // namespace canopen
