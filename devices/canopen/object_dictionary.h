// The object dictionary: every entry a node exposes, with type, access, PDO-mappability, limits,
// defaults and behaviour hooks. Protocol services (SDO, PDO, store) go through read()/write();
// device code reads and publishes values with get<T>()/set<T>() and adds behaviour with hooks
// (CANopenNode's OD extensions, Lely's typed OnWrite): the SDO server never learns what a valve is.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "devices/canopen/data_type.h"
#include "devices/canopen/sdo_abort.h"
#include "devices/canopen/stored_value.h"

namespace canopen {

enum class Access : std::uint8_t { ReadOnly, WriteOnly, ReadWrite, Const };
enum class ObjectCode : std::uint8_t { Null = 0, Domain = 2, DefType = 5, DefStruct = 6, Var = 7, Array = 8, Record = 9 };

/// EDS AccessType "rwr" / "rww" (CiA 306): a read-write entry that is a process input (mainly
/// mapped to TPDOs) or a process output (mainly mapped to RPDOs). Documentation only: the access
/// rights are those of ReadWrite; kept so an EDS round-trips.
enum class ProcessData : std::uint8_t { None, Input, Output };

/// Who is accessing an entry; checks and hooks may behave differently (e.g. an RPDO value out of
/// range is clamped, an SDO value is refused).
enum class Origin : std::uint8_t { Sdo, Pdo, Internal, Restore };

class OdEntry;

/// Validates (and may normalise, e.g. clamp) a value before it is committed. Returns an abort
/// code to refuse. `data` has exactly the entry's size for fixed-size types.
using WriteCheck = std::function<SdoAbort(const OdEntry& entry, std::span<std::uint8_t> data, Origin origin)>;
/// Runs after a value was committed by write() (not by set()).
using WriteObserver = std::function<void(OdEntry& entry, Origin origin)>;
/// Runs before a read: refreshes the value from the device model, or refuses with an abort code.
using ReadHook = std::function<SdoAbort(OdEntry& entry, Origin origin)>;

/// When a check runs relative to the built-in limit check. Device-state checks (abort 0x0800002x)
/// must win over value-range aborts, which is what the manuals' precedence rules require.
enum class CheckStage : std::uint8_t { State, Value };

/// One sub-index.
class OdEntry {
 public:
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::string name;
  DataType type = DataType::Unsigned8;
  Access access = Access::ReadWrite;
  bool pdo_mappable = false;
  /// Saved by store parameters (0x1010) when its group is stored. Process data should not be.
  bool persistent = true;
  /// The EDS default was written "$NODEID+x": default_value holds x and the node-ID is added.
  bool node_id_relative = false;
  StoredValue value;    ///< current value, little-endian (a scalar inline: stored_value.h)
  Bytes default_value;  ///< factory default (without the node-ID for node-relative entries)
  std::optional<Bytes> low_limit, high_limit;  ///< in the entry's type encoding
  std::size_t max_length = 0;  ///< variable-length types: capacity (0 = unlimited)
  /// Force segmented SDO upload even when short (some devices always segment strings).
  bool force_segmented = false;
  /// With access ReadWrite: EDS "rwr" (Input) or "rww" (Output).
  ProcessData process_data = ProcessData::None;

  std::vector<WriteCheck> state_checks;
  std::vector<WriteCheck> value_checks;
  std::vector<WriteObserver> observers;
  std::vector<ReadHook> read_hooks;

  bool readable() const { return access != Access::WriteOnly; }
  bool writable() const { return access == Access::ReadWrite || access == Access::WriteOnly; }
  std::size_t size() const { return value.size(); }
  std::size_t bit_length() const { return value.size() * 8; }

  /// Sets the value to the default (adding node_id for node-relative entries).
  void reset_to_default(std::uint8_t node_id);
  Bytes default_for_node(std::uint8_t node_id) const;

