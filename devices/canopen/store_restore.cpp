#include "devices/canopen/store_restore.h"

#include <cstdio>

#include "sim/log.h"

namespace canopen {

namespace {
constexpr std::uint16_t kStore = 0x1010;
constexpr std::uint16_t kRestore = 0x1011;

// An integer value in decimal (limits are only set on numbers; other types print as bytes).
std::string number_text(DataType type, std::span<const std::uint8_t> bytes) {
  if (is_signed_integer(type)) return std::to_string(decode_signed(bytes));
  if (is_unsigned_integer(type)) return std::to_string(decode_unsigned(bytes));
  std::string hex;
  char buf[4];
  for (auto b : bytes) {
    std::snprintf(buf, sizeof buf, "%02X", b);
    hex += buf;
  }
  return "0x" + hex;
}
}  // namespace

StoreRestore::StoreRestore(ObjectDictionary& od, const StorePolicy& policy, const NodeStatus& status,
                           const std::string& node_name, SilenceRequest& silence)
    : od_(od), policy_(policy), status_(status), node_name_(node_name), silence_(silence), store_(policy.path) {}

StoreRestore::Ranges StoreRestore::group_ranges(std::uint8_t sub) const {
  for (const auto& g : policy_.groups)
    if (g.sub == sub) return g.ranges;
  if (!policy_.groups.empty()) return {};
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
  auto& od = od_;
  for (std::uint16_t idx : {kStore, kRestore}) {
    auto* obj = od.object(idx);
    if (!obj) continue;
    for (auto& [sub, e] : obj->entries) {
      if (sub == 0 || !e.writable()) continue;
      od.add_check(idx, sub, [this, idx, s = sub](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        if (origin != Origin::Sdo) return SdoAbort::None;
        const auto v = static_cast<std::uint32_t>(decode_unsigned(data));
        if (v != (idx == kStore ? kSaveSignature : kLoadSignature)) return policy_.wrong_signature;
        return idx == kStore ? save_group(s) : restore_group(s);
      });
      // Reading back shows the capability (default 1), never the signature.
      od.add_observer(idx, sub, [this](OdEntry& entry, Origin) { entry.reset_to_default(status_.node_id); });
    }
  }
}

bool StoreRestore::power_on(std::string& error) {
  pending_restore_.clear();
  reported_.clear();
  rejected_.clear();
  store_.set_path(policy_.path);
  const bool ok = store_.load(error);
  for (const auto& p : policy_.preset) store_.put(p.index, p.sub, ParameterStore::Value{false, p.bytes});
  return ok;
}

bool StoreRestore::in_pending_restore(std::uint16_t index) const {
  for (auto sub : pending_restore_)
    for (const auto& [first, last] : group_ranges(sub))
      if (index >= first && index <= last) return true;
  return false;
}

void StoreRestore::load_area(std::uint16_t first, std::uint16_t last) {
  auto& od = od_;
  od.reset_range(first, last, status_.node_id);
  for (const auto& [key, v] : store_.values()) {
    if (key.first < first || key.first > last || in_pending_restore(key.first)) continue;
    if (device_stored_.count(key) && !od.entry(key.first, key.second)) continue;  // a private cell
    Bytes value;
    if (const std::string why = refusal(key, v, value); !why.empty()) {
      if (reported_.insert(key).second) {
        rejected_.push_back(store_.where(v) + ": " + why);
        sim::log(sim::LogLevel::Warn, "node {}: {}; the entry keeps its default", node_name_, rejected_.back());
      }
      continue;
    }
    od.entry(key.first, key.second)->value = std::move(value);
  }
}

std::string StoreRestore::refusal(const ParameterStore::Key& key, const ParameterStore::Value& v, Bytes& out) const {
  char name[24];
  std::snprintf(name, sizeof name, "%04Xh sub %u", key.first, key.second);
  const OdEntry* e = od_.entry(key.first, key.second);
  if (!e) return std::string(name) + (od_.object(key.first) ? ": no such sub-index" : ": no such object");
  if (e->access == Access::Const) return std::string(name) + " is constant";
  if (!e->writable() && !device_stored_.count(key)) return std::string(name) + " is read-only";
  const std::size_t fixed = type_size(e->type);
  const std::string type(type_name(e->type));
  if (fixed != 0 && v.bytes.size() != fixed) {
    return std::to_string(v.bytes.size()) + "-byte value for " + name + " (" + type + ", " + std::to_string(fixed) + " bytes)";
  }
  if (fixed == 0 && e->max_length != 0 && v.bytes.size() > e->max_length) {
    return std::to_string(v.bytes.size()) + "-byte value for " + name + " (at most " + std::to_string(e->max_length) + " bytes)";
  }
  out = v.bytes;
  if (v.node_relative) {
    if (fixed == 0 || fixed > 8 || !(is_signed_integer(e->type) || is_unsigned_integer(e->type))) {
      return "$NODEID+ value for " + std::string(name) + ", which is not an integer";
    }
    const std::uint64_t base = decode_unsigned(v.bytes);
    const std::uint64_t sum = base + status_.node_id;
    const bool overflow = fixed < 8 ? (sum >> (8 * fixed)) != 0 : sum < base;
    if (overflow) {
      return "$NODEID+" + std::to_string(base) + " overflows " + type + " with node-ID " + std::to_string(status_.node_id) +
             " (" + name + ")";
    }
    encode_unsigned(sum, out);
  }
  if (e->low_limit && compare_values(e->type, out, *e->low_limit) < 0) {
    return "value " + number_text(e->type, out) + " of " + name + " is below its low limit " + number_text(e->type, *e->low_limit);
  }
  if (e->high_limit && compare_values(e->type, out, *e->high_limit) > 0) {
    return "value " + number_text(e->type, out) + " of " + name + " is above its high limit " + number_text(e->type, *e->high_limit);
  }
  return {};
}

SdoAbort StoreRestore::save_group(std::uint8_t sub) {
  const auto ranges = group_ranges(sub);
  if (ranges.empty()) return SdoAbort::DataTransfer;
  if (store_.failing()) return policy_.hardware_error;
  const bool freeze = policy_.freeze_node_relative;
  for (const auto& [first, last] : ranges) {
    for (auto it = od_.objects().lower_bound(first); it != od_.objects().end() && it->first <= last; ++it) {
      for (const auto& [s, e] : it->second.entries) {
        if (!storable(e)) continue;
        ParameterStore::Value v;
        if (!freeze && e.node_id_relative && e.value == e.default_for_node(status_.node_id)) {
          v.node_relative = true;
          v.bytes = e.default_value;
        } else {
          v.bytes = e.value.bytes();
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
    sim::log(sim::LogLevel::Error, "node {}: {}", node_name_, error);
    return policy_.hardware_error;
  }
  const auto busy = policy_.busy_time;
  if (busy.count() > 0) silence_.go_silent_until(status_.now + busy);
  return SdoAbort::None;
}

SdoAbort StoreRestore::save_entry(std::uint16_t index, std::uint8_t sub) {
  const OdEntry* e = od_.entry(index, sub);
  if (!e) return SdoAbort::NoObject;
  if (store_.failing()) return policy_.hardware_error;
  store_.put(index, sub, ParameterStore::Value{false, e->value.bytes()});
  std::string error;
  return store_.save(error) ? SdoAbort::None : policy_.hardware_error;
}

SdoAbort StoreRestore::restore_group(std::uint8_t sub) {
  const auto ranges = group_ranges(sub);
  if (ranges.empty()) return SdoAbort::DataTransfer;
  if (store_.failing()) return policy_.hardware_error;
  if (policy_.restore == StorePolicy::Restore::PendingUntilReset) {
    pending_restore_.insert(sub);
  } else {
    for (const auto& [first, last] : ranges) store_.erase_range(first, last);
    std::string error;
    if (!store_.save(error)) return policy_.hardware_error;
  }
  const auto busy = policy_.restore_busy_time;
  if (busy.count() > 0) silence_.go_silent_until(status_.now + busy);
  return SdoAbort::None;
}

}  // namespace canopen
