#include "devices/device.h"

namespace devices {

std::string Device::set_input(std::string_view name, double value) {
  for (const auto& p : ports()) {
    if (p.name == name) {
      if (p.direction != sim::PortDirection::Input) return "port '" + std::string(name) + "' is an output";
      *p.value = value;
      return {};
    }
  }
  std::string known;
  for (const auto& p : ports()) {
    if (p.direction == sim::PortDirection::Input) known += (known.empty() ? "" : ", ") + p.name;
  }
  return "unknown input '" + std::string(name) + "' (inputs: " + (known.empty() ? "none" : known) + ")";
}

std::string Device::inject_fault(std::string_view name, bool) {
  std::string known;
  for (const auto& f : faults()) known += (known.empty() ? "" : ", ") + f.name;
  return "unknown fault '" + std::string(name) + "' (faults: " + (known.empty() ? "none" : known) + ")";
}

}  // namespace devices
