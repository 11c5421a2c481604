#include "devices/hlt1100/hlt1100_object_dictionary.h"

#include "devices/canopen/standard_objects.h"

namespace hlt1100 {

using canopen::Access;
using canopen::ObjectCode;
using canopen::ObjectDictionary;
using DT = canopen::DataType;

namespace {

void add_fixed_tpdo(ObjectDictionary& od, int number, std::uint32_t cob_base, std::uint8_t type, const Settings& s) {
  canopen::PdoDefaults d{.cob_base = cob_base, .transmission_type = type, .mapping = {kPositionMapping}};
  d.mapping_capacity = s.dynamic_mapping ? 2 : 1;
  canopen::add_tpdo(od, number, d);
  const auto comm = static_cast<std::uint16_t>(0x1800 + number - 1);
  const auto map = static_cast<std::uint16_t>(0x1A00 + number - 1);
  od.entry(comm, 1)->access = Access::ReadOnly;  // COB-ID and type are fixed [M]
  od.entry(comm, 2)->access = Access::ReadOnly;
  if (!s.dynamic_mapping) {
    for (auto& [sub, e] : od.object(map)->entries) e.access = Access::ReadOnly;
  }
}

}  // namespace

ObjectDictionary make_object_dictionary(const Settings& s) {
  ObjectDictionary od;
  canopen::CommunicationProfile p;
  p.device_type = kDeviceType;
  p.vendor_id = kVendorId;
  p.product_code = s.product_code;
  p.revision = s.revision;
  p.serial = s.serial;
  p.device_name = s.device_name;
  p.hardware_version = s.hardware_version;
  p.software_version = s.software_version;
  p.error_history_depth = 0;  // 0x1003 has one entry and a running count: built below
  p.store_groups = 1;
  p.emcy_cob_id = false;
  p.emcy_inhibit = false;
  p.heartbeat_consumers = 0;
  p.heartbeat_producer = false;
  p.sdo_server_parameter = false;
  canopen::add_communication_objects(od, p);
  for (std::uint16_t strings : {0x1008, 0x1009, 0x100A}) {
    if (auto* e = od.entry(strings, 0)) e->force_segmented = true;  // always segmented [M]
  }
  od.object(0x1000)->entries.at(0).access = Access::Const;
  od.entry(obj::kErrorRegister, 0)->pdo_mappable = false;
  // SYNC consumer with the 11-bit ID 0x080 (bit 31 set: consumes SYNC) [M].
  auto& sync = *od.entry(0x1005, 0);
  sync.default_value = ObjectDictionary::encode(DT::Unsigned32, 0x80000080u);
  sync.value = sync.default_value;

  od.add_object(obj::kErrorField, "Pre-defined error field", ObjectCode::Array);
  od.add_entry(obj::kErrorField, 0, "Number of errors", DT::Unsigned8, Access::ReadWrite, 0).persistent = false;
  od.add_entry(obj::kErrorField, 1, "Standard error field", DT::Unsigned32, Access::ReadOnly, 0u).persistent = false;

  add_fixed_tpdo(od, 1, 0x180, 254, s);
  add_fixed_tpdo(od, 2, 0x280, 1, s);
  od.add_var(obj::kNmtStartup, "NMT startup", DT::Unsigned32, Access::ReadWrite, s.nmt_startup_prose ? 0x08u : 0x0Cu);

  od.add_var(obj::kOperatingParameters, "Operating parameters", DT::Unsigned16, Access::ReadWrite, 0);
  od.add_object(obj::kMeasuringStepSettings, "Linear encoder measuring step settings", ObjectCode::Record);
  od.add_entry(obj::kMeasuringStepSettings, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 2);
  od.add_entry(obj::kMeasuringStepSettings, 1, "Position step setting", DT::Unsigned32, Access::ReadOnly, 100000u);
  od.add_entry(obj::kMeasuringStepSettings, 2, "Speed step setting", DT::Unsigned32, Access::ReadOnly, s.speed_step);
  od.add_object(obj::kPreset, "Preset value", ObjectCode::Array);
  od.add_entry(obj::kPreset, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(obj::kPreset, 1, "Preset value", DT::Integer32, Access::ReadWrite, 0);
  od.add_object(obj::kPosition, "Position value", ObjectCode::Array);
  od.add_entry(obj::kPosition, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(obj::kPosition, 1, "Position value", DT::Integer32, Access::ReadOnly, 0, true).persistent = false;
  od.add_object(obj::kSpeed, "Speed value", ObjectCode::Array);
  od.add_entry(obj::kSpeed, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(obj::kSpeed, 1, "Speed value", DT::Integer16, Access::ReadOnly, 0, true).persistent = false;
  od.add_var(obj::kCyclicTimer, "Cyclic timer", DT::Unsigned16, Access::ReadWrite, 0);

  od.add_var(obj::kOperatingStatus, "Operating status", DT::Unsigned16, Access::ReadOnly, 0).persistent = false;
  od.add_var(obj::kMeasuringStep, "Measuring step", DT::Unsigned32, Access::ReadOnly, 100000u);
  od.add_var(obj::kAlarms, "Alarms", DT::Unsigned16, Access::ReadOnly, 0).persistent = false;
  od.add_var(obj::kSupportedAlarms, "Supported alarms", DT::Unsigned16, Access::ReadOnly, s.supported_alarms);
  od.add_var(0x6505, "Warnings", DT::Unsigned16, Access::ReadOnly, 0);
  od.add_var(0x6506, "Supported warnings", DT::Unsigned16, Access::ReadOnly, 0);
  od.add_var(0x6507, "Profile and software version", DT::Unsigned32, Access::ReadOnly,
             static_cast<std::uint32_t>(s.software_version_bcd) << 16 | 0x0302u);
  od.add_var(0x6508, "Operating time", DT::Unsigned32, Access::ReadOnly, 0xFFFFFFFFu);
  od.add_object(0x650A, "Module identification", ObjectCode::Record);
  od.add_entry(0x650A, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 3);
  od.add_entry(0x650A, 1, "Manufacturer offset value", DT::Integer32, Access::ReadOnly, s.manufacturer_offset);
  od.add_entry(0x650A, 2, "Manufacturer minimum position value", DT::Integer32, Access::ReadOnly, s.manufacturer_min);
  od.add_entry(0x650A, 3, "Manufacturer maximum position value", DT::Integer32, Access::ReadOnly,
               s.manufacturer_max >= 0 ? s.manufacturer_max : s.steps() - 1);
  od.add_var(0x650B, "Serial number", DT::Unsigned32, Access::ReadOnly, s.serial);
  od.add_object(obj::kOffset, "Offset values", ObjectCode::Array);
  od.add_entry(obj::kOffset, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(obj::kOffset, 1, "Offset value", DT::Integer32, Access::ReadOnly, 0);
  return od;
}

}  // namespace hlt1100
