// EMCY producer with error register (0x1001) and pre-defined error field (0x1003).
// The device raises and clears error conditions; the producer sends one EMCY per rising edge,
// the "no error" EMCY when the last one clears (if the policy says so), honours 0x1014 (COB-ID,
// bit 31 = disabled) and 0x1015 (inhibit time, frames queued not dropped), and never sends in
// Stopped.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "devices/canopen/node_policy.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"
#include "sim/ring_buffer.h"
#include "sim/time.h"

namespace canopen {

class Emergency {
 public:
  using Info = std::array<std::uint8_t, 5>;  ///< manufacturer-specific bytes 3..7

  /// `status`: NMT state (EMCY is not sent in Stopped), node-ID (default COB-ID) and time.
  Emergency(ObjectDictionary& od, const EmcyPolicy& policy, const NodeStatus& status, FrameSender& sender)
      : od_(od), policy_(policy), status_(status), sender_(sender) {}

  /// Installs behaviour on 0x1001/0x1003 (if present). Called once when the node is built.
  void bind_objects();

  /// Rising edge of an error condition: record, set register bits, send one EMCY. A code that
  /// is already active is not signalled again.
  void raise(std::uint16_t code, std::uint8_t register_bits, Info info = {});
  /// Falling edge. When nothing is active any more, the "no error" EMCY may follow.
  void clear(std::uint16_t code);
  /// Clears every active error (fault reset); one "no error" EMCY at most.
  void clear_all();
  /// Sends an EMCY frame for an event without a lasting condition (recorded in 0x1003 too).
  void signal(std::uint16_t code, std::uint8_t register_bits, Info info = {});
  /// Sends an EMCY with an explicit code and register, without touching the bookkeeping
  /// (for devices whose manual defines extra EMCY frames, e.g. a per-read "error reset").
  void send_frame(std::uint16_t code, std::uint8_t error_register, Info info = {});

  bool active(std::uint16_t code) const {
    for (const auto& e : active_)  // inline: devices ask every tick, mostly with nothing active
      if (e.code == code) return true;
    return false;
  }
  bool any_active() const { return !active_.empty(); }
  std::uint8_t error_register() const;
  /// Extra register bits the device holds itself (e.g. a latched communication bit).
  void set_extra_register_bits(std::uint8_t bits);
  const std::vector<std::uint32_t>& history() const { return history_; }
  void clear_history();

  void reset_communication();  ///< 0x1003 handling per policy, queue flushed
  void process(sim::Time now);  ///< sends queued frames when the inhibit time allows
  /// process() has nothing to do: no frame queued.
  bool idle() const { return queue_.empty(); }

 private:
  struct ActiveError {
    std::uint16_t code;
    std::uint8_t bits;
  };
  bool may_send() const;  ///< the NMT state (and policy) allows EMCY frames now
  void record(std::uint16_t code, const Info& info);
  void enqueue(std::uint16_t code, const Info& info);
  void update_register();
  void publish_history();

  ObjectDictionary& od_;
  const EmcyPolicy& policy_;
  const NodeStatus& status_;
  FrameSender& sender_;
  std::vector<ActiveError> active_;
  std::uint8_t extra_bits_ = 0;
  std::vector<std::uint32_t> history_;  // newest first
  sim::RingBuffer<sim::CanFrame> queue_{16};
  sim::Time next_allowed_{};
};

}  // namespace canopen
