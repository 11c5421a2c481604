#include "devices/wdga/measurement.h"

#include <cmath>

#include "devices/wdga/wdga_object_dictionary.h"

namespace wdga {

using cia406::Int128;

Measurement::Measurement(canopen::ObjectDictionary& od, const Settings& settings) : od_(od), settings_(settings) {
  shaft_.set_signal([&] {
    cia406::ScriptedInput signal;
    (void)signal.parse(settings.signal);  // validated by parse_settings
    return signal;
  }());
  config_.physical_resolution = kPhysicalResolution;
  config_.physical_revolutions = kPhysicalRevolutions;
  config_.multiturn = settings.multiturn;
  range_ = config_.effective_range();
  position_ = canopen::EntryRef<std::uint32_t>(od, obj::kPosition, 0);
  position_high_ = canopen::EntryRef<std::uint64_t>(od, obj::kPositionHigh, 0);
  speed_ = canopen::EntryRef<std::int16_t>(od, obj::kSpeed, 1);
  acceleration_ = canopen::EntryRef<std::int16_t>(od, obj::kAcceleration, 1);
  jerk_ = canopen::EntryRef<std::int16_t>(od, obj::kJerk, 1);
  status_ = canopen::EntryRef<std::uint16_t>::optional(od, obj::kOperatingStatus, 0);
  offset_view_ = canopen::EntryRef<std::int32_t>(od, obj::kOffset, 0);
  cams_.bind(od);
  work_area_.bind(od);
}

void Measurement::load_parameters() {
  config_.operating_parameters = od_.get<std::uint16_t>(obj::kOperatingParameters);
  config_.measuring_units_per_revolution = od_.get<std::uint32_t>(obj::kUnitsPerRevolution);
  const auto tmr = od_.get<std::uint32_t>(obj::kTotalRange);
  config_.total_measuring_range = tmr == 0 ? (1ull << 32) : tmr;  // 0 is legal only on the 32-bit variant
  filter_constant_ = od_.get<std::uint8_t>(obj::kIntegration, 1);
  speed_numerator_ = od_.get<std::uint16_t>(obj::kSpeedScaling, 1);
  speed_denominator_ = od_.get<std::uint16_t>(obj::kSpeedScaling, 2);
  frequency_limit_ = od_.get<std::uint16_t>(obj::kFrequencyLimit);
  units_per_rev_ = settings_.speed_physical_units ? static_cast<double>(kPhysicalResolution)
                                                  : static_cast<double>(config_.effective_units_per_revolution());
  range_ = config_.effective_range();
  status_.set(config_.operating_parameters);
}

void Measurement::window_changed() {
  motion_.configure(od_.get<std::uint32_t>(obj::kIntegration, 2), 1e-3);
}

void Measurement::restart(sim::Time now, Int128 offset) {
  load_parameters();
  window_changed();
  offset_ = offset;
  cams_.reset();
  restart_tracking(now);
}

void Measurement::restart_tracking(sim::Time now) {
  const double revs = shaft_.revolutions(now);
  cia406::RotaryConfig unwrapped = config_;
  unwrapped.multiturn = true;
  const Int128 s = cia406::scaled_count(cia406::physical_count(revs, unwrapped), unwrapped);
  filter_.reset(s);
  motion_.reset(settings_.speed_physical_units ? static_cast<std::int64_t>(cia406::physical_count(revs, unwrapped))
                                               : static_cast<std::int64_t>(s));
  output_count_ = cia406::within_turn(s, config_);
  publish(now);
}

void Measurement::cycle(sim::Time now) {
  // Filter and speed run on the unwrapped count: no spike when a singleturn value wraps.
  const double revs = shaft_.revolutions(now);
  cia406::RotaryConfig unwrapped = config_;
  unwrapped.multiturn = true;
  const std::int64_t physical = cia406::physical_count(revs, unwrapped);
  const Int128 s = cia406::scaled_count(physical, unwrapped);
  output_count_ = cia406::within_turn(filter_.update(s, filter_constant_), config_);
  const std::int64_t directed_physical = config_.counter_clockwise() ? -physical : physical;
  motion_.push(settings_.speed_physical_units ? directed_physical : static_cast<std::int64_t>(s));
  publish(now);
}

void Measurement::publish(sim::Time) {
  // output_position() with the range worked out when the parameters were loaded.
  const auto x = static_cast<std::uint64_t>(cia406::floor_mod(output_count_ + offset_, static_cast<Int128>(range_)));
  position_.set(static_cast<std::uint32_t>(x));  // 6004h shows the low 32 bits
  position_high_.set(x);
  // Speed in steps/s, scaled by 2106h (truncated), saturated to ±32767 [M §8.9].
  const double v = motion_.speed();
  // (Truncated toward zero: saturate_i16 with integer bounds gives what it gives for trunc(v).)
  speed_.set(cia406::saturate_i16(v * speed_numerator_ / speed_denominator_, -32767, 32767));
  acceleration_.set(cia406::saturate_i16(motion_.acceleration(), -32767, 32767));
  jerk_.set(cia406::saturate_i16(motion_.jerk(), -32767, 32767));
  offset_view_.set(cia406::truncate_i32(offset_));
  frequency_exceeded_ = std::fabs(v) / units_per_rev_ > frequency_limit_;
  cams_.update(static_cast<std::int64_t>(static_cast<std::uint32_t>(x)));
  work_area_.update(static_cast<std::int64_t>(static_cast<std::uint32_t>(x)));
}

void Measurement::preset(std::uint64_t value) {
  offset_ = cia406::offset_for_preset(value, output_count_, config_);
  publish(sim::Time{});
}

void Measurement::parameters_changed(sim::Time now) {
  load_parameters();
  offset_ = 0;
  od_.set<std::uint32_t>(obj::kPreset, 0, 0u);
  od_.set<std::uint64_t>(obj::kPresetHigh, 0, 0ull);
  restart_tracking(now);  // the count changed its scale: no filter lag, no speed spike
}

}  // namespace wdga
