// The HLT 1100 as a vplant device: node + behaviour + ports to the plant + fault injection (its
// registry entry is product.cpp). Ports (SI): position, position2 (m, from the start of the measuring range
// at the sensor head), magnet_count (0, 1, 2). Faults: magnet_lost, second_magnet, out_of_range,
// can_error, eeprom_error.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "devices/device.h"
#include "devices/fault_table.h"
#include "devices/hlt1100/hlt1100_emcy_codes.h"
#include "devices/profiles/cia406/profile_status.h"
#include "devices/profiles/cia406/status_machines.h"
#include "devices/hlt1100/hlt1100_application.h"
#include "devices/hlt1100/hlt1100_settings.h"

namespace hlt1100 {

class Hlt1100Device final : public devices::Device {
 public:
  /// Builds the device; nullptr with `error` set on bad options.
  static std::unique_ptr<Hlt1100Device> create(const devices::DeviceOptions& options, std::string& error);

  canopen::Node& node() override { return *node_; }
  sim::PortList ports() override;
  std::vector<devices::FaultInfo> faults() const override;
  std::string inject_fault(std::string_view name, bool active) override;
  devices::ProfileStatus profile_status() override { return cia406::profile_status(node_->od()); }
  std::vector<devices::MachineView> machines() override {
    auto out = devices::Device::machines();
    cia406::append_status_machines(*node_, Application::status_bits(), out);
    return out;
  }
  std::span<const devices::EmcyCode> emcy_codes() const override { return hlt1100::emcy_codes(); }
  canopen::ValueScaling value_scaling(std::uint16_t index, std::uint8_t sub) override;

  Application& application() { return *app_; }
  const Settings& settings() const { return *settings_; }

 private:
  explicit Hlt1100Device(std::unique_ptr<Settings> settings, std::uint8_t node_id, const std::string& store_path);

  std::unique_ptr<Settings> settings_;  // stable address: the node's hooks refer to it
  std::unique_ptr<canopen::Node> node_;
  std::unique_ptr<Application> app_;
  /// Name, EMCY code, what it does, and the action, per fault (the .cpp's table).
  static const devices::FaultEntry<Hlt1100Device> kFaults[];
};

/// The node policy the manual implies (abort codes, silent save, LSS services, PDO triggers).
canopen::NodePolicy make_policy(const Settings& s, const std::string& store_path);

}  // namespace hlt1100
