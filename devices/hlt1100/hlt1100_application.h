// The HLT 1100's behaviour on top of the CiA 301 stack: the 1 ms measurement cycle (magnet →
// steps → counting direction → offsets → 6020h:01, speed 6030h:01), the preset, the cyclic timer
// shared by 6200h and 1800h:05, NMT autostart (1F80h), the alarm/EMCY handling and the reaction
// to communication errors (Operational → Pre-operational).
#pragma once

#include <cstdint>

#include "devices/canopen/application.h"
#include "devices/canopen/entry_ref.h"
#include "devices/canopen/node.h"
#include "devices/hlt1100/diagnostics.h"
#include "devices/hlt1100/hlt1100_settings.h"
#include "devices/hlt1100/magnet_sensor.h"
#include "devices/profiles/cia406/linear_position.h"
#include "devices/profiles/cia406/motion_estimator.h"
#include "devices/profiles/cia406/scripted_input.h"
#include "devices/profiles/cia406/status_machines.h"

namespace hlt1100 {

class Application final : public canopen::Application {
 public:
  Application(canopen::Node& node, const Settings& settings);
  /// Installs the object-dictionary hooks (once, after the node is built).
  void bind();

  MagnetInputs& inputs() { return inputs_; }
  Diagnostics& diagnostics() { return diagnostics_; }
  /// A CAN-controller error (fault injection): EMCY 0x8100, Operational → Pre-operational.
  void can_controller_error();
  /// The non-volatile memory fails (fault injection): saves abort, 6503h bit 12.
  void set_eeprom_failure(bool failing);

  // canopen::Application
  void on_reset_application() override;
  void after_reset_communication() override;
  void on_nmt_command(canopen::NmtCommand command) override;
  void on_nmt_state_changed(canopen::NmtState from, canopen::NmtState to) override;
  bool on_communication_error(canopen::CommError error) override;
  void process(sim::Time now, sim::Duration dt) override;
  /// The CiA 406 bits this product's manual names (machines cia406.status/alarms/warnings).
  static const cia406::StatusBitNames& status_bits();

 private:
  void sample(sim::Time now, bool evaluate_alarms);
  void load_parameters();
  void sync_cyclic_timer(std::uint16_t ms, std::uint16_t written_index);
  bool autostart() const;
  canopen::SdoAbort parameter_out_of_range(const canopen::OdEntry& entry, std::span<std::uint8_t> data);

  canopen::Node& node_;
  const Settings& settings_;
  Diagnostics diagnostics_;
  MagnetInputs inputs_;
  cia406::ScriptedInput signal_;
  double signal_base_ = 0.0;  // the position input a scripted signal moves around
  cia406::LinearConfig config_;
  cia406::MotionEstimator motion_;
  std::int64_t offset_ = 0;
  std::int64_t raw_ = 0;      // last valid raw count (output direction)
  std::int64_t steps_ = 0;    // last valid count along the rod
  bool valid_ = false;
  bool eeprom_failing_ = false;
  bool reset_node_pending_ = false;
  bool write_ignored_ = false;  // an out-of-range parameter was confirmed but not applied
  bool eeprom_check_pending_ = false;  // a failing EEPROM is found at start-up (6503h bit 12)
  sim::Time next_sample_{};
  canopen::EntryRef<std::int32_t> position_;
  canopen::EntryRef<std::int16_t> speed_;
  canopen::EntryRef<std::uint16_t> status_;
  cia406::StatusRecorder status_recorder_{node_, status_bits()};
};

}  // namespace hlt1100
