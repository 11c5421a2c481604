#include "devices/dsv/dsv_object_dictionary.h"

#include "devices/dsv/control_mode.h"
#include "devices/dsv/dsv_objects.h"
#include "devices/profiles/wandfluh/communication.h"
#include "devices/profiles/wandfluh/node_address.h"

namespace dsv {

using canopen::Access;
using canopen::DataType;
using canopen::ObjectCode;
using canopen::ObjectDictionary;
using DT = DataType;

namespace {

template <typename T>
void limit(canopen::OdEntry& e, T lo, T hi) {
  e.low_limit = ObjectDictionary::encode(e.type, lo);
  e.high_limit = ObjectDictionary::encode(e.type, hi);
}

void add_pdo(ObjectDictionary& od, bool receive, int n, std::uint32_t cob, int capacity, bool cob_writable) {
  const auto comm = static_cast<std::uint16_t>((receive ? 0x1400 : 0x1800) + n - 1);
  const auto map = static_cast<std::uint16_t>((receive ? 0x1600 : 0x1A00) + n - 1);
  od.add_object(comm, receive ? "RxPDO communication parameter" : "TxPDO communication parameter", ObjectCode::Record);
  od.add_entry(comm, 0, "Number of entries", DT::Unsigned8, Access::ReadOnly, 2);
  auto& c = od.add_entry(comm, 1, "COB-ID used by PDO", DT::Unsigned32, cob_writable ? Access::ReadWrite : Access::ReadOnly, cob);
  c.node_id_relative = true;
  od.add_entry(comm, 2, "Transmission type", DT::Unsigned8, Access::ReadWrite, 255);
  // The mapping is fixed by the control mode (§5.4.16/18: every sub-index "Read only").
  od.add_object(map, receive ? "RxPDO mapping" : "TxPDO mapping", ObjectCode::Record);
  od.add_entry(map, 0, "Number of mapped objects", DT::Unsigned8, Access::ReadOnly, 0).persistent = false;
  for (int i = 1; i <= capacity; ++i) {
    od.add_entry(map, static_cast<std::uint8_t>(i), "Mapped object " + std::to_string(i), DT::Unsigned32,
                 Access::ReadOnly, 0u)
        .persistent = false;
  }
}

std::int64_t resolve_default(std::int64_t v, const DsvOptions& o) {
  switch (v) {
    case kDefaultImin: return o.imin;
    case kDefaultImax: return o.imax;
    case kDefaultDitherFrequency: return o.dither_frequency;
    case kDefaultDitherAmplitude: return o.dither_amplitude;
    case kDefaultModeOfOperation: return 1;  // printed default; the delivery value is seeded
    default: return v;
  }
}

void add_application_object(ObjectDictionary& od, const ObjectSpec& s, const DsvOptions& o) {
  const std::int64_t def = resolve_default(s.default_value, o);
  Access access = s.access;
  const bool measured = s.index == 0x6381 || s.index == 0x6501 || s.index == 0x6601 || s.index == 0x63D0 ||
                        s.index == 0x6550 || s.index == 0x6650;
  if (measured && !o.actual_value_writable) access = Access::ReadOnly;
  canopen::OdEntry* e = nullptr;
  if (s.shape == Shape::Var) {
    e = &od.add_var(s.index, s.name, s.type, access, def, s.mappable);
  } else {
    od.add_object(s.index, s.name, ObjectCode::Record);
    od.add_entry(s.index, 0, "Number of entries", DT::Unsigned8, Access::ReadOnly, 1).persistent = false;
    e = &od.add_entry(s.index, 1, "Value", s.type, access, def, s.mappable);
  }
  if (s.low <= s.high) {
    e->low_limit = ObjectDictionary::encode(s.type, s.low);
    e->high_limit = ObjectDictionary::encode(s.type, s.index == 0x2340 || s.index == 0x23C0 || s.index == 0x2243 ||
                                                             s.index == 0x2341 || s.index == 0x23C1 || s.index == 0x2244
                                                         ? static_cast<std::int64_t>(o.imax_limit)
                                                         : s.high);
  }
  // Process data is not a parameter: set points, actual values and deviations are not saved.
  if (s.mappable || measured || s.index == 0x2050) e->persistent = false;
}

void add_characteristic_optimisation(ObjectDictionary& od, std::uint16_t index, const char* name) {
  od.add_object(index, name, ObjectCode::Array);
  od.add_entry(index, 0, "Number of entries", DT::Unsigned8, Access::ReadOnly, 5);
  struct Sub {
    const char* name;
    std::uint16_t def, lo, hi;
  };
  const Sub subs[] = {{"Characteristic optimisation on", 0, 0, 1},
                      {"Solenoid selector", 0, 0, 1},
                      {"Point index", 1, 1, 11},
                      {"Preset value of the point", 0, 0, 100},
                      {"Solenoid current of the point", 0, 0, 1000}};
  for (std::uint8_t i = 0; i < 5; ++i) {
    auto& e = od.add_entry(index, static_cast<std::uint8_t>(i + 1), subs[i].name, DT::Unsigned16, Access::ReadWrite,
                           subs[i].def);
    limit<std::uint16_t>(e, subs[i].lo, subs[i].hi);
    if (i >= 3) e.persistent = false;  // the points themselves are stored by the device (DsvDevice)
  }
}

std::uint32_t entry(std::uint16_t index, std::uint8_t sub, std::uint8_t bits) {
  return static_cast<std::uint32_t>(index) << 16 | static_cast<std::uint32_t>(sub) << 8 | bits;
}

}  // namespace

PdoSet pdo_set(std::int8_t m, std::int8_t op, bool m4_six_bytes) {
  PdoSet p;
  const std::uint32_t cw = entry(0x6040, 0, 16), sw = entry(0x6041, 0, 16);
  p.tpdo1 = {sw};
  switch (m) {
    case mode::kVpoc:
    case mode::kVprcOpen: {
      const std::uint16_t a = m == mode::kVpoc ? 0x6300 : 0x6380, b = m == mode::kVpoc ? 0x6B00 : 0x6B80;
      p.rpdo1 = {cw, entry(a, 1, 16)};
      p.rpdo2 = {cw, entry(a, 1, 16), entry(b, 1, 16)};
      p.active_rpdo = op == 3 ? 2 : 1;
      break;
    }
    case mode::kVprcClosed:
      p.rpdo1 = {cw, entry(0x6380, 1, 16)};
      // As printed (§5.4.18): 63'81'00'10h, sub-index 00; it carries 6381h:01.
      p.tpdo2 = {sw, m4_six_bytes ? entry(0x6381, 0, 32) : entry(0x6381, 0, 16)};
      p.active_tpdo = 2;
      break;
    case mode::kDcol: p.rpdo1 = {cw, entry(0x6480, 1, 32)}; break;
    case mode::kDsc:
      p.rpdo1 = {cw, entry(0x6500, 1, 32)};
      p.tpdo2 = {sw, entry(0x6501, 1, 32)};
      p.active_tpdo = 2;
      break;
    case mode::kDpc:
      p.rpdo1 = {cw, entry(0x6600, 1, 32)};
      p.tpdo2 = {sw, entry(0x6601, 1, 32)};
      p.active_tpdo = 2;
      break;
    default: p.rpdo1 = {cw}; break;  // mode 0: control word / status word only
  }
  return p;
}

ObjectDictionary build_object_dictionary(const DsvOptions& o) {
  ObjectDictionary od;
  canopen::add_communication_objects(od, wandfluh::communication_profile(kDeviceType, o.common));
  add_pdo(od, true, 1, 0x200, 2, o.pdo_cobid_writable);
  add_pdo(od, true, 2, 0x300, 3, o.pdo_cobid_writable);
  add_pdo(od, false, 1, 0x180, 1, o.pdo_cobid_writable);
  add_pdo(od, false, 2, 0x280, 2, o.pdo_cobid_writable);
  wandfluh::mark_saved_communication_entries(od, o.common.save_all_pdo_parameters);

  wandfluh::NodeAddress::add_objects(od);
  od.add_var(0x2002, "Device temperature", DT::Integer16, Access::ReadOnly, static_cast<std::int16_t>(o.ambient_temperature))
      .persistent = false;
  od.add_var(0x6040, "Device control word", DT::Unsigned16, Access::ReadWrite, 0, true).persistent = false;
  od.add_var(0x6041, "Device status word", DT::Unsigned16, Access::ReadOnly, 0, true).persistent = false;
  limit<std::int8_t>(od.add_var(0x6043, "Device control mode", DT::Integer8, Access::ReadWrite, 0), 0, 9);
  limit<std::int8_t>(od.add_var(0x604F, "Device local", DT::Integer8, Access::ReadWrite, 0), 0, 1);
  wandfluh::add_device_strings(od, o.common);
  od.add_var(0x605F, "Device capability", DT::Unsigned32, Access::ReadOnly,
             o.capability != 0 ? o.capability : default_capability(o.variant));
  for (const auto& s : application_objects()) add_application_object(od, s, o);
  add_characteristic_optimisation(od, 0x2344, "vpoc dvg characteristic optimisation");
  add_characteristic_optimisation(od, 0x23C4, "vprc dvg characteristic optimisation");
  od.access_aborts().write_read_only = canopen::SdoAbort::UnsupportedAccess;
  od.access_aborts().read_write_only = canopen::SdoAbort::UnsupportedAccess;
  return od;
}

}  // namespace dsv
