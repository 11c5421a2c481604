#include "devices/wdga/temperature_monitor.h"

#include <algorithm>
#include <cmath>

#include "devices/wdga/wdga_object_dictionary.h"

namespace wdga {

using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

namespace {
constexpr std::uint8_t kInfoHigh = 0x10, kInfoLow = 0x20, kInfoRead = 0x40;
constexpr std::uint8_t kCurrent = 1, kUpper = 2, kLower = 3, kHighest = 4, kLowest = 5;
}  // namespace

TemperatureMonitor::TemperatureMonitor(canopen::ObjectDictionary& od, Diagnostics& diagnostics, unsigned period_s)
    : od_(od), diagnostics_(diagnostics), period_(sim::milliseconds(static_cast<std::int64_t>(period_s) * 1000)) {}

void TemperatureMonitor::bind() {
  od_.add_check(obj::kTemperature, kUpper, [this](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    return canopen::value_as<int>(e.type, data) > od_.get<int>(obj::kTemperature, kLower) ? SdoAbort::None
                                                                                          : SdoAbort::MaxLessThanMin;
  });
  od_.add_check(obj::kTemperature, kLower, [this](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    return canopen::value_as<int>(e.type, data) < od_.get<int>(obj::kTemperature, kUpper) ? SdoAbort::None
                                                                                          : SdoAbort::MaxLessThanMin;
  });
  // The extremes are the device's own record, not dictionary defaults.
  for (std::uint8_t sub : {kHighest, kLowest}) {
    od_.add_read_hook(obj::kTemperature, sub, [this, sub](OdEntry& e, Origin) {
      canopen::encode_unsigned(static_cast<std::uint64_t>(static_cast<std::int64_t>(sub == kHighest ? highest_ : lowest_)),
                               e.value);
      return SdoAbort::None;
    });
  }
}

void TemperatureMonitor::restart(sim::Time now) { next_ = now; }

void TemperatureMonitor::process(sim::Time now) {
  if (now < next_) return;
  next_ = now + period_;
  sample();
}

void TemperatureMonitor::sample() {
  const int upper = od_.get<int>(obj::kTemperature, kUpper);
  const int lower = od_.get<int>(obj::kTemperature, kLower);
  std::uint8_t info = 0;
  if (read_failure) {
    info = kInfoRead;
  } else {
    const double celsius = over_temperature ? std::max(input, upper + 10.0) : input;
    const auto t = static_cast<std::int16_t>(std::clamp(std::lround(celsius), -32768L, 32767L));
    od_.set<std::int16_t>(obj::kTemperature, kCurrent, t);
    highest_ = have_extremes_ ? std::max(highest_, t) : t;
    lowest_ = have_extremes_ ? std::min(lowest_, t) : t;
    have_extremes_ = true;
    if (t > upper) info = kInfoHigh;
    if (t < lower) info = kInfoLow;
  }
  std::uint16_t warnings = diagnostics_.warnings() & ~(kWarnOverTemperature | kWarnUnderTemperature | kWarnTemperatureRead);
  if (info == kInfoHigh) warnings |= kWarnOverTemperature;
  if (info == kInfoLow) warnings |= kWarnUnderTemperature;
  if (info == kInfoRead) warnings |= kWarnTemperatureRead;
  diagnostics_.set_warnings(warnings, kEmcyTemperature);  // a temperature excursion is a device fault
  // One EMCY per excursion [M "einmaliger Temperaturalarm"]; register 08h only.
  if (info != 0 && excursion_ == 0) diagnostics_.raise(kEmcyTemperature, kErTemperature, {info, 0, 0, 0, 0});
  if (info == 0 && excursion_ != 0) diagnostics_.clear(kEmcyTemperature);
  excursion_ = info;
}

}  // namespace wdga
