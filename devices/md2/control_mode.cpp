#include "devices/md2/control_mode.h"

namespace md2 {

bool mode_supported(Variant v, std::int8_t m) {
  switch (m) {
    case mode::kNone: return true;
    case mode::kVpoc: return v == Variant::Amplifier;  // "only selectable with MD2 amplifier"
    case mode::kVprcOpen: return true;                  // amplifier and controller
    case mode::kVprcClosed:
    case mode::kDcol:
    case mode::kDsc:
    case mode::kDpc:
    case mode::kVprcClosed2:
    case mode::kTwoPoint1:
    case mode::kTwoPoint2:
    case mode::kThreePoint: return v == Variant::Controller;
    default: return false;
  }
}

std::uint32_t default_capability(Variant v) {
  // Amplifier: proportional valve, spool open loop, pressure open loop (bits 24, 25, 27).
  // Controller: n-point (14), drive (16), open-loop movement (17), velocity (18), position (20),
  // proportional valve (24), pressure open (27) and closed loop (28).
  return v == Variant::Amplifier ? 0x0B000000u : 0x19174000u;
}

std::uint16_t ChannelIndices::setpoint_for(std::int8_t m) const {
  switch (m) {
    case mode::kVpoc:
    case mode::kNone: return vpoc_setpoint();
    case mode::kVprcOpen:
    case mode::kVprcClosed:
    case mode::kVprcClosed2: return vprc_setpoint();
    case mode::kDcol: return dcol_setpoint();
    case mode::kDsc: return dsc_setpoint();
    case mode::kDpc: return dpc_setpoint();
    default: return n_point_setpoint();
  }
}

std::uint16_t ChannelIndices::actual_for(std::int8_t m) const {
  switch (m) {
    case mode::kVprcClosed:
    case mode::kVprcClosed2: return vprc_actual();
    case mode::kDsc: return dsc_actual();
    case mode::kDpc: return dpc_actual();
    default: return 0;
  }
}

}  // namespace md2
