// Named signal ports: how devices and the plant exchange physical values without knowing each
// other. A component publishes a list of ports pointing at its own doubles; a scenario wires an
// output port to an input port, and each tick the wiring copies the value (no allocation).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "sim/display_unit.h"

namespace sim {

enum class PortDirection { Input, Output };

struct Port {
  std::string name;        ///< e.g. "solenoid_a_current", "piston_position"
  PortDirection direction;
  std::string unit;        ///< SI unit, e.g. "A", "m", "rad", "Pa", "1" for normalised
  double* value;           ///< owned by the component; stable for the component's lifetime
  std::string description;
  DisplayUnit display{};   ///< how an engineer reads it (bar, mm, rpm, ...); chosen by the port's owner
};

using PortList = std::vector<Port>;

/// Finds a port by name; nullptr if absent.
inline const Port* find_port(const PortList& ports, std::string_view name) {
  for (const auto& p : ports)
    if (p.name == name) return &p;
  return nullptr;
}

/// One connection from an output to an input, copied once per tick.
struct Wire {
  const double* from;
  double* to;
  void transfer() const { *to = *from; }
};

}  // namespace sim
