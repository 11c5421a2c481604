// How an engineer reads a physical value: the display unit a port's owner chooses for its SI
// value (bar for a pressure in Pa, mm for a position in m, rpm for a shaft speed in rad/s ...),
// with display = si × scale + offset. Metadata only: nothing converts values on the tick.
#pragma once

#include <numbers>
#include <string_view>

namespace sim {

struct DisplayUnit {
  std::string_view unit;  ///< "" = show the SI unit itself (scale 1, offset 0)
  double scale = 1.0;
  double offset = 0.0;
  /// The smallest range a plot's axis spans, in the display unit (0: any): what an engineer
  /// calls "not moving" (a pressure at rest to a hundredth of a bar) is drawn flat, not
  /// magnified into ticks of -0.00702 bar.
  double span = 0.0;
};

/// The display units the plant's and the devices' ports use; the port's owner picks one.
namespace display {
inline constexpr DisplayUnit as_si{};
inline constexpr DisplayUnit bar{"bar", 1e-5, 0.0, 1.0};            // Pa
inline constexpr DisplayUnit mm{"mm", 1e3, 0.0, 1.0};               // m
inline constexpr DisplayUnit mm_per_s{"mm/s", 1e3, 0.0, 1.0};       // m/s
inline constexpr DisplayUnit rpm{"rpm", 60.0 / (2.0 * std::numbers::pi), 0.0, 10.0};  // rad/s
inline constexpr DisplayUnit l_per_min{"l/min", 6e4, 0.0, 1.0};     // m^3/s
inline constexpr DisplayUnit percent{"%", 100.0, 0.0, 1.0};         // a fraction (1)
inline constexpr DisplayUnit degree{"°", 180.0 / std::numbers::pi, 0.0, 1.0};          // rad
inline constexpr DisplayUnit turns{"turns", 1.0 / (2.0 * std::numbers::pi), 0.0, 0.01};  // rad, multiturn
inline constexpr DisplayUnit mA{"mA", 1e3, 0.0, 10.0};               // A
inline constexpr DisplayUnit ampere{"A", 1.0, 0.0, 0.01};            // A
inline constexpr DisplayUnit volt{"V", 1.0, 0.0, 0.1};              // V
inline constexpr DisplayUnit degree_celsius{"°C", 1.0, 0.0, 1.0};   // degC
inline constexpr DisplayUnit kilonewton{"kN", 1e-3, 0.0, 0.1};      // N
inline constexpr DisplayUnit newton_metre{"N m", 1.0, 0.0, 1.0};    // N m
inline constexpr DisplayUnit on_off{"on/off", 1.0, 0.0, 1.0};       // a binary input 0/1
}  // namespace display

}  // namespace sim
