#include "devices/md2/md2_emcy_codes.h"

#include <array>

namespace md2 {

std::span<const devices::EmcyCode> emcy_codes() {
  static constexpr std::array<devices::EmcyCode, 7> kCodes{{
    {0x0000, "no error / error reset"},
    {0x1000, "general error"},
    {0x2311, "solenoid driver 1 cable break / short"},
    {0x2312, "solenoid driver 2 cable break / short"},
    {0x3412, "supply voltage too low"},
    {0x3422, "control voltage too low (analog signal below its minimum or cable break)"},
    {0x8100, "communication (NMT Stop or Reset communication in an enabled state, life guarding)"},
  }};
  return kCodes;
}

}  // namespace md2
