#include "devices/wdga/wdga_device.h"

#include "devices/canopen/lss_slave.h"
#include "devices/wdga/wdga_object_dictionary.h"
#include "devices/wdga/wdga_scaling.h"

namespace wdga {

namespace {

canopen::LssPolicy lss_policy() {
  canopen::LssPolicy p;
  p.in_operational = false;       // "only in Stopped or Pre-operational" [M §8.2.1]
  p.activate_bit_timing = false;  // not in the manual's service list
  p.fastscan = false;
  p.selective_response_mode = 0x01;  // 44h "Mode = 1 -> Konfig-Modus" [M Tab. 8.5]
  p.accept_unconfigured_node_id = false;
  p.store_error_code = 0x02;  // storage media access error
  p.store_error_specific = 0x00;
  p.bit_rates.set();  // 0..8 and 9 = automatic [M Tab. 8.9]
  p.automatic_bit_rate_index = 9;
  return p;
}

}  // namespace

canopen::NodePolicy make_policy(const Settings& s, const std::string& store_path) {
  canopen::NodePolicy p;
  p.sdo.pad_short_requests = true;
  p.sdo.size_mode = canopen::SdoPolicy::SizeMode::ExcessMustBeZero;  // e.g. 23h to U8 6301h:01 [M Tab. 8.68]
  p.sdo.segmented_exact_size = true;
  p.nmt.require_dlc_2 = false;
  p.nmt.boot_delay = sim::milliseconds(s.boot_delay_ms);
  p.error_control.guard_while_heartbeat = false;
  p.error_control.communication_error_register = 0x10;
  p.emcy.history_depth = 5;
  p.emcy.clear_history_on_reset_communication = false;  // kept in EEPROM [M Tab. 6.1]
  p.pdo.type254 = {.on_change = true, .after_rpdo = false, .on_timer = true};
  p.pdo.type255 = {.on_change = false, .after_rpdo = false, .on_timer = true};
  p.pdo.type255_off_without_timer = true;  // FFh + timer 0 = "PDO deaktiviert" [M Tab. 8.46]
  p.pdo.send_async_on_operational = s.initial_tpdo;
  p.pdo.change_baseline_on_operational = !s.initial_tpdo;
  p.pdo.tpdo_types.reset();
  for (int t = 0; t <= 240; ++t) p.pdo.tpdo_types.set(t);
  p.pdo.tpdo_types.set(254);
  p.pdo.tpdo_types.set(255);
  p.pdo.cobid_change_requires_invalid = false;
  p.pdo.mapping_requires_invalid = false;  // the manual's procedure does not invalidate the COB-ID
  p.pdo.dummy_mapping = false;
  p.pdo.width_conversion = s.tpdo3_literal_mapping;  // 6008h (64 bit) in a 32-bit slot
  p.store.freeze_node_relative = true;  // COB-IDs stop following the node-ID once stored [M §4.2]
  p.store.restore = canopen::StorePolicy::Restore::EraseStored;
  // Customer data (auto-saved) is not touched by restore [M §8.12.2].
  p.store.groups = {{1, {{0x1000, 0x211F}, {0x2121, 0xFFFF}}},
                    {2, {{0x1000, 0x1FFF}}},
                    {3, {{0x6000, 0x9FFF}}},
                    {4, {{0x2000, 0x211F}, {0x2121, 0x5FFF}}}};
  p.store.path = store_path;
  return p;
}

WdgaDevice::WdgaDevice(std::unique_ptr<Settings> settings, std::uint8_t node_id, const std::string& store_path)
    : settings_(std::move(settings)) {
  node_ = std::make_unique<canopen::Node>(settings_->multiturn ? "wdga-mt" : "wdga-st",
                                          make_object_dictionary(*settings_), make_policy(*settings_, store_path),
                                          node_id);
  node_->enable_lss(lss_policy());
  node_->lss()->set_default_bit_rate(settings_->factory_bit_rate);
  app_ = std::make_unique<Application>(*node_, *settings_);
  app_->bind();
  node_->set_application(app_.get());
  node_->set_transition_log(&transition_log_);
}

std::unique_ptr<WdgaDevice> WdgaDevice::create(const devices::DeviceOptions& options, std::string& error) {
  auto settings = std::make_unique<Settings>();
  if (error = parse_settings(options.variant, options.settings, *settings); !error.empty()) return nullptr;
  const std::uint8_t id = options.node_id == 0 ? settings->factory_node_id : options.node_id;
  if (id < 1 || id > 127) {
    error = "node-ID " + std::to_string(id) + ": the WDGA takes 1..127";
    return nullptr;
  }
  return std::unique_ptr<WdgaDevice>(new WdgaDevice(std::move(settings), id, options.store_path));
}

canopen::ValueScaling WdgaDevice::value_scaling(std::uint16_t index, std::uint8_t sub) {
  return wdga::value_scaling(settings_->multiturn, node_->od(), index, sub);
}

sim::PortList WdgaDevice::ports() {
  auto& shaft = app_->measurement().shaft();
  // A multiturn encoder counts turns; a singleturn one reads an angle within one turn.
  const sim::DisplayUnit angle_display = settings_->multiturn ? sim::display::turns : sim::display::degree;
  return {
      {"angle", sim::PortDirection::Input, "rad", &shaft.angle,
       "shaft angle, continuous and unbounded, clockwise positive looking at the shaft", angle_display},
      {"speed", sim::PortDirection::Input, "rad/s", &shaft.speed,
       "shaft speed (derivative of angle): advances the shaft between updates of angle", sim::display::rpm},
      {"temperature", sim::PortDirection::Input, "degC", &app_->temperature().input, "device temperature", sim::display::degree_celsius},
  };
}

// The fault table: what each fault switches in the application, and the EMCY code that follows.
const devices::FaultEntry<WdgaDevice> WdgaDevice::kFaults[] = {
    {"position_error", 0, "sensor fault: 6503h bit 0, 1002h bit 0/1, error register bit 0, 1029h:02",
     [](WdgaDevice& d, bool on) { d.app_->set_position_error(on); }},
    {"eeprom_error", 0x5000, "EEPROM defective: EMCY 5000h (at start-up and on store), saves abort 0x06060000",
     [](WdgaDevice& d, bool on) { d.app_->set_eeprom_failure(on); }},
    {"can_error_passive", 0x8120, "CAN controller error passive (CRC errors): EMCY 8120h while active",
     [](WdgaDevice& d, bool on) { d.app_->set_error_passive(on); }},
    {"can_bus_warning", 0x8100,
     "CAN controller bus warning: EMCY 8100h, and 8100h info 01h back to error-active (bus_warning_emcy)",
     [](WdgaDevice& d, bool on) { d.app_->set_bus_warning(on); }},
    {"can_overrun", 0x8110, "CAN receive overrun (event on activation): EMCY 8110h",
     [](WdgaDevice& d, bool on) {
       if (on) d.app_->receive_overrun();
     }},
    {"bus_off", 0x8140, "CAN bus-off (on activation): silent until power cycle or the 2103h auto-reset (EMCY 8140h)",
     [](WdgaDevice& d, bool on) {
       if (on) d.app_->go_bus_off();
     }},
    {"temperature_sensor_failure", 0x4200, "temperature read fails: EMCY 4200h info 40h, 6505h bit 14",
     [](WdgaDevice& d, bool on) { d.app_->temperature().read_failure = on; }},
    {"over_temperature", 0x4200, "the sensor reads 10 degC above the upper limit: EMCY 4200h info 10h",
     [](WdgaDevice& d, bool on) { d.app_->temperature().over_temperature = on; }},
};

std::vector<devices::FaultInfo> WdgaDevice::faults() const { return devices::fault_infos<WdgaDevice>(kFaults, *this); }

std::string WdgaDevice::inject_fault(std::string_view name, bool active) {
  if (!devices::apply_fault<WdgaDevice>(kFaults, *this, name, active)) return devices::Device::inject_fault(name, active);
  return {};
}

void WdgaDevice::power_off() {
  // The shaft keeps turning and EnDra keeps counting: nothing to remember but the angle input,
  // which the plant (or the speed input) goes on moving.
  node_->power_off();
}

void WdgaDevice::power_on(sim::Time now) { node_->power_on(now); }

Led WdgaDevice::led() const {
  const auto& n = *node_;
  if (!n.powered()) return Led::Off;
  if (n.bus_off()) return Led::Red;
  if (n.detecting_bit_rate()) return Led::RedGreenFlicker;
  auto* lss = const_cast<canopen::Node&>(n).lss();
  if (lss && lss->state() == canopen::LssSlave::State::Configuration) return Led::RedGreenFlicker;
  switch (n.nmt_state()) {
    case canopen::NmtState::Operational: return Led::Green;
    case canopen::NmtState::Stopped: return Led::GreenSingleFlash;
    case canopen::NmtState::PreOperational: return Led::GreenBlinking;
    default: return Led::RedGreenFlicker;
  }
}

}  // namespace wdga
