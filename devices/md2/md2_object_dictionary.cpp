#include "devices/md2/md2_object_dictionary.h"

#include "devices/md2/control_mode.h"
#include "devices/profiles/wandfluh/communication.h"
#include "devices/profiles/wandfluh/node_address.h"

namespace md2 {

using canopen::Access;
using canopen::DataType;
using canopen::ObjectCode;
using canopen::ObjectDictionary;
using DT = DataType;

namespace {

constexpr std::uint32_t kDummyU32 = 0x00070020;  // unused entries read "Dummy mapping (unsigned32)"

std::uint32_t entry(std::uint16_t index, std::uint8_t sub, std::uint8_t bits) {
  return static_cast<std::uint32_t>(index) << 16 | static_cast<std::uint32_t>(sub) << 8 | bits;
}

template <typename T>
void limit(canopen::OdEntry& e, T lo, T hi) {
  e.low_limit = ObjectDictionary::encode(e.type, lo);
  e.high_limit = ObjectDictionary::encode(e.type, hi);
}

/// A DSP 408 "value parameter record": sub 0 = number of entries (1), sub 1 = the value.
canopen::OdEntry& add_value_record(ObjectDictionary& od, std::uint16_t index, const std::string& name, DT type,
                                   Access access, bool mappable) {
  od.add_object(index, name, ObjectCode::Record);
  od.add_entry(index, 0, "Number of entries", DT::Unsigned8, Access::ReadOnly, 1).persistent = false;
  auto& v = od.add_entry(index, 1, "Value", type, access, 0, mappable);
  return v;
}

/// PDO communication parameter as the MD2 has it: sub 0 = 2 although the inhibit time (sub 3,
/// shown by PASO) exists; no event timer.
void add_pdo(ObjectDictionary& od, bool receive, int n, std::uint32_t cob, const std::vector<std::uint32_t>& mapping) {
  const auto comm = static_cast<std::uint16_t>((receive ? 0x1400 : 0x1800) + n - 1);
  const auto map = static_cast<std::uint16_t>((receive ? 0x1600 : 0x1A00) + n - 1);
  od.add_object(comm, receive ? "RxPDO communication parameter" : "TxPDO communication parameter", ObjectCode::Record);
  od.add_entry(comm, 0, "Number of entries", DT::Unsigned8, Access::ReadOnly, 2);
  auto& c = od.add_entry(comm, 1, "COB-ID used by PDO", DT::Unsigned32, Access::ReadWrite, cob);
  c.node_id_relative = !(cob & 0x80000000u);
  od.add_entry(comm, 2, "Transmission type", DT::Unsigned8, Access::ReadWrite, 255);
  od.add_entry(comm, 3, "Inhibit time", DT::Unsigned16, Access::ReadWrite, 0);
  od.add_object(map, receive ? "RxPDO mapping" : "TxPDO mapping", ObjectCode::Record);
  auto& count = od.add_entry(map, 0, "Number of mapped objects", DT::Unsigned8, Access::ReadWrite,
                             static_cast<std::uint8_t>(mapping.size()));
  limit<std::uint8_t>(count, 0, 64);  // printed range "0 to 64"; more than 4 → 0x06090031 via the mapping check
  for (int i = 1; i <= 4; ++i) {
    const std::uint32_t v = i <= static_cast<int>(mapping.size()) ? mapping[static_cast<std::size_t>(i - 1)] : kDummyU32;
    od.add_entry(map, static_cast<std::uint8_t>(i), "Mapped object " + std::to_string(i), DT::Unsigned32,
                 Access::ReadWrite, v);
  }
}

void add_channel(ObjectDictionary& od, const Md2Options& o, int c) {
  const auto ix = ChannelIndices::of(c);
  const std::string ch = " channel " + std::to_string(c);
  od.add_var(ix.control_word(), "Device control word" + ch, DT::Unsigned16, Access::ReadWrite, 0, true).persistent = false;
  od.add_var(ix.status_word(), "Device status word" + ch, DT::Unsigned16, Access::ReadOnly, 0x0008, true).persistent = false;
  limit<std::int8_t>(od.add_var(ix.device_mode(), "Device mode" + ch, DT::Integer8, Access::ReadWrite, 1), 1, 2);
  // Printed range −8..9 for both variants; a mode the variant lacks is "value invalid".
  limit<std::int8_t>(od.add_var(ix.control_mode(), "Device control mode" + ch, DT::Integer8, Access::ReadWrite, 0), -8, 9);
  limit<std::int8_t>(od.add_var(ix.device_local(), "Device local" + ch, DT::Integer8, Access::ReadWrite, 0), 0, 1);
  od.add_var(ix.capability(), "Device capability" + ch, DT::Unsigned32, Access::ReadOnly,
             o.capability != 0 ? o.capability : default_capability(o.variant));
  const auto n = static_cast<std::int16_t>(o.bus_full_scale);
  auto setpoint16 = [&](std::uint16_t index, const std::string& name) {
    auto& v = add_value_record(od, index, name + ch, DT::Integer16, Access::ReadWrite, true);
    limit<std::int16_t>(v, static_cast<std::int16_t>(-n), n);
    v.persistent = false;
  };
  setpoint16(ix.vpoc_setpoint(), "vpoc setpoint");
  setpoint16(ix.vprc_setpoint(), "vprc setpoint");

  if (o.variant != Variant::Controller || !ix.has_manufacturer_objects()) return;
  const auto smin = static_cast<std::int32_t>(o.setpoint_min), smax = static_cast<std::int32_t>(o.setpoint_max);
  auto setpoint32 = [&](std::uint16_t index, const std::string& name) {
    auto& v = add_value_record(od, index, name + ch, DT::Integer32, Access::ReadWrite, true);
    limit<std::int32_t>(v, smin, smax);
    v.persistent = false;
  };
  setpoint32(ix.dcol_setpoint(), "dcol setpoint");
  setpoint32(ix.dsc_setpoint(), "dsc setpoint");
  setpoint32(ix.dpc_setpoint(), "dpc setpoint");
  auto measured = [&](std::uint16_t index, const std::string& name, DT type) {
    add_value_record(od, index, name + ch, type, Access::ReadOnly, true).persistent = false;
  };
  measured(ix.vprc_actual(), "vprc actual value", DT::Integer16);
  measured(ix.dsc_actual(), "dsc actual value", DT::Integer32);
  measured(ix.dpc_actual(), "dpc actual value", DT::Integer32);
  measured(ix.vprc_deviation(), "vprc control deviation", DT::Integer16);
  measured(ix.dsc_deviation(), "dsc control deviation", DT::Integer32);
  measured(ix.dpc_deviation(), "dpc control deviation", DT::Integer32);

  limit<std::int8_t>(od.add_var(ix.actual_value_mode(), "Actual value mode" + ch, DT::Integer8, Access::ReadWrite, 2), 1, 2);
  od.add_var(ix.actual_input_16(), "Actual value input 16 bits" + ch, DT::Integer16, Access::ReadWrite, 0, true).persistent = false;
  od.add_var(ix.actual_input_32(), "Actual value input 32 bits" + ch, DT::Integer32, Access::ReadWrite, 0, true).persistent = false;
  const auto umax = static_cast<std::int32_t>(o.unit.max);
  limit<std::uint32_t>(od.add_var(ix.speed_positive(), "Speed positive" + ch, DT::Unsigned32, Access::ReadWrite, 0u),
                       0u, static_cast<std::uint32_t>(umax));
  limit<std::int32_t>(od.add_var(ix.speed_negative(), "Speed negative" + ch, DT::Integer32, Access::ReadWrite, 0), 0, umax);
  if (ix.n_point_setpoint() != 0) {
    auto& np = od.add_var(ix.n_point_setpoint(), "n-point controller set point" + ch, DT::Integer32, Access::ReadWrite, 0, true);
    limit<std::int32_t>(np, smin, smax);
    np.persistent = false;
  }
}

}  // namespace

std::vector<std::uint32_t> default_rpdo_mapping(const Md2Options& o, int channel, std::int8_t m) {
  const auto ix = ChannelIndices::of(channel);
  const std::uint16_t sp = o.vpoc_mapping_literal && is_16_bit(m) ? ix.vpoc_setpoint() : ix.setpoint_for(m);
  if (sp == 0) return {entry(ix.control_word(), 0, 16)};  // channel 4 has no n-point set point
  return {entry(ix.control_word(), 0, 16), entry(sp, ix.setpoint_sub(m), is_16_bit(m) ? 16 : 32)};
}

std::vector<std::uint32_t> default_tpdo_mapping(const Md2Options& o, int channel, std::int8_t m) {
  const auto ix = ChannelIndices::of(channel);
  const std::uint16_t actual = ix.actual_for(m);
  if (actual == 0 || !o.tpdo_actual_value) return {entry(ix.status_word(), 0, 16)};
  return {entry(ix.status_word(), 0, 16), entry(actual, 1, is_16_bit(m) ? 16 : 32)};
}

ObjectDictionary build_object_dictionary(const Md2Options& o) {
  ObjectDictionary od;
  auto profile = wandfluh::communication_profile(o.device_type, o.common);
  profile.revision = o.identity_revision;  // "configurable" (digest §1.1)
  profile.serial = o.identity_serial;
  canopen::add_communication_objects(od, profile);
  for (int n = 1; n <= kPdoCount; ++n) {
    const bool has_channel = n <= 4 && n <= o.channels;
    const auto base = static_cast<std::uint32_t>(0x100 * (n - 1));
    add_pdo(od, true, n, has_channel ? 0x200 + base : 0x80000000u,
            has_channel ? default_rpdo_mapping(o, n, o.delivery_control_mode) : std::vector<std::uint32_t>{});
    add_pdo(od, false, n, has_channel ? 0x180 + base : 0x80000000u,
            has_channel ? default_tpdo_mapping(o, n, o.delivery_control_mode) : std::vector<std::uint32_t>{});
  }
  wandfluh::mark_saved_communication_entries(od, o.common.save_all_pdo_parameters);

  wandfluh::NodeAddress::add_objects(od);
  od.add_var(0x2002, "Device temperature", DT::Integer16, Access::ReadOnly, static_cast<std::int16_t>(o.ambient_temperature), true)
      .persistent = false;
  wandfluh::add_device_strings(od, o.common);
  for (int c = 1; c <= o.channels; ++c) add_channel(od, o, c);
  od.access_aborts().write_read_only = canopen::SdoAbort::UnsupportedAccess;  // the manual lists 0x06010000 only
  od.access_aborts().read_write_only = canopen::SdoAbort::UnsupportedAccess;
  return od;
}

}  // namespace md2
