// The HLT 1100 as a vplant device: node + behaviour + ports to the plant + fault injection, and
// its registry entry. Ports (SI): position, position2 (m, from the start of the measuring range
// at the sensor head), magnet_count (0, 1, 2). Faults: magnet_lost, second_magnet, out_of_range,
// can_error, eeprom_error.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "devices/device.h"
#include "devices/profiles/cia406/profile_status.h"
#include "devices/profiles/cia406/status_machines.h"
#include "devices/hlt1100/hlt1100_application.h"
#include "devices/hlt1100/hlt1100_settings.h"
#include "devices/registry.h"

namespace hlt1100 {

class Device final : public devices::Device {
 public:
  /// Builds the device; nullptr with `error` set on bad options.
  static std::unique_ptr<Device> make(const devices::DeviceOptions& options, std::string& error);

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

  Application& application() { return *app_; }
  const Settings& settings() const { return *settings_; }

 private:
  explicit Device(std::unique_ptr<Settings> settings, std::uint8_t node_id, const std::string& store_path);

  std::unique_ptr<Settings> settings_;  // stable address: the node's hooks refer to it
  std::unique_ptr<canopen::Node> node_;
  std::unique_ptr<Application> app_;
};

/// The node policy the manual implies (abort codes, silent save, LSS services, PDO triggers).
canopen::NodePolicy make_policy(const Settings& s, const std::string& store_path);
/// The EDS of the device with its default settings (generated from the emulated dictionary).
std::string eds();
/// The registry entry "hlt1100".
devices::Product product();

}  // namespace hlt1100
