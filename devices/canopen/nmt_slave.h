// NMT slave (CiA 301 §7.2.8.3.1): parses node-control frames on COB-ID 0x000 and hands the
// command on (NmtCommandHandler: the node runs the state transitions and resets).
#pragma once

#include "devices/canopen/node_policy.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"

namespace canopen {

class NmtSlave {
 public:
  /// `status`: the node-ID a command must address (or 0, broadcast).
  NmtSlave(const NmtPolicy& policy, const NodeStatus& status, NmtCommandHandler& commands)
      : policy_(policy), status_(status), commands_(commands) {}
  void on_frame(const sim::CanFrame& frame);

 private:
  const NmtPolicy& policy_;
  const NodeStatus& status_;
  NmtCommandHandler& commands_;
};

}  // namespace canopen
