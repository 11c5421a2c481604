#include "devices/dsv/dsv_emcy_codes.h"

#include <array>

namespace dsv {

std::span<const devices::EmcyCode> emcy_codes() {
  static constexpr std::array<devices::EmcyCode, 10> kCodes{{
    {0x0000, "no error"},
    {0x1000, "general error"},
    {0x2300, "output current (solenoid over-current or short circuit)"},
    {0x3412, "power supply voltage too low"},
    {0x3422, "control voltage too low (command signal too low or cable break)"},
    {0x5411, "valve: solenoid A cable break or short circuit"},
    {0x5412, "valve: solenoid B cable break or short circuit"},
    {0x5510, "EPROM/EEPROM: profile data cannot be updated after a resolution change"},
    {0x5520, "RAM: profile data cannot be read from or saved in memory"},
    {0x8100, "communication (NMT Stop or Reset communication in an enabled state, life guarding)"},
  }};
  return kCodes;
}

}  // namespace dsv
