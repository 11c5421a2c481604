#include "devices/md2/md2_channel.h"

#include <algorithm>
#include <cmath>


namespace md2 {

using canopen::CheckStage;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;
using dsp408::DeviceState;

namespace {
bool from_bus(Origin o) { return o == Origin::Sdo || o == Origin::Pdo; }
}  // namespace

Md2Channel::Md2Channel(canopen::ObjectDictionary& od, const Md2Options& options, int channel)
    : o_(options),
      ix_(ChannelIndices::of(channel)),
      control_(od, dsp408::ChannelObjects::for_channel(channel, true)) {
  ramp_.set_full_scale(o_.bus_full_scale);
  const double up = o_.ramp_up_ms / 1000, down = o_.ramp_down_ms / 1000;
  ramp_.set_times({.a_up = up, .a_down = down, .b_up = up, .b_down = down});
  ramp_.set_enabled(up > 0 || down > 0);
  dither_.configure(o_.dither_sine ? dsp408::Dither::Shape::Sine : dsp408::Dither::Shape::Square, o_.dither_frequency, 1.0);
  const double threshold = o_.deadband / o_.bus_full_scale;
  curve_a_ = {.i_min = o_.i_min_a, .i_max = o_.i_max_a, .threshold = threshold};
  curve_b_ = {.i_min = o_.i_min_b, .i_max = o_.i_max_b, .threshold = threshold};
  install(od);
}

void Md2Channel::install(canopen::ObjectDictionary& od) {
  device_mode_ = canopen::EntryRef<std::int8_t>(od, ix_.device_mode(), 0);
  control_mode_ = canopen::EntryRef<std::int8_t>(od, ix_.control_mode(), 0);
  actual_mode_ = canopen::EntryRef<std::int8_t>::optional(od, ix_.actual_value_mode(), 0);
  actual_in_16_ = od.entry(ix_.actual_input_16(), 0);
  actual_in_32_ = od.entry(ix_.actual_input_32(), 0);
  speed_pos_ = od.entry(ix_.speed_positive(), 0);
  speed_neg_ = od.entry(ix_.speed_negative(), 0);
  const std::uint16_t sp[6] = {ix_.vpoc_setpoint(), ix_.vprc_setpoint(), ix_.dcol_setpoint(),
                               ix_.dsc_setpoint(),  ix_.dpc_setpoint(),  ix_.n_point_setpoint()};
  for (int i = 0; i < 6; ++i) setpoints_[i] = sp[i] ? od.entry(sp[i], i == 5 ? 0 : 1) : nullptr;
  const std::uint16_t act[3] = {ix_.vprc_actual(), ix_.dsc_actual(), ix_.dpc_actual()};
  const std::uint16_t dev[3] = {ix_.vprc_deviation(), ix_.dsc_deviation(), ix_.dpc_deviation()};
  for (int i = 0; i < 3; ++i) {
    actuals_[i] = canopen::EntryRef<std::int64_t>::optional(od, act[i], 1);
    deviations_[i] = canopen::EntryRef<std::int64_t>::optional(od, dev[i], 1);
  }

  // Command values are stored in any state but refused while the set point comes from a local
  // source (device mode 2): SDO gets 0x08000021, an RPDO value is dropped.
  for (auto* e : setpoints_) {
    if (!e) continue;
    od.add_check(
        e->index, e->sub,
        [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
          if (from_bus(origin) && device_mode_.get() == 2) return SdoAbort::DataLocalControl;
          return SdoAbort::None;
        },
        CheckStage::State);
  }
  od.on_write<std::int8_t>(ix_.control_mode(), 0, [this](std::int8_t m, Origin) {
    return mode_supported(o_.variant, m) ? SdoAbort::None : SdoAbort::ParameterIncompatible;
  });
  od.after_write<std::int8_t>(ix_.control_mode(), 0,
                              [this](std::int8_t m, Origin) { control_.dsm().set_active_allowed(m != mode::kNone); });
  if (actual_mode_) od.add_check(ix_.actual_value_mode(), 0, control_.mode_lock(), CheckStage::State);
  for (int i = 0; i < 3; ++i) {
    if (!actuals_[i]) continue;
    auto refresh = [this](OdEntry&, Origin) {
      last_actual_ = actual_raw();  // the feedback as it is now (set between two cycles)
      publish_measurements();
      return SdoAbort::None;
    };
    od.add_read_hook(actuals_[i].entry().index, 1, refresh);
    od.add_read_hook(deviations_[i].entry().index, 1, refresh);
  }
  control_.set_status_flags([this] { return status_flags(); }, true);  // see status_flags()
  control_.dsm().set_listener([this](DeviceState from, DeviceState to) { on_state_change(from, to); });
}

void Md2Channel::reset_model() {
  ramp_.reset(0);
  limiter_.reset(0);
  pid_.reset();
  n_point_.reset();
  hold_setpoint_ = effective_ = 0;
  at_rest_ = true;
  solenoid_a = solenoid_b = 0;
  control_.dsm().set_active_allowed(control_mode() != mode::kNone);
  publish_measurements();
  control_.publish_status();
}

void Md2Channel::on_state_change(DeviceState from, DeviceState to) {
  // HOLD keeps "the last set-point value present": the effective set point when coming from
  // ACTIVE, nothing (0) when coming from DISABLED or a fault.
  if (to == DeviceState::Hold) hold_setpoint_ = from == DeviceState::Active ? effective_ : 0.0;
}

bool Md2Channel::uses_analog_input() const {
  if (device_mode_.get() == 2) return true;
  return actual_mode_ && actual_mode_.get() == 2 && is_closed_loop(control_mode());
}

double Md2Channel::span(std::int8_t m) const {
  return is_16_bit(m) ? o_.bus_full_scale : o_.setpoint_max - o_.setpoint_min;
}

double Md2Channel::setpoint_raw() const {
  const std::int8_t m = control_mode();
  if (device_mode_.get() == 2) {
    const double full = is_16_bit(m) ? o_.bus_full_scale : o_.setpoint_max;
    return std::clamp(local_command, -1.0, 1.0) * full;
  }
  if (m == mode::kNone) return 0;
  const OdEntry* e = nullptr;
  switch (m) {
    case mode::kVpoc: e = setpoints_[0]; break;
    case mode::kVprcOpen:
    case mode::kVprcClosed:
    case mode::kVprcClosed2: e = o_.vpoc_mapping_literal ? setpoints_[0] : setpoints_[1]; break;
    case mode::kDcol: e = setpoints_[2]; break;
    case mode::kDsc: e = setpoints_[3]; break;
    case mode::kDpc: e = setpoints_[4]; break;
    default: e = setpoints_[5]; break;
  }
  return e ? e->as<double>() : 0.0;
}

double Md2Channel::actual_raw() const {
  if (!actual_mode_) return 0;  // no feedback on this channel (amplifier, channels 5..8)
  const std::int8_t m = control_mode();
  if (!is_closed_loop(m)) return 0;
  if (actual_mode_.get() == 1) {  // actual value via CAN
    return is_16_bit(m) ? actual_in_16_->as<double>() : actual_in_32_->as<double>();
  }
  if (is_16_bit(m)) return o_.bus_full_scale * actual_value / o_.p_range;  // pressure sensor
  return actual_value / o_.unit.si * 1000.0;                                 // unit/1000
}

dsp408::StatusFlags Md2Channel::status_flags() const {
  const DeviceState s = control_.state();
  return status_flags(control_mode(), s, s == DeviceState::Active ? setpoint_raw() : 0.0);
}

dsp408::StatusFlags Md2Channel::status_flags(std::int8_t m, DeviceState s, double live_setpoint) const {
  dsp408::StatusFlags f;
  if (s == DeviceState::Active && ramp_mode(m)) {
    const double n = o_.bus_full_scale;
    f.ramp_running = ramp_.running(std::clamp(live_setpoint, -n, n));
  }
  if ((m == mode::kVprcClosed || m == mode::kDsc || m == mode::kDpc) && (s == DeviceState::Active || s == DeviceState::Hold)) {
    const double w = s == DeviceState::Hold ? hold_setpoint_ : live_setpoint;
    double window = o_.window;
    if (!is_16_bit(m)) window = o_.window_scaled > 0 ? o_.window_scaled : 0.01 * span(m);
    f.window_reached = std::abs(w - last_actual_) <= window;
  }
  return f;
}

void Md2Channel::publish_measurements() {
  if (!actuals_[0]) return;
  const std::int8_t m = control_mode();
  const int active = (m == mode::kVprcClosed || m == mode::kVprcClosed2) ? 0 : m == mode::kDsc ? 1 : m == mode::kDpc ? 2 : -1;
  // The set point only matters for the deviation of the active loop (setpoint_raw() is pure).
  const double w = active < 0 ? 0.0 : control_.state() == DeviceState::Hold ? hold_setpoint_ : setpoint_raw();
  for (int i = 0; i < 3; ++i) {
    const bool on = i == active;
    const double lim = i == 0 ? 32767.0 : 2147483647.0;
    actuals_[i].set_rounded(on ? last_actual_ : 0.0, -lim - 1, lim);
    deviations_[i].set_rounded(on ? w - last_actual_ : 0.0, -lim - 1, lim);
  }
}

void Md2Channel::reset_functions() {
  ramp_.reset(0);
  pid_.reset();
  n_point_.reset();
  effective_ = 0;
  at_rest_ = true;
}

void Md2Channel::process_live(sim::Time now, double dt, DeviceState s) {
  const std::int8_t m = control_mode();
  const double n = o_.bus_full_scale;
  last_actual_ = actual_raw();
  const bool active = s == DeviceState::Active;
  at_rest_ = false;
  double w = 0;  // the live set point (ACTIVE only; setpoint_raw() is pure)
  if (active) {
    w = setpoint_raw();
    if (ramp_mode(m)) {
      effective_ = ramp_.step(std::clamp(w, -n, n), dt);
    } else if (speed_mode(m) && speed_pos_) {
      limiter_.set_rates(speed_pos_->as<double>(), speed_neg_->as<double>());
      effective_ = limiter_.step(w, dt);
    } else {
      effective_ = w;
    }
  } else {
    effective_ = hold_setpoint_;
  }

  double u = 0;
  bool switched = false, on_a = false, on_b = false;
  const double sp = span(m);
  dsp408::PidParameters pid{.kp_pos = o_.kp, .kp_neg = o_.kp, .ki_pos = o_.ki, .ki_neg = o_.ki,
                            .kd_pos = o_.kd, .kd_neg = o_.kd, .ff_w = o_.kff};
  switch (m) {
    case mode::kVpoc: u = effective_ / n; break;
    case mode::kVprcOpen: u = std::max(effective_, 0.0) / n; break;
    case mode::kDcol: u = effective_ / std::max(std::abs(o_.setpoint_min), std::abs(o_.setpoint_max)); break;
    case mode::kVprcClosed:
      pid.out_min = 0;
      [[fallthrough]];
    case mode::kVprcClosed2:
    case mode::kDsc:
    case mode::kDpc:
      pid_.set_parameters(pid);
      u = pid_.update((effective_ - last_actual_) / sp, effective_ / sp, dt);
      break;
    case mode::kTwoPoint1:
    case mode::kTwoPoint2:
    case mode::kThreePoint: {
      const auto out = n_point_.update(m, effective_ - last_actual_, o_.hysteresis * sp);
      switched = true;
      on_a = out.a;
      on_b = out.b;
      break;
    }
    default: break;
  }
  u = std::clamp(u, -1.0, 1.0);
  double ia = 0, ib = 0;
  if (switched) {
    ia = on_a ? o_.i_max_a : 0.0;
    ib = on_b ? o_.i_max_b : 0.0;
  } else {
    // The dead band applies in every mode (digest §5.1 step 5); deadband_modes=open_loop keeps it
    // off the closed loops' output (any demand opens the valve: current Imin + span·|u|).
    dsp408::SolenoidCurve a = curve_a_, b = curve_b_;
    if (!o_.deadband_all_modes && is_closed_loop(m)) a.threshold = b.threshold = 0;
    ia = u > 0 ? dsp408::solenoid_current(a, u) : 0.0;
    ib = u < 0 ? dsp408::solenoid_current(b, -u) : 0.0;
  }
  if (o_.solenoids == 1) ib = 0;
  const double d = dither_.offset(now) * o_.dither_level;
  solenoid_a = driver_ok_a_ && ia > 0 ? std::clamp(ia + d * o_.i_max_a, 0.0, o_.i_limit) : 0.0;
  solenoid_b = driver_ok_b_ && ib > 0 ? std::clamp(ib + d * o_.i_max_b, 0.0, o_.i_limit) : 0.0;
  publish_measurements();
  control_.publish_status(status_flags(m, s, w));  // as status_flags() would find them now
}

}  // namespace md2
