// The manual's parameter conversion (RE 30028-02-Z §3.3/§3.4): every value crosses the bus in
// the card's internal integer format, raw = round((EU - offset) * scale), EU = raw / scale +
// offset, with offset 0 for every object of this card. Scales such as 327.67 are kept as exact
// rationals (32767/100) so the .5 boundaries round as the manual's arithmetic does
// (50 % * 327.67 = 16383.5 -> 16384), not as binary floating point happens to.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace vtvpcd {

/// A printed scale as the exact fraction num/den (327,67 = 32767/100; 12,6 = 63/5).
struct Scale {
  std::int64_t num = 1;
  std::int64_t den = 1;

  constexpr double value() const { return static_cast<double>(num) / static_cast<double>(den); }
  constexpr bool operator==(const Scale&) const = default;
};

inline constexpr Scale kScalePercent{32767, 100};   ///< 327,67: +-100 % <-> +-32767
inline constexpr Scale kScaleTable{3277, 10};       ///< 327,7: tables, valve, zero point pump
inline constexpr Scale kScalePressCmdPrinted{3247, 10};  ///< 324,7: as printed for Press CMD (A7)
inline constexpr Scale kScaleRamp{125, 1};          ///< ramp seconds: 1 LSB = 8 ms
inline constexpr Scale kScaleGain{128, 1};          ///< controller gain: 1 LSB = 1/128
inline constexpr Scale kScaleValveZero{150, 1};     ///< Zeropoint valve
inline constexpr Scale kScaleLvdtGain{63, 5};       ///< 12,6: Gain LVDT pump
inline constexpr Scale kScaleOne{1, 1};

/// floor(y) for y >= 0: below 2^63 the truncation of one conversion (no libm call; the readouts
/// are converted every cycle), the library above and for NaN.
inline double floor_non_negative(double y) {
  return y < 9223372036854775808.0 ? static_cast<double>(static_cast<std::int64_t>(y)) : std::floor(y);
}

/// "Arithmetically rounded": half away from zero.
inline double round_half_away(double x) { return x < 0 ? -floor_non_negative(-x + 0.5) : floor_non_negative(x + 0.5); }

/// EU -> raw: round(EU * num / den). The product EU*num is exact for the manual's decimal
/// examples, and the one division rounds correctly, so x.5 cases land exactly on x.5.
inline double to_raw_exact(double eu, Scale s) {
  return round_half_away(eu * static_cast<double>(s.num) / static_cast<double>(s.den));
}

/// EU -> raw, saturated to the range of a bus integer of `bytes` bytes (signed or not).
inline std::int64_t to_raw(double eu, Scale s, std::int64_t lo = std::numeric_limits<std::int32_t>::min(),
                           std::int64_t hi = std::numeric_limits<std::int32_t>::max()) {
  if (std::isnan(eu)) return 0;
  const double r = to_raw_exact(eu, s);
  if (r <= static_cast<double>(lo)) return lo;
  if (r >= static_cast<double>(hi)) return hi;
  return static_cast<std::int64_t>(r);
}

/// raw -> EU.
inline double to_eu(std::int64_t raw, Scale s) {
  return static_cast<double>(raw) * static_cast<double>(s.den) / static_cast<double>(s.num);
}

}  // namespace vtvpcd
