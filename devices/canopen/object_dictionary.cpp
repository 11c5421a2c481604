#include "devices/canopen/object_dictionary.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <stdexcept>
#include <utility>

namespace canopen {

int compare_values(DataType type, std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
  if (is_real(type)) {
    const double x = decode_real(type, a), y = decode_real(type, b);
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  if (is_signed_integer(type)) {
    const auto x = decode_signed(a), y = decode_signed(b);
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  if (is_unsigned_integer(type) || type == DataType::TimeOfDay || type == DataType::TimeDifference) {
    const auto x = decode_unsigned(a), y = decode_unsigned(b);
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  return 0;
}

Bytes resize_value(DataType type, std::span<const std::uint8_t> bytes, std::size_t size) {
  Bytes out(size, 0);
  resize_value_into(type, bytes, out);
  return out;
}

void resize_value_into(DataType type, std::span<const std::uint8_t> bytes, std::span<std::uint8_t> out) {
  const std::size_t n = std::min(out.size(), bytes.size());
  std::copy_n(bytes.begin(), n, out.begin());
  const bool negative = is_signed_integer(type) && !bytes.empty() && (bytes.back() & 0x80);
  std::fill(out.begin() + static_cast<std::ptrdiff_t>(n), out.end(), negative ? 0xFF : 0x00);
}

// ---- OdEntry -----------------------------------------------------------------------------------

Bytes OdEntry::default_for_node(std::uint8_t node_id) const {
  if (!node_id_relative) return default_value;
  Bytes v = default_value;
  encode_unsigned(decode_unsigned(v) + node_id, v);
  return v;
}

void OdEntry::reset_to_default(std::uint8_t node_id) { value = default_for_node(node_id); }

// ---- ObjectDictionary: building ----------------------------------------------------------------

std::uint64_t ObjectDictionary::LayoutStamp::next() {
  static std::atomic<std::uint64_t> counter{0};  // dictionaries are built on several threads
  return counter.fetch_add(1, std::memory_order_relaxed) + 1;
}

OdObject& ObjectDictionary::add_object(std::uint16_t index, std::string name, ObjectCode code) {
  auto [it, inserted] = objects_.try_emplace(index);
  if (inserted) {
    layout_.change();
    it->second.index = index;
    it->second.name = std::move(name);
    it->second.code = code;
  }
  return it->second;
}

OdEntry& ObjectDictionary::add_entry(std::uint16_t index, std::uint8_t sub, std::string name, DataType type,
                                     Access access, Bytes default_value, bool pdo_mappable) {
  auto& obj = add_object(index, sub == 0 ? name : std::string{}, ObjectCode::Var);
  if (sub != 0 && obj.code == ObjectCode::Var) obj.code = ObjectCode::Record;
  OdEntry& e = obj.entries[sub];
  layout_.change();  // a new entry, or one replaced (its type and size may differ)
  e.index = index;
  e.sub = sub;
  e.name = std::move(name);
  e.type = type;
  e.access = access;
  e.pdo_mappable = pdo_mappable;
  const std::size_t n = type_size(type);
  if (n != 0) default_value = resize_value(type, default_value, n);
  e.default_value = default_value;
  e.value = std::move(default_value);
  return e;
}

OdEntry& ObjectDictionary::add_entry(OdEntry entry) {
  auto& obj = add_object(entry.index, std::string{}, ObjectCode::Record);
  layout_.change();
  return obj.entries[entry.sub] = std::move(entry);
}

OdEntry& ObjectDictionary::add_var(std::uint16_t index, std::string name, DataType type, Access access,
                                   Bytes default_value, bool pdo_mappable) {
  auto& obj = add_object(index, name, ObjectCode::Var);
  obj.code = ObjectCode::Var;
  return add_entry(index, 0, std::move(name), type, access, std::move(default_value), pdo_mappable);
}

Bytes ObjectDictionary::encode(DataType type, std::string_view text) {
  (void)type;
  return Bytes(text.begin(), text.end());
}

void ObjectDictionary::remove_object(std::uint16_t index) {
  objects_.erase(index);
  layout_.change();
}

void ObjectDictionary::remove_entry(std::uint16_t index, std::uint8_t sub) {
  if (auto* o = object(index)) o->entries.erase(sub);
  layout_.change();
}

// ---- lookup ------------------------------------------------------------------------------------

OdObject* ObjectDictionary::object(std::uint16_t index) {
  auto it = objects_.find(index);
  return it == objects_.end() ? nullptr : &it->second;
}

const OdObject* ObjectDictionary::object(std::uint16_t index) const {
  auto it = objects_.find(index);
  return it == objects_.end() ? nullptr : &it->second;
}

const OdEntry* ObjectDictionary::entry(std::uint16_t index, std::uint8_t sub) const {
  const OdObject* o = object(index);
  if (!o) return nullptr;
  auto it = o->entries.find(sub);
  return it == o->entries.end() ? nullptr : &it->second;
}

SdoAbort ObjectDictionary::locate(std::uint16_t index, std::uint8_t sub, OdEntry*& out) {
  if (auto* e = entry(index, sub)) {
    out = e;
    return SdoAbort::None;
  }
  auto* o = object(index);
  if (!o) return SdoAbort::NoObject;
  auto it = o->entries.find(sub);
  if (it == o->entries.end()) return SdoAbort::NoSubIndex;
  out = &it->second;
  return SdoAbort::None;
}

OdEntry& ObjectDictionary::must_entry(std::uint16_t index, std::uint8_t sub) {
  if (auto* e = entry(index, sub)) return *e;
  throw std::out_of_range("object dictionary has no entry " + std::to_string(index) + ":" + std::to_string(sub));
}

const OdEntry& ObjectDictionary::must_entry(std::uint16_t index, std::uint8_t sub) const {
  if (const auto* e = entry(index, sub)) return *e;
  throw std::out_of_range("object dictionary has no entry " + std::to_string(index) + ":" + std::to_string(sub));
}

// ---- protocol access ---------------------------------------------------------------------------

SdoAbort ObjectDictionary::read(OdEntry& e, Origin origin) {
  const bool external = origin == Origin::Sdo || origin == Origin::Pdo;
  if (external && !e.readable()) return access_aborts_.read_write_only;
  for (auto& hook : e.read_hooks) {
    if (auto a = hook(e, origin); a != SdoAbort::None) return a;
  }
  return SdoAbort::None;
}

SdoAbort ObjectDictionary::read(std::uint16_t index, std::uint8_t sub, Bytes& out, Origin origin) {
  OdEntry* e = nullptr;
  if (auto a = locate(index, sub, e); a != SdoAbort::None) return a;
  if (auto a = read(*e, origin); a != SdoAbort::None) return a;
  out.assign(e->value.begin(), e->value.end());
  return SdoAbort::None;
}

SdoAbort ObjectDictionary::check_write(OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
  const bool external = origin == Origin::Sdo || origin == Origin::Pdo;
  if (external && !e.writable()) return access_aborts_.write_read_only;
  const std::size_t fixed = type_size(e.type);
  if (fixed != 0 && data.size() != fixed) return data.size() > fixed ? SdoAbort::LengthTooHigh : SdoAbort::LengthTooLow;
  if (fixed == 0 && e.max_length != 0 && data.size() > e.max_length) return SdoAbort::LengthTooHigh;
  for (auto& check : e.state_checks) {
    if (auto a = check(e, data, origin); a != SdoAbort::None) return a;
  }
  if (e.low_limit && compare_values(e.type, data, *e.low_limit) < 0) {
    if (origin != Origin::Pdo) return SdoAbort::ValueTooLow;
    std::copy(e.low_limit->begin(), e.low_limit->end(), data.begin());  // a PDO cannot be refused: clamp
  }
  if (e.high_limit && compare_values(e.type, data, *e.high_limit) > 0) {
    if (origin != Origin::Pdo) return SdoAbort::ValueTooHigh;
    std::copy(e.high_limit->begin(), e.high_limit->end(), data.begin());
  }
  for (auto& check : e.value_checks) {
    if (auto a = check(e, data, origin); a != SdoAbort::None) return a;
  }
  return SdoAbort::None;
}

SdoAbort ObjectDictionary::write(OdEntry& e, std::span<const std::uint8_t> data, Origin origin) {
  // Checks may normalise the value, so they work on a copy. Numeric values fit the stack buffer.
  std::array<std::uint8_t, 8> small{};
  Bytes large;
  std::span<std::uint8_t> scratch;
  if (data.size() <= small.size()) {
    std::copy(data.begin(), data.end(), small.begin());
    scratch = std::span<std::uint8_t>(small.data(), data.size());
  } else {
    large.assign(data.begin(), data.end());
    scratch = large;
  }
  if (auto a = check_write(e, scratch, origin); a != SdoAbort::None) return a;
  if (e.value.size() == scratch.size()) {
    std::copy(scratch.begin(), scratch.end(), e.value.begin());
  } else {
    e.value.assign(scratch.begin(), scratch.end());
  }
  for (auto& obs : e.observers) obs(e, origin);
  return SdoAbort::None;
}

SdoAbort ObjectDictionary::write(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> data,
                                 Origin origin) {
  OdEntry* e = nullptr;
  if (auto a = locate(index, sub, e); a != SdoAbort::None) return a;
  return write(*e, data, origin);
}

// ---- device access -----------------------------------------------------------------------------

void ObjectDictionary::set_bytes(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> data) {
  auto& e = must_entry(index, sub);
  e.value.assign(data.begin(), data.end());
}

std::string ObjectDictionary::get_string(std::uint16_t index, std::uint8_t sub) const {
  const auto& e = must_entry(index, sub);
  return std::string(e.value.begin(), e.value.end());
}

// ---- hooks -------------------------------------------------------------------------------------

void ObjectDictionary::add_check(std::uint16_t index, std::uint8_t sub, WriteCheck check, CheckStage stage) {
  auto& e = must_entry(index, sub);
  (stage == CheckStage::State ? e.state_checks : e.value_checks).push_back(std::move(check));
}

void ObjectDictionary::add_observer(std::uint16_t index, std::uint8_t sub, WriteObserver observer) {
  must_entry(index, sub).observers.push_back(std::move(observer));
}

void ObjectDictionary::add_read_hook(std::uint16_t index, std::uint8_t sub, ReadHook hook) {
  must_entry(index, sub).read_hooks.push_back(std::move(hook));
}

void ObjectDictionary::reset_range(std::uint16_t first, std::uint16_t last, std::uint8_t node_id) {
  for (auto it = objects_.lower_bound(first); it != objects_.end() && it->first <= last; ++it) {
    for (auto& [sub, e] : it->second.entries) e.reset_to_default(node_id);
  }
}

}  // namespace canopen
