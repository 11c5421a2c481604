// The WDGA's behaviour on top of the CiA 301 stack: the measurement cycle, node-ID and bit rate
// as objects (2100h/2101h, the LSS cells), the vendor's parameter rules (Pre-operational-only
// PDO parameters, scaling, preset, CAM and limits), NMT start-up (1F80h), configuration stamp
// (1020h), CAN-controller faults with bus-off auto-reset (2103h), EEPROM and position faults.
#pragma once

#include <cstdint>

#include "devices/canopen/application.h"
#include "devices/canopen/node.h"
#include "devices/wdga/diagnostics.h"
#include "devices/wdga/measurement.h"
#include "devices/wdga/temperature_monitor.h"
#include "devices/wdga/wdga_settings.h"
#include "devices/profiles/cia406/status_machines.h"

namespace wdga {

class Application final : public canopen::Application {
 public:
  Application(canopen::Node& node, const Settings& settings);
  void bind();

  Measurement& measurement() { return measurement_; }
  TemperatureMonitor& temperature() { return temperature_; }
  Diagnostics& diagnostics() { return diagnostics_; }

  // Fault injection.
  void set_position_error(bool active);
  void set_eeprom_failure(bool failing);
  void set_error_passive(bool active);
  /// Bus warning (error counters above 96): EMCY 8100h, and 8100h "back to error-active" when
  /// it ends (A-32; setting bus_warning_emcy).
  void set_bus_warning(bool active);
  void receive_overrun();
  void go_bus_off();
  /// Back from bus-off (its own or one made on the wire): EMCY 8140h, then 1029h:01.
  void bus_off_recovered();

  // canopen::Application
  void on_reset_application() override;
  void on_reset_communication() override;
  void after_reset_communication() override;
  void on_nmt_state_changed(canopen::NmtState from, canopen::NmtState to) override;
  bool on_communication_error(canopen::CommError error) override;
  /// The bus's fault confinement: the same EMCY 8120h as the can_error_passive fault.
  bool on_error_passive(bool passive) override {
    set_error_passive(passive);
    return true;
  }
  void process(sim::Time now, sim::Duration dt) override;
  /// The CiA 406 bits this product's manual names (machines cia406.status/alarms/warnings).
  static const cia406::StatusBitNames& status_bits();

 private:
  void bind_node_objects();
  void bind_measurement_objects();
  void bind_pdo_rules();
  void bind_storage();
  void bind_configuration_stamp();
  void apply_cyclic_timer();
  void eeprom_error(std::uint8_t info2);
  void stage_offset();
  /// 1011h sub `sub` succeeded with restore_at_once: the group's values in use become the
  /// defaults now instead of at the next reset.
  void apply_restored_defaults(std::uint8_t sub);

  canopen::Node& node_;
  const Settings& settings_;
  Diagnostics diagnostics_;
  Measurement measurement_;
  TemperatureMonitor temperature_;
  cia406::StatusRecorder status_recorder_{node_, status_bits()};
  sim::Time next_cycle_{};
  bool position_error_ = false;
  bool eeprom_failing_ = false;
  bool eeprom_boot_check_ = false;
  bool bus_off_ = false;
  bool bus_warning_ = false;
  bool bus_off_recovers_ = false;
  sim::Time bus_off_until_{};
};

}  // namespace wdga
