// Faults of the card and how the bus sees them (manual §3.5 and §4.42; digest §3.3, §4.9, A21-A26):
// the fault numbers of Bus Status 0x2C68, their EMCY codes and error-register bits, the stop
// reaction (valve de-energised), latching until an Enable 1->0->1 edge, and the EMCY-only
// conditions of the code table. One EMCY per code when its first condition appears, the
// "no error" EMCY when the last error clears (the shared Emergency producer does the frames).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "devices/vtvpcd/settings.h"

namespace canopen {
class Emergency;
}

namespace vtvpcd {

enum class Condition : std::uint8_t {
  AngleCmdInput,       ///< fault 0  "Angle Cmd Stopp"
  PressureCmdInput,    ///< fault 1  "Pressure CMD Stopp"
  PowerCmdInput,       ///< fault 2  "Power CMD Stopp"
  PressureBSensor,     ///< fault 3  "act.Pressure B Stopp"
  PressureASensor,     ///< fault 4  "act.Pressure A Stopp"
  ResAngleCmdInput,    ///< fault 5  "res.Angle CMD Stopp"
  LvdtElectronics,     ///< fault 6  "MCP-40/4742 Stopp"
  BusTimeout,          ///< fault 16 "Timeout Stopp"
  TriggerInvalid,      ///< fault 18 "Trigger Stopp"
  LoopFault,           ///< fault 19 "Loop Fault Stopp", not attributable (0x8300)
  LoopFaultPosition,   ///< fault 19, swivel-angle loop (0x8301)
  LoopFaultPressure,   ///< fault 19, pressure loop (0x8302)
  ParameterChecksum,   ///< fault 22 "Checksum"
  ConfigurationChecksum,  ///< fault 23 "Checksum"
  SupplyVoltage,       ///< fault 24 "Voltage Ub"
  ReferenceVoltage,    ///< fault 25 "Reference Voltage"
  Do1Short,            ///< faults 26..33 "DO1 Short": DO1, OK, DO2..DO7 in 0x2F26 bit order
  OkShort,
  Do2Short,
  Do3Short,
  Do4Short,
  Do5Short,
  Do6Short,
  Do7Short,
  Watchdog,            ///< EMCY 0x6010 after a watchdog reset (event)
  SensorGeneral,       ///< EMCY-only codes of the table (injection only)
  Software,
  InternalSoftware,
  UserSoftware,
  DataSet,
  kCount
};

enum class Reaction : std::uint8_t {
  Stop,    ///< valve de-energised, controllers off, OK = 0
  Output,  ///< a discrete output short: that output forced off
  Report,  ///< EMCY and status only
};

struct FaultDefinition {
  Condition condition;
  const char* name;         ///< Device::inject_fault name
  int number;               ///< Bus Status low byte; -1 = EMCY-only
  std::uint16_t emcy;
  std::uint8_t error_register;
  Reaction reaction;
  bool event;               ///< no lasting cause: stays until acknowledged (Enable edge, NMT 0x81)
  const char* description;
};

std::span<const FaultDefinition> fault_definitions();
const FaultDefinition& definition(Condition c);
std::optional<Condition> find_condition(std::string_view name);

class FaultMonitor {
 public:
  FaultMonitor(canopen::Emergency& emcy, const Settings& settings);

  /// A cause injected from the side interface (hardware: survives resets until removed).
  void set_injected(Condition c, bool present) { assign(injected_, c, present); }
  /// A cause the emulator detects itself (bus timeout, Trigger, loop monitoring).
  void set_detected(Condition c, bool present) { assign(detected_, c, present); }
  bool injected(Condition c) const { return (injected_ & bit(c)) != 0; }
  /// An event error (watchdog): active until acknowledged.
  void signal_event(Condition c);

  /// Once per control cycle: raise new faults, drop cleared ones (latched ones only on an Enable
  /// rising edge), keep EMCY, 0x1001 and 0x1003 in step.
  void update(bool enable_rising_edge);
  /// Power-on / NMT "reset of amplifier card": forget everything but the injected causes, which
  /// raise again (with their EMCY) in the first cycle after the boot-up frame.
  void reset();

  bool active(Condition c) const { return (active_ & bit(c)) != 0; }
  bool any_active() const { return active_ != 0; }
  bool stop_active() const { return (active_ & stopping_) != 0; }
  /// Bus Status 0x2C68: error flags (= error register, A25) << 8 | number of the latest fault.
  std::uint16_t bus_status() const;
  /// Discrete Outputs bits forced off by a short (faults 26..33).
  std::uint8_t shorted_outputs() const {
    // Do1Short..Do7Short are consecutive, in the 0x2F26 bit order.
    static_assert(static_cast<int>(Condition::Do7Short) - static_cast<int>(Condition::Do1Short) == 7);
    return static_cast<std::uint8_t>(active_ >> static_cast<unsigned>(Condition::Do1Short));
  }

 private:
  /// One bit per condition (bit n = Condition n): the per-cycle work is a few mask operations.
  using Set = std::uint32_t;
  static_assert(static_cast<std::size_t>(Condition::kCount) <= 32);
  static constexpr Set bit(Condition c) { return Set{1} << static_cast<unsigned>(c); }
  static void assign(Set& set, Condition c, bool present) { set = present ? (set | bit(c)) : (set & ~bit(c)); }
  void activate(Condition c);
  void sync_emergency();

  canopen::Emergency& emcy_;
  /// Conditions that stay active until acknowledged once their cause is gone (settings are
  /// fixed for the card's life: worked out once).
  const Set latching_;
  /// Conditions whose reaction is Stop (with this card's settings).
  const Set stopping_;
  Set injected_ = 0, detected_ = 0, events_ = 0, active_ = 0;
  /// Activation order (oldest first) for "the most recent fault".
  std::array<Condition, static_cast<std::size_t>(Condition::kCount)> order_{};
  std::size_t order_len_ = 0;
  std::uint8_t register_bits_ = 0;
};

}  // namespace vtvpcd
