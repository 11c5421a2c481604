#include "devices/vtvpcd/dictionary.h"

#include "devices/canopen/standard_objects.h"
#include "devices/vtvpcd/manufacturer_objects.h"

namespace vtvpcd {

namespace {
using canopen::Access;
using canopen::DataType;
using canopen::Origin;
using canopen::SdoAbort;

void add_communication_area(canopen::ObjectDictionary& od, const Settings& s) {
  canopen::CommunicationProfile p;
  p.device_type = s.device_type;
  p.vendor_id = s.identity[0];
  p.product_code = s.identity[1];
  p.revision = s.identity[2];
  p.serial = s.identity[3];
  p.identity_entries = 4;
  p.error_history_depth = 4;  // "A maximum of 4 errors are saved" (manual §3.5)
  p.store_groups = 0;         // RAM only
  p.heartbeat_consumers = 1;
  canopen::add_communication_objects(od, p);
  // Only the chapter-4 parameters are "available" to the Bus Manager.
  od.entry(0x1001, 0)->pdo_mappable = false;
  // Listed in the predefined connection set without a function (SYNC, TIME are ignored).
  od.add_var(0x1006, "Communication cycle period", DataType::Unsigned32, Access::ReadWrite, 0u);
  od.add_var(0x1012, "COB-ID time stamp object", DataType::Unsigned32, Access::ReadWrite, 0x100u);
  od.add_var(0x1013, "High resolution time stamp", DataType::Unsigned32, Access::ReadWrite, 0u);
  od.entry(0x1014, 0)->access = Access::ReadOnly;  // digest §2.7 (R): the EMCY identifier is fixed
}

void add_pdos(canopen::ObjectDictionary& od, const Settings& s) {
  BusManagerAreas::Mapping m;
  std::string error;
  (void)s.areas.to_mapping(m, error);  // validated by Settings::parse
  for (int n = 1; n <= 4; ++n) {
    canopen::PdoDefaults r;
    r.cob_base = canopen::default_rpdo_cob_base(n);
    r.transmission_type = 0xFF;
    r.mapping = m.rpdo[static_cast<std::size_t>(n - 1)];
    canopen::add_rpdo(od, n, r);
    canopen::PdoDefaults t;
    t.cob_base = canopen::default_tpdo_cob_base(n);
    t.transmission_type = 0xFF;
    t.event_timer = 0;  // no TPDO is sent until the master sets its event timer (manual §3.4)
    t.mapping = m.tpdo[static_cast<std::size_t>(n - 1)];
    canopen::add_tpdo(od, n, t);
  }
}

/// sdo_range_mode = strict: SDO writes outside the documented range are refused (A15). RPDO
/// values are stored as received, as in the default mode.
void add_strict_range_check(canopen::ObjectDictionary& od, const ObjectSpec& spec) {
  od.add_check(spec.index, 0, [&spec](const canopen::OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const std::int64_t v = canopen::is_signed_integer(e.type) ? canopen::decode_signed(data)
                                                               : static_cast<std::int64_t>(canopen::decode_unsigned(data));
    if (v < spec.strict_raw_min()) return SdoAbort::ValueTooLow;
    if (v > spec.strict_raw_max()) return SdoAbort::ValueTooHigh;
    return SdoAbort::None;
  });
}

void add_manufacturer_objects(canopen::ObjectDictionary& od, const Settings& s) {
  for (const auto& spec : manufacturer_objects()) {
    auto& e = od.add_var(spec.index, spec.name, spec.type, spec.read_only ? Access::ReadOnly : Access::ReadWrite,
                         spec.start_raw, true);
    e.persistent = false;
    if (s.sdo_range_strict && !spec.read_only && spec.range_checked) add_strict_range_check(od, spec);
  }
  if (s.node_id_object != 0) {
    auto& e = od.add_var(s.node_id_object, "Node-ID", DataType::Unsigned8, Access::ReadWrite, s.node_id);
    e.persistent = false;
    od.add_check(s.node_id_object, 0, [](const canopen::OdEntry&, std::span<std::uint8_t> data, Origin) {
      if (data[0] == 0) return SdoAbort::ValueTooLow;
      if (data[0] > 127) return SdoAbort::ValueTooHigh;
      return SdoAbort::None;
    });
  }
}

}  // namespace

canopen::ObjectDictionary build_dictionary(const Settings& settings) {
  canopen::ObjectDictionary od;
  od.access_aborts().write_read_only = SdoAbort::UnsupportedAccess;  // "Only reading or writing possible"
  add_communication_area(od, settings);
  add_pdos(od, settings);
  add_manufacturer_objects(od, settings);
  return od;
}

}  // namespace vtvpcd
