#include "devices/md2/md2_device.h"

#include <array>
#include <bit>
#include <cmath>

#include "devices/canopen/pdo_service.h"
#include "devices/canopen/store_restore.h"
#include "devices/md2/md2_object_dictionary.h"

namespace md2 {

namespace {
// EMCY codes (§4.4.1) with the error-register bits this emulation sets (generic + class).
constexpr std::uint16_t kGeneral = 0x1000, kSolenoid1 = 0x2311, kSolenoid2 = 0x2312, kSupplyLow = 0x3412,
                        kControlVoltageLow = 0x3422;
constexpr std::uint8_t kRegGeneric = 0x01, kRegCurrent = 0x03, kRegVoltage = 0x05;
}  // namespace

std::unique_ptr<Md2Device> Md2Device::create(const devices::DeviceOptions& options, std::string& error) {
  Md2Options o;
  error = o.read(options);
  if (!error.empty()) return nullptr;
  if (!mode_supported(o.variant, o.delivery_control_mode)) {
    error = "setting 'control_mode': mode " + std::to_string(o.delivery_control_mode) + " is not available on this variant";
    return nullptr;
  }
  auto node = std::make_unique<canopen::Node>("md2", build_object_dictionary(o),
                                              wandfluh::node_policy(o.common, options.store_path), o.node_id);
  return std::unique_ptr<Md2Device>(new Md2Device(std::move(node), o));
}

Md2Device::Md2Device(std::unique_ptr<canopen::Node> node, const Md2Options& options)
    : ValveApplication(*node, options.common), options_(options), node_owner_(std::move(node)) {
  auto& n = *node_owner_;
  auto& policy = n.policy().pdo;
  // Dynamic mapping (§5.4.16): PDO parameters only in Pre-operational (§2.5), mapping only while
  // the PDO is disabled and sub 0 is 0; COB-IDs may change at any time there.
  policy.parameters_preop_only = options_.pdo_params_preop_only;
  policy.type255.on_change = options_.tpdo255_on_change;  // digest §7 #32: option for change-driven sending
  policy.cobid_change_requires_invalid = false;
  policy.mapping_requires_invalid = true;
  policy.mapping_entry_requires_sub0_zero = true;
  policy.dummy_mapping = true;
  policy.mapping_length_mismatch = canopen::SdoAbort::ParameterIncompatible;

  for (int c = 1; c <= options_.channels; ++c) {
    channels_.push_back(std::make_unique<Md2Channel>(n.od(), options_, c));
  }
  temperature_out_ = canopen::EntryRef<std::int64_t>::optional(n.od(), 0x2002, 0);
  n.od().add_read_hook(0x2002, 0, [this](canopen::OdEntry&, canopen::Origin) {
    temperature_out_.set_rounded(temperature_, -55, 150);  // the hook's entry
    return canopen::SdoAbort::None;
  });
  // Delivery state (§5.8): node address from the command line, the pre-configured control mode.
  set_delivery_value(wandfluh::NodeAddress::kNodeAddress, 0, {options_.node_id});
  for (int c = 1; c <= options_.channels; ++c) {
    set_delivery_value(ChannelIndices::of(c).control_mode(), 0,
                       {static_cast<std::uint8_t>(options_.delivery_control_mode)});
  }
  install();
  n.set_application(this);
  n.set_transition_log(&transition_log_);
}

void Md2Device::reset_model() {
  conditions_passed_ = kNoConditionsPassed;  // the errors were cleared: detect afresh
  for (auto& ch : channels_) ch->reset_model();
  temperature_ = options_.ambient_temperature;
}

void Md2Device::regenerate_pdos() {
  // "If the control mode has changed, the PDOs must be mapped new. This will be done
  // automatically after a reset" (§5.4.26): PDO n follows channel n's control mode.
  auto& od = node_owner_->od();
  for (int n = 1; n <= 4 && n <= options_.channels; ++n) {
    const std::int8_t m = channels_[static_cast<std::size_t>(n - 1)]->control_mode();
    const auto rpdo = default_rpdo_mapping(options_, n, m), tpdo = default_tpdo_mapping(options_, n, m);
    auto write = [&od](std::uint16_t index, const std::vector<std::uint32_t>& mapping) {
      od.set<std::uint8_t>(index, 0, static_cast<std::uint8_t>(mapping.size()));
      for (std::uint8_t sub = 1; sub <= 4; ++sub) {
        od.set<std::uint32_t>(index, sub, sub <= mapping.size() ? mapping[sub - 1u] : 0x00070020u);
      }
    };
    write(static_cast<std::uint16_t>(0x1600 + n - 1), rpdo);
    write(static_cast<std::uint16_t>(0x1A00 + n - 1), tpdo);
  }
  node_owner_->pdo().reload();
}

void Md2Device::detect_errors() {
  const bool solenoid_1 = faults_.solenoid_a_open || faults_.solenoid_a_short;
  const bool solenoid_2 = options_.solenoids == 2 && (faults_.solenoid_b_open || faults_.solenoid_b_short);
  const bool supply_low = faults_.supply_low || supply_voltage_ < options_.supply_min;
  const bool control_voltage_low = faults_.analog_signal_lost && channels_[0]->uses_analog_input();
  const bool general = faults_.general_error;
  // Passing a condition as it was passed last time changes nothing (no edge): only a change, or
  // the first cycle after the errors were cleared (application reset), needs DeviceErrors.
  const auto now = std::bit_cast<std::uint64_t>(
      std::array<bool, 8>{solenoid_1, solenoid_2, supply_low, control_voltage_low, general, false, false, false});
  if (now == conditions_passed_) return;
  conditions_passed_ = now;
  auto& e = errors();
  e.set_condition(kSolenoid1, kRegCurrent, solenoid_1);
  e.set_condition(kSolenoid2, kRegCurrent, solenoid_2);
  e.set_condition(kSupplyLow, kRegVoltage, supply_low);
  e.set_condition(kControlVoltageLow, kRegVoltage, control_voltage_low);
  e.set_condition(kGeneral, kRegGeneric, general);
}

void Md2Device::process(sim::Time now, sim::Duration dt) {
  const bool enable = enable_input_ >= 0.5;
  for (auto& ch : channels_) {
    if (ch->control().dsm().enable_input() != enable) ch->control().dsm().set_enable_input(enable);
  }
  detect_errors();
  channels_[0]->set_driver_ok(!faults_.solenoid_a_open, !faults_.solenoid_b_open);
  const double seconds = sim::seconds(dt);
  for (auto& ch : channels_) {
    ch->process(now, seconds);
    if (!outputs_allowed()) ch->solenoid_a = ch->solenoid_b = 0;
  }
  // Temperature: first-order approach (τ = 60 s) to ambient + k·(I_A² + I_B²) of the drivers.
  const auto& ch1 = *channels_[0];
  const double target = options_.ambient_temperature +
                        options_.thermal_gain * (ch1.solenoid_a * ch1.solenoid_a + ch1.solenoid_b * ch1.solenoid_b);
  temperature_ += (target - temperature_) * std::min(1.0, seconds / 60.0);
  temperature_out_.set_rounded(temperature_, -55, 150);
}

sim::PortList Md2Device::ports() {
  sim::PortList p;
  for (auto& ch : channels_) {
    const std::string c = "ch" + std::to_string(ch->number()) + ".";
    p.push_back({c + "solenoid_a_current", sim::PortDirection::Output, "A", &ch->solenoid_a, "solenoid A (driver 1) current", sim::display::mA});
    p.push_back({c + "solenoid_b_current", sim::PortDirection::Output, "A", &ch->solenoid_b, "solenoid B (driver 2) current", sim::display::mA});
    p.push_back({c + "local_command", sim::PortDirection::Input, "1", &ch->local_command,
                 "local set point (device mode 2), fraction of full scale", sim::display::percent});
    if (options_.variant == Variant::Controller && ch->number() <= 4) {
      p.push_back({c + "actual_value", sim::PortDirection::Input, "SI", &ch->actual_value,
                   "local feedback (actual value mode 2): Pa in modes 4/-5, else the unit's SI quantity", sim::display::as_si});
    }
  }
  p.push_back({"enable_input", sim::PortDirection::Input, "1", &enable_input_, "hardware enable input (>= 0.5 = on)", sim::display::on_off});
  p.push_back({"supply_voltage", sim::PortDirection::Input, "V", &supply_voltage_, "supply voltage", sim::display::volt});
  p.push_back({"temperature", sim::PortDirection::Output, "degC", &temperature_, "device temperature (0x2002)", sim::display::degree_celsius});
  return p;
}

std::string Md2Device::set_input(std::string_view name, double value) {
  if (name == "actual") name = "ch1.actual_value";
  return Device::set_input(name, value);
}

// The fault table: what each fault sets for detect_errors(), and the EMCY code that follows.
const devices::FaultEntry<Md2Device> Md2Device::kFaults[] = {
    {"solenoid_a_open", 0x2311, "solenoid driver 1 cable break: EMCY 0x2311, FAULT, no current on A",
     [](Md2Device& d, bool on) { d.faults_.solenoid_a_open = on; }},
    {"solenoid_a_short", 0x2311, "solenoid driver 1 short circuit: EMCY 0x2311, FAULT",
     [](Md2Device& d, bool on) { d.faults_.solenoid_a_short = on; }},
    {"solenoid_b_open", 0x2312, "solenoid driver 2 cable break: EMCY 0x2312, FAULT, no current on B",
     [](Md2Device& d, bool on) { d.faults_.solenoid_b_open = on; }, &Md2Device::has_solenoid_b},
    {"solenoid_b_short", 0x2312, "solenoid driver 2 short circuit: EMCY 0x2312, FAULT",
     [](Md2Device& d, bool on) { d.faults_.solenoid_b_short = on; }, &Md2Device::has_solenoid_b},
    {"supply_low", 0x3412, "supply voltage too low: EMCY 0x3412, FAULT",
     [](Md2Device& d, bool on) { d.faults_.supply_low = on; }},
    {"analog_signal_lost", 0x3422,
     "analog command/feedback below minimum or cable break: EMCY 0x3422 while the analog input is in use "
     "(0x6042 = 2 or 0x2200 = 2)",
     [](Md2Device& d, bool on) { d.faults_.analog_signal_lost = on; }},
    {"general_error", 0x1000, "general internal error: EMCY 0x1000, FAULT",
     [](Md2Device& d, bool on) { d.faults_.general_error = on; }},
    {"storage_failure", 0, "non-volatile memory fails: 0x1010/0x1011 abort with 0x06060000",
     [](Md2Device& d, bool on) {
       d.faults_.storage_failure = on;
       d.node_owner_->store().set_failing(on);
     }},
    {"paso_control", 0, "the PASO tool holds control: bus control words refused (0x08000021)",
     [](Md2Device& d, bool on) {
       d.faults_.paso_control = on;
       for (auto& ch : d.channels_) ch->control().set_paso_control(on);
     }},
};

std::vector<devices::FaultInfo> Md2Device::faults() const { return devices::fault_infos<Md2Device>(kFaults, *this); }

std::string Md2Device::inject_fault(std::string_view name, bool active) {
  if (!devices::apply_fault<Md2Device>(kFaults, *this, name, active)) return Device::inject_fault(name, active);
  return {};
}

}  // namespace md2
