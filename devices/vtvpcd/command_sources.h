// The commands and controller parameters of one cycle (digest §4.2): from binary set k, or in
// direct mode from the bus objects (cmd_source = bus) or the card's analog inputs
// (cmd_source = analog). Each raw bus value is converted with its own printed scale and clamped
// to its documented range before use: the manual leaves limit checks to the PLC (§3.3) and the
// card must not act on an overflowed value.
#pragma once

#include <bit>
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

/// What select_commands() reads in one cycle: the raw values of the objects (or the analog
/// inputs) that the selected set and the settings use, everything else zero. Equal inputs give
/// equal commands: select_commands() = convert_commands(gather_commands()).
struct CommandInputs {
  enum class Source : std::uint8_t { Binary, Bus, Analog };
  Source source = Source::Binary;
  std::int32_t alpha = 0, pressure = 0, power = 0;  ///< raw commands (Binary: set k; Bus: the BUS objects)
  std::uint16_t ramp_alpha = 0, ramp_pressure = 0;  ///< raw ramp times (set k; set 0 or none in direct mode)
  std::uint16_t contr_p = 0, contr_i = 0;           ///< raw controller parameters of the set's group
  std::int32_t slave_alpha = 0;                     ///< raw res. Angle CMD (BUS) (cmd_source = bus)
  double analog_alpha = 0, analog_pressure = 0, analog_power = 0;  ///< Analog
  double analog_slave = 0;                          ///< Angle CMD (b2/b4) (cmd_source = analog)
  /// The same bits (a pure function of them gives the same commands; -0.0 and NaN inputs simply
  /// convert anew). Branch-free: compared in every cycle.
  bool same_as(const CommandInputs& o) const {
    auto bits = [](double d) { return std::bit_cast<std::uint64_t>(d); };
    const std::uint64_t ints =
        (static_cast<std::uint64_t>(static_cast<std::uint8_t>(source) ^ static_cast<std::uint8_t>(o.source))) |
        static_cast<std::uint32_t>(alpha ^ o.alpha) | static_cast<std::uint32_t>(pressure ^ o.pressure) |
        static_cast<std::uint32_t>(power ^ o.power) | static_cast<std::uint32_t>(slave_alpha ^ o.slave_alpha) |
        static_cast<std::uint32_t>(ramp_alpha ^ o.ramp_alpha) | static_cast<std::uint32_t>(ramp_pressure ^ o.ramp_pressure) |
        static_cast<std::uint32_t>(contr_p ^ o.contr_p) | static_cast<std::uint32_t>(contr_i ^ o.contr_i);
    const std::uint64_t reals = (bits(analog_alpha) ^ bits(o.analog_alpha)) | (bits(analog_pressure) ^ bits(o.analog_pressure)) |
                                (bits(analog_power) ^ bits(o.analog_power)) | (bits(analog_slave) ^ bits(o.analog_slave));
    return (ints | reals) == 0;
  }
};

CommandInputs gather_commands(const SetSelection& sel, const CardParameters& p, const AnalogInputs& analog,
                              const Settings& s);
SelectedCommands convert_commands(const CommandInputs& in, const Settings& s);
SelectedCommands select_commands(const SetSelection& sel, const CardParameters& p, const AnalogInputs& analog,
                                 const Settings& s);

/// select_commands() once per cycle, converting only when what it reads changed: the raw values
/// are read every cycle, so a parameter written by SDO or RPDO acts in the next cycle as before.
class CommandSelector {
 public:
  const SelectedCommands& select(const SetSelection& sel, const CardParameters& p, const AnalogInputs& analog,
                                 const Settings& s);

 private:
  bool valid_ = false;
  CommandInputs last_;
  SelectedCommands commands_;
};

}  // namespace vtvpcd
