#include "devices/dsv/dsv_device.h"

#include <array>
#include <bit>
#include <cmath>

#include "devices/canopen/pdo_service.h"
#include "devices/canopen/store_restore.h"
#include "devices/dsv/control_mode.h"
#include "devices/dsv/dsv_object_dictionary.h"
#include "devices/dsv/dsv_objects.h"
#include "devices/dsv/dsv_scaling.h"

namespace dsv {

using canopen::CheckStage;
using canopen::OdEntry;
using canopen::Origin;
using canopen::PdoDirection;
using canopen::SdoAbort;

namespace {
// EMCY codes (§4.4.1) and the error-register bits this emulation sets with them.
constexpr std::uint16_t kGeneral = 0x1000, kOutputCurrent = 0x2300, kSupplyLow = 0x3412, kControlVoltageLow = 0x3422,
                        kEeprom = 0x5510, kSolenoidA = 0x5411, kSolenoidB = 0x5412;
constexpr std::uint8_t kRegGeneric = 0x01, kRegCurrent = 0x03, kRegVoltage = 0x05;
constexpr std::uint16_t kSetpoints[] = {0x6300, 0x6380, 0x6480, 0x6500, 0x6600, 0x6B00, 0x6B80};
constexpr std::uint16_t kMeasured[] = {0x6381, 0x6501, 0x6601, 0x63D0, 0x6550, 0x6650};
constexpr std::uint16_t kAlias = 0x230E, kAliasTarget = 0x250E;

std::uint32_t mapping_entry(std::uint16_t index, std::uint8_t sub, std::uint8_t bits) {
  return static_cast<std::uint32_t>(index) << 16 | static_cast<std::uint32_t>(sub) << 8 | bits;
}
}  // namespace

std::unique_ptr<DsvDevice> DsvDevice::create(const devices::DeviceOptions& options, std::string& error) {
  DsvOptions o;
  error = o.read(options);
  if (!error.empty()) return nullptr;
  if (!mode_supported(o.variant, o.delivery_control_mode)) {
    error = "setting 'control_mode': mode " + std::to_string(o.delivery_control_mode) + " is not available on this variant";
    return nullptr;
  }
  auto node = std::make_unique<canopen::Node>("dsv", build_object_dictionary(o),
                                              wandfluh::node_policy(o.common, options.store_path), o.node_id);
  return std::unique_ptr<DsvDevice>(new DsvDevice(std::move(node), o));
}

DsvDevice::DsvDevice(std::unique_ptr<canopen::Node> node, const DsvOptions& options)
    : ValveApplication(*node, options.common), options_(options), node_owner_(std::move(node)) {
  auto& n = *node_owner_;
  auto& pdo = n.policy().pdo;
  // "A TPDO with transmission type 255 is to be transmitted immediately after the receipt of a
  // corresponding RPDO" (§5.4.18): the active RPDO and TPDO need not have the same number, so
  // the device pairs them (on_rpdo).
  pdo.type255.after_rpdo = false;
  pdo.width_conversion = options_.m4_tpdo_six_bytes;
  pdo.parameters_preop_only = false;  // "can be changed in any way required by the user"
  pdo.dummy_mapping = false;          // the mapping is fixed
  pdo.pad_tpdo_to_8 = options_.pdo_padding;

  dsp408::ChannelObjects objects = dsp408::ChannelObjects::for_channel(1, false);
  objects.local_locks_modes = true;
  control_ = std::make_unique<dsp408::ChannelControl>(n.od(), objects);
  parameters_ = std::make_unique<DsvParameters>(n.od(), options_);
  input_ = std::make_unique<ActualValueInput>(*parameters_, options_);
  chain_ = std::make_unique<DsvSignalChain>(*parameters_, *input_, *control_, options_, n.od());
  control_->set_status_flags([this] { return chain_->status_flags(); }, true);  // see status_flags()
  control_->dsm().set_fault_hold(options_.fault_hold);
  control_->dsm().set_strict_reset_sources(options_.strict_fault_reset);
  set_restore_keeps_address(options_.restore_keeps_address);
  control_->dsm().set_listener([this](dsp408::DeviceState from, dsp408::DeviceState to) { chain_->on_state_change(from, to); });
  install_device_hooks();

  set_delivery_value(wandfluh::NodeAddress::kNodeAddress, 0, {options_.node_id});
  set_delivery_value(0x604F, 0, {static_cast<std::uint8_t>(options_.delivery_device_local)});
  set_delivery_value(0x6043, 0, {static_cast<std::uint8_t>(options_.delivery_control_mode)});
  set_delivery_value(0x2042, 0, {static_cast<std::uint8_t>(options_.delivery_mode_of_operation)});
  install();
  n.set_application(this);
  n.set_transition_log(&transition_log_);
}

void DsvDevice::install_device_hooks() {
  auto& od = node_owner_->od();
  // Objects of other control modes do not exist for the bus (§5.3: "depending on the Device
  // control mode only the appropriate objects are accessible"), from the moment 6043h changes.
  if (options_.objects_follow_mode) {
    od.set_visibility([this](std::uint16_t index) {
      const ModeSet m = modes_of(index);
      if (index == kAlias && options_.alias_230e_mode7 && parameters_->control_mode() == mode::kDsc) return true;
      return m == 0 || in(m, parameters_->control_mode());
    });
  }
  if (options_.alias_230e_mode7) {
    // the overview table names 230Eh for the I-window inside negative of mode 7. In mode 7
    // 230Eh:01 reads and writes 250Eh:01; its own (mode 4) value is kept aside meanwhile.
    auto aliased = [this] { return parameters_->control_mode() == mode::kDsc; };
    od.add_read_hook(kAlias, 1, [this, aliased](OdEntry& e, Origin) {
      if (!aliased()) return SdoAbort::None;
      if (!alias_saved_) alias_saved_ = e.value.bytes();
      e.value = node_owner_->od().entry(kAliasTarget, 1)->value;
      return SdoAbort::None;
    });
    od.add_check(
        kAlias, 1,
        [this, aliased](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
          if (!aliased()) return SdoAbort::None;
          if (!alias_saved_) alias_saved_ = e.value.bytes();
          return node_owner_->od().write(kAliasTarget, 1, data, origin);
        },
        CheckStage::Value);
    od.add_observer(kAlias, 1, [this](OdEntry&, Origin) { restore_alias_entry(); });
  }
  od.on_write<std::int8_t>(0x6043, 0, [this](std::int8_t m, Origin) {
    return mode_supported(options_.variant, m) ? SdoAbort::None : SdoAbort::ParameterIncompatible;
  });
  od.after_write<std::int8_t>(0x6043, 0, [this](std::int8_t m, Origin) { control_->dsm().set_active_allowed(m != 0); });
  // Under local (or PASO) control, set points and the mode of operation are refused.
  od.add_check(0x2042, 0, control_->local_lock(), CheckStage::State);
  od.add_check(0x2042, 0, control_->mode_lock(), CheckStage::State);
  for (std::uint16_t index : kSetpoints) od.add_check(index, 1, control_->local_lock(), CheckStage::State);
  if (options_.local_strict) {
    for (const auto& [index, object] : od.objects()) {
      if (index == 0x604F) continue;
      for (const auto& [sub, e] : object.entries) {
        if (e.writable() && index != 0x6040 && index != 0x2042) od.add_check(index, sub, control_->local_lock(), CheckStage::State);
      }
    }
  }
  auto refresh = [this](OdEntry&, Origin) {
    input_->sample(actual_value_, actual_cable_break_ >= 0.5 || faults_.actual_cable_break);
    chain_->publish_measurements();
    return SdoAbort::None;
  };
  for (std::uint16_t index : kMeasured) od.add_read_hook(index, 1, refresh);
  od.add_read_hook(0x2050, 1, [this](OdEntry& e, Origin) {
    canopen::EntryRef<std::int64_t>(e).set(input_->internal_resolution(parameters_->control_mode()));
    return SdoAbort::None;
  });
  temperature_out_ = canopen::EntryRef<std::int64_t>::optional(od, 0x2002, 0);
  od.add_read_hook(0x2002, 0, [this](OdEntry&, Origin) {
    temperature_out_.set_rounded(temperature_, -55, 150);  // the hook's entry
    return SdoAbort::None;
  });
  tpdo2_entry2_ = canopen::EntryRef<std::int64_t>(od, 0x1A01, 2);  // restored every cycle in mode 4
  // 1A01h:02 reads as printed for mode 4 (63'81'00'10h, A-05) while the PDO carries 6381h:01.
  od.add_read_hook(0x1A01, 2, [this](OdEntry& e, Origin) {
    if (mapping_mode_ == mode::kVprcClosed) canopen::EntryRef<std::int64_t>(e).set(mapping_entry(0x6381, 0, options_.m4_tpdo_six_bytes ? 32 : 16));
    return SdoAbort::None;
  });
  for (std::uint16_t comm : {0x1400, 0x1401, 0x1800, 0x1801}) {
    for (std::uint8_t sub : {std::uint8_t{1}, std::uint8_t{2}}) {
      if (od.entry(comm, sub)->writable()) {
        od.add_observer(comm, sub, [this](OdEntry&, Origin) {
          restore_mapping_entry();
          node_owner_->pdo().reload();
        });
      }
    }
  }
  // What 1010h/1011h do on a DSV beyond the node's store (dsv_stored_objects.h).
  stored_ = std::make_unique<DsvStoredObjects>(od, node_owner_->store(), *parameters_, errors(),
                                               [this] { restore_alias_entry(); });
}

void DsvDevice::power_on(sim::Time now) {
  stored_->power_on();
  node_owner_->power_on(now);
}

void DsvDevice::reset_model() {
  conditions_passed_ = kNoConditionsPassed;  // the errors were cleared: detect afresh
  chain_->reset();
  open_a_detected_ = open_b_detected_ = false;
  stored_->reset();
  temperature_ = options_.ambient_temperature;
  control_->dsm().set_active_allowed(parameters_->control_mode() != 0);
}

void DsvDevice::restore_mapping_entry() {
  if (mapping_mode_ == mode::kVprcClosed) tpdo2_entry2_.set(tpdo2_internal_);
}

void DsvDevice::restore_alias_entry() {
  if (!alias_saved_) return;
  node_owner_->od().entry(kAlias, 1)->value = *alias_saved_;
  alias_saved_.reset();
}

void DsvDevice::regenerate_pdos() {
  // The mapping follows 6043h/2042h at every reset (§5.4.21 note, §5.4.16/18).
  auto& od = node_owner_->od();
  const std::int8_t m = parameters_->control_mode();
  const PdoSet set = pdo_set(m, parameters_->mode_of_operation(), options_.m4_tpdo_six_bytes);
  auto write = [&od](std::uint16_t index, std::vector<std::uint32_t> entries, int capacity) {
    canopen::EntryRef<std::int64_t>(*od.entry(index, 0)).set(static_cast<std::int64_t>(entries.size()));
    for (int sub = 1; sub <= capacity; ++sub) {
      const auto i = static_cast<std::size_t>(sub - 1);
      canopen::EntryRef<std::int64_t>(*od.entry(index, static_cast<std::uint8_t>(sub))).set(i < entries.size() ? entries[i] : 0u);
    }
  };
  mapping_mode_ = m;
  auto tpdo2 = set.tpdo2;
  if (m == mode::kVprcClosed) {
    tpdo2[1] = mapping_entry(0x6381, 1, options_.m4_tpdo_six_bytes ? 32 : 16);  // what the PDO carries
    tpdo2_internal_ = tpdo2[1];
  }
  write(0x1600, set.rpdo1, 2);
  write(0x1601, set.rpdo2, 3);
  write(0x1A00, set.tpdo1, 1);
  write(0x1A01, tpdo2, 2);
  active_rpdo_ = set.active_rpdo;
  active_tpdo_ = set.active_tpdo;
  auto& pdo = node_owner_->pdo();
  pdo.set_active(PdoDirection::Receive, 1, active_rpdo_ == 1);
  pdo.set_active(PdoDirection::Receive, 2, active_rpdo_ == 2);
  pdo.set_active(PdoDirection::Transmit, 1, active_tpdo_ == 1);
  pdo.set_active(PdoDirection::Transmit, 2, active_tpdo_ == 2);
  pdo.reload();
}

void DsvDevice::on_rpdo(int pdo_number) {
  if (pdo_number != active_rpdo_) return;
  const auto type = node_owner_->od().get<std::uint8_t>(static_cast<std::uint16_t>(0x1800 + active_tpdo_ - 1), 2);
  if (type == 255) node_owner_->pdo().request_tpdo(active_tpdo_);
}

void DsvDevice::detect_errors() {
  auto& e = errors();
  // An open circuit shows only while the solenoid is driven; once seen it stays present until
  // the wire is whole again (a fault reset meanwhile is refused).
  open_a_detected_ = faults_.solenoid_a_open && (open_a_detected_ || chain_->commanded_a() > 0);
  open_b_detected_ = faults_.solenoid_b_open && (open_b_detected_ || chain_->commanded_b() > 0);
  const bool solenoid_a = faults_.solenoid_a_short || open_a_detected_;
  const bool solenoid_b = options_.solenoids == 2 && (faults_.solenoid_b_short || open_b_detected_);
  const bool over_current = faults_.over_current;
  const bool supply_low = faults_.supply_low || supply_voltage_ < options_.supply_min;
  const bool control_voltage_low = is_closed_loop(parameters_->control_mode()) && input_->cable_break();
  const bool general = faults_.general_error;
  const bool eeprom = faults_.resolution_update_failure;
  // Passing a condition as it was passed last time changes nothing (no edge): only a change, or
  // the first cycle after the errors were cleared (application reset), needs DeviceErrors.
  const auto now = std::bit_cast<std::uint64_t>(
      std::array<bool, 8>{solenoid_a, solenoid_b, over_current, supply_low, control_voltage_low, general, eeprom, false});
  if (now == conditions_passed_) return;
  conditions_passed_ = now;
  e.set_condition(kSolenoidA, kRegCurrent, solenoid_a);
  e.set_condition(kSolenoidB, kRegCurrent, solenoid_b);
  e.set_condition(kOutputCurrent, kRegCurrent, over_current);
  e.set_condition(kSupplyLow, kRegVoltage, supply_low);
  e.set_condition(kControlVoltageLow, kRegVoltage, control_voltage_low);
  e.set_condition(kGeneral, kRegGeneric, general);
  e.set_condition(kEeprom, kRegGeneric, eeprom);
}

void DsvDevice::process(sim::Time now, sim::Duration dt) {
  const bool enable = enable_input_ >= 0.5;
  if (control_->dsm().enable_input() != enable) control_->dsm().set_enable_input(enable);
  input_->sample(actual_value_, actual_cable_break_ >= 0.5 || faults_.actual_cable_break);
  detect_errors();
  chain_->set_driver_ok(!faults_.solenoid_a_open, !faults_.solenoid_b_open);
  const double seconds = sim::seconds(dt);
  chain_->process(now, seconds);
  solenoid_a_ = outputs_allowed() ? chain_->solenoid_a() : 0.0;
  solenoid_b_ = outputs_allowed() ? chain_->solenoid_b() : 0.0;
  const double target = options_.ambient_temperature + options_.thermal_gain * (solenoid_a_ * solenoid_a_ + solenoid_b_ * solenoid_b_);
  temperature_ += (target - temperature_) * std::min(1.0, seconds / 60.0);
  temperature_out_.set_rounded(temperature_, -55, 150);
  restore_mapping_entry();
  restore_alias_entry();
}

canopen::ValueScaling DsvDevice::value_scaling(std::uint16_t index, std::uint8_t sub) {
  return dsv::value_scaling(options_, index, sub);
}

sim::PortList DsvDevice::ports() {
  return {
      {"solenoid_a_current", sim::PortDirection::Output, "A", &solenoid_a_, "solenoid A current", sim::display::mA},
      {"solenoid_b_current", sim::PortDirection::Output, "A", &solenoid_b_, "solenoid B current", sim::display::mA},
      {"actual_value", sim::PortDirection::Input, "SI", &actual_value_,
       "measurand of the actual-value sensor; [sensor_min, sensor_max] spans the signal range of 2200h", sim::display::as_si},
      {"actual_cable_break", sim::PortDirection::Input, "1", &actual_cable_break_, "sensor wire broken (>= 0.5)", sim::display::on_off},
      {"enable_input", sim::PortDirection::Input, "1", &enable_input_, "hardware enable input (>= 0.5 = on)", sim::display::on_off},
      {"supply_voltage", sim::PortDirection::Input, "V", &supply_voltage_, "supply voltage", sim::display::volt},
      {"temperature", sim::PortDirection::Output, "degC", &temperature_, "device temperature (0x2002)", sim::display::degree_celsius},
  };
}

std::string DsvDevice::set_input(std::string_view name, double value) {
  if (name == "actual") name = "actual_value";
  return Device::set_input(name, value);
}

// The fault table: what each fault sets for detect_errors(), and the EMCY code that follows.
const devices::FaultEntry<DsvDevice> DsvDevice::kFaults[] = {
    {"solenoid_a_open", 0x5411, "solenoid A cable break: EMCY 0x5411 when A is driven, FAULT, no current on A",
     [](DsvDevice& d, bool on) { d.faults_.solenoid_a_open = on; }},
    {"solenoid_a_short", 0x5411, "solenoid A short circuit: EMCY 0x5411, FAULT",
     [](DsvDevice& d, bool on) { d.faults_.solenoid_a_short = on; }},
    {"solenoid_b_open", 0x5412, "solenoid B cable break: EMCY 0x5412 when B is driven, FAULT, no current on B",
     [](DsvDevice& d, bool on) { d.faults_.solenoid_b_open = on; }, &DsvDevice::has_solenoid_b},
    {"solenoid_b_short", 0x5412, "solenoid B short circuit: EMCY 0x5412, FAULT",
     [](DsvDevice& d, bool on) { d.faults_.solenoid_b_short = on; }, &DsvDevice::has_solenoid_b},
    {"over_current", 0x2300, "output current too high: EMCY 0x2300, FAULT",
     [](DsvDevice& d, bool on) { d.faults_.over_current = on; }},
    {"supply_low", 0x3412, "supply voltage too low: EMCY 0x3412, FAULT",
     [](DsvDevice& d, bool on) { d.faults_.supply_low = on; }},
    {"actual_cable_break", 0x3422, "actual-value wire broken (signal 0): EMCY 0x3422 with 2201h = 1 and 4..20 mA",
     [](DsvDevice& d, bool on) { d.faults_.actual_cable_break = on; }},
    {"general_error", 0x1000, "general internal error: EMCY 0x1000, FAULT",
     [](DsvDevice& d, bool on) { d.faults_.general_error = on; }},
    {"memory_failure", 0x5520, "non-volatile memory fails: 0x1010/0x1011 abort 0x06060000 and EMCY 0x5520",
     [](DsvDevice& d, bool on) {
       d.faults_.memory_failure = on;
       d.node_owner_->store().set_failing(on);
     }},
    {"resolution_update_failure", 0x5510, "profile data not updated after a resolution change: EMCY 0x5510",
     [](DsvDevice& d, bool on) { d.faults_.resolution_update_failure = on; }},
    {"paso_control", 0, "the PASO tool holds control: bus control refused (0x08000021)",
     [](DsvDevice& d, bool on) {
       d.faults_.paso_control = on;
       d.control_->set_paso_control(on);
     }},
};

std::vector<devices::FaultInfo> DsvDevice::faults() const { return devices::fault_infos<DsvDevice>(kFaults, *this); }

std::string DsvDevice::inject_fault(std::string_view name, bool active) {
  if (!devices::apply_fault<DsvDevice>(kFaults, *this, name, active)) return Device::inject_fault(name, active);
  return {};
}

}  // namespace dsv
