// The commands and controller parameters of one cycle (digest §4.2): from binary set k, or in
// direct mode from the bus objects (cmd_source = bus) or the card's analog inputs
// (cmd_source = analog). Each raw bus value is converted with its own printed scale and clamped
// to its documented range before use: the manual leaves limit checks to the PLC (§3.3) and the
// card must not act on an overflowed value.
#pragma once

#include <cstdint>

#include "devices/vtvpcd/binary_set_selector.h"
#include "devices/vtvpcd/card_parameters.h"
#include "devices/vtvpcd/settings.h"

namespace vtvpcd {

/// The card's analog command inputs in EU (side interface / plant ports).
struct AnalogInputs {
  double angle_b14_b16_pct = 0;   ///< Angle CMD (b14/b16)
  double angle_b2_b4_pct = 0;     ///< Angle CMD (b2/b4): resulting-angle input of a slave
  double pressure_b18_b20_bar = 0;  ///< Press CMD (b18/b20)
  double power_f8_f10_pct = 0;    ///< Power CMD (f8/f10)
};

struct PumpLimits {
  double alpha_lo = 0;    ///< swivel range of the pump type, %
  double alpha_hi = 100;
};
PumpLimits limits_of(PumpType type);

struct SelectedCommands {
  double alpha_pct = 0;       ///< alpha_sel, clamped to the swivel range
  double pressure_bar = 0;    ///< p_sel, clamped to 0..600 bar
  double power_pct = 0;       ///< P_sel, clamped to 0..100 %
  double ramp_alpha_s = 0;    ///< 0 = no ramp
  double ramp_pressure_s = 0;
  double kp = 1;              ///< pressure controller gain (Contr P / 128)
  double ti_ms = 100;         ///< pressure controller integral time (Contr I)
  double slave_alpha_pct = 0; ///< resulting angle commanded to a slave
};

SelectedCommands select_commands(const SetSelection& sel, const CardParameters& p, const AnalogInputs& analog,
                                 const Settings& s);

}  // namespace vtvpcd
