// MD2 control modes (object 0x6043, §5.3/§5.4.26) and the objects each mode uses per channel.
#pragma once

#include <cstdint>

#include "devices/canopen/data_type.h"
#include "devices/md2/md2_options.h"

namespace md2 {

namespace mode {
constexpr std::int8_t kNone = 0;         ///< waiting for a control mode
constexpr std::int8_t kVpoc = 1;         ///< spool position open loop (amplifier)
constexpr std::int8_t kVprcOpen = 3;     ///< pressure valve open loop
constexpr std::int8_t kVprcClosed = 4;   ///< pressure valve closed loop, 1 solenoid (controller)
constexpr std::int8_t kDcol = 6;         ///< open-loop movement (controller)
constexpr std::int8_t kDsc = 7;          ///< velocity control axis (controller)
constexpr std::int8_t kDpc = 9;          ///< position control axis (controller)
constexpr std::int8_t kVprcClosed2 = -5; ///< pressure closed loop, 2 solenoids (Wandfluh)
constexpr std::int8_t kTwoPoint1 = -6;   ///< 2-point controller, 1 solenoid
constexpr std::int8_t kTwoPoint2 = -7;   ///< 2-point controller, 2 solenoids
constexpr std::int8_t kThreePoint = -8;  ///< 3-point controller, 2 solenoids
}  // namespace mode

bool mode_supported(Variant v, std::int8_t m);
constexpr bool is_n_point(std::int8_t m) {
  return m == mode::kTwoPoint1 || m == mode::kTwoPoint2 || m == mode::kThreePoint;
}
constexpr bool is_closed_loop(std::int8_t m) {
  return m == mode::kVprcClosed || m == mode::kDsc || m == mode::kDpc || m == mode::kVprcClosed2 || is_n_point(m);
}
/// 16-bit set point in bus resolution (modes 0, 1, 3, 4, −5) vs 32-bit scaled value.
constexpr bool is_16_bit(std::int8_t m) {
  return m == mode::kNone || m == mode::kVpoc || m == mode::kVprcOpen || m == mode::kVprcClosed ||
         m == mode::kVprcClosed2;
}
std::uint32_t default_capability(Variant v);

/// Object indices of channel c (1-based). Manufacturer objects exist for channels 1..4 only.
struct ChannelIndices {
  int channel = 1;
  std::uint16_t profile_offset = 0;  ///< 0x800·(c−1)
  std::uint16_t control_word() const { return static_cast<std::uint16_t>(0x6040 + profile_offset); }
  std::uint16_t status_word() const { return static_cast<std::uint16_t>(0x6041 + profile_offset); }
  std::uint16_t device_mode() const { return static_cast<std::uint16_t>(0x6042 + profile_offset); }
  std::uint16_t control_mode() const { return static_cast<std::uint16_t>(0x6043 + profile_offset); }
  std::uint16_t device_local() const { return static_cast<std::uint16_t>(0x604F + profile_offset); }
  std::uint16_t capability() const { return static_cast<std::uint16_t>(0x605F + profile_offset); }
  std::uint16_t vpoc_setpoint() const { return static_cast<std::uint16_t>(0x6300 + profile_offset); }
  std::uint16_t vprc_setpoint() const { return static_cast<std::uint16_t>(0x6380 + profile_offset); }
  std::uint16_t dcol_setpoint() const { return static_cast<std::uint16_t>(0x6480 + profile_offset); }
  std::uint16_t dsc_setpoint() const { return static_cast<std::uint16_t>(0x6500 + profile_offset); }
  std::uint16_t dpc_setpoint() const { return static_cast<std::uint16_t>(0x6600 + profile_offset); }
  std::uint16_t vprc_actual() const { return static_cast<std::uint16_t>(0x6381 + profile_offset); }
  std::uint16_t dsc_actual() const { return static_cast<std::uint16_t>(0x6501 + profile_offset); }
  std::uint16_t dpc_actual() const { return static_cast<std::uint16_t>(0x6601 + profile_offset); }
  std::uint16_t vprc_deviation() const { return static_cast<std::uint16_t>(0x63D0 + profile_offset); }
  std::uint16_t dsc_deviation() const { return static_cast<std::uint16_t>(0x6550 + profile_offset); }
  std::uint16_t dpc_deviation() const { return static_cast<std::uint16_t>(0x6650 + profile_offset); }
  // Manufacturer area (§5.4.3 table: 2200/2900/3000/3700, 2400/2B00/3200/3900, ...).
  std::uint16_t actual_value_mode() const { return static_cast<std::uint16_t>(0x2200 + manufacturer_offset()); }
  std::uint16_t actual_input_16() const { return static_cast<std::uint16_t>(0x2201 + manufacturer_offset()); }
  std::uint16_t actual_input_32() const { return static_cast<std::uint16_t>(0x2202 + manufacturer_offset()); }
  std::uint16_t speed_positive() const { return static_cast<std::uint16_t>(0x2400 + manufacturer_offset()); }
  std::uint16_t speed_negative() const { return static_cast<std::uint16_t>(0x2401 + manufacturer_offset()); }
  /// n-point set point 0x2280/0x2300/0x2380; channel 4's would be 0x2400, which is Speed+ of
  /// channel 1 (§7 #17): channel 4 has none (0).
  std::uint16_t n_point_setpoint() const {
    return channel <= 3 ? static_cast<std::uint16_t>(0x2280 + 0x80 * (channel - 1)) : 0;
  }
  bool has_manufacturer_objects() const { return channel <= 4; }

  /// Set-point object (sub 1; the n-point one is a VAR at sub 0) of a control mode.
  std::uint16_t setpoint_for(std::int8_t m) const;
  std::uint8_t setpoint_sub(std::int8_t m) const { return is_n_point(m) ? 0 : 1; }
  /// Actual value object of a closed-loop mode (sub 1), 0 if none.
  std::uint16_t actual_for(std::int8_t m) const;

  static ChannelIndices of(int c) {
    return ChannelIndices{c, static_cast<std::uint16_t>(0x800 * (c - 1))};
  }

 private:
  std::uint16_t manufacturer_offset() const { return static_cast<std::uint16_t>(0x700 * (channel - 1)); }
};

}  // namespace md2