  /// Typed views of the value (integral, bool, float, double). Converts between widths with
  /// sign extension for signed types.
  template <typename T>
  T as() const;
  template <typename T>
  void assign(T v);
};

struct OdObject {
  std::uint16_t index = 0;
  std::string name;
  ObjectCode code = ObjectCode::Var;
  /// CiA 306 ObjFlags: hints for configuration tools (bit 0 refuse write on download, bit 1
  /// refuse read on scan). The device itself ignores them.
  std::uint32_t obj_flags = 0;
  // Node-based: entry addresses stay valid until the entry is removed. Add and remove entries
  // only through ObjectDictionary (it changes its layout() stamp).
  std::map<std::uint8_t, OdEntry> entries;
};

/// Numeric helpers on little-endian byte strings of a given CiA type. Inline, with the common
/// widths as single loads and stores: devices and PDOs decode and encode values every tick.
inline std::uint64_t decode_unsigned(std::span<const std::uint8_t> bytes) {
  const std::uint8_t* p = bytes.data();
  if constexpr (std::endian::native == std::endian::little) {
    switch (bytes.size()) {
      case 0: return 0;
      case 1: return p[0];
      case 2: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
      }
      case 4: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
      }
      default:
        if (bytes.size() >= 8) {
          std::uint64_t v;
          std::memcpy(&v, p, 8);
          return v;
        }
        break;
    }
  }
  std::uint64_t u = 0;
  const std::size_t n = bytes.size() < 8 ? bytes.size() : 8;
  for (std::size_t i = 0; i < n; ++i) u |= static_cast<std::uint64_t>(p[i]) << (8 * i);
  return u;
}

inline std::int64_t decode_signed(std::span<const std::uint8_t> bytes) {
  const std::size_t n = bytes.size() < 8 ? bytes.size() : 8;
  switch (n) {
    case 0: return 0;
    case 1: return static_cast<std::int8_t>(bytes[0]);
    case 2: return static_cast<std::int16_t>(decode_unsigned(bytes));
    case 4: return static_cast<std::int32_t>(decode_unsigned(bytes));
    case 8: return static_cast<std::int64_t>(decode_unsigned(bytes));
    default: {
      std::uint64_t u = decode_unsigned(bytes);
      if (bytes[n - 1] & 0x80) u |= ~std::uint64_t{0} << (8 * n);
      return static_cast<std::int64_t>(u);
    }
  }
}

inline double decode_real(DataType type, std::span<const std::uint8_t> bytes) {
  if (type == DataType::Real32 && bytes.size() >= 4) {
    float f;
    std::memcpy(&f, bytes.data(), 4);
    return f;
  }
  if (type == DataType::Real64 && bytes.size() >= 8) {
    double d;
    std::memcpy(&d, bytes.data(), 8);
    return d;
  }
  return 0.0;
}

