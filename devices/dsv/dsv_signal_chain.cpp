#include "devices/dsv/dsv_signal_chain.h"

#include <algorithm>
#include <cmath>

#include "devices/dsv/control_mode.h"
#include "devices/canopen/entry_ref.h"
#include "devices/profiles/dsp408/solenoid_current.h"

namespace dsv {

using dsp408::DeviceState;

namespace {
constexpr double kDitherAmpere = 0.400 / 4266;  // 0..4266 = 0..400 mA (§5.4.55)
bool ms_elapsed(sim::Time since, sim::Time now, std::int64_t ms) { return now - since >= sim::milliseconds(ms); }
}  // namespace

DsvSignalChain::DsvSignalChain(DsvParameters& parameters, ActualValueInput& input, dsp408::ChannelControl& control,
                               const DsvOptions& options, canopen::ObjectDictionary& od)
    : p_(parameters), input_(input), control_(control), o_(options) {
  loops_[0] = loop_objects(mode::kVprcClosed, od);
  loops_[1] = loop_objects(mode::kDsc, od);
  loops_[2] = loop_objects(mode::kDpc, od);
  for (int i = 0; i < 3; ++i) {
    measured_[static_cast<std::size_t>(2 * i)] = canopen::EntryRef<std::int64_t>(*loops_[i].actual);
    measured_[static_cast<std::size_t>(2 * i + 1)] = canopen::EntryRef<std::int64_t>(*loops_[i].deviation);
  }
  auto e = [this](std::uint16_t index) { return p_.bind_value(index); };
  par_ = {e(0x6300), e(0x6B00), e(0x6380), e(0x6B80), e(0x6480), e(0x62F0), e(0x2043),
          e(0x2044), e(0x2045), e(0x2046), e(0x2047), e(0x2048), e(0x22B2), e(0x22B3)};
  ramp_.set_full_scale(1.0);
  ramp_b_.set_full_scale(1.0);
}

DsvSignalChain::LoopObjects DsvSignalChain::loop_objects(std::int8_t m, canopen::ObjectDictionary& od) {
  auto e = [&od](std::uint16_t index) {
    canopen::OdEntry* v = od.entry(index, 1);
    return v ? v : od.entry(index, 0);
  };
  const auto ref = DsvParameters::scaling_objects(m);
  LoopObjects l = loop_objects_of(m, e);
  l.min_reference = p_.value_entry(ref.min_reference);
  l.max_reference = p_.value_entry(ref.max_reference);
  return l;
}

template <typename E>
DsvSignalChain::LoopObjects DsvSignalChain::loop_objects_of(std::int8_t m, E e) {
  switch (m) {
    case mode::kVprcClosed:
      return {e(0x6380), e(0x6381), e(0x63D0), e(0x2303), e(0x2304), e(0x2305), e(0x2306), e(0x2307), e(0x2308),
              e(0x2309), e(0x230A), e(0x230B), e(0x230C), e(0x230D), e(0x230E), e(0x2301), e(0x2302), e(0x2300),
              nullptr,   e(0x63F0), e(0x63F3), e(0x23F1), e(0x63D1), e(0x63D3), e(0x63D2), e(0x23F3), e(0x23F2), nullptr, nullptr};
    case mode::kDsc:
      return {e(0x6500), e(0x6501), e(0x6550), e(0x6503), e(0x2504), e(0x6509), e(0x2506), e(0x650A), e(0x2508),
              e(0x2509), e(0x250A), e(0x250B), e(0x250C), e(0x250D), e(0x250E), e(0x2501), e(0x2502), e(0x2500),
              nullptr,   e(0x6570), e(0x6573), e(0x2571), e(0x6551), e(0x6553), e(0x6552), e(0x2573), e(0x2572), nullptr, nullptr};
    default:
      return {e(0x6600), e(0x6601), e(0x6650), e(0x6603), e(0x2604), e(0x6609), e(0x2606), e(0x660A), e(0x2608),
              e(0x2609), e(0x260A), e(0x260B), e(0x260C), e(0x260D), e(0x260E), e(0x2601), e(0x2602), e(0x2600),
              e(0x6608), e(0x6670), e(0x6673), e(0x2671), e(0x6651), e(0x6653), e(0x6652), e(0x2673), e(0x2672), nullptr, nullptr};
  }
}

const DsvSignalChain::LoopObjects* DsvSignalChain::loop(std::int8_t m) const {
  switch (m) {
    case mode::kVprcClosed: return &loops_[0];
    case mode::kDsc: return &loops_[1];
    case mode::kDpc: return &loops_[2];
    default: return nullptr;
  }
}

void DsvSignalChain::reset() {
  ramp_.reset(0);
  ramp_b_.reset(0);
  limiter_.reset(0);
  pid_.reset();
  hold_w_ = last_w_ = last_e_ = 0;
  window_reached_ = trailing_ = solenoid_off_ = false;
  in_window_ = out_of_trailing_ = in_off_window_ = false;
  out_a_ = out_b_ = cmd_a_ = cmd_b_ = 0;
}

void DsvSignalChain::on_state_change(DeviceState from, DeviceState to) {
  if (to == DeviceState::FaultReaction) before_fault_ = from;
  // FAULT_HOLD (option fault_hold, TR_9) holds like HOLD, judged by the state before the fault;
  // TR_11 from FAULT_HOLD keeps holding that set point.
  if (to == DeviceState::FaultHold) from = before_fault_;
  if (to == DeviceState::Hold && from == DeviceState::FaultHold) return;
  if (to != DeviceState::Hold && to != DeviceState::FaultHold) return;
  if (from == DeviceState::Hold) return;  // FAULT_HOLD entered from HOLD: the same hold set point
  if (from == DeviceState::Active) {
    hold_w_ = limiter_.output();  // closed loop; the open-loop ramps simply stop
  } else {
    hold_w_ = 0;
    ramp_.reset(0);
    ramp_b_.reset(0);
    limiter_.reset(0);
  }
}

double DsvSignalChain::closed_loop_current(int solenoid, double demand) const {
  const bool a = solenoid == 0;
  dsp408::SolenoidCurve c;
  c.i_min = to_amperes(p_.shared(a ? Shared::IminA : Shared::IminB));
  c.i_max = to_amperes(p_.shared(a ? Shared::ImaxA : Shared::ImaxB));
  c.falling = value(a ? par_.falling_a : par_.falling_b) == 1;
  c.imin_at_zero = value(par_.imin_always) == 0;  // "0 = Imin always active yes"
  return dsp408::solenoid_current(c, demand);
}

void DsvSignalChain::open_loop_currents(std::int8_t m, double a, double b, double& ia, double& ib) {
  // Each shared parameter read once. A demand of 0 or less is 0 A in open loop (no "Imin always
  // active" there): nothing to read for it.
  const bool deadband = p_.shared(Shared::DeadbandType) == 1;
  const bool optimise = (m == mode::kVpoc || m == mode::kVprcOpen) && p_.characteristic_on();
  auto side = [&](int solenoid, double demand) {
    if (demand <= 0) return 0.0;
    const bool is_a = solenoid == 0;
    dsp408::SolenoidCurve c;
    c.i_min = to_amperes(p_.shared(is_a ? Shared::IminA : Shared::IminB));
    c.i_max = to_amperes(p_.shared(is_a ? Shared::ImaxA : Shared::ImaxB));
    if (deadband) {
      // m6 has threshold A only, used for both sides.
      const auto thr = (is_a || m == mode::kDcol) ? p_.shared(Shared::DeadbandA) : p_.shared(Shared::DeadbandB);
      c.threshold = static_cast<double>(thr) / 32768.0;  // 0..16384 = 0..50 %
      c.rescale = true;
    }
    return dsp408::solenoid_current(c, demand, optimise ? &p_.curve(solenoid) : nullptr);
  };
  ia = side(0, a);
  ib = o_.solenoids == 2 ? side(1, b) : 0.0;
}

DsvSignalChain::RampParameters DsvSignalChain::ramp_parameters() const {
  return {p_.shared(Shared::RampType), p_.shared(Shared::RampAUp), p_.shared(Shared::RampADown), p_.shared(Shared::RampBUp),
          p_.shared(Shared::RampBDown)};
}

void DsvSignalChain::configure_ramps(dsp408::CommandValueRamp& a, dsp408::CommandValueRamp& b, const RampParameters& r) {
  const bool on = r[0] == 3;
  const auto sec = [](std::int64_t ms) { return static_cast<double>(ms) / 1000.0; };
  a.set_enabled(on);
  b.set_enabled(on);
  const double a_up = sec(r[1]), a_down = sec(r[2]);
  const double b_up = sec(r[3]), b_down = sec(r[4]);
  a.set_times({a_up, a_down, b_up, b_down});
  // Set point B (op-mode 3) is ramped on its own magnitude with the B times.
  b.set_times({b_up, b_down, b_up, b_down});
}

void DsvSignalChain::configure_ramps(dsp408::CommandValueRamp& a, dsp408::CommandValueRamp& b) const {
  configure_ramps(a, b, ramp_parameters());
}

void DsvSignalChain::configure_own_ramps() {
  // Nothing else configures ramp_ and ramp_b_: with the parameters as last time they are set.
  const RampParameters r = ramp_parameters();
  const RampParameters& was = ramps_configured_with_;
  if (ramps_configured_ && r[0] == was[0] && r[1] == was[1] && r[2] == was[2] && r[3] == was[3] && r[4] == was[4]) return;
  configure_ramps(ramp_, ramp_b_, r);
  ramps_configured_with_ = r;
  ramps_configured_ = true;
}

void DsvSignalChain::open_loop(std::int8_t m, std::int8_t op, bool active, double dt, double& a, double& b) {
  double w = 0, wb = 0;
  switch (m) {
    case mode::kVpoc:
      w = static_cast<double>(value(par_.vpoc_a)) / 16384.0;
      if (op == 3) wb = static_cast<double>(value(par_.vpoc_b)) / 16384.0;  // set point B acts in op-mode 3 only
      break;
    case mode::kVprcOpen:
      w = static_cast<double>(value(par_.vprc_a)) / 16384.0;
      if (op == 3) wb = static_cast<double>(value(par_.vprc_b)) / 16384.0;
      break;
    case mode::kDcol: w = static_cast<double>(value(par_.dcol)) / 100000.0; break;
    default: break;
  }
  // Inversion mirrors the set point about the neutral point of the mode of operation.
  if ((m == mode::kVpoc || m == mode::kVprcOpen) && value(par_.inversion) == -1) {
    if (op == 2 || (op == 1 && o_.op_mode1_bipolar)) w = -w;
    if (op == 1 && !o_.op_mode1_bipolar) w = 1.0 - w;
  }
  configure_own_ramps();
  target_ = op == 3 ? std::clamp(w, 0.0, 1.0) : w;
  target_b_ = std::clamp(wb, 0.0, 1.0);
  if (active) {
    ramp_.step(target_, dt);
    if (op == 3) ramp_b_.step(target_b_, dt);
  }
  const double r = ramp_.output();
  switch (op) {
    case 0: a = std::clamp(r, 0.0, 1.0); break;
    case 1:
      if (o_.op_mode1_bipolar) {
        a = std::max(r, 0.0);
        b = std::max(-r, 0.0);
      } else {  // 0 % = full B, 50 % = neutral, 100 % = full A
        const double c = std::clamp(r, 0.0, 1.0);
        a = std::max(0.0, 2 * c - 1);
        b = std::max(0.0, 1 - 2 * c);
      }
      break;
    case 3: {
      const std::uint16_t cw = control_.dsm().control_word();
      a = (cw & dsp408::control::kReleaseSolenoidA) ? std::clamp(r, 0.0, 1.0) : 0.0;
      b = (cw & dsp408::control::kReleaseSolenoidB) ? ramp_b_.output() : 0.0;
      break;
    }
    default:
      a = std::max(r, 0.0);
      b = std::max(-r, 0.0);
      break;
  }
}

void DsvSignalChain::closed_loop(std::int8_t m, bool active, sim::Time now, double dt, double& a, double& b, bool& off) {
  const LoopObjects& l = *loop(m);
  const bool pressure = m == mode::kVprcClosed;
  // Thresholds, windows and speeds are in unit/1000; mode 4 works in counts.
  const double k = pressure ? input_.counts_per_unit() : 1.0;
  const double fs = pressure ? 16384.0 : std::max(1.0, static_cast<double>(value(l.max_reference) - value(l.min_reference)));
  const double w = l.setpoint->as<double>();
  const double x = input_.value(m);
  limiter_.set_rates(static_cast<double>(value(par_.speed_pos)) * k, static_cast<double>(value(par_.speed_neg)) * k);
  const double w_lim = active ? limiter_.step(w, dt) : hold_w_;
  double e = w_lim - x;
  if (value(par_.system_inverted) == 1) e = -e;  // system control inverted
  last_w_ = w;
  last_x_ = x;
  last_e_ = e;

  auto par = [](const canopen::OdEntry* en) { return en ? en->as<double>() : 0.0; };
  dsp408::PidParameters pid;
  pid.kp_pos = par(l.kp_pos) / 1000;  // 0..25000 = 0..25
  pid.kp_neg = par(l.kp_neg) / 1000;
  const bool integrator = !l.integrator_type || l.integrator_type->as<int>() == 1;
  const double ti_pos = par(l.ti_pos) / 1000, ti_neg = par(l.ti_neg) / 1000;  // s
  pid.ki_pos = integrator && ti_pos > 0 ? pid.kp_pos / ti_pos : 0;
  pid.ki_neg = integrator && ti_neg > 0 ? pid.kp_neg / ti_neg : 0;
  pid.kd_pos = par(l.kd_pos) / 1000 * par(l.td_pos) / 1000;
  pid.kd_neg = par(l.kd_neg) / 1000 * par(l.td_neg) / 1000;
  pid.i_window_outside_pos = par(l.iwo_pos) * k / fs;
  pid.i_window_outside_neg = par(l.iwo_neg) * k / fs;
  pid.i_window_inside_pos = pressure ? par(l.iwi_pos) / 16384.0 : par(l.iwi_pos) / fs;  // 230Dh: % of 16384
  pid.i_window_inside_neg = par(l.iwi_neg) * k / fs;
  pid.hold_i_outside = l.i_part_kept->as<int>() == 1;
  pid.ff_w = par(l.preset_offering) / 1000;
  pid.ff_dw = par(l.speed_offering) / 1000;
  pid_.set_parameters(pid);
  const double u = pid_.update(e / fs, w_lim / fs, dt);
  a = std::max(u, 0.0);
  b = (o_.solenoids == 2) ? std::max(-u, 0.0) : 0.0;

  const double mag = std::abs(e);
  // Target window: |e| within the threshold for the delay → bit 12.
  const bool target_on = l.target_type->as<int>() == 2;
  const bool inside = mag <= par(l.target_threshold) * k;
  if (inside && !in_window_) in_window_since_ = now;
  in_window_ = inside;
  window_reached_ = target_on && inside && ms_elapsed(in_window_since_, now, l.target_delay->as<std::int64_t>());
  // Trailing window: |e| beyond the threshold for the delay → warning (bit 5).
  const bool outside = mag > par(l.trailing_threshold) * k;
  if (outside && !out_of_trailing_) out_of_trailing_since_ = now;
  out_of_trailing_ = outside;
  trailing_ = l.trailing_type->as<int>() == 2 && outside && ms_elapsed(out_of_trailing_since_, now, l.trailing_delay->as<std::int64_t>());
  // Solenoid-off window: both solenoids off while |e| stays small (unless 2048h = 1).
  const bool in_off = mag <= par(l.off_threshold) * k;
  if (in_off && !in_off_window_) in_off_window_since_ = now;
  in_off_window_ = in_off;
  off = value(par_.solenoid_off_disabled) == 0 && par(l.off_threshold) > 0 && in_off && ms_elapsed(in_off_window_since_, now, l.off_delay->as<std::int64_t>());
}

void DsvSignalChain::publish_measurements() {
  const std::int8_t m = p_.control_mode();
  const int on = m == mode::kVprcClosed ? 0 : m == mode::kDsc ? 1 : m == mode::kDpc ? 2 : -1;
  for (int i = 0; i < 3; ++i) {
    if (i != on) {  // the objects of the other modes read 0
      measured_[static_cast<std::size_t>(2 * i)].set(0);
      measured_[static_cast<std::size_t>(2 * i + 1)].set(0);
    }
  }
  if (on < 0) return;
  const double lim = on == 0 ? 32767.0 : 2147483647.0;
  const double x = input_.value(m);
  const double w = loops_[on].setpoint->as<double>();
  measured_[static_cast<std::size_t>(2 * on)].set_rounded(x, -lim - 1, lim);
  measured_[static_cast<std::size_t>(2 * on + 1)].set_rounded(w - x, -lim - 1, lim);
}

dsp408::StatusFlags DsvSignalChain::status_flags() const {
  const std::int8_t m = p_.control_mode();
  const bool ramps_used = control_.state() == DeviceState::Active && (m == mode::kVpoc || m == mode::kVprcOpen || m == mode::kDcol);
  if (!ramps_used) return status_flags(ramp_, ramp_b_);
  // Ramps as the parameters stand now: the TPDO answering an RPDO shows the new ramp at once.
  dsp408::CommandValueRamp ra = ramp_, rb = ramp_b_;
  configure_ramps(ra, rb);
  return status_flags(ra, rb);
}

dsp408::StatusFlags DsvSignalChain::status_flags(const dsp408::CommandValueRamp& ra, const dsp408::CommandValueRamp& rb) const {
  dsp408::StatusFlags f;
  const std::int8_t m = p_.control_mode();
  const DeviceState s = control_.state();
  const bool live = s == DeviceState::Active;
  if (live && (m == mode::kVpoc || m == mode::kVprcOpen || m == mode::kDcol)) {
    // The set point may have changed since the last cycle (an RPDO is answered at once).
    const std::int8_t op = p_.mode_of_operation();
    double w = m == mode::kVpoc ? value(par_.vpoc_a) / 16384.0 : m == mode::kVprcOpen ? value(par_.vprc_a) / 16384.0 : value(par_.dcol) / 100000.0;
    if ((m == mode::kVpoc || m == mode::kVprcOpen) && value(par_.inversion) == -1) {
      if (op == 2 || (op == 1 && o_.op_mode1_bipolar)) w = -w;
      if (op == 1 && !o_.op_mode1_bipolar) w = 1.0 - w;
    }
    if (op == 3) w = std::clamp(w, 0.0, 1.0);
    f.ramp_running = ra.running(w);
    if (op == 3) {
      const double wb = std::clamp((m == mode::kVpoc ? value(par_.vpoc_b) : value(par_.vprc_b)) / 16384.0, 0.0, 1.0);
      f.ramp_running = f.ramp_running || rb.running(wb);
    }
  }
  if (is_closed_loop(m) && (live || s == DeviceState::Hold)) {
    f.window_reached = window_reached_;
    f.warning = trailing_;
  }
  if (p_.mode_of_operation() == 3 && (m == mode::kVpoc || m == mode::kVprcOpen || m == mode::kDcol) && live) {
    const std::uint16_t cw = control_.dsm().control_word();
    f.solenoid_a_released = cw & dsp408::control::kReleaseSolenoidA;
    f.solenoid_b_released = cw & dsp408::control::kReleaseSolenoidB;
  }
  return f;
}

void DsvSignalChain::process(sim::Time now, double dt) {
  const std::int8_t m = p_.control_mode();
  const std::int8_t op = p_.mode_of_operation();
  const DeviceState s = control_.state();
  const bool active = s == DeviceState::Active;
  const bool hold = s == DeviceState::Hold || s == DeviceState::FaultHold;
  double ia = 0, ib = 0;
  bool dither_on = true;
  if (s == DeviceState::Fault || s == DeviceState::FaultReaction) {
    // Error handling 2043h: the solenoids the reaction switches on carry Imax, without dither.
    const auto reaction = value(par_.error_handling);
    if (reaction == 1 || reaction == 3) ia = to_amperes(p_.shared(Shared::ImaxA));
    if ((reaction == 2 || reaction == 3) && o_.solenoids == 2) ib = to_amperes(p_.shared(Shared::ImaxB));
    dither_on = false;
    ramp_.reset(0);
    ramp_b_.reset(0);
    pid_.reset();
  } else if (active || hold) {
    double a = 0, b = 0;
    bool off = false;
    if (is_closed_loop(m)) {
      closed_loop(m, active, now, dt, a, b, off);
      ia = closed_loop_current(0, a);
      ib = o_.solenoids == 2 ? closed_loop_current(1, b) : 0.0;
      if (off) ia = ib = 0;
    } else if (m != mode::kLocal) {
      open_loop(m, op, active, dt, a, b);
      open_loop_currents(m, a, b, ia, ib);
    }
  } else {
    ramp_.reset(0);
    ramp_b_.reset(0);
    limiter_.reset(0);
    pid_.reset();
    window_reached_ = trailing_ = false;
  }
  cmd_a_ = ia;
  cmd_b_ = ib;
  const double fs = o_.current_full_scale();
  if (dither_on && p_.shared(Shared::DitherType) == 1) {
    dither_.configure(dsp408::Dither::Shape::Square, static_cast<double>(p_.shared(Shared::DitherFrequency)),
                      static_cast<double>(p_.shared(Shared::DitherAmplitude)) * kDitherAmpere);
  } else {
    dither_.configure(dsp408::Dither::Shape::Off, 0, 0);
  }
  out_a_ = driver_ok_a_ ? dither_.apply(ia, now, fs) : 0.0;
  out_b_ = driver_ok_b_ ? dither_.apply(ib, now, fs) : 0.0;
  publish_measurements();

  // The flags status_flags() would find now, from what this cycle computed: in ACTIVE with an
  // open-loop mode, open_loop() has just configured the ramps with the parameters as they stand
  // and its targets are the set points status_flags() derives (but set point B of mode 6, which
  // open_loop() does not use).
  dsp408::StatusFlags f;
  const bool open_mode = m == mode::kVpoc || m == mode::kVprcOpen || m == mode::kDcol;
  if (active && open_mode) {
    f.ramp_running = ramp_.running(target_);
    if (op == 3) {
      const double wb = m == mode::kDcol ? std::clamp(value(par_.vprc_b) / 16384.0, 0.0, 1.0) : target_b_;
      f.ramp_running = f.ramp_running || ramp_b_.running(wb);
    }
    if (op == 3) {
      const std::uint16_t cw = control_.dsm().control_word();
      f.solenoid_a_released = cw & dsp408::control::kReleaseSolenoidA;
      f.solenoid_b_released = cw & dsp408::control::kReleaseSolenoidB;
    }
  }
  if (is_closed_loop(m) && (active || s == DeviceState::Hold)) {
    f.window_reached = window_reached_;
    f.warning = trailing_;
  }
  control_.publish_status(f);
}

}  // namespace dsv
