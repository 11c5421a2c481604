// SYNC consumer (CiA 301 §7.2.5, objects 0x1005 and optionally 0x1019): triggers synchronous
// PDOs and tells the device.
#pragma once

#include <cstdint>

#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

class Node;

class SyncConsumer {
 public:
  explicit SyncConsumer(Node& node) : node_(node) {}
  void bind_objects();
  /// COB-ID and extended flag from 0x1005 (default 0x80).
  std::uint32_t cob_id() const;
  bool extended() const;
  void on_frame(const sim::CanFrame& frame, sim::Time now);
  std::uint64_t count() const { return count_; }

 private:
  Node& node_;
  std::uint64_t count_ = 0;
};

}  // namespace canopen
