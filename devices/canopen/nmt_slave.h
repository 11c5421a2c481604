// NMT slave (CiA 301 §7.2.8.3.1): parses node-control frames on COB-ID 0x000 and hands the
// command to the node, which runs the state transitions and resets.
#pragma once

#include "sim/can_frame.h"

namespace canopen {

class Node;

class NmtSlave {
 public:
  explicit NmtSlave(Node& node) : node_(node) {}
  void on_frame(const sim::CanFrame& frame);

 private:
  Node& node_;
};

}  // namespace canopen
