// LSS slave (CiA 305): switch state global/selective, configure node-ID, configure and activate
// bit timing, store configuration, inquire identity and node-ID, identify (non-configured)
// remote slave, fastscan. COB-IDs 0x7E5 (master → slave) and 0x7E4 (slave → master).
#pragma once

#include <bitset>
#include <cstdint>
#include <optional>

#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/parameter_store.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

struct LssPolicy {
  /// Inquire services (0x5A-0x5E) answered in LSS waiting too (CiA 305: configuration only).
  bool inquire_in_waiting = false;
  /// LSS frames processed while NMT Operational.
  bool in_operational = true;
  bool activate_bit_timing = true;
  bool fastscan = true;
  bool fastscan_only_unconfigured = false;
  /// Byte 1 of the switch-state-selective answer (0x44).
  std::uint8_t selective_response_mode = 0x00;
  /// CiA 305 transition 4 (waiting with a newly configured node-ID leaves the unconfigured
  /// state) only after the configuration was stored.
  bool transition4_requires_store = true;
  /// Bit-timing table indices accepted by "configure bit timing" (CiA 305 table 1).
  std::bitset<10> bit_rates = default_bit_rates();
  /// Short frames (DLC < 8) read with missing bytes as 0 (else ignored).
  bool pad_short_frames = true;
  /// "Configure node-ID" accepts 0xFF (back to unconfigured, CiA 305); false: only 1..127.
  bool accept_unconfigured_node_id = true;
  /// Error code / specific error answered when "store configuration" fails.
  std::uint8_t store_error_code = 0xFF;
  std::uint8_t store_error_specific = 0x02;
  /// A successful "store configuration" is answered only after this long, the node silent
  /// meanwhile (a device busy writing its EEPROM, like a 1010h save); 0 = at once.
  sim::Duration store_answer_delay{0};
  /// Bit-timing table index meaning "automatic bit-rate detection" (e.g. 9 on devices that
  /// list "auto" in their table); none by default. A node whose active rate is this index
  /// stays passive after power-on until it has seen another node's frame (see Node).
  std::optional<std::uint8_t> automatic_bit_rate_index;

  static std::bitset<10> default_bit_rates() {
    std::bitset<10> b;
    for (int i : {0, 1, 2, 3, 4, 6, 7, 8}) b.set(i);
    return b;
  }
};

/// Bit rate in kbit/s for a CiA 305 table index (0 = 1000 … 8 = 10, 9 = automatic → 0).
unsigned lss_bit_rate_kbit(std::uint8_t table_index);

class LssSlave {
 public:
  static constexpr std::uint32_t kMasterToSlave = 0x7E5;
  static constexpr std::uint32_t kSlaveToMaster = 0x7E4;
  static constexpr std::uint16_t kNvIndex = 0x0000;  ///< LSS configuration in the node's NV store

  enum class State : std::uint8_t { Waiting, Configuration };

  /// `od`: identity (0x1018); `status`: node-ID, pending node-ID, NMT state, silence; `memory`:
  /// the node's non-volatile memory (node-ID and bit rate at kNvIndex); `events`: node-ID
  /// configured / to apply; `silence`: "store configuration" and "activate bit timing" pauses.
  LssSlave(const LssPolicy& policy, const ObjectDictionary& od, const NodeStatus& status, ParameterStore& memory,
           FrameSender& sender, LssEvents& events, SilenceRequest& silence)
      : od_(od), status_(status), memory_(memory), sender_(sender), events_(events), silence_(silence), policy_(policy) {}

  /// Power-on: stored node-ID/bit rate become the pending (and so the active) values.
  void power_on();
  void on_frame(const sim::CanFrame& frame, sim::Time now);
  void process(sim::Time now);
  /// process() has nothing to do: no answer held back, no bit-rate switch under way.
  bool idle() const { return !held_answer_ && !switching_; }

  // The configuration services without the protocol, for devices that also expose node-ID and
  // bit rate as objects (the same non-volatile cells as LSS). Return the CiA 305 error code.
  /// Sets the pending node-ID (active after the next communication reset); 0 ok, 1 out of range.
  std::uint8_t configure_node_id(std::uint8_t id);
  /// Sets the pending bit-rate table index; 0 ok, 1 not supported.
  std::uint8_t configure_bit_rate(std::uint8_t table_index);
  /// Stores pending node-ID and bit rate in non-volatile memory; true on success.
  bool store_configuration();
  /// Makes the pending bit rate the active one (devices that apply a configured rate at an NMT
  /// reset instead of through "activate bit timing").
  void activate_pending_bit_rate() { active_bit_rate_ = pending_bit_rate_; }

  State state() const { return state_; }
  std::uint8_t pending_node_id() const { return pending_node_id_; }
  std::uint8_t pending_bit_rate() const { return pending_bit_rate_; }
  std::uint8_t active_bit_rate() const { return active_bit_rate_; }
  /// Default bit-rate table index used when nothing is stored.
  void set_default_bit_rate(std::uint8_t index) { active_bit_rate_ = pending_bit_rate_ = default_bit_rate_ = index; }
  LssPolicy& policy() { return policy_; }

 private:
  static sim::CanFrame answer(std::initializer_list<std::uint8_t> bytes);
  void reply(std::initializer_list<std::uint8_t> bytes);
  void switch_global(std::uint8_t mode);
  void switch_selective(std::uint8_t cs, std::uint32_t value);
  void identify_remote(std::uint8_t cs, std::uint32_t value);
  void fastscan(const std::uint8_t* d);
  std::uint32_t identity(int sub) const;
  bool unconfigured() const;

  const ObjectDictionary& od_;
  const NodeStatus& status_;
  ParameterStore& memory_;
  FrameSender& sender_;
  LssEvents& events_;
  SilenceRequest& silence_;
  LssPolicy policy_;
  State state_ = State::Waiting;
  std::uint8_t pending_node_id_ = 0xFF;
  std::uint8_t default_bit_rate_ = 3;
  std::uint8_t pending_bit_rate_ = 3;
  std::uint8_t active_bit_rate_ = 3;
  bool stored_since_configure_ = false;
  int selective_step_ = 0;       // next expected switch-selective specifier offset (0..3)
  int identify_step_ = 0;        // identify remote slave progress
  bool identify_match_ = true;
  std::uint32_t identify_low_ = 0;
  int fastscan_position_ = 0;
  std::optional<sim::CanFrame> held_answer_;  // "store configuration" answer sent after the delay
  // Activate bit timing: silent for delay, switch, silent for delay again.
  bool switching_ = false;
  sim::Time switch_at_{};
  sim::Time resume_at_{};
};

}  // namespace canopen
