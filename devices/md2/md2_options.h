// Configuration of an emulated MD2: the variant and every knob (DeviceOptions::settings by
// name). The MD2's tuning (Imin/Imax, dither, ramps, controller gains, scaling) lives in the PASO
// tool, not in bus objects, so it is configuration here; docs/devices/md2.md lists each knob with
// its default and the digest reference.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "devices/device.h"
#include "devices/profiles/wandfluh/communication.h"

namespace md2 {

enum class Variant : std::uint8_t { Amplifier, Controller };

/// Engineering unit of the 32-bit scaled objects (§5.4.1): value = physical/unit × 1000.
struct Unit {
  std::string name;  ///< "mm", "bar", "l/min", ...
  double si = 1;     ///< one unit in SI (1 mm = 0.001 m)
  double max = 0;    ///< largest raw value of the unit's range
};
/// Looks up a unit by name; false if unknown.
bool find_unit(const std::string& name, Unit& out);

struct Md2Options {
  Variant variant = Variant::Amplifier;
  wandfluh::CommonOptions common;
  std::uint8_t node_id = 1;
  int channels = 8;
  std::int8_t delivery_control_mode = 1;  ///< control_mode: 1 amplifier, 3 controller
  int solenoids = 2;
  // Current stage (A), dither, dead band, ramps.
  double i_min_a = 0.2, i_max_a = 1.0, i_min_b = 0.2, i_max_b = 1.0;
  double i_limit = 2.6;            ///< output stage full scale (A)
  double dither_frequency = 100;   ///< Hz
  double dither_level = 0.05;      ///< fraction of Imax, peak-to-peak
  bool dither_sine = false;
  double deadband = 164;           ///< bus units (1 % of 16384)
  double ramp_up_ms = 0, ramp_down_ms = 0;
  double bus_full_scale = 16384;
  // Scaled (32-bit) modes and closed loop.
  Unit unit{"mm", 0.001, 2000000};
  double setpoint_min = 0, setpoint_max = 2000000;
  double p_range = 315e5;          ///< Pa at 100 % (16-bit pressure modes)
  double kp = 1, ki = 0, kd = 0, kff = 0;
  double window = 164;             ///< target window (bit 12) of the 16-bit modes, bus units
  double window_scaled = 0;        ///< target window of modes 7, 9 (unit/1000); 0 → 1 % of the span
  double hysteresis = 0.005;       ///< n-point controllers, fraction of the span
  // Supply and temperature.
  double supply_min = 18;          ///< V: below → EMCY 0x3412
  double ambient_temperature = 25; ///< °C
  double thermal_gain = 10;        ///< °C per A² (both solenoids)
  std::uint32_t capability = 0;    ///< 0x605F; 0 = the variant's default
  std::uint32_t device_type = 0x10000198;  ///< 0x1000 as printed (the text's bit 31 would give 0x80000198)
  bool vpoc_mapping_literal = false;  ///< RPDOs map "command value VPOC" (0x6300) in modes 3, 4, −5 too
  bool tpdo_actual_value = true;      ///< closed-loop default TPDO carries the actual value
  bool pdo_params_preop_only = true;  ///< PDO parameters refused (0x08000022) in Operational
  std::uint32_t identity_revision = 0;  ///< 0x1018:03 (shown with identity_entries=4)
  std::uint32_t identity_serial = 0;    ///< 0x1018:04 (shown with identity_entries=4)
  bool tpdo255_on_change = false;       ///< type-255 TPDOs also sent when their mapped data change
  std::vector<std::int8_t> speed_modes = {6, 7, 9};  ///< control modes rate-limited by Speed±
  bool deadband_all_modes = true;       ///< dead band in every mode (false: open-loop modes only)

  bool is_speed_mode(std::int8_t m) const {
    for (auto s : speed_modes) {
      if (s == m) return true;
    }
    return false;
  }

  /// Reads `options`; returns an error message (empty on success).
  std::string read(const devices::DeviceOptions& options);
};

}  // namespace md2
