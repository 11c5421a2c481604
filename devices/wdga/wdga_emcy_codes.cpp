#include "devices/wdga/wdga_emcy_codes.h"

#include <array>

namespace wdga {

std::span<const devices::EmcyCode> emcy_codes() {
  static constexpr std::array<devices::EmcyCode, 7> kCodes{{
    {0x0000, "no error / error reset"},
    {0x4200, "device temperature out of tolerance"},
    {0x5000, "hardware fault (EEPROM)"},
    {0x8110, "CAN overrun"},
    {0x8120, "CAN error passive"},
    {0x8130, "heartbeat consumer / life-guard error"},
    {0x8140, "recovered from bus-off"},
  }};
  return kCodes;
}

}  // namespace wdga
