// The DSV's signal chain (digest §5), once per control cycle:
//   open loop (modes 1, 3, 6): set point(s) → inversion (62F0h) → four-quadrant ramp →
//     split into solenoids A/B by the mode of operation (2042h) → dead band → characteristic
//     optimisation → Imin..Imax → dither;
//   closed loop (modes 4, 7, 9): set point → Speed± → PID with switched integrator and
//     feed-forward on the actual value → A/B → Imin..Imax ("Imin always active", inverted
//     outputs, solenoid-off window) → dither; target and trailing windows for bits 12 and 5;
// gated by the device state (ACTIVE live, HOLD frozen, INIT/DISABLED off, FAULT per 2043h).
#pragma once

#include <array>
#include <cstdint>

#include "devices/dsv/actual_value_input.h"
#include "devices/dsv/dsv_options.h"
#include "devices/dsv/dsv_parameters.h"
#include "devices/profiles/dsp408/channel_control.h"
#include "devices/profiles/dsp408/command_value_ramp.h"
#include "devices/profiles/dsp408/dither.h"
#include "devices/profiles/dsp408/pid_controller.h"
#include "sim/time.h"

namespace dsv {

class DsvSignalChain {
 public:
  DsvSignalChain(DsvParameters& parameters, ActualValueInput& input, dsp408::ChannelControl& control,
                 const DsvOptions& options, canopen::ObjectDictionary& od);

  void reset();
  /// One control cycle of `dt` seconds at `now`.
  void process(sim::Time now, double dt);
  /// Entering HOLD: from ACTIVE the present (ramped / limited) set point is held, otherwise 0.
  void on_state_change(dsp408::DeviceState from, dsp408::DeviceState to);
  dsp408::StatusFlags status_flags() const;  ///< all clear outside ACTIVE and HOLD
  /// Actual value and deviation objects of the active closed-loop mode (read hooks call this).
  void publish_measurements();

  double solenoid_a() const { return out_a_; }  ///< A, after dither
  double solenoid_b() const { return out_b_; }
  double commanded_a() const { return cmd_a_; }  ///< A, before the driver (open-circuit detection)
  double commanded_b() const { return cmd_b_; }
  void set_driver_ok(bool a, bool b) {
    driver_ok_a_ = a;
    driver_ok_b_ = b;
  }

 private:
  struct LoopObjects {
    canopen::OdEntry *setpoint, *actual, *deviation, *kp_pos, *kp_neg, *ti_pos, *ti_neg, *iwo_pos, *iwo_neg, *td_pos,
        *td_neg, *kd_pos, *kd_neg, *iwi_pos, *iwi_neg, *preset_offering, *speed_offering, *i_part_kept,
        *integrator_type, *target_type, *target_threshold, *target_delay, *trailing_type, *trailing_threshold,
        *trailing_delay, *off_threshold, *off_delay, *min_reference, *max_reference;
  };
  /// Parameters read every cycle (DsvParameters::bind_value, bound once; unbound when absent).
  struct Parameters {
    canopen::EntryRef<std::int64_t> vpoc_a, vpoc_b, vprc_a, vprc_b, dcol, inversion, error_handling, system_inverted, falling_a,
        falling_b, imin_always, solenoid_off_disabled, speed_pos, speed_neg;
  };
  static std::int64_t value(const canopen::EntryRef<std::int64_t>& e) { return e.get(); }
  static std::int64_t value(const canopen::OdEntry* e) { return e ? e->as<std::int64_t>() : 0; }
  LoopObjects loop_objects(std::int8_t m, canopen::ObjectDictionary& od);
  template <typename E>
  static LoopObjects loop_objects_of(std::int8_t m, E e);
  const LoopObjects* loop(std::int8_t m) const;

  /// Ramp type and the A up, A down, B up, B down times (shared parameters).
  using RampParameters = std::array<std::int64_t, 5>;
  RampParameters ramp_parameters() const;
  static void configure_ramps(dsp408::CommandValueRamp& a, dsp408::CommandValueRamp& b, const RampParameters& r);
  void configure_ramps(dsp408::CommandValueRamp& a, dsp408::CommandValueRamp& b) const;
  /// configure_ramps(ramp_, ramp_b_), skipped when the parameters are those they were set with.
  void configure_own_ramps();
  /// status_flags() with ramps that have the parameters as they stand now (configure_ramps()).
  dsp408::StatusFlags status_flags(const dsp408::CommandValueRamp& ra, const dsp408::CommandValueRamp& rb) const;
  void open_loop(std::int8_t m, std::int8_t op, bool active, double dt, double& a, double& b);
  void closed_loop(std::int8_t m, bool active, sim::Time now, double dt, double& a, double& b, bool& off);
  double to_amperes(std::int64_t counts) const { return static_cast<double>(counts) * o_.current_full_scale() / 16384.0; }
  double closed_loop_current(int solenoid, double demand) const;
  /// Open-loop currents of both solenoids in mode `m` for demands a and b.
  void open_loop_currents(std::int8_t m, double a, double b, double& ia, double& ib);

  DsvParameters& p_;
  ActualValueInput& input_;
  dsp408::ChannelControl& control_;
  const DsvOptions& o_;
  LoopObjects loops_[3];  // modes 4, 7, 9
  // Actual and deviation of each loop, published every cycle (publish_measurements).
  std::array<canopen::EntryRef<std::int64_t>, 6> measured_{};
  Parameters par_;

  dsp408::CommandValueRamp ramp_, ramp_b_;  // ramp_b_: set point B in mode of operation 3
  RampParameters ramps_configured_with_{};
  bool ramps_configured_ = false;
  dsp408::RateLimiter limiter_;
  dsp408::PidController pid_;
  dsp408::Dither dither_;
  dsp408::DeviceState before_fault_ = dsp408::DeviceState::Init;  ///< state that TR_8 left
  double hold_w_ = 0;
  double last_w_ = 0, last_x_ = 0, last_e_ = 0;
  double target_ = 0, target_b_ = 0;  // ramp targets (for "ramp running"); target_b_ in op-mode 3 only
  bool window_reached_ = false, trailing_ = false, solenoid_off_ = false;
  sim::Time in_window_since_{}, out_of_trailing_since_{}, in_off_window_since_{};
  bool in_window_ = false, out_of_trailing_ = false, in_off_window_ = false;
  double out_a_ = 0, out_b_ = 0, cmd_a_ = 0, cmd_b_ = 0;
  bool driver_ok_a_ = true, driver_ok_b_ = true;
};

}  // namespace dsv
