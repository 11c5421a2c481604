#include "devices/dsv/control_mode.h"

namespace dsv {

bool mode_supported(Variant v, std::int8_t m) {
  switch (m) {
    case mode::kLocal: return true;
    case mode::kVpoc:
    case mode::kVprcOpen: return v == Variant::Amplifier;
    case mode::kVprcClosed:
    case mode::kDcol:  // "only selectable with DSV controller"
    case mode::kDsc:
    case mode::kDpc: return v == Variant::Controller;
    default: return false;
  }
}

std::uint32_t default_capability(Variant v) {
  // Amplifier: proportional valve, spool open loop, pressure open loop (bits 24, 25, 27);
  // controller: proportional valve, pressure closed loop (24, 28). A-47.
  return v == Variant::Amplifier ? 0x0B000000u : 0x11000000u;
}

}  // namespace dsv
