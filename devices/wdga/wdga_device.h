// The WDGA as a vplant device, variants "multiturn" (default) and "singleturn". Ports (SI):
// angle (rad, continuous and unbounded, clockwise positive), speed (rad/s, its derivative),
// temperature (°C). Faults: position_error, eeprom_error, can_error_passive, can_bus_warning,
// can_overrun (an event), bus_off, temperature_sensor_failure, over_temperature. A power cycle
// keeps every turn the shaft made (EnDra).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "devices/device.h"
#include "devices/fault_table.h"
#include "devices/profiles/cia406/profile_status.h"
#include "devices/profiles/cia406/status_machines.h"
#include "devices/wdga/wdga_application.h"
#include "devices/wdga/wdga_emcy_codes.h"
#include "devices/wdga/wdga_settings.h"

namespace wdga {

/// The status LED (not visible on the bus; CiA 303-3 patterns, manual §3.3).
enum class Led { Off, RedGreenFlicker, GreenBlinking, GreenSingleFlash, Green, Red };

class WdgaDevice final : public devices::Device {
 public:
  static std::unique_ptr<WdgaDevice> create(const devices::DeviceOptions& options, std::string& error);

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
  std::span<const devices::EmcyCode> emcy_codes() const override { return wdga::emcy_codes(); }
  canopen::ValueScaling value_scaling(std::uint16_t index, std::uint8_t sub) override;
  void power_off() override;
  void power_on(sim::Time now) override;

  Application& application() { return *app_; }
  const Settings& settings() const { return *settings_; }
  Led led() const;

 private:
  WdgaDevice(std::unique_ptr<Settings> settings, std::uint8_t node_id, const std::string& store_path);

  std::unique_ptr<Settings> settings_;
  std::unique_ptr<canopen::Node> node_;
  std::unique_ptr<Application> app_;
  /// Name, EMCY code, what it does, and the action, per fault (the .cpp's table).
  static const devices::FaultEntry<WdgaDevice> kFaults[];
};

canopen::NodePolicy make_policy(const Settings& s, const std::string& store_path);

}  // namespace wdga