/// Writes the low out.size() bytes of v (zeros beyond 8 bytes).
inline void encode_unsigned(std::uint64_t v, std::span<std::uint8_t> out) {
  std::uint8_t* p = out.data();
  if constexpr (std::endian::native == std::endian::little) {
    switch (out.size()) {
      case 1: p[0] = static_cast<std::uint8_t>(v); return;
      case 2: {
        const auto w = static_cast<std::uint16_t>(v);
        std::memcpy(p, &w, 2);
        return;
      }
      case 4: {
        const auto w = static_cast<std::uint32_t>(v);
        std::memcpy(p, &w, 4);
        return;
      }
      case 8: std::memcpy(p, &v, 8); return;
      default: break;
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) p[i] = i < 8 ? static_cast<std::uint8_t>(v >> (8 * i)) : 0;
}

/// The size encode() gives a T value of `type`: the type's size, sizeof(T) for variable length.
template <typename T>
constexpr std::size_t encoded_size(DataType type) {
  const std::size_t n = type_size(type);
  return n == 0 ? sizeof(T) : n;
}
/// Encodes a typed value into `type`'s byte representation, into `out` (encoded_size<T>(type)
/// bytes), without allocating.
template <typename T>
void encode_into(DataType type, T v, std::span<std::uint8_t> out) {
  static_assert(std::is_arithmetic_v<T>);
  if (type == DataType::Real32) {
    const float f = static_cast<float>(v);
    std::memcpy(out.data(), &f, 4);
  } else if (type == DataType::Real64) {
    const double d = static_cast<double>(v);
    std::memcpy(out.data(), &d, 8);
  } else if constexpr (std::is_floating_point_v<T>) {
    encode_unsigned(static_cast<std::uint64_t>(static_cast<std::int64_t>(v)), out);
  } else {
    encode_unsigned(static_cast<std::uint64_t>(v), out);
  }
}
/// Compares two values of `type`; <0, 0, >0. Strings/domains compare as equal.
int compare_values(DataType type, std::span<const std::uint8_t> a, std::span<const std::uint8_t> b);
/// Widens (sign- or zero-extends) or truncates little-endian bytes of `type` to `size` bytes.
Bytes resize_value(DataType type, std::span<const std::uint8_t> bytes, std::size_t size);
/// The same into `out` (out.size() bytes), without allocating: for the per-frame paths.
void resize_value_into(DataType type, std::span<const std::uint8_t> bytes, std::span<std::uint8_t> out);

class ObjectDictionary {
 public:
  /// Abort codes for access violations; devices differ (CiA 301 vs manuals listing 0x06010000).
  struct AccessAborts {
    SdoAbort write_read_only = SdoAbort::ReadOnly;
    SdoAbort read_write_only = SdoAbort::WriteOnly;
  };

  // --- building -------------------------------------------------------------------------------
  OdObject& add_object(std::uint16_t index, std::string name, ObjectCode code);
  /// Adds sub-index `sub` to an existing object (creates a VAR object for sub 0 if absent).
  OdEntry& add_entry(std::uint16_t index, std::uint8_t sub, std::string name, DataType type, Access access,
                     Bytes default_value, bool pdo_mappable = false);
  /// Adds (or replaces) a complete entry at its index and sub-index, e.g. a copy of another one.
  OdEntry& add_entry(OdEntry entry);
  /// A VAR (single sub-index 0).
  OdEntry& add_var(std::uint16_t index, std::string name, DataType type, Access access, Bytes default_value,
                   bool pdo_mappable = false);
  template <typename T>
  OdEntry& add_var(std::uint16_t index, std::string name, DataType type, Access access, T default_value,
                   bool pdo_mappable = false) {
    return add_var(index, std::move(name), type, access, encode(type, default_value), pdo_mappable);
  }
  template <typename T>
  OdEntry& add_entry(std::uint16_t index, std::uint8_t sub, std::string name, DataType type, Access access,
                     T default_value, bool pdo_mappable = false) {
    return add_entry(index, sub, std::move(name), type, access, encode(type, default_value), pdo_mappable);
  }
  void remove_object(std::uint16_t index);
  void remove_entry(std::uint16_t index, std::uint8_t sub);

  /// Encodes a typed value into `type`'s byte representation.
  template <typename T>
  static Bytes encode(DataType type, T v);
  static Bytes encode(DataType type, std::string_view text);
  static Bytes encode(DataType type, const char* text) { return encode(type, std::string_view(text)); }
  static Bytes encode(DataType type, const std::string& text) { return encode(type, std::string_view(text)); }

  // --- lookup ---------------------------------------------------------------------------------
  OdObject* object(std::uint16_t index);
  const OdObject* object(std::uint16_t index) const;
  OdEntry* entry(std::uint16_t index, std::uint8_t sub) {
    return const_cast<OdEntry*>(std::as_const(*this).entry(index, sub));
  }
  const OdEntry* entry(std::uint16_t index, std::uint8_t sub) const;
  const std::map<std::uint16_t, OdObject>& objects() const { return objects_; }
  /// Changes whenever an object or entry is added, replaced or removed, or the dictionary is
  /// assigned: code holding entry pointers beyond a build (PDO mappings) resolves them again when
  /// it differs from the stamp it resolved them under. Unique across dictionaries and copies.
  std::uint64_t layout() const { return layout_.value; }
  /// NoObject / NoSubIndex / None.
  SdoAbort locate(std::uint16_t index, std::uint8_t sub, OdEntry*& out);

  // --- protocol access (checks, hooks) ----------------------------------------------------------
  /// Reads through access rights and read hooks.
  SdoAbort read(std::uint16_t index, std::uint8_t sub, Bytes& out, Origin origin);
  SdoAbort read(OdEntry& e, Origin origin);  ///< runs access check + hooks; value is then in e.value
  /// Writes `data` (exactly the entry's size for fixed-size types) through access rights, state
  /// checks, limits, value checks; commits; runs observers.
  SdoAbort write(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> data, Origin origin);
  SdoAbort write(OdEntry& e, std::span<const std::uint8_t> data, Origin origin);
  /// Same checks as write() without committing (used to validate before side effects).
  SdoAbort check_write(OdEntry& e, std::span<std::uint8_t> data, Origin origin);

  // --- device access (no checks, no hooks) ----------------------------------------------------
  template <typename T>
  T get(std::uint16_t index, std::uint8_t sub = 0) const;
  template <typename T>
  void set(std::uint16_t index, std::uint8_t sub, T v);
  void set_bytes(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> data);
  std::string get_string(std::uint16_t index, std::uint8_t sub = 0) const;

  // --- hooks ----------------------------------------------------------------------------------
  void add_check(std::uint16_t index, std::uint8_t sub, WriteCheck check, CheckStage stage = CheckStage::Value);
  void add_observer(std::uint16_t index, std::uint8_t sub, WriteObserver observer);
  void add_read_hook(std::uint16_t index, std::uint8_t sub, ReadHook hook);
  /// Typed conveniences: `od.on_write<std::uint16_t>(0x6040, 0, [](std::uint16_t v, Origin){...})`.
  template <typename T, typename F>
  void on_write(std::uint16_t index, std::uint8_t sub, F&& fn, CheckStage stage = CheckStage::Value);
  template <typename T, typename F>
  void after_write(std::uint16_t index, std::uint8_t sub, F&& fn);

  /// Resets every entry in [first, last] to its default.
  void reset_range(std::uint16_t first, std::uint16_t last, std::uint8_t node_id);

  AccessAborts& access_aborts() { return access_aborts_; }

  /// Objects the device hides at the moment (e.g. CiA 408 products whose object set follows the
  /// control mode): the SDO server answers 0x06020000 for a hidden index before any other check.
  /// PDOs, store/restore, EDS and device code still see every object.
  using Visibility = std::function<bool(std::uint16_t index)>;
  void set_visibility(Visibility visibility) { visibility_ = std::move(visibility); }
  bool visible(std::uint16_t index) const { return !visibility_ || visibility_(index); }

 private:
  OdEntry& must_entry(std::uint16_t index, std::uint8_t sub);
  const OdEntry& must_entry(std::uint16_t index, std::uint8_t sub) const;

  /// A fresh value on construction, copy, assignment and every change of the object set.
  struct LayoutStamp {
    std::uint64_t value = next();
    LayoutStamp() = default;
    LayoutStamp(const LayoutStamp&) : value(next()) {}
    LayoutStamp& operator=(const LayoutStamp&) {
      value = next();
      return *this;
    }
    void change() { value = next(); }
    static std::uint64_t next();
  };

  std::map<std::uint16_t, OdObject> objects_;
  LayoutStamp layout_;
  AccessAborts access_aborts_;
  Visibility visibility_;
};

// ---- template implementations ---------------------------------------------------------------

/// Decodes little-endian bytes of CiA type `type` as T (with sign extension for signed types).
template <typename T>
T value_as(DataType type, std::span<const std::uint8_t> bytes) {
  static_assert(std::is_arithmetic_v<T>);
  if (is_real(type)) return static_cast<T>(decode_real(type, bytes));
  if (is_signed_integer(type)) return static_cast<T>(decode_signed(bytes));
  return static_cast<T>(decode_unsigned(bytes));
}

template <typename T>
T OdEntry::as() const {
  return value_as<T>(type, value);
}

template <typename T>
Bytes ObjectDictionary::encode(DataType type, T v) {
  Bytes out(encoded_size<T>(type), 0);
  encode_into(type, v, out);
  return out;
}

template <typename T>
void OdEntry::assign(T v) {
  const std::size_t n = encoded_size<T>(type);
  if (value.size() != n) value.assign(n, 0);  // a fixed-size entry keeps its storage: no allocation
  encode_into(type, v, value);
}

template <typename T>
T ObjectDictionary::get(std::uint16_t index, std::uint8_t sub) const {
  return must_entry(index, sub).as<T>();
}

template <typename T>
void ObjectDictionary::set(std::uint16_t index, std::uint8_t sub, T v) {
  must_entry(index, sub).assign(v);
}

template <typename T, typename F>
void ObjectDictionary::on_write(std::uint16_t index, std::uint8_t sub, F&& fn, CheckStage stage) {
  add_check(
      index, sub,
      [fn = std::forward<F>(fn)](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) -> SdoAbort {
        return fn(value_as<T>(e.type, data), origin);
      },
      stage);
}

template <typename T, typename F>
void ObjectDictionary::after_write(std::uint16_t index, std::uint8_t sub, F&& fn) {
  add_observer(index, sub, [fn = std::forward<F>(fn)](OdEntry& e, Origin origin) { fn(e.as<T>(), origin); });
}

}  // namespace canopen
