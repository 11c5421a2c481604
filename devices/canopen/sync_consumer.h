// SYNC consumer (CiA 301 §7.2.5, objects 0x1005 and optionally 0x1019): triggers synchronous
// PDOs and tells the device (SyncEvents: the node passes the SYNC to the PDO service and the
// application). With 0x1019 in the dictionary the SYNC length is checked against it
// (0: no data; 2..240: one counter byte) and a SYNC of the wrong length raises EMCY 0x8240
// instead of being acted on; the counter then reaches the TPDOs' SYNC start values (sub 6).
#pragma once

#include <cstdint>

#include "devices/canopen/node_policy.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

class SyncConsumer {
 public:
  /// `status`: the NMT state (SYNC is consumed in Pre-operational and Operational); `emcy`
  /// gets 8240h for a SYNC of the wrong length; `routes` a change of 0x1005.
  SyncConsumer(ObjectDictionary& od, const PdoPolicy& policy, const NodeStatus& status, SyncEvents& events,
               EmcyRequests& emcy, RoutesChanged& routes)
      : od_(od), policy_(policy), status_(status), events_(events), emcy_(emcy), routes_(routes) {}
  void bind_objects();
  /// COB-ID and extended flag from 0x1005 (default 0x80).
  std::uint32_t cob_id() const;
  bool extended() const;
  void on_frame(const sim::CanFrame& frame, sim::Time now);
  std::uint64_t count() const { return count_; }
  /// 0x1019: 0 = SYNC without counter (also when the object is absent), else 2..240.
  std::uint8_t counter_overflow() const { return overflow_ ? overflow_->as<std::uint8_t>() : 0; }

 private:
  void bind_counter_overflow();

  ObjectDictionary& od_;
  const PdoPolicy& policy_;
  const NodeStatus& status_;
  SyncEvents& events_;
  EmcyRequests& emcy_;
  RoutesChanged& routes_;
  const OdEntry* overflow_ = nullptr;  ///< 0x1019, if the dictionary has it
  std::uint64_t count_ = 0;
};

}  // namespace canopen
