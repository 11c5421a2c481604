// What the scheduler's thread publishes for the server threads: plain values copied between
// ticks, so a server thread never touches a node, a bus or the plant.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "devices/profile_status.h"
#include "devices/transition_log.h"
#include "sim/can_frame.h"

namespace control {

/// A state machine's transition as the stream carries it (its texts are static).
struct NodeTransition {
  std::uint32_t node = 0;  ///< scenario order
  devices::Transition transition;
};

struct EmcyRecord {
  std::int64_t t_us = 0;
  std::uint16_t code = 0;
  std::uint8_t error_register = 0;
  std::array<std::uint8_t, 5> data{};
};

/// One channel of a multi-channel DSP 408 device (the MD2): its device state machine.
struct ChannelStatus {
  std::string_view state;  ///< static text
  std::uint16_t control_word = 0;
  std::uint16_t status_word = 0;
  std::uint32_t transitions = 0;
  std::string_view transition_from, transition_to;
  std::uint16_t transition_control_word = 0;
  std::int64_t transition_t_us = -1;  ///< when a snapshot first saw `transitions` change

  bool operator==(const ChannelStatus&) const = default;
};

/// One node as the dashboard shows it.
struct NodeStatus {
  static constexpr std::size_t kEmcyHistory = 32;
  static constexpr std::size_t kMaxChannels = 8;
  bool powered = false;
  std::uint8_t nmt = 0;             ///< canopen::NmtState value
  std::uint8_t node_id = 0;         ///< current (LSS may change it)
  std::uint8_t error_register = 0;  ///< 0x1001
  devices::ProfileStatus profile;
  std::int64_t transition_t_us = -1;  ///< when a snapshot first saw profile.transitions change
  /// Every channel of a multi-channel DSP 408 device (the MD2; channel 1 is also `profile`);
  /// channel_count 0 for every other device.
  std::array<ChannelStatus, kMaxChannels> channels{};
  std::uint8_t channel_count = 0;
  std::array<EmcyRecord, kEmcyHistory> emcy{};  ///< ring: the newest is emcy[(emcy_count-1) % size]
  std::uint32_t emcy_count = 0;

  /// Equal for the dashboard (what a "nodes" event would show).
  bool same_as(const NodeStatus& o) const;
};

/// A frame as it crossed a bus.
struct CapturedFrame {
  std::int64_t t_us = 0;
  std::uint8_t bus = 0;
  sim::CanFrame frame;
};

/// A PDO's mapping as configured in a node's dictionary (read between ticks).
struct PdoMap {
  static constexpr std::size_t kMaxEntries = 8;
  std::uint32_t cob_id = 0;
  bool valid = false;
  bool transmit = false;
  std::uint8_t number = 0;  ///< 1-based
  std::uint8_t count = 0;
  std::array<std::uint32_t, kMaxEntries> entries{};  ///< index << 16 | sub << 8 | bits
};

}  // namespace control
