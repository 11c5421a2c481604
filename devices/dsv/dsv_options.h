// Configuration of an emulated DSV: variant, hardware (solenoids, supply), the values stored at
// delivery, the valve-dependent defaults the manual leaves open, and every knob of the digest's
// [I] readings that changes what the bus sees (docs/devices/dsv.md lists them all).
#pragma once

#include <cstdint>
#include <string>

#include "devices/device.h"
#include "devices/profiles/wandfluh/communication.h"

namespace dsv {

enum class Variant : std::uint8_t { Amplifier, Controller };

struct DsvOptions {
  Variant variant = Variant::Amplifier;
  wandfluh::CommonOptions common;
  std::uint8_t node_id = 1;
  int solenoids = 2;
  int supply = 24;  ///< V: current full scale 1536 mA (24 V) or 2560 mA (12 V)
  // Delivery state (non-volatile memory at delivery, A-15): local operation, no control mode.
  std::int8_t delivery_device_local = 1;
  std::int8_t delivery_control_mode = 0;
  std::int8_t delivery_mode_of_operation = 1;
  // "Valve dependent" defaults (counts of 0..16384 = I_FS; dither in its own counts).
  std::int32_t imin = 2731, imax = 8192, imax_limit = 16384;
  std::int16_t dither_frequency = 100, dither_amplitude = 533;
  std::uint32_t capability = 0;  ///< 0x605F; 0 = the variant's default
  // Interpretation knobs.
  bool objects_follow_mode = true;    ///< objects of other control modes answer 0x06020000
  bool actual_value_writable = true;  ///< A-24: writes to actual/deviation accepted (and overwritten)
  bool pdo_cobid_writable = false;    ///< A-08: 0x1400/0x1401/0x1800/0x1801 sub 1 writable
  bool local_strict = false;          ///< A-41: in local operation every write but 0x604F is refused
  bool op_mode1_bipolar = false;      ///< A-33: op-mode 1 split like op-mode 2 instead of 50 % centre
  bool m4_tpdo_six_bytes = false;     ///< A-04: TPDO2 of mode 4 carries the actual value in 4 bytes
  bool quantise_on_write = false;     ///< A-52: written values truncated to the resolution step
  bool restore_keeps_address = false; ///< A-18: a restore leaves 2000h/2001h alone
  bool alias_230e_mode7 = false;      ///< A-21: in mode 7, 230Eh:01 is another name for 250Eh:01
  bool strict_fault_reset = false;    ///< A-36: TR_10 only from FAULT, TR_11 only from FAULT_HOLD
  bool fault_hold = false;            ///< A-36: the fault reaction ends in FAULT_HOLD (TR_9)
  bool pdo_padding = false;           ///< A-50: TPDOs padded to 8 bytes ("not used" = 0)
  double cable_break_ma = 3.0;        ///< below this (4..20 mA input) the cable is broken
  double supply_min = 18;             ///< V: below → EMCY 0x3412
  double sensor_min = 0, sensor_max = 1;  ///< SI measurand at the bottom / top of the signal range
  double ambient_temperature = 25, thermal_gain = 10;

  double current_full_scale() const { return supply == 12 ? 2.560 : 1.536; }  ///< A at 16384 counts
  std::string read(const devices::DeviceOptions& options);
};

}  // namespace dsv
