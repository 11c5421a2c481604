// The DSV controller's actual-value acquisition (§5.4.2, §5.4.41-43, §5.4.57-60, §5.4.74): a
// transducer turns the plant's measurand into the analog signal of analog input 3 (0..10 V,
// 0..20 mA or 4..20 mA after 2200h), which becomes
//   mode 4: counts of the internal bus resolution (0 V/0 mA → 0, 10 V/20 mA → 16384,
//           4..20 mA: 3277 + (I − 4 mA)·13107/16 mA, rounded half up);
//   modes 7, 9: a 10-bit conversion scaled from the interface range (Min/Max interface, mV or
//           µA) to the reference range (Min/Max reference, unit/1000).
// A broken 4..20 mA loop (below the threshold, 2201h = 1) is the cable break (EMCY 0x3422).
#pragma once

#include <algorithm>
#include <cstdint>

#include "devices/dsv/dsv_options.h"
#include "devices/dsv/dsv_parameters.h"

namespace dsv {

class ActualValueInput {
 public:
  ActualValueInput(DsvParameters& parameters, const DsvOptions& options);

  /// One sample: the plant's measurand (SI) and whether the signal wire is broken.
  void sample(double measurand, bool wire_broken) {
    const double p = std::clamp((measurand - o_.sensor_min) / (o_.sensor_max - o_.sensor_min), 0.0, 1.0);
    const std::int64_t type = signal_type();
    switch (type) {
      case 0: signal_ = 10.0 * p; break;                   // V
      case 2: signal_ = wire_broken ? 0 : 20.0 * p; break;  // mA
      default: signal_ = wire_broken ? 0 : 4.0 + 16.0 * p; break;
    }
    if (wire_broken && type == 0) signal_ = 0;
  }
  /// The analog signal: V for signal type 0, mA for 2 and 3.
  double signal() const { return signal_; }
  bool cable_break() const;
  /// Actual value of closed-loop mode `m` in its bus unit (counts for 4, unit/1000 for 7, 9).
  double value(std::int8_t m) const;
  /// 2050h: reference range / interface range in ADC counts (integer part, at least 1).
  std::uint32_t internal_resolution(std::int8_t m) const;
  /// Mode 4 thresholds are given in unit/1000: counts per unit through the same scaling.
  double counts_per_unit() const;

 private:
  double interface_counts_16384(std::int64_t raw) const;  ///< an interface value (mV/µA) in bus counts
  double adc_full_scale() const;                            ///< 10000 mV or 20000 µA
  /// Min/max reference and interface of closed-loop mode `m` (DsvParameters::scaling_objects), bound.
  struct Scaling {
    canopen::EntryRef<std::int64_t> min_reference, max_reference, min_interface, max_interface;
  };
  const Scaling& scaling(std::int8_t m) const;
  std::int64_t signal_type() const { return signal_type_.get(); }  // 2200h

  DsvParameters& p_;
  const DsvOptions& o_;
  // Read every cycle: bound once instead of looked up by index.
  canopen::EntryRef<std::int64_t> signal_type_, cable_break_detection_;  // 2200h, 2201h
  Scaling scaling_[3];                                          // modes 4, 7, 9
  double signal_ = 0;
};

}  // namespace dsv
