// NMT error control of the node itself (CiA 301 §7.2.8.3.2): heartbeat producer (0x1017) and
// node guarding with toggle bit plus life guarding (0x100C × 0x100D), all on COB-ID 0x700+N.
#pragma once

#include <cstdint>

#include "devices/canopen/node_policy.h"
#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

class ErrorControl {
 public:
  /// `status`: node-ID and NMT state (the heartbeat's byte) and time; `events`: life guarding
  /// timed out / resumed.
  ErrorControl(ObjectDictionary& od, const ErrorControlPolicy& policy, const NodeStatus& status, FrameSender& sender,
               CommErrorEvents& events)
      : od_(od), policy_(policy), status_(status), sender_(sender), events_(events) {}
  void bind_objects();

  void on_frame(const sim::CanFrame& frame, sim::Time now);  ///< frames on 0x700+N
  void process(sim::Time now);
  /// process() has nothing to do at `now`: guarding is not armed and no heartbeat is due (a
  /// heartbeat is due when its time has come and the period, read then, is not 0).
  bool idle(sim::Time now) const { return !armed_ && (now < next_heartbeat_ || heartbeat_period_ms() == 0); }
  /// After boot-up: toggle 0, guarding disarmed, first heartbeat one period from `now`.
  void reset_communication(sim::Time now);

  /// 0x1017 (0 = no heartbeat), read every tick.
  std::uint16_t heartbeat_period_ms() const { return heartbeat_time_.get(); }
  bool life_guarding_armed() const { return armed_; }
  bool life_guarding_error() const { return in_error_; }

 private:
  std::uint32_t life_time_ms() const;

  ObjectDictionary& od_;
  const ErrorControlPolicy& policy_;
  const NodeStatus& status_;
  FrameSender& sender_;
  CommErrorEvents& events_;
  // 0x1017, 0x100C, 0x100D (null when absent): read every tick, bound by bind_objects().
  EntryRef<std::uint16_t> heartbeat_time_;
  const OdEntry* guard_time_ = nullptr;
  const OdEntry* life_time_factor_ = nullptr;
  bool toggle_ = false;
  bool armed_ = false;
  bool in_error_ = false;
  sim::Time last_guard_{};
  sim::Time next_heartbeat_{};
};

}  // namespace canopen
