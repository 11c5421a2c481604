// What a product's device profile shows from outside at one moment (the live control plane's
// node view): the DSP 408 device state with control and status word and the last transition,
// the VT-VPCD's run state and active faults, the CiA 406 operating status and alarms. A plain
// value with static texts, so taking it on the scheduler's thread allocates nothing.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace devices {

struct ProfileStatus {
  enum class Profile : std::uint8_t { Generic, Dsp408, Vtvpcd, Cia406 };
  Profile profile = Profile::Generic;
  std::string_view state;  ///< DSP 408 device state / the VT-VPCD's run state (static text)

  // DSP 408 (MD2: channel 1)
  std::uint16_t control_word = 0;
  std::uint16_t status_word = 0;
  std::uint32_t transitions = 0;  ///< counts state changes, so a watcher notices each one
  std::string_view transition_from, transition_to;
  std::uint16_t transition_control_word = 0;  ///< the control word when the last change happened

  // VT-VPCD
  static constexpr std::size_t kMaxFaults = 8;
  std::array<std::string_view, kMaxFaults> faults{};  ///< active faults' names (static text)
  std::uint8_t fault_count = 0;

  // CiA 406
  std::uint16_t operating_status = 0;  ///< 0x6500
  std::uint16_t alarms = 0;            ///< 0x6503
  std::uint16_t warnings = 0;          ///< 0x6505
};

constexpr std::string_view to_string(ProfileStatus::Profile p) {
  switch (p) {
    case ProfileStatus::Profile::Dsp408: return "dsp408";
    case ProfileStatus::Profile::Vtvpcd: return "vtvpcd";
    case ProfileStatus::Profile::Cia406: return "cia406";
    case ProfileStatus::Profile::Generic: break;
  }
  return "generic";
}

}  // namespace devices
