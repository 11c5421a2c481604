#include "devices/wdga/wdga_object_dictionary.h"

#include <string>

#include "devices/canopen/standard_objects.h"
#include "devices/profiles/cia406/cam_unit.h"
#include "devices/profiles/cia406/work_area.h"

namespace wdga {

using canopen::Access;
using canopen::ObjectCode;
using canopen::ObjectDictionary;
using DT = canopen::DataType;

namespace {

void add_communication_area(ObjectDictionary& od, const Settings& s) {
  canopen::CommunicationProfile p;
  p.device_type = s.multiturn ? 0x00020196 : 0x00010196;
  p.vendor_id = kVendorId;
  p.product_code = kProductCode;
  p.revision = s.revision;
  p.serial = s.serial;
  p.device_name = s.multiturn ? "WDGA-MT-CO" : "WDGA-ST-CO";
  p.hardware_version = s.hardware_version;
  p.software_version = s.software_version;
  p.error_history_depth = 5;
  p.store_groups = 4;
  p.heartbeat_consumers = 1;
  p.sdo_server_parameter = false;
  p.error_behaviour = true;
  canopen::add_communication_objects(od, p);
  if (s.hardware_version_4_bytes) {
    auto& hw = *od.entry(0x1009, 0);
    hw.default_value.resize(4, 0);
    hw.value = hw.default_value;
  }
  // The manual marks these "co".
  for (auto [index, sub] : {std::pair<std::uint16_t, std::uint8_t>{0x1000, 0}, {0x1010, 0}, {0x1011, 0}, {0x1016, 0},
                            {0x1018, 0}, {0x1018, 1}, {0x1018, 2}, {0x1018, 3}, {0x1018, 4}}) {
    od.entry(index, sub)->access = Access::Const;
  }
  od.add_var(obj::kManufacturerStatus, "Manufacturer status register", DT::Unsigned32, Access::ReadOnly, 0u, true)
      .persistent = false;
  od.add_object(obj::kVerifyConfiguration, "Verify configuration", ObjectCode::Array);
  od.add_entry(obj::kVerifyConfiguration, 0, "Highest sub-index supported", DT::Unsigned8, Access::Const, 2);
  od.add_entry(obj::kVerifyConfiguration, 1, "Configuration date", DT::Unsigned32, Access::ReadWrite, 0u);
  od.add_entry(obj::kVerifyConfiguration, 2, "Configuration time", DT::Unsigned32, Access::ReadWrite, 0u);
  auto& behaviour_count = *od.entry(obj::kErrorBehaviour, 0);
  behaviour_count.access = Access::Const;
  behaviour_count.default_value = ObjectDictionary::encode(DT::Unsigned8, 2);
  behaviour_count.value = behaviour_count.default_value;
  od.add_entry(obj::kErrorBehaviour, 2, "Encoder error", DT::Unsigned8, Access::ReadWrite, 0);

  // Four TPDOs: sub 3 (inhibit time) does not exist, sub 0 still reads 5 [M Tab. 6.3].
  const std::uint32_t no_rtr = s.cobid_no_rtr_bit ? 0x40000000u : 0u;
  const std::uint8_t types[] = {0xFE, 0x01, 0x01, 0x01};
  const std::uint32_t position = 0x60040020, high = s.tpdo3_literal_mapping ? 0x60080020 : 0x60080040;
  const std::vector<std::uint32_t> mappings[] = {{position}, {position}, {high}, {}};
  for (int n = 1; n <= 4; ++n) {
    canopen::PdoDefaults d;
    d.cob_base = no_rtr | canopen::default_tpdo_cob_base(n);
    d.transmission_type = types[n - 1];
    d.mapping = mappings[n - 1];
    canopen::add_tpdo(od, n, d);
    const auto comm = static_cast<std::uint16_t>(0x1800 + n - 1);
    od.remove_entry(comm, 3);
    od.entry(comm, 0)->access = Access::Const;
    // Bit 30 is part of the default; the value follows the node-ID (CiA 301 "$NODEID+").
    auto& cob = *od.entry(comm, 1);
    cob.node_id_relative = true;
  }
  od.add_var(obj::kNmtStartup, "NMT startup", DT::Unsigned32, Access::ReadWrite, 0u);
}

void add_manufacturer_area(ObjectDictionary& od, const Settings& s) {
  // Views of the LSS configuration cells (saved on write, not by 1010h) [M §8.3.3, §8.3.4].
  od.add_var(obj::kBitRate, "Baudrate", DT::Unsigned8, Access::ReadWrite, s.factory_bit_rate).persistent = false;
  od.add_var(obj::kNodeId, "Node-ID", DT::Unsigned8, Access::ReadWrite, s.factory_node_id).persistent = false;
  od.add_var(obj::kBusOffReset, "Bus-off auto-reset", DT::Unsigned8, Access::ReadWrite, 0);
  od.add_object(obj::kIntegration, "Integration value", ObjectCode::Record);
  od.add_entry(obj::kIntegration, 0, "Highest sub-index supported", DT::Unsigned8, Access::Const, 2);
  auto& filter = od.add_entry(obj::kIntegration, 1, "Position filter", DT::Unsigned8, Access::ReadWrite, 1);
  filter.low_limit = ObjectDictionary::encode(DT::Unsigned8, 1);
  filter.high_limit = ObjectDictionary::encode(DT::Unsigned8, 4);
  auto& window = od.add_entry(obj::kIntegration, 2, "Speed integration time", DT::Unsigned32, Access::ReadWrite, 1000u);
  window.low_limit = ObjectDictionary::encode(DT::Unsigned32, 1u);
  window.high_limit = ObjectDictionary::encode(DT::Unsigned32, 65535u);
  od.add_object(obj::kSpeedScaling, "Speed scaling", ObjectCode::Record);
  od.add_entry(obj::kSpeedScaling, 0, "Highest sub-index supported", DT::Unsigned8, Access::Const, 2);
  od.add_entry(obj::kSpeedScaling, 1, "Multiplier", DT::Unsigned16, Access::ReadWrite, 1);
  od.add_entry(obj::kSpeedScaling, 2, "Divisor", DT::Unsigned16, Access::ReadWrite, 1).low_limit =
      ObjectDictionary::encode(DT::Unsigned16, 1);
  od.add_var(obj::kFrequencyLimit, "Frequency limit", DT::Unsigned16, Access::ReadWrite, 0xFFFF).low_limit =
      ObjectDictionary::encode(DT::Unsigned16, 1);
  od.add_object(obj::kCustomerData, "Customer flash area", ObjectCode::Array);
  od.add_entry(obj::kCustomerData, 0, "Highest sub-index supported", DT::Unsigned8, Access::Const, 8);
  for (int i = 1; i <= 8; ++i) {
    od.add_entry(obj::kCustomerData, static_cast<std::uint8_t>(i), "Customer data " + std::to_string(i), DT::Unsigned32,
                 Access::ReadWrite, 0xFFFFFFFFu);
  }
  od.add_object(obj::kTemperature, "Temperature", ObjectCode::Record);
  od.add_entry(obj::kTemperature, 0, "Highest sub-index supported", DT::Unsigned8, Access::Const, 5);
  od.add_entry(obj::kTemperature, 1, "Current temperature", DT::Integer16, Access::ReadOnly, 25, true).persistent = false;
  od.add_entry(obj::kTemperature, 2, "Upper limit", DT::Integer16, Access::ReadWrite, 100);
  od.add_entry(obj::kTemperature, 3, "Lower limit", DT::Integer16, Access::ReadWrite, -40);
  od.add_entry(obj::kTemperature, 4, "Highest temperature", DT::Integer16, Access::ReadOnly, 25, true).persistent = false;
  od.add_entry(obj::kTemperature, 5, "Lowest temperature", DT::Integer16, Access::ReadOnly, 25, true).persistent = false;
  od.add_object(obj::kErrorHistory, "Error history", ObjectCode::Array);
  od.add_entry(obj::kErrorHistory, 0, "Number of errors", s.error_history_count_u32 ? DT::Unsigned32 : DT::Unsigned8,
               Access::Const, 0);
  od.add_object(obj::kAlarmHistory, "Alarm history", ObjectCode::Array);
  od.add_entry(obj::kAlarmHistory, 0, "Number of alarms", DT::Unsigned8, Access::Const, 0);
  od.add_object(obj::kWarningHistory, "Warning history", ObjectCode::Array);
  od.add_entry(obj::kWarningHistory, 0, "Number of warnings", DT::Unsigned8, Access::ReadWrite, 0).persistent = false;
  for (int i = 1; i <= 5; ++i) {
    const auto sub = static_cast<std::uint8_t>(i);
    od.add_entry(obj::kErrorHistory, sub, "Error field " + std::to_string(i), DT::Unsigned32, Access::ReadOnly, 0u);
    od.add_entry(obj::kAlarmHistory, sub, "Alarm value " + std::to_string(i), DT::Unsigned16, Access::ReadOnly, 0);
    od.add_entry(obj::kWarningHistory, sub, "Warning value " + std::to_string(i), DT::Unsigned16, Access::ReadOnly, 0);
  }
}

void add_profile_area(ObjectDictionary& od, const Settings& s) {
  od.add_var(obj::kOperatingParameters, "Operating parameters", DT::Unsigned16, Access::ReadWrite, 0x0004);
  auto& mur = od.add_var(obj::kUnitsPerRevolution, "Measuring units per revolution", DT::Unsigned32, Access::ReadWrite,
                         kPhysicalResolution);
  mur.low_limit = ObjectDictionary::encode(DT::Unsigned32, 1u);
  mur.high_limit = ObjectDictionary::encode(DT::Unsigned32, kPhysicalResolution);
  od.add_var(obj::kTotalRange, "Total measuring range in measuring units", DT::Unsigned32, Access::ReadWrite,
             s.default_total_range());
  od.add_var(obj::kPreset, "Preset value", DT::Unsigned32, Access::ReadWrite, 0u);
  od.add_var(obj::kPosition, "Position value", DT::Unsigned32, Access::ReadOnly, 0u, true).persistent = false;
  od.add_var(obj::kPositionHigh, "High precision position value", DT::Unsigned64, Access::ReadOnly, 0ull, true)
      .persistent = false;
  od.add_var(obj::kPresetHigh, "High precision preset value", DT::Unsigned64, Access::ReadWrite, 0ull);
  const std::pair<std::uint16_t, const char*> motion[] = {
      {obj::kSpeed, "Speed value"}, {obj::kAcceleration, "Acceleration value"}, {obj::kJerk, "Jerk value"}};
  for (const auto& [index, name] : motion) {
    od.add_object(index, name, ObjectCode::Array);
    od.add_entry(index, 0, "Highest sub-index supported", DT::Unsigned8, Access::ReadOnly, 1);
    od.add_entry(index, 1, std::string(name) + " channel 1", DT::Integer16, Access::ReadOnly, 0, true).persistent = false;
  }
  od.add_var(obj::kCyclicTimer, "Cyclic timer", DT::Unsigned16, Access::ReadWrite, 1);
  cia406::CamUnit::add_objects(od);
  cia406::WorkArea::add_objects(od, 0, 0x4000);
  od.entry(cia406::WorkArea::kState, 0)->pdo_mappable = true;  // "Map yes" on the record [M Tab. 6.9]
  od.add_var(obj::kOperatingStatus, "Operating status", DT::Unsigned16, Access::ReadOnly, 0x0004).persistent = false;
  od.add_var(0x6501, "Singleturn resolution", DT::Unsigned32, Access::Const, kPhysicalResolution);
  od.add_var(0x6502, "Number of distinguishable revolutions", DT::Unsigned16, Access::Const, s.multiturn ? 0xFFFF : 0x0001);
  od.add_var(obj::kAlarms, "Alarms", DT::Unsigned16, Access::ReadOnly, 0, true).persistent = false;
  od.add_var(0x6504, "Supported alarms", DT::Unsigned16, Access::Const, 0x0001);
  od.add_var(obj::kWarnings, "Warnings", DT::Unsigned16, Access::ReadOnly, 0, true).persistent = false;
  od.add_var(0x6506, "Supported warnings", DT::Unsigned16, Access::Const, 0x7001);
  od.add_var(0x6507, "Profile and software version", DT::Unsigned32, Access::Const, s.profile_software_version);
  od.add_var(0x6508, "Operating time", DT::Unsigned32, Access::Const, 0xFFFFFFFFu);
  od.add_var(obj::kOffset, "Offset value", DT::Integer32, Access::ReadOnly, 0).persistent = false;
  od.add_object(obj::kModuleIdentification, "Module identification", ObjectCode::Record);
  od.add_entry(obj::kModuleIdentification, 0, "Highest sub-index supported", DT::Unsigned8, Access::Const, 3);
  od.add_entry(obj::kModuleIdentification, 1, "Manufacturer offset value", DT::Integer32, Access::Const, 0);
  od.add_entry(obj::kModuleIdentification, 2, "Manufacturer minimum position value", DT::Integer32, Access::Const, 0);
  const std::uint64_t tmr = s.default_total_range() == 0 ? (1ull << 32) : s.default_total_range();
  od.add_entry(obj::kModuleIdentification, 3, "Manufacturer maximum position value", DT::Integer32, Access::Const,
               static_cast<std::int32_t>(static_cast<std::uint32_t>(tmr - 1)));
  od.add_object(0x650B, "Serial number", ObjectCode::Record);
  od.add_entry(0x650B, 0, "Highest sub-index supported", DT::Unsigned8, Access::Const, 1);
  od.add_entry(0x650B, 1, "Serial number", DT::Unsigned32, Access::Const, s.serial);
  od.add_var(0x6510, "Number of high precision revolutions", DT::Unsigned40, Access::Const, kPhysicalRevolutions);
}

}  // namespace

ObjectDictionary make_object_dictionary(const Settings& s) {
  ObjectDictionary od;
  add_communication_area(od, s);
  add_manufacturer_area(od, s);
  add_profile_area(od, s);
  return od;
}

}  // namespace wdga
