// Heartbeat consumer (CiA 301 §7.2.8.3.2.1, object 0x1016): watches other nodes' heartbeats.
// Monitoring of an entry starts with the first heartbeat received from its producer.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

class Node;

class HeartbeatConsumer {
 public:
  explicit HeartbeatConsumer(Node& node);
  void bind_objects();
  /// Re-reads 0x1016 (after a reset or a write).
  void reload();
  /// Producer node-IDs to route to on_frame().
  std::vector<std::uint8_t> producers() const;
  void on_frame(const sim::CanFrame& frame, sim::Time now);
  void process(sim::Time now);
  /// process() has nothing to do: no producer is watched.
  bool idle() const { return watches_.empty(); }
  bool timed_out(std::uint8_t producer) const;
  bool any_timed_out() const;

 private:
  struct Watch {
    std::uint8_t producer = 0;
    std::uint16_t time_ms = 0;
    bool monitoring = false;
    bool timed_out = false;
    sim::Time last_seen{};
  };
  Node& node_;
  std::vector<Watch> watches_;
};

}  // namespace canopen
