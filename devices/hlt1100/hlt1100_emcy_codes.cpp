#include "devices/hlt1100/hlt1100_emcy_codes.h"

#include <array>

namespace hlt1100 {

std::span<const devices::EmcyCode> emcy_codes() {
  static constexpr std::array<devices::EmcyCode, 5> kCodes{{
    {0x0000, "error reset / no error"},
    {0x8100, "communication error (error passive, bus-off recovery, RX overrun)"},
    {0xFF00, "position error: no magnet detected"},
    {0x5000, "EEPROM error"},
    {0x6300, "parameter error"},
  }};
  return kCodes;
}

}  // namespace hlt1100
