#include "devices/dsv/actual_value_input.h"

#include <algorithm>
#include <cmath>

#include "devices/dsv/control_mode.h"

namespace dsv {

namespace {
constexpr double kAdcCounts = 1024;  // 10-bit acquisition (§5.4.1)
}

ActualValueInput::ActualValueInput(DsvParameters& parameters, const DsvOptions& options)
    : p_(parameters),
      o_(options),
      signal_type_(parameters.bind_value(0x2200)),
      cable_break_detection_(parameters.bind_value(0x2201)) {
  const std::int8_t modes[3] = {mode::kVprcClosed, mode::kDsc, mode::kDpc};
  for (int i = 0; i < 3; ++i) {
    const auto s = DsvParameters::scaling_objects(modes[i]);
    scaling_[i] = {p_.bind_value(s.min_reference), p_.bind_value(s.max_reference), p_.bind_value(s.min_interface),
                   p_.bind_value(s.max_interface)};
  }
}

const ActualValueInput::Scaling& ActualValueInput::scaling(std::int8_t m) const {
  // The objects DsvParameters::scaling_objects(m) names: any mode but 4 and 7 has those of 9.
  return scaling_[m == mode::kVprcClosed ? 0 : m == mode::kDsc ? 1 : 2];
}

bool ActualValueInput::cable_break() const {
  return cable_break_detection_.get() == 1 && signal_type() == 3 && signal_ < o_.cable_break_ma;
}

double ActualValueInput::adc_full_scale() const { return signal_type() == 0 ? 10000.0 : 20000.0; }

double ActualValueInput::interface_counts_16384(std::int64_t raw) const {
  const double s = static_cast<double>(raw) / 1000.0;  // V or mA
  switch (signal_type()) {
    case 0: return s / 10.0 * 16384;
    case 2: return s / 20.0 * 16384;
    default: return 3277 + (s - 4.0) * 13107.0 / 16.0;
  }
}

double ActualValueInput::value(std::int8_t m) const {
  if (m == mode::kVprcClosed) {
    double counts;
    switch (signal_type()) {
      case 0: counts = signal_ / 10.0 * 16384; break;
      case 2: counts = signal_ / 20.0 * 16384; break;
      default: counts = std::floor(3277 + (signal_ - 4.0) * 13107.0 / 16.0 + 0.5); break;
    }
    return std::clamp(std::round(counts), 0.0, 16384.0);
  }
  const Scaling& s = scaling(m);
  auto get = [](const canopen::EntryRef<std::int64_t>& e) { return e.get(); };  // as DsvParameters::value()
  const double min_ref = static_cast<double>(get(s.min_reference));
  const double max_ref = static_cast<double>(get(s.max_reference));
  const double fs = adc_full_scale();
  const double c_min = static_cast<double>(get(s.min_interface)) * kAdcCounts / fs;
  const double c_max = static_cast<double>(get(s.max_interface)) * kAdcCounts / fs;
  if (c_max <= c_min) return min_ref;  // no interface range configured yet
  const double signal_raw = signal_ * 1000.0;  // mV or µA
  const double count = std::floor(signal_raw * kAdcCounts / fs + 1e-9);  // exact at the steps
  return std::round(min_ref + (count - c_min) * (max_ref - min_ref) / (c_max - c_min));
}

std::uint32_t ActualValueInput::internal_resolution(std::int8_t m) const {
  const auto s = DsvParameters::scaling_objects(m);
  const double reference = static_cast<double>(p_.value(s.max_reference) - p_.value(s.min_reference));
  const double interface = static_cast<double>(p_.value(s.max_interface) - p_.value(s.min_interface)) * kAdcCounts /
                           adc_full_scale();
  if (interface <= 0 || reference <= 0) return 1;
  return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(reference / interface));
}

double ActualValueInput::counts_per_unit() const {
  const auto s = DsvParameters::scaling_objects(mode::kVprcClosed);
  const double reference = static_cast<double>(p_.value(s.max_reference) - p_.value(s.min_reference));
  const double counts = interface_counts_16384(p_.value(s.max_interface)) - interface_counts_16384(p_.value(s.min_interface));
  if (reference <= 0 || counts <= 0) return 1;  // unscaled: thresholds taken as counts
  return counts / reference;
}

}  // namespace dsv
