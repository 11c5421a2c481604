#include "devices/hlt1100/hlt1100_device.h"

#include "devices/canopen/lss_slave.h"
#include "devices/hlt1100/hlt1100_object_dictionary.h"
#include "devices/hlt1100/hlt1100_scaling.h"

namespace hlt1100 {

namespace {

std::uint8_t bit_rate_index(unsigned kbit) {
  for (std::uint8_t i = 0; i < 9; ++i)
    if (canopen::lss_bit_rate_kbit(i) == kbit) return i;
  return 3;
}

canopen::LssPolicy lss_policy(const Settings& s) {
  canopen::LssPolicy p;
  p.in_operational = s.lss_in_operational;
  p.fastscan = true;
  p.fastscan_only_unconfigured = !s.lss_fastscan_configured;
  p.transition4_requires_store = s.lss_store_before_waiting;
  p.store_answer_delay = sim::milliseconds(s.lss_store_delay_ms);
  p.bit_rates.reset();
  for (int i : {0, 1, 2, 3, 4, 6, 7}) p.bit_rates.set(i);  // index 5 is "reserved" [M §4.7.4.2]
  return p;
}

}  // namespace

canopen::NodePolicy make_policy(const Settings& s, const std::string& store_path) {
  canopen::NodePolicy p;
  p.sdo.pad_short_requests = true;
  p.sdo.length_mismatch = canopen::SdoAbort::TypeMismatch;
  p.nmt.boot_delay = sim::milliseconds(s.boot_delay_ms);
  p.error_control.life_guard_emcy = 0;  // the application decides (no EMCY by default)
  p.emcy.history_depth = 0;             // 0x1003 is the device's own (one entry + count)
  p.emcy.send_no_error = false;
  p.pdo.type254 = {.on_change = false, .after_rpdo = false, .on_timer = true};  // 6200h = 0 stops TPDO1 [M]
  p.pdo.send_async_on_operational = true;  // TPDO1 once after every Node Start [M §11]
  p.pdo.sync_requires_dlc0 = s.sync_dlc_strict;
  p.pdo.cobid_change_requires_invalid = true;
  p.pdo.mapping_requires_invalid = false;  // the COB-ID is read-only: it can never be invalidated
  p.store.wrong_signature = canopen::SdoAbort::General;  // "error class 8, code 0" [M]
  p.store.hardware_error = static_cast<canopen::SdoAbort>(s.eeprom_abort);
  p.store.busy_time = sim::milliseconds(s.save_delay_ms);
  p.store.restore_busy_time = sim::milliseconds(s.save_delay_ms);
  p.store.restore = canopen::StorePolicy::Restore::EraseStored;
  p.store.path = store_path;
  return p;
}

Hlt1100Device::Hlt1100Device(std::unique_ptr<Settings> settings, std::uint8_t node_id, const std::string& store_path)
    : settings_(std::move(settings)) {
  node_ = std::make_unique<canopen::Node>("hlt1100", make_object_dictionary(*settings_),
                                          make_policy(*settings_, store_path), node_id);
  node_->od().access_aborts().write_read_only = canopen::SdoAbort::UnsupportedAccess;
  node_->od().access_aborts().read_write_only = canopen::SdoAbort::UnsupportedAccess;
  node_->enable_lss(lss_policy(*settings_));
  node_->lss()->set_default_bit_rate(bit_rate_index(settings_->bit_rate_kbit));
  app_ = std::make_unique<Application>(*node_, *settings_);
  app_->bind();
  node_->set_application(app_.get());
  node_->set_transition_log(&transition_log_);
}

std::unique_ptr<Hlt1100Device> Hlt1100Device::create(const devices::DeviceOptions& options, std::string& error) {
  if (!options.variant.empty()) {
    error = "the HLT 1100 has no variants";
    return nullptr;
  }
  auto settings = std::make_unique<Settings>();
  if (error = parse_settings(options.settings, *settings); !error.empty()) return nullptr;
  const std::uint8_t id = options.node_id == 0 ? settings->node_id : options.node_id;
  if (!((id >= 1 && id <= 127) || id == canopen::Node::kUnconfigured)) {
    error = "node-ID " + std::to_string(id) + ": the HLT 1100 takes 1..127 or 255 (unconfigured)";
    return nullptr;
  }
  return std::unique_ptr<Hlt1100Device>(new Hlt1100Device(std::move(settings), id, options.store_path));
}

canopen::ValueScaling Hlt1100Device::value_scaling(std::uint16_t index, std::uint8_t sub) {
  return hlt1100::value_scaling(node_->od(), index, sub);
}

sim::PortList Hlt1100Device::ports() {
  auto& in = app_->inputs();
  return {
      {"position", sim::PortDirection::Input, "m", &in.position,
       "magnet position from the start of the measuring range (sensor head end)", sim::display::mm},
      {"position2", sim::PortDirection::Input, "m", &in.position2, "second magnet (counts with magnet_count = 2)", sim::display::mm},
      {"magnet_count", sim::PortDirection::Input, "1", &in.magnet_count, "magnets on the rod: 0, 1 or 2", sim::display::as_si},
  };
}

// The fault table: what each fault switches in the application, and the EMCY code that follows.
const devices::FaultEntry<Hlt1100Device> Hlt1100Device::kFaults[] = {
    {"magnet_lost", 0xFF00, "no magnet detected: position error (6503h bit 0), EMCY",
     [](Hlt1100Device& d, bool on) { d.app_->inputs().fault_magnet_lost = on; }},
    {"second_magnet", 0xFF00, "a second magnet inside the measuring range: position error, EMCY",
     [](Hlt1100Device& d, bool on) { d.app_->inputs().fault_second_magnet = on; }},
    {"out_of_range", 0xFF00, "the magnet reads outside the measuring range: position error, EMCY",
     [](Hlt1100Device& d, bool on) { d.app_->inputs().fault_out_of_range = on; }},
    {"can_error", 0x8100, "CAN-controller error (event on activation): EMCY 0x8100, Operational -> Pre-operational",
     [](Hlt1100Device& d, bool on) {
       if (on) d.app_->can_controller_error();
     }},
    {"eeprom_error", 0x5000, "EEPROM defective: save/restore abort, 6503h bit 12, EMCY 0x5000",
     [](Hlt1100Device& d, bool on) { d.app_->set_eeprom_failure(on); }},
};

std::vector<devices::FaultInfo> Hlt1100Device::faults() const {
  return devices::fault_infos<Hlt1100Device>(kFaults, *this);
}

std::string Hlt1100Device::inject_fault(std::string_view name, bool active) {
  if (!devices::apply_fault<Hlt1100Device>(kFaults, *this, name, active)) return devices::Device::inject_fault(name, active);
  return {};
}

}  // namespace hlt1100
