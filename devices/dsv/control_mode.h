// DSV control modes (object 6043h, §5.3/§5.4.21): which the variant offers, and the set of
// control modes in which each object exists (§5.4.3 "depending on the device control mode only
// the appropriate objects are accessible").
#pragma once

#include <cstdint>

#include "devices/dsv/dsv_options.h"

namespace dsv {

namespace mode {
constexpr std::int8_t kLocal = 0;       ///< local operating mode
constexpr std::int8_t kVpoc = 1;        ///< spool position open loop (amplifier)
constexpr std::int8_t kVprcOpen = 3;    ///< pressure valve open loop (amplifier)
constexpr std::int8_t kVprcClosed = 4;  ///< pressure valve closed loop (controller)
constexpr std::int8_t kDcol = 6;        ///< open-loop movement (controller)
constexpr std::int8_t kDsc = 7;         ///< velocity control axis (controller)
constexpr std::int8_t kDpc = 9;         ///< position control axis (controller)
}  // namespace mode

/// A set of control modes as a bit mask (bit m for mode m).
using ModeSet = std::uint16_t;
constexpr ModeSet modes(std::initializer_list<int> list) {
  ModeSet s = 0;
  for (int m : list) s = static_cast<ModeSet>(s | (1u << m));
  return s;
}
constexpr ModeSet kAllModes = modes({0, 1, 3, 4, 6, 7, 9});
constexpr bool in(ModeSet s, std::int8_t m) { return m >= 0 && m < 16 && (s >> m) & 1u; }

bool mode_supported(Variant v, std::int8_t m);
constexpr bool is_closed_loop(std::int8_t m) { return m == mode::kVprcClosed || m == mode::kDsc || m == mode::kDpc; }
std::uint32_t default_capability(Variant v);

}  // namespace dsv
