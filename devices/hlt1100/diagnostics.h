// The HLT 1100's error reporting (manual §10, §12; digest §2.7): alarm bits in 6503h, the error
// register 0x1001 (bit 5 while an alarm is set, bit 4 latched by a CAN-controller error), EMCY
// on every rising edge and "error reset" (code 0) when an alarm clears, and the one-entry error
// list 0x1003 whose count the master consumes by reading 0x1001 (one EMCY 0x0000 per entry).
#pragma once

#include <array>
#include <cstddef>
#include <array>
#include <cstddef>
#include <cstdint>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/node.h"
#include "devices/hlt1100/hlt1100_settings.h"
#include "devices/profiles/cia406/status_machines.h"

namespace hlt1100 {

/// 6503h alarm bits [M].
inline constexpr std::uint16_t kPositionError = 0x0001;
inline constexpr std::uint16_t kEepromError = 0x1000;
inline constexpr std::uint16_t kParameterError = 0x2000;

inline constexpr std::uint16_t kEmcyNoError = 0x0000;
inline constexpr std::uint16_t kEmcyCommunication = 0x8100;
inline constexpr std::uint16_t kEmcyEeprom = 0x5000;
inline constexpr std::uint16_t kEmcyParameter = 0x6300;

class Diagnostics {
 public:
  Diagnostics(canopen::Node& node, const Settings& settings);
  /// Installs the 0x1001 read side effect and the 0x1003 write rule; an alarm's setting is
  /// recorded in `recorder` as the device fault with its EMCY code.
  void bind(cia406::StatusRecorder& recorder);

  /// Sets or clears an alarm bit of 6503h; a change sends its EMCY.
  void set_alarm(std::uint16_t bit, bool active);
  /// CAN-controller error (EMCY 0x8100); the communication bit stays until the list is empty.
  void communication_error();
  /// An event with its own EMCY code and register bits (e.g. a life-guarding timeout).
  void signal(std::uint16_t code, std::uint8_t register_bits);
  /// Reset Communication: the list is cleared [M].
  void reset_communication();
  /// Sends the queued EMCYs (after the SDO answer that caused them); keeps 0x1001 current.
  void process();

  std::uint16_t alarms() const { return alarms_; }
  std::uint8_t error_register() const;
  std::uint8_t count() const { return count_; }

 private:
  std::uint16_t emcy_code(std::uint16_t bit) const;
  void record(std::uint16_t code);
  void publish();
  void clear_list(bool send_reset);

  canopen::Node& node_;
  const Settings& settings_;
  std::uint16_t alarms_ = 0;
  bool communication_latched_ = false;
  std::uint8_t count_ = 0;
  std::uint32_t last_entry_ = 0;
  void emcy(std::uint16_t code);
  struct Pending {
    std::uint16_t code;
    std::uint8_t error_register;
  };
  std::array<Pending, 16> queue_{};  // EMCYs go out from process(), after the frame that caused them
  std::size_t queued_ = 0;
  std::uint8_t published_register_ = 0;
  cia406::StatusRecorder* recorder_ = nullptr;
  canopen::EntryRef<std::uint16_t> alarms_entry_;
  canopen::EntryRef<std::uint8_t> count_entry_;
  canopen::EntryRef<std::uint32_t> last_entry_entry_;  // EMCY 0x0000 owed after 0x1001 reads (sent after the SDO answer)
};

}  // namespace hlt1100
