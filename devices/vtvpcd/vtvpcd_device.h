// The emulated VT-VPCD pump controller card: a CANopen node (the manual's communication and its
// 116 manufacturer objects) plus the card's control loop, fault handling and discrete I/O, with
// ports to the plant. It is the node's Application: it reacts to resets, NMT and communication
// errors and runs one control cycle per control period in process().
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "devices/canopen/entry_ref.h"
#include "devices/device.h"
#include "devices/vtvpcd/builtin_pump_model.h"
#include "devices/vtvpcd/card_parameters.h"
#include "devices/vtvpcd/command_sources.h"
#include "devices/vtvpcd/discrete_outputs.h"
#include "devices/vtvpcd/fault_monitor.h"
#include "devices/vtvpcd/loop_monitor.h"
#include "devices/vtvpcd/parameter_conversion.h"
#include "devices/vtvpcd/pump_controller.h"
#include "devices/vtvpcd/settings.h"
#include "devices/vtvpcd/vtvpcd_emcy_codes.h"

namespace vtvpcd {

class VtvpcdDevice final : public devices::Device, public canopen::Application {
 public:
  static constexpr std::uint8_t kFactoryNodeId = 63;

  /// Builds the card; nullptr with `error` on bad options.
  static std::unique_ptr<VtvpcdDevice> create(const devices::DeviceOptions& options, std::string& error);
  ~VtvpcdDevice() override;

  // devices::Device
  canopen::Node& node() override { return *node_; }
  sim::PortList ports() override;
  std::vector<devices::FaultInfo> faults() const override;
  std::string inject_fault(std::string_view name, bool active) override;
  /// Run state (fault stop / not enabled / running) and the active faults.
  devices::ProfileStatus profile_status() override;
  std::span<const devices::EmcyCode> emcy_codes() const override { return vtvpcd::emcy_codes(); }
  /// Unpowered, the pilot valve is de-energised.
  void power_off() override;
  /// The card's run state (manual §3.1: "internal operational states ... fault states, waiting
  /// for enable"): OFF, INITIALISING (until the boot-up message), NOT_ENABLED, RUNNING, FAULT_STOP.
  std::string_view run_state() const;

  // canopen::Application
  void on_reset_application() override;
  void on_power_off() override;
  void on_reset_communication() override;
  void after_reset_communication() override;
  void on_nmt_command(canopen::NmtCommand command) override;
  void on_nmt_state_changed(canopen::NmtState from, canopen::NmtState to) override;
  bool on_communication_error(canopen::CommError error) override;
  void on_communication_recovered(canopen::CommError error) override;
  void process(sim::Time now, sim::Duration dt) override;

  // Side interface (tests, scenarios).
  const Settings& settings() const { return settings_; }
  const ControlOutputs& control() const { return controller_.outputs(); }
  const FaultMonitor& fault_monitor() const { return *faults_; }
  BuiltinPumpModel* builtin_plant() { return builtin_ ? &*builtin_ : nullptr; }
  /// Discrete Inputs word as the card reads it from the input ports.
  std::uint16_t discrete_inputs() const;

 private:
  explicit VtvpcdDevice(Settings settings);

  void install_device_hooks();
  void control_cycle(double dt_s);
  void publish(const SetSelection& sel, double alpha_meas, double p_a, double p_b, std::uint16_t di_word);
  void apply_plant_to_inputs();
  /// Records a change of run_state() in the transition log (machine "vtvpcd").
  void note_run_state(devices::TransitionCause cause, std::uint32_t value, std::string_view detail);
  /// After a control cycle: a change of run state with its cause (a stop fault, the enable input).
  void note_cycle_state(bool enable_rising);

  Settings settings_;
  std::unique_ptr<canopen::Node> node_;
  std::unique_ptr<CardParameters> params_;
  CommandSelector command_selector_;
  DiscreteOutputs discrete_outputs_;
  PumpController controller_;
  std::unique_ptr<FaultMonitor> faults_;
  LoopMonitor loop_monitor_;
  std::optional<BuiltinPumpModel> builtin_;

  // Ports (plant side, SI / normalised).
  double pilot_command_ = 0;          ///< out: pilot valve command, -1..1 (= spool command / 100 %)
  double swivel_angle_ = 0;           ///< in: LVDT swivel angle, -1..1
  double pressure_a_ = 0;             ///< in: Pa
  double pressure_b_ = 0;             ///< in: Pa
  double pilot_spool_position_ = 0;   ///< in: pilot spool position, -1..1 (act. valve)
  std::array<double, 6> di_{};        ///< in: DI1..DI6, 0/1
  double enable_ = 1;                 ///< in: Enable, 0/1
  double analog_angle_b14_b16_ = 0;   ///< in: -1..1
  double analog_angle_b2_b4_ = 0;     ///< in: -1..1
  double analog_pressure_b18_b20_ = 0;  ///< in: Pa
  double analog_power_f8_f10_ = 0;    ///< in: 0..1

  // Run state.
  /// A read-only INTEGER32 readout the cycle converts from an EU value: its entry, the scale, and
  /// the EU value it was last converted from (the conversion is skipped while that does not
  /// change; the bytes are written every cycle all the same: a reset may have put the start value
  /// there meanwhile).
  struct EuReadout {
    canopen::EntryRef<std::int32_t> entry;
    Scale scale;
    double last_eu = std::numeric_limits<double>::quiet_NaN();
    std::int32_t last_raw = 0;
    void put(double eu) {
      if (!(eu == last_eu)) {  // NaN never compares equal: converted anew (to 0)
        last_eu = eu;
        last_raw = static_cast<std::int32_t>(to_raw(eu, scale));  // saturated to the INTEGER32 range
      }
      entry.set(last_raw);
    }
  };
  std::array<EuReadout, 14> eu_out_{};  ///< by EU readout (EuSlot)
  /// The raw readouts: the binary set's table entries (INTEGER32) and three UNSIGNED16 words.
  canopen::EntryRef<std::int32_t> angle_binary_out_, press_binary_out_, power_binary_out_;
  canopen::EntryRef<std::uint16_t> bus_status_out_, discrete_inputs_out_, discrete_outputs_out_;
  sim::Duration cycle_debt_{0};
  bool previous_enable_ = true;
  bool initialising_ = false;                ///< from power-on / NMT 81h until the boot-up message
  std::string_view recorded_state_ = "OFF";  ///< run_state() as last recorded
  bool lifeguard_timeout_ = false;
  bool heartbeat_timeout_ = false;
  bool watchdog_pending_ = false;
  bool nmt_reset_pending_ = false;
  std::uint8_t requested_node_id_ = 0;
  std::vector<std::pair<canopen::OdEntry*, canopen::Bytes>> kept_communication_;  ///< nmt_82 = can_controller
};

}  // namespace vtvpcd
