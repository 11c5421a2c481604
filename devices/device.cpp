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

std::vector<MachineView> Device::machines() {
  auto& n = node();
  const bool on = n.powered();
  std::vector<MachineView> out;
  out.push_back({nmt_diagram(), on ? std::string(canopen::to_string(n.nmt_state())) : "OFF"});
  const ProfileStatus p = profile_status();
  if (p.profile == ProfileStatus::Profile::Dsp408) {
    static constexpr std::string_view kChannels[] = {"dsp408.ch1", "dsp408.ch2", "dsp408.ch3", "dsp408.ch4",
                                                     "dsp408.ch5", "dsp408.ch6", "dsp408.ch7", "dsp408.ch8"};
    const int channels = profile_channel_count();
    if (channels == 0) out.push_back({dsp408_diagram("dsp408"), on ? std::string(p.state) : "OFF"});
    for (int c = 1; c <= channels && c <= 8; ++c)
      out.push_back({dsp408_diagram(kChannels[c - 1]), on ? std::string(channel_profile_status(c).state) : "OFF"});
  } else if (p.profile == ProfileStatus::Profile::Vtvpcd) {
    out.push_back({vtvpcd_diagram(), on ? std::string(p.state) : "OFF"});
  }
  return out;
}

std::string Device::inject_fault(std::string_view name, bool) {
  std::string known;
  for (const auto& f : faults()) known += (known.empty() ? "" : ", ") + f.name;
  return "unknown fault '" + std::string(name) + "' (faults: " + (known.empty() ? "none" : known) + ")";
}

}  // namespace devices
