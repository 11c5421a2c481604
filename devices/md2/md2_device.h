// The Wandfluh MD2 valve electronics (amplifier and controller variants) as an emulated CANopen
// device with the CiA DSP 408 profile: up to 8 channels, each with its device state machine and
// signal chain; channel 1 owns the two solenoid drivers the fault inputs act on.
//
// Ports (SI units; channel c = 1..channels):
//   chC.solenoid_a_current, chC.solenoid_b_current   out  A   after ramp, dead band, dither; 0 when off
//   chC.actual_value                                  in   SI  local feedback (controller, 0x2200 = 2):
//                                                             Pa in modes 4/−5, else the unit's SI
//                                                             quantity (m, m/s, rad, ...)
//   chC.local_command                                 in   1   local set point (0x6042 = 2), −1..1
//   enable_input                                      in   1   hardware enable (≥ 0.5 = on)
//   supply_voltage                                    in   V   below u_supply_min → EMCY 0x3412
//   temperature                                       out  °C  device temperature (0x2002)
// `--set actual=…` is channel 1's actual value.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "devices/device.h"
#include "devices/fault_table.h"
#include "devices/md2/md2_channel.h"
#include "devices/md2/md2_emcy_codes.h"
#include "devices/md2/md2_options.h"
#include "devices/canopen/entry_ref.h"
#include "devices/profiles/wandfluh/valve_application.h"

namespace md2 {

class Md2Device final : public devices::Device, private wandfluh::ValveApplication {
 public:
  /// Builds an MD2; nullptr with `error` set on bad options.
  static std::unique_ptr<Md2Device> create(const devices::DeviceOptions& options, std::string& error);

  canopen::Node& node() override { return *node_owner_; }
  sim::PortList ports() override;
  std::string set_input(std::string_view name, double value) override;
  std::vector<devices::FaultInfo> faults() const override;
  std::string inject_fault(std::string_view name, bool active) override;
  /// Channel 1's device state.
  devices::ProfileStatus profile_status() override { return channels_.front()->control().profile_status(); }
  std::span<const devices::EmcyCode> emcy_codes() const override { return md2::emcy_codes(); }
  int profile_channel_count() const override { return options_.channels; }
  devices::ProfileStatus channel_profile_status(int channel) override {
    if (channel < 1 || channel > static_cast<int>(channels_.size())) return {};
    return md2_channel(channel).control().profile_status();
  }

  const Md2Options& options() const { return options_; }
  Md2Channel& md2_channel(int c) { return *channels_[static_cast<std::size_t>(c - 1)]; }
  /// Bit rate in use since the last communication reset (kbit/s; the virtual bus has none).
  std::uint16_t active_bit_rate_kbit() { return address().active_bit_rate_kbit(); }
  double temperature() const { return temperature_; }

 private:
  Md2Device(std::unique_ptr<canopen::Node> node, const Md2Options& options);

  // wandfluh::ValveApplication
  int channel_count() const override { return static_cast<int>(channels_.size()); }
  dsp408::ChannelControl& channel(int index) override { return channels_[static_cast<std::size_t>(index)]->control(); }
  void reset_model() override;
  void regenerate_pdos() override;
  void process(sim::Time now, sim::Duration dt) override;

  void detect_errors();
  static constexpr std::uint64_t kNoConditionsPassed = ~std::uint64_t{0};  // no bool array is all ones

  Md2Options options_;
  std::unique_ptr<canopen::Node> node_owner_;
  std::vector<std::unique_ptr<Md2Channel>> channels_;
  canopen::EntryRef<std::int64_t> temperature_out_;  // 0x2002, published every cycle

  // Inputs and fault conditions.
  double enable_input_ = 1;
  double supply_voltage_ = 24;
  double temperature_ = 25;
  struct Faults {
    bool solenoid_a_open = false, solenoid_a_short = false;
    bool solenoid_b_open = false, solenoid_b_short = false;
    bool supply_low = false, analog_signal_lost = false, general_error = false;
    bool storage_failure = false, paso_control = false;
  } faults_;
  /// Name, EMCY code, what it does, and the condition it sets, per fault (the .cpp's table).
  static const devices::FaultEntry<Md2Device> kFaults[];
  static bool has_solenoid_b(const Md2Device& d) { return d.options_.solenoids == 2; }
  std::uint64_t conditions_passed_ = kNoConditionsPassed;  ///< detect_errors()' conditions as last passed on
};

}  // namespace md2
