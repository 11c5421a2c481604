#include "devices/vtvpcd/vtvpcd_emcy_codes.h"

#include <array>

namespace vtvpcd {

std::span<const devices::EmcyCode> emcy_codes() {
  static constexpr std::array<devices::EmcyCode, 18> kCodes{{
    {0x0000, "no error (error reset)"},
    {0x1000, "generic error"},
    {0x3400, "cable break, current inputs"},
    {0x3422, "control voltage undervoltage"},
    {0x5230, "sensors, general"},
    {0x5235, "external sensor (pressure transducer)"},
    {0x5236, "position sensor (swivel-angle LVDT)"},
    {0x6000, "software"},
    {0x6010, "software reset (watchdog)"},
    {0x6100, "internal software"},
    {0x6200, "user software"},
    {0x6300, "data set"},
    {0x6310, "parameter lost / overwritten"},
    {0x6320, "parameter error"},
    {0x8100, "communication error (life guarding or heartbeat consumer)"},
    {0x8300, "closed-loop controller monitoring"},
    {0x8301, "position monitoring error (swivel-angle loop)"},
    {0x8302, "pressure monitoring error (pressure loop)"},
  }};
  return kCodes;
}

}  // namespace vtvpcd
