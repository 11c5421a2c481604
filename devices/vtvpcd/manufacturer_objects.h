// The 116 manufacturer-specific objects of the manual's chapter 4 ("Busparameter"), one row each
// exactly as printed (section, index, name, byte count, access, min/max, scale), plus the data
// type and start-up value this emulator gives them (digest §2.8, §4.10). Every entry is a simple
// variable at sub-index 0, readable, PDO-mappable ("Busmanager: available"), accepted "also with
// active enabling", offset 0.
#pragma once

#include <cstdint>
#include <span>

#include "devices/canopen/data_type.h"
#include "devices/vtvpcd/parameter_conversion.h"

namespace vtvpcd {

struct ObjectSpec {
  const char* section;       ///< manual section, e.g. "4.55"
  std::uint16_t index;
  const char* name;          ///< as printed
  canopen::DataType type;    ///< INTEGER32 / UNSIGNED32 (Trigger) / UNSIGNED16 / INTEGER16 (Zeropoint valve)
  bool read_only;
  double printed_min, printed_max;  ///< "Min./Max. Value" as printed, in EU
  Scale scale;
  const char* unit;          ///< EU unit this emulator uses ("" = none / bitfield)
  std::int64_t start_raw;    ///< start-up value (configuration image default)
  double strict_min, strict_max;  ///< EU range checked with sdo_range_mode = strict
  bool range_checked;        ///< false: never range-checked (Trigger: bits 17-31 are stored)

  std::size_t bytes() const { return canopen::type_size(type); }
  std::int64_t strict_raw_min() const;
  std::int64_t strict_raw_max() const;
};

/// All 116 rows in manual order.
std::span<const ObjectSpec> manufacturer_objects();
/// The row of `index`, or nullptr.
const ObjectSpec* find_object_spec(std::uint16_t index);

/// Indices the controller reads and writes (manual names).
namespace idx {
// Read-only process values.
inline constexpr std::uint16_t kActAngle = 0x2F07;
inline constexpr std::uint16_t kActPressureA = 0x2F10;
inline constexpr std::uint16_t kActPressureB = 0x2F0F;
inline constexpr std::uint16_t kActValve = 0x2F19;
inline constexpr std::uint16_t kAngleCmd = 0x2F33;
inline constexpr std::uint16_t kAngleCmdB14B16 = 0x2F03;
inline constexpr std::uint16_t kAngleCmdB2B4 = 0x2F1A;
inline constexpr std::uint16_t kAngleCmdBinary = 0x2F2F;
inline constexpr std::uint16_t kBusStatus = 0x2C68;
inline constexpr std::uint16_t kDiscreteInputs = 0x2F27;
inline constexpr std::uint16_t kDiscreteOutputs = 0x2F26;
inline constexpr std::uint16_t kPowerCmd = 0x2F18;
inline constexpr std::uint16_t kPowerCmdF8F10 = 0x2F17;
inline constexpr std::uint16_t kPowerCmdBinary = 0x2F31;
inline constexpr std::uint16_t kPressCmd = 0x2F0E;
inline constexpr std::uint16_t kPressCmdB18B20 = 0x2F0D;
inline constexpr std::uint16_t kPressCmdBinary = 0x2F30;
inline constexpr std::uint16_t kPressureStroke = 0x2F32;
inline constexpr std::uint16_t kResAngleCmd = 0x2F20;
inline constexpr std::uint16_t kValveCmd = 0x2F1F;
// Read/write commands and parameters.
inline constexpr std::uint16_t kAngleCmdBus = 0x2C72;
inline constexpr std::uint16_t kPressureCmdBus = 0x2C74;
inline constexpr std::uint16_t kPowerCmdBus = 0x2C76;
inline constexpr std::uint16_t kResAngleCmdBus = 0x2C99;
inline constexpr std::uint16_t kTrigger = 0x2C67;
inline constexpr std::uint16_t kZeropointPump = 0x2C69;
inline constexpr std::uint16_t kZeropointValve = 0x2F2A;
inline constexpr std::uint16_t kGainLvdtPump = 0x2F2C;
// Tables of the 16 binary parameter sets: base + k (k = 0..15).
inline constexpr std::uint16_t kAngleCmdBinary0 = 0x2001;
inline constexpr std::uint16_t kPressCmdBinary0 = 0x2023;
inline constexpr std::uint16_t kPowerCmdBinary0 = 0x2045;
inline constexpr std::uint16_t kAngleRampBinary0 = 0x2101;
inline constexpr std::uint16_t kPressRampBinary0 = 0x2123;
// Pressure controller, one per group of four sets: base + 4 * g (g = 0..3).
inline constexpr std::uint16_t kContrPBinary0 = 0x2323;
inline constexpr std::uint16_t kContrIBinary0 = 0x2423;
}  // namespace idx

}  // namespace vtvpcd
