// The Wandfluh DSV valve electronics (amplifier and controller variants) as an emulated CANopen
// device with the CiA DSP 408 profile: one valve with one or two solenoids, control modes
// 0/1/3 (amplifier) or 0/4/6/7/9 (controller), objects and fixed PDOs following the control mode.
//
// Ports (SI units):
//   solenoid_a_current, solenoid_b_current  out  A    after ramp, dead band, dither; 0 when off
//                                                     (in FAULT: as error handling 2043h says)
//   actual_value                            in   SI   the measurand of the actual-value sensor
//                                                     (m, Pa, m/s, …); a transducer maps
//                                                     [sensor_min, sensor_max] onto the signal range
//                                                     of 2200h (0..10 V, 0..20 mA, 4..20 mA)
//   actual_cable_break                      in   0/1  the sensor wire is broken (signal 0)
//   enable_input                            in   0/1  hardware enable (≥ 0.5 = on)
//   supply_voltage                          in   V    below u_supply_min → EMCY 0x3412
//   temperature                             out  °C   device temperature (0x2002)
// `--set actual=…` sets actual_value.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "devices/device.h"
#include "devices/fault_table.h"
#include "devices/dsv/actual_value_input.h"
#include "devices/dsv/dsv_emcy_codes.h"
#include "devices/dsv/dsv_options.h"
#include "devices/dsv/dsv_parameters.h"
#include "devices/dsv/dsv_signal_chain.h"
#include "devices/dsv/dsv_stored_objects.h"
#include "devices/profiles/dsp408/channel_control.h"
#include "devices/canopen/entry_ref.h"
#include "devices/profiles/wandfluh/valve_application.h"

namespace dsv {

class DsvDevice final : public devices::Device, private wandfluh::ValveApplication {
 public:
  static std::unique_ptr<DsvDevice> create(const devices::DeviceOptions& options, std::string& error);

  canopen::Node& node() override { return *node_owner_; }
  sim::PortList ports() override;
  std::string set_input(std::string_view name, double value) override;
  std::vector<devices::FaultInfo> faults() const override;
  std::string inject_fault(std::string_view name, bool active) override;
  void power_on(sim::Time now) override;
  devices::ProfileStatus profile_status() override { return control_->profile_status(); }
  std::span<const devices::EmcyCode> emcy_codes() const override { return dsv::emcy_codes(); }
  canopen::ValueScaling value_scaling(std::uint16_t index, std::uint8_t sub) override;

  const DsvOptions& options() const { return options_; }
  dsp408::ChannelControl& control() { return *control_; }
  double solenoid_a() const { return solenoid_a_; }
  double solenoid_b() const { return solenoid_b_; }
  std::uint16_t active_bit_rate_kbit() { return address().active_bit_rate_kbit(); }
  /// Analog input 3 (V or mA) as the device sees it.
  double actual_signal() const { return input_->signal(); }

 private:
  DsvDevice(std::unique_ptr<canopen::Node> node, const DsvOptions& options);

  // wandfluh::ValveApplication / canopen::Application
  int channel_count() const override { return 1; }
  dsp408::ChannelControl& channel(int) override { return *control_; }
  void reset_model() override;
  void regenerate_pdos() override;
  void process(sim::Time now, sim::Duration dt) override;
  void on_rpdo(int pdo_number) override;

  void install_device_hooks();
  void detect_errors();
  static constexpr std::uint64_t kNoConditionsPassed = ~std::uint64_t{0};  // no bool array is all ones
  void restore_mapping_entry();
  void restore_alias_entry();

  DsvOptions options_;
  std::unique_ptr<canopen::Node> node_owner_;
  std::unique_ptr<dsp408::ChannelControl> control_;
  std::unique_ptr<DsvParameters> parameters_;
  std::unique_ptr<ActualValueInput> input_;
  std::unique_ptr<DsvSignalChain> chain_;
  std::unique_ptr<DsvStoredObjects> stored_;
  canopen::EntryRef<std::int64_t> temperature_out_;  // 0x2002, published every cycle

  int active_rpdo_ = 1, active_tpdo_ = 1;
  std::int8_t mapping_mode_ = 0;     ///< control mode the PDO set was generated for
  std::uint32_t tpdo2_internal_ = 0; ///< 1A01h:02 as the PDO service resolves it
  canopen::EntryRef<std::int64_t> tpdo2_entry2_;  ///< 1A01h:02
  std::optional<canopen::Bytes> alias_saved_;  ///< 230Eh:01's own (mode 4) value while it shows 250Eh:01
  bool open_a_detected_ = false, open_b_detected_ = false;  ///< an open circuit seen while driven

  // Ports and fault conditions.
  double solenoid_a_ = 0, solenoid_b_ = 0;
  double actual_value_ = 0, actual_cable_break_ = 0, enable_input_ = 1, supply_voltage_ = 24, temperature_ = 25;
  struct Faults {
    bool solenoid_a_open = false, solenoid_a_short = false, solenoid_b_open = false, solenoid_b_short = false;
    bool over_current = false, supply_low = false, general_error = false, memory_failure = false;
    bool resolution_update_failure = false, actual_cable_break = false, paso_control = false;
  } faults_;
  /// Name, EMCY code, what it does, and the condition it sets, per fault (the .cpp's table).
  static const devices::FaultEntry<DsvDevice> kFaults[];
  static bool has_solenoid_b(const DsvDevice& d) { return d.options_.solenoids == 2; }
  std::uint64_t conditions_passed_ = kNoConditionsPassed;  ///< detect_errors()' conditions as last passed on
};

}  // namespace dsv
