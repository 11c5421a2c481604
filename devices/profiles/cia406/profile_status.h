// The CiA 406 status objects as the live control plane shows them: operating status (0x6500),
// alarms (0x6503) and warnings (0x6505), read from the encoder's dictionary (0 when absent).
#pragma once

#include "devices/canopen/object_dictionary.h"
#include "devices/profile_status.h"

namespace cia406 {

inline devices::ProfileStatus profile_status(const canopen::ObjectDictionary& od) {
  const auto word = [&od](std::uint16_t index) -> std::uint16_t {
    const auto* e = od.entry(index, 0);
    return e ? e->as<std::uint16_t>() : std::uint16_t{0};
  };
  devices::ProfileStatus s;
  s.profile = devices::ProfileStatus::Profile::Cia406;
  s.operating_status = word(0x6500);
  s.alarms = word(0x6503);
  s.warnings = word(0x6505);
  return s;
}

}  // namespace cia406
