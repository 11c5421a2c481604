// Device temperature (2500h, manual §7.13): sampled every 60 s (the first sample at start-up),
// highest and lowest values kept (EEPROM), and an excursion beyond the limits or a failed read
// gives one EMCY 4200h (info 10h over, 20h under, 40h read error), error register 08h and its
// 6505h warning bit; back inside the limits the bits clear and EMCY 0000h follows.
#pragma once

#include <cstdint>

#include "devices/canopen/object_dictionary.h"
#include "devices/wdga/diagnostics.h"
#include "sim/time.h"

namespace wdga {

inline constexpr std::uint16_t kEmcyTemperature = 0x4200;

class TemperatureMonitor {
 public:
  TemperatureMonitor(canopen::ObjectDictionary& od, Diagnostics& diagnostics, unsigned period_s);
  /// Installs the limit rule (upper > lower, else 0x06090036).
  void bind();

  double input = 25.0;  ///< °C, input port
  bool read_failure = false;
  bool over_temperature = false;  ///< fault: the sensor reads above the upper limit

  /// Start-up: the next sample is due now. The extremes are kept (EEPROM).
  void restart(sim::Time now);
  void process(sim::Time now);

 private:
  void sample();

  canopen::ObjectDictionary& od_;
  Diagnostics& diagnostics_;
  sim::Duration period_;
  sim::Time next_{};
  bool have_extremes_ = false;
  std::int16_t highest_ = 0, lowest_ = 0;
  std::uint8_t excursion_ = 0;  // EMCY info of the excursion in progress (0 = none)
};

}  // namespace wdga
