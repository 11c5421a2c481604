// An emulated product: a CANopen node, the behaviour its manual describes, and its ports to the
// plant. The CLI (`vplant node --device NAME`) and scenarios create devices through the product
// registry (registry.h) and talk to them only through this interface.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devices/canopen/node.h"
#include "devices/canopen/value_scaling.h"
#include "devices/profile_status.h"
#include "devices/state_machine_diagram.h"
#include "devices/transition_log.h"
#include "sim/ports.h"

namespace devices {

/// How to build a device. `settings` are the product's configuration knobs (every [R] reading
/// of its manual that changes what the bus sees), by name, as text; each product validates its
/// own and rejects unknown names.
struct DeviceOptions {
  std::uint8_t node_id = 0;  ///< 0 = the product's factory default
  std::string variant;       ///< "" = the product's default variant
  std::map<std::string, std::string> settings;
  std::string store_path;    ///< non-volatile memory file ("" = in memory for the run)
  bool strict_eds = false;   ///< an EDS node: reject the file's CiA 306 deviations (canopen::EdsStrictness)
  /// Where the product adds its warnings about usable but doubtful settings (a deprecated
  /// name); nullptr = nobody listens. The caller shows them with the settings' position.
  std::vector<std::string>* warnings = nullptr;
};

/// A product's own EMCY code (a manufacturer-specific code, or a standard one its manual gives a
/// precise meaning), as its manual words it.
struct EmcyCode {
  std::uint16_t code = 0;
  std::string_view text;
};

struct FaultInfo {
  std::string name;         ///< e.g. "magnet_lost", "cable_break", "over_temperature"
  std::string description;
  std::uint16_t emcy = 0;   ///< the EMCY code it raises; 0 = none (an SDO abort, a refusal, silence)
};

class Device {
 public:
  virtual ~Device() = default;

  virtual canopen::Node& node() = 0;
  /// Plant-facing ports in SI units (inputs: measured values; outputs: actuator commands).
  /// Pointers stay valid for the device's lifetime.
  virtual sim::PortList ports() = 0;
  /// Sets an input port or a run-time quantity by name (`--set actual=0.25`); returns an error
  /// message, empty on success.
  virtual std::string set_input(std::string_view name, double value);
  /// Faults this product can simulate (scenario fault injection).
  virtual std::vector<FaultInfo> faults() const { return {}; }
  /// Activates/clears a named fault; returns an error message, empty on success.
  virtual std::string inject_fault(std::string_view name, bool active);

  /// The device profile's state now (on the scheduler's thread; allocates nothing).
  virtual ProfileStatus profile_status() { return {}; }
  /// Devices with one profile state machine per axis (the MD2's channels) say how many, and
  /// profile_status() shows the first; 0 = one device-level profile only.
  virtual int profile_channel_count() const { return 0; }
  /// Channel `channel` (1-based, up to profile_channel_count()); empty for anything else.
  virtual ProfileStatus channel_profile_status(int /*channel*/) { return {}; }

  /// The product's documented scaling of dictionary entry index:sub as its configuration stands
  /// now (the manual's resolution, e.g. steps of 0.1 mm); none when the manual gives none. Reads
  /// the dictionary: call it on the scheduler's thread or before the run.
  virtual canopen::ValueScaling value_scaling(std::uint16_t /*index*/, std::uint8_t /*sub*/) { return {}; }

  /// The EMCY codes this product's manual defines, with their text (static storage).
  virtual std::span<const EmcyCode> emcy_codes() const { return {}; }

  /// Power cycle as a scenario sees it. Devices with state that survives power-off (multiturn
  /// counters, non-volatile memory) override and keep it.
  virtual void power_off() { node().power_off(); }
  virtual void power_on(sim::Time now) { node().power_on(now); }

  /// The device's state machines (NMT first, then its profile's: DSP 408 per channel, VT-VPCD,
  /// CiA 406 bits), each with its state now. Read between ticks; allocates (not for the tick).
  virtual std::vector<MachineView> machines();

  /// Every state change of this device's state machines (NMT, profile, product), oldest first.
  /// Read it between ticks (the scheduler's thread writes it).
  const TransitionLog& transition_log() const { return transition_log_; }

 protected:
  TransitionLog transition_log_;
};

}  // namespace devices
