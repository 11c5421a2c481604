#include "devices/canopen/standard_objects.h"

namespace canopen {

namespace {
using DT = DataType;
}

std::uint32_t default_tpdo_cob_base(int number) {
  return number >= 1 && number <= 4 ? 0x180u + 0x100u * static_cast<std::uint32_t>(number - 1) : 0x80000000u;
}

std::uint32_t default_rpdo_cob_base(int number) {
  return number >= 1 && number <= 4 ? 0x200u + 0x100u * static_cast<std::uint32_t>(number - 1) : 0x80000000u;
}

void add_communication_objects(ObjectDictionary& od, const CommunicationProfile& p) {
  od.add_var(0x1000, "Device type", DT::Unsigned32, Access::ReadOnly, p.device_type);
  od.add_var(0x1001, "Error register", DT::Unsigned8, Access::ReadOnly, 0, true).persistent = false;
  if (p.error_history_depth > 0) {
    od.add_object(0x1003, "Pre-defined error field", ObjectCode::Array);
    od.add_entry(0x1003, 0, "Number of errors", DT::Unsigned8, Access::ReadWrite, 0).persistent = false;
    for (int i = 1; i <= p.error_history_depth; ++i) {
      od.add_entry(0x1003, static_cast<std::uint8_t>(i), "Standard error field", DT::Unsigned32, Access::ReadOnly, 0)
          .persistent = false;
    }
  }
  if (p.sync) od.add_var(0x1005, "COB-ID SYNC", DT::Unsigned32, Access::ReadWrite, 0x80u);
  if (p.sync_counter) od.add_var(0x1019, "Synchronous counter overflow value", DT::Unsigned8, Access::ReadWrite, 0);
  if (!p.device_name.empty()) {
    od.add_var(0x1008, "Manufacturer device name", DT::VisibleString, Access::Const, ObjectDictionary::encode(DT::VisibleString, p.device_name));
  }
  if (!p.hardware_version.empty()) {
    od.add_var(0x1009, "Manufacturer hardware version", DT::VisibleString, Access::Const, ObjectDictionary::encode(DT::VisibleString, p.hardware_version));
  }
  if (!p.software_version.empty()) {
    od.add_var(0x100A, "Manufacturer software version", DT::VisibleString, Access::Const, ObjectDictionary::encode(DT::VisibleString, p.software_version));
  }
  if (p.guarding) {
    od.add_var(0x100C, "Guard time", DT::Unsigned16, Access::ReadWrite, 0);
    od.add_var(0x100D, "Life time factor", DT::Unsigned8, Access::ReadWrite, 0);
  }
  if (p.store_groups > 0) {
    static constexpr const char* kGroup[] = {"", "Save all parameters", "Save communication parameters",
                                             "Save application parameters", "Save manufacturer parameters"};
    static constexpr const char* kRestoreGroup[] = {"", "Restore all default parameters",
                                                    "Restore communication default parameters",
                                                    "Restore application default parameters",
                                                    "Restore manufacturer default parameters"};
    od.add_object(0x1010, "Store parameters", ObjectCode::Array);
    od.add_entry(0x1010, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, p.store_groups);
    od.add_object(0x1011, "Restore default parameters", ObjectCode::Array);
    od.add_entry(0x1011, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, p.store_groups);
    for (int i = 1; i <= p.store_groups; ++i) {
      const auto sub = static_cast<std::uint8_t>(i);
      od.add_entry(0x1010, sub, i <= 4 ? kGroup[i] : "Save parameters", DT::Unsigned32, Access::ReadWrite, 1u).persistent = false;
      od.add_entry(0x1011, sub, i <= 4 ? kRestoreGroup[i] : "Restore parameters", DT::Unsigned32, Access::ReadWrite, 1u).persistent = false;
    }
  }
  if (p.emcy_cob_id) {
    auto& e = od.add_var(0x1014, "COB-ID EMCY", DT::Unsigned32, Access::ReadWrite, 0x80u);
    e.node_id_relative = true;
  }
  if (p.emcy_inhibit) od.add_var(0x1015, "Inhibit time EMCY", DT::Unsigned16, Access::ReadWrite, 0);
  if (p.heartbeat_consumers > 0) {
    od.add_object(0x1016, "Consumer heartbeat time", ObjectCode::Array);
    od.add_entry(0x1016, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, p.heartbeat_consumers);
    for (int i = 1; i <= p.heartbeat_consumers; ++i) {
      od.add_entry(0x1016, static_cast<std::uint8_t>(i), "Consumer heartbeat time", DT::Unsigned32, Access::ReadWrite, 0u);
    }
  }
  if (p.heartbeat_producer) od.add_var(0x1017, "Producer heartbeat time", DT::Unsigned16, Access::ReadWrite, 0);
  od.add_object(0x1018, "Identity object", ObjectCode::Record);
  od.add_entry(0x1018, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, p.identity_entries);
  const std::uint32_t ids[] = {p.vendor_id, p.product_code, p.revision, p.serial};
  static constexpr const char* kIdNames[] = {"Vendor-ID", "Product code", "Revision number", "Serial number"};
  for (int i = 1; i <= p.identity_entries && i <= 4; ++i) {
    od.add_entry(0x1018, static_cast<std::uint8_t>(i), kIdNames[i - 1], DT::Unsigned32, Access::ReadOnly, ids[i - 1]);
  }
  if (p.error_behaviour) {
    od.add_object(0x1029, "Error behavior", ObjectCode::Array);
    od.add_entry(0x1029, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 1);
    od.add_entry(0x1029, 1, "Communication error", DT::Unsigned8, Access::ReadWrite, 0);
  }
  if (p.sdo_server_parameter) {
    od.add_object(0x1200, "SDO server parameter", ObjectCode::Record);
    od.add_entry(0x1200, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 2);
    od.add_entry(0x1200, 1, "COB-ID client to server (rx)", DT::Unsigned32, Access::ReadOnly, 0x600u).node_id_relative = true;
    od.add_entry(0x1200, 2, "COB-ID server to client (tx)", DT::Unsigned32, Access::ReadOnly, 0x580u).node_id_relative = true;
  }
}

namespace {

void add_mapping(ObjectDictionary& od, std::uint16_t index, const char* name, const PdoDefaults& d) {
  od.add_object(index, name, ObjectCode::Record);
  od.add_entry(index, 0, "Number of mapped application objects in PDO", DT::Unsigned8, Access::ReadWrite,
               static_cast<std::uint8_t>(d.mapping.size()));
  for (int i = 1; i <= d.mapping_capacity; ++i) {
    const std::uint32_t v = i <= static_cast<int>(d.mapping.size()) ? d.mapping[static_cast<std::size_t>(i - 1)] : 0u;
    od.add_entry(index, static_cast<std::uint8_t>(i), "Application object " + std::to_string(i), DT::Unsigned32,
                 Access::ReadWrite, v);
  }
}

void add_cob_entry(ObjectDictionary& od, std::uint16_t index, const PdoDefaults& d) {
  auto& cob = od.add_entry(index, 1, "COB-ID used by PDO", DT::Unsigned32, Access::ReadWrite, d.cob_base);
  cob.node_id_relative = !d.absolute && !(d.cob_base & 0x80000000u);
  if (cob.node_id_relative) cob.value = cob.default_value;  // value follows the node-ID at reset
}

}  // namespace

void add_rpdo(ObjectDictionary& od, int number, const PdoDefaults& d) {
  const auto comm = static_cast<std::uint16_t>(0x1400 + number - 1);
  od.add_object(comm, "RPDO communication parameter", ObjectCode::Record);
  od.add_entry(comm, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly,
               static_cast<std::uint8_t>(d.event_timer ? 5 : 2));
  add_cob_entry(od, comm, d);
  od.add_entry(comm, 2, "Transmission type", DT::Unsigned8, Access::ReadWrite, d.transmission_type);
  if (d.event_timer) od.add_entry(comm, 5, "Event timer", DT::Unsigned16, Access::ReadWrite, d.event_timer);
  add_mapping(od, static_cast<std::uint16_t>(0x1600 + number - 1), "RPDO mapping parameter", d);
}

void add_tpdo(ObjectDictionary& od, int number, const PdoDefaults& d) {
  const auto comm = static_cast<std::uint16_t>(0x1800 + number - 1);
  od.add_object(comm, "TPDO communication parameter", ObjectCode::Record);
  od.add_entry(comm, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly,
               static_cast<std::uint8_t>(d.with_sync_start ? 6 : d.with_inhibit_and_timer ? 5 : 2));
  add_cob_entry(od, comm, d);
  od.add_entry(comm, 2, "Transmission type", DT::Unsigned8, Access::ReadWrite, d.transmission_type);
  if (d.with_inhibit_and_timer) {
    od.add_entry(comm, 3, "Inhibit time", DT::Unsigned16, Access::ReadWrite, d.inhibit_time);
    od.add_entry(comm, 5, "Event timer", DT::Unsigned16, Access::ReadWrite, d.event_timer);
  }
  if (d.with_sync_start) od.add_entry(comm, 6, "SYNC start value", DT::Unsigned8, Access::ReadWrite, 0);
  add_mapping(od, static_cast<std::uint16_t>(0x1A00 + number - 1), "TPDO mapping parameter", d);
}

}  // namespace canopen
