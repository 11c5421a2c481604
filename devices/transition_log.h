// What a device's state machines did, as they did it: one entry per state change (each step of a
// chain on its own: 0x0000 in DEVICE_MODE_ACTIVE is TR_5, TR_6, TR_7), with the cause in words and
// its evidence. The page, the exercises and the reports read this; none of them re-derives a
// state machine. Recording runs on the scheduler's thread: a fixed ring of static texts and
// numbers, so it allocates nothing and a client cannot grow it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace devices {

/// Why a state machine moved (the evidence is in Transition::value / detail).
enum class TransitionCause : std::uint8_t {
  Boot,             ///< power-on / application start (TR_0, TR_1, NMT initialisation)
  ControlWord,      ///< value = the control word that was written (SDO or RPDO)
  NmtCommand,       ///< value = the NMT command specifier (01h, 02h, 80h, 81h, 82h); detail = who sent it
  Input,            ///< value = the input's new level / value; detail = the input's name
  HeartbeatTimeout, ///< value = the node-ID whose heartbeat was missed (1016h consumer)
  GuardingTimeout,  ///< node guarding / life guarding ran out (100Ch × 100Dh)
  BusOff,           ///< the CAN controller went bus-off (or recovered)
  Power,            ///< power off / power on (a scenario's power_cycle, the page's button)
  Reset,            ///< an application reset the device performed itself
  DeviceFault,      ///< value = the EMCY error code; detail = the fault's name
  Internal,         ///< the device's own sequence (a ramp finished, initialisation completed)
};

constexpr std::string_view to_string(TransitionCause c) {
  switch (c) {
    case TransitionCause::Boot: return "boot";
    case TransitionCause::ControlWord: return "control_word";
    case TransitionCause::NmtCommand: return "nmt_command";
    case TransitionCause::Input: return "input";
    case TransitionCause::HeartbeatTimeout: return "heartbeat_timeout";
    case TransitionCause::GuardingTimeout: return "guarding_timeout";
    case TransitionCause::BusOff: return "bus_off";
    case TransitionCause::Power: return "power";
    case TransitionCause::Reset: return "reset";
    case TransitionCause::DeviceFault: return "device_fault";
    case TransitionCause::Internal: break;
  }
  return "internal";
}

struct Transition {
  std::uint64_t seq = 0;           ///< 1, 2, 3, … per log: a watcher asks for "everything after seq"
  std::uint64_t t_us = 0;          ///< virtual time of the change
  std::string_view machine;        ///< "nmt", "dsp408", "dsp408.ch2", "vtvpcd", "cia406.status", …
  std::string_view from, to;       ///< state names as the manual spells them (static text)
  std::string_view transition;     ///< "TR_5", "NMT 01h", … ("" if the manual names none)
  TransitionCause cause = TransitionCause::Internal;
  std::uint32_t value = 0;         ///< the cause's evidence (see TransitionCause)
  std::string_view detail;         ///< static text: the input's or fault's name, the sender
};

/// A bounded history, oldest first. When full, the oldest entry goes (seq numbers show the gap).
class TransitionLog {
 public:
  static constexpr std::size_t kCapacity = 256;

  /// Stamps seq and stores the entry; never allocates.
  void record(Transition t) {
    t.seq = ++last_seq_;
    entries_[static_cast<std::size_t>((t.seq - 1) % kCapacity)] = t;
  }
  std::uint64_t last_seq() const { return last_seq_; }
  std::size_t size() const { return last_seq_ < kCapacity ? static_cast<std::size_t>(last_seq_) : kCapacity; }
  void clear() { last_seq_ = 0; }

  /// Calls fn(const Transition&) for every kept entry with seq > after, oldest first.
  template <class Fn>
  void for_each_after(std::uint64_t after, Fn&& fn) const {
    const std::uint64_t first = last_seq_ - size() + 1;
    for (std::uint64_t s = after + 1 > first ? after + 1 : first; s <= last_seq_; ++s)
      fn(entries_[static_cast<std::size_t>((s - 1) % kCapacity)]);
  }

 private:
  std::array<Transition, kCapacity> entries_{};
  std::uint64_t last_seq_ = 0;
};

}  // namespace devices
