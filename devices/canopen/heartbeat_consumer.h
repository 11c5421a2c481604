// Heartbeat consumer (CiA 301 §7.2.8.3.2.1, object 0x1016): watches other nodes' heartbeats.
// Monitoring of an entry starts with the first heartbeat received from its producer.
#pragma once

#include <cstdint>
#include <vector>

#include "devices/canopen/node_policy.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

class HeartbeatConsumer {
 public:
  /// `events`: a producer's heartbeat timed out / came back; `routes`: 0x1016 changed.
  HeartbeatConsumer(ObjectDictionary& od, const ErrorControlPolicy& policy, CommErrorEvents& events,
                    RoutesChanged& routes)
      : od_(od), policy_(policy), events_(events), routes_(routes) {}
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
  ObjectDictionary& od_;
  const ErrorControlPolicy& policy_;
  CommErrorEvents& events_;
  RoutesChanged& routes_;
  std::vector<Watch> watches_;
};

}  // namespace canopen
