// The WDGA's error reporting (manual §7.3, §7.4, §7.9; digest §2.7, §2.8, §4.13): EMCYs through
// the stack's producer (0x1003 newest first, 5 entries, kept over power cycles), the
// manufacturer histories 2502h (errors), 2503h (alarms 6503h) and 2504h (warnings 6505h), the
// manufacturer status 1002h, and the error behaviour 1029h (communication / encoder errors).
#pragma once

#include <array>
#include <cstdint>

#include "devices/canopen/emergency.h"
#include "devices/canopen/node.h"
#include "devices/profiles/cia406/status_machines.h"
#include "devices/wdga/wdga_settings.h"

namespace wdga {

/// 1002h bits [M Tab. 7.10].
inline constexpr std::uint32_t kStatusSingleturnError = 0x01, kStatusMultiturnError = 0x02, kStatusEeprom = 0x04;
/// 6505h bits [M Tab. 7.12].
inline constexpr std::uint16_t kWarnFrequency = 0x0001, kWarnOverTemperature = 0x1000;
inline constexpr std::uint16_t kWarnUnderTemperature = 0x2000, kWarnTemperatureRead = 0x4000;
/// Error register bits [M Tab. 7.8].
inline constexpr std::uint8_t kErGeneric = 0x01, kErTemperature = 0x08, kErCommunication = 0x10;

class Diagnostics {
 public:
  Diagnostics(canopen::Node& node, const Settings& settings);
  /// Installs the histories' hooks; a bit set by a fault is recorded in `recorder` as the
  /// device fault with its EMCY code.
  void bind(cia406::StatusRecorder& recorder);

  /// A lasting error condition: EMCY (once), 0x1003 and 2502h.
  void raise(std::uint16_t code, std::uint8_t register_bits, canopen::Emergency::Info info = {});
  void clear(std::uint16_t code);
  /// An event without a lasting condition.
  void signal(std::uint16_t code, std::uint8_t register_bits, canopen::Emergency::Info info = {});
  /// An EMCY the stack raised itself (heartbeat consumer, life guarding): 2502h only.
  void record_error(std::uint16_t code, const canopen::Emergency::Info& info = {});

  /// 6503h (2503h on a rising edge); the bits it sets come from a device fault with EMCY
  /// `emcy_code` (0: none documented).
  void set_alarms(std::uint16_t alarms, std::uint16_t emcy_code);
  void set_warnings(std::uint16_t warnings);  ///< 6505h (2504h on a rising edge)
  /// 6505h, the bits it sets come from a device fault with EMCY `emcy_code`.
  void set_warnings(std::uint16_t warnings, std::uint16_t emcy_code);
  std::uint16_t warnings() const { return warnings_; }
  void set_status(std::uint32_t bits, bool on);  ///< 1002h

  /// 1029h:02 / :01 — 0 Pre-operational (from Operational), 1 no change, 2 Stopped.
  void apply_device_error_behaviour();
  void apply_communication_error_behaviour();

 private:
  template <typename T>
  void push(std::array<T, 5>& history, std::uint8_t& count, T value, std::uint16_t index);
  void apply(std::uint8_t sub);

  canopen::Node& node_;
  const Settings& settings_;
  cia406::StatusRecorder* recorder_ = nullptr;
  std::array<std::uint32_t, 5> errors_{};
  std::array<std::uint16_t, 5> alarm_history_{}, warning_history_{};
  std::uint8_t error_count_ = 0, alarm_count_ = 0, warning_count_ = 0;
  std::uint16_t alarms_ = 0, warnings_ = 0;
  std::uint32_t status_ = 0;
};

}  // namespace wdga
