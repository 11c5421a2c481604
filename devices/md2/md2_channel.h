// One MD2 channel: DSP 408 device control plus the signal chain of §5 of the digest.
//   set point (bus object of the control mode, or the local command input)
//   → state gating (ACTIVE live, HOLD frozen, otherwise off)
//   → ramp (modes 1, 3) or Speed± rate limitation (setting speed_modes, 6, 7, 9)
//   → mode function (open loop, PID closed loop, n-point switching) → u ∈ [−1, 1]
//   → solenoid current Imin + (Imax − Imin)·|u| above the dead band → dither → outputs.
#pragma once

#include <cstdint>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/md2/control_mode.h"
#include "devices/md2/md2_options.h"
#include "devices/md2/n_point_controller.h"
#include "devices/profiles/dsp408/channel_control.h"
#include "devices/profiles/dsp408/command_value_ramp.h"
#include "devices/profiles/dsp408/dither.h"
#include "devices/profiles/dsp408/pid_controller.h"
#include "devices/profiles/dsp408/solenoid_current.h"
#include "sim/time.h"

namespace md2 {

class Md2Channel {
 public:
  Md2Channel(canopen::ObjectDictionary& od, const Md2Options& options, int channel);
  Md2Channel(const Md2Channel&) = delete;
  Md2Channel& operator=(const Md2Channel&) = delete;

  dsp408::ChannelControl& control() { return control_; }
  int number() const { return ix_.channel; }
  std::int8_t control_mode() const { return control_mode_.get(); }

  /// Application reset: ramps, controllers and outputs back to rest.
  void reset_model();
  /// One control cycle. Most channels of an MD2 idle (INIT, DISABLED, FAULT, NOT_READY): that
  /// cycle is inline and short.
  void process(sim::Time now, double dt) {
    const dsp408::DeviceState s = control_.state();
    if (s == dsp408::DeviceState::Active || s == dsp408::DeviceState::Hold || s == dsp408::DeviceState::FaultHold) {
      process_live(now, dt, s);
    } else {
      rest();
    }
  }

  /// Solenoid driver usable (false while open-circuited: no current flows).
  void set_driver_ok(bool a, bool b) {
    driver_ok_a_ = a;
    driver_ok_b_ = b;
  }
  /// The analog input that this channel uses is in use (device mode or actual value mode 2).
  bool uses_analog_input() const;

  // Port storage (sim::Port points here).
  double solenoid_a = 0;     ///< A
  double solenoid_b = 0;     ///< A
  double actual_value = 0;   ///< SI measurand of the local feedback (Pa, m, m/s, ...)
  double local_command = 0;  ///< local set point, fraction of full scale (−1..1)

 private:
  void install(canopen::ObjectDictionary& od);
  void process_live(sim::Time now, double dt, dsp408::DeviceState s);
  /// The cycle outside ACTIVE and HOLD: functions disabled, solenoids 0 A.
  void rest() {
    last_actual_ = actual_mode_ ? actual_raw() : 0.0;  // no feedback on this channel: 0
    if (!at_rest_) reset_functions();
    limiter_.reset(last_actual_);
    solenoid_a = solenoid_b = 0;
    if (actuals_[0]) publish_measurements();
    control_.publish_status();
  }
  /// Ramp, controllers and effective set point to rest (only a live state moves them).
  void reset_functions();
  void on_state_change(dsp408::DeviceState from, dsp408::DeviceState to);
  double setpoint_raw() const;     ///< the set point of the active mode (bus or local)
  double actual_raw() const;       ///< feedback in the mode's bus unit
  double span(std::int8_t m) const;
  void publish_measurements();
  dsp408::StatusFlags status_flags() const;  ///< all clear outside ACTIVE and HOLD
  /// The same for mode `m`, state `s` and the live set point (setpoint_raw(), used in ACTIVE).
  dsp408::StatusFlags status_flags(std::int8_t m, dsp408::DeviceState s, double live_setpoint) const;
  bool ramp_mode(std::int8_t m) const { return m == mode::kVpoc || m == mode::kVprcOpen; }
  bool speed_mode(std::int8_t m) const { return o_.is_speed_mode(m); }

  const Md2Options& o_;
  ChannelIndices ix_;
  dsp408::ChannelControl control_;
  dsp408::CommandValueRamp ramp_;
  dsp408::RateLimiter limiter_;
  dsp408::PidController pid_;
  NPointController n_point_;
  dsp408::Dither dither_;
  dsp408::SolenoidCurve curve_a_, curve_b_;

  // Entries read every cycle (stable addresses in the node's dictionary).
  canopen::EntryRef<std::int8_t> device_mode_;
  canopen::EntryRef<std::int8_t> control_mode_;
  canopen::EntryRef<std::int8_t> actual_mode_;  // unbound on channels without feedback
  canopen::OdEntry* actual_in_16_ = nullptr;
  canopen::OdEntry* actual_in_32_ = nullptr;
  canopen::OdEntry* speed_pos_ = nullptr;
  canopen::OdEntry* speed_neg_ = nullptr;
  canopen::OdEntry* setpoints_[6] = {};  // vpoc, vprc, dcol, dsc, dpc, n-point
  canopen::EntryRef<std::int64_t> actuals_[3];  // vprc, dsc, dpc: published every cycle
  canopen::EntryRef<std::int64_t> deviations_[3];

  double hold_setpoint_ = 0;   ///< frozen on entering HOLD
  double effective_ = 0;       ///< set point after ramp / rate limitation
  double last_actual_ = 0;
  bool driver_ok_a_ = true, driver_ok_b_ = true;
  bool at_rest_ = false;  ///< ramp, controllers and effective set point already reset (idle)
};

}  // namespace md2
