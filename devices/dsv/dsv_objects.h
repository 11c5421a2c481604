// The DSV's application objects (manual §5.4.28-§5.4.94, digest §3.2) as a table: index, type,
// access, default, static range, the control modes in which the object exists, and the rule
// that checks its value beyond the range. The builder and the parameter checks read this table.
#pragma once

#include <cstdint>
#include <span>

#include "devices/canopen/data_type.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/dsv/control_mode.h"

namespace dsv {

enum class Shape : std::uint8_t {
  Var,     ///< sub 0 only
  Record,  ///< DSP 408 value parameter record: sub 0 = 1 (number of entries), sub 1 = value
};

/// Value rules beyond the static range (A-numbers refer to the digest's ambiguity list).
enum class Rule : std::uint8_t {
  None,
  SignalType,      ///< 2200h: {0, 2, 3}
  CableBreak,      ///< 2201h: 1 only with signal type 3
  DisplayedUnit,   ///< 2202h: 0..4 without the "–" entries of the mode
  MeasuringSystem, ///< 6202h: {−1, 2, 67}
  RampType,        ///< {0, 3}
  WindowType,      ///< {0, 2}
  DitherFrequency, ///< {20, 25, ..., 500}
  Scaled,          ///< 0 .. the selected unit's maximum (unit/1000)
  Interface,       ///< 0..10000 mV or 0..20000 µA after the signal type
  SetpointToMaxRef,///< 0 .. max reference of the mode
  PressureSetpoint,///< 6380h: m3 ±16384, m4 0..16384
  ModeOfOperation, ///< 2042h: hardware-dependent values (0x06090032)
  ErrorHandling,   ///< 2043h: 2, 3 only with two solenoids (0x06090032)
  IminA, IminB, ImaxA, ImaxB,  ///< cross-checks (0x06090031 / 0x06090032)
};

/// Parameters that are "the same PASO parameter" behind several indices (one per mode group):
/// they share one value.
enum class Shared : std::uint8_t {
  None, RampType, RampAUp, RampBUp, RampADown, RampBDown, IminA, IminB, ImaxA, ImaxB, DeadbandType,
  DeadbandA, DeadbandB, DitherType, DitherAmplitude, DitherFrequency, CharacteristicOptimisation,
};

struct ObjectSpec {
  std::uint16_t index;
  const char* name;
  Shape shape;
  canopen::DataType type;
  canopen::Access access;
  bool mappable;
  std::int64_t default_value;
  std::int64_t low, high;  ///< static range (inclusive); low > high = none
  ModeSet modes;
  Rule rule = Rule::None;
  Shared shared = Shared::None;
};

/// Defaults that come from the valve configuration (the manual: "valve dependent").
constexpr std::int64_t kDefaultImin = -1000001, kDefaultImax = -1000002, kDefaultDitherFrequency = -1000003,
                       kDefaultDitherAmplitude = -1000004, kDefaultModeOfOperation = -1000005;

/// Every application object except device control (6040h-604Fh), node address/bit rate/
/// temperature (2000h-2002h), the strings and the characteristic optimisation arrays.
std::span<const ObjectSpec> application_objects();
const ObjectSpec* find_spec(std::uint16_t index);

/// The control modes of every application index (including device control and 2344h/23C4h);
/// indices the DSV does not know map to 0.
ModeSet modes_of(std::uint16_t index);

}  // namespace dsv
