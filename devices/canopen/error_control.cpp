#include "devices/canopen/error_control.h"

namespace canopen {

namespace {
constexpr std::uint16_t kGuardTime = 0x100C;
constexpr std::uint16_t kLifeTimeFactor = 0x100D;
constexpr std::uint16_t kProducerHeartbeat = 0x1017;
}  // namespace

void ErrorControl::bind_objects() {
  auto& od = od_;
  heartbeat_time_ = EntryRef<std::uint16_t>::optional(od, kProducerHeartbeat, 0);
  guard_time_ = od.entry(kGuardTime, 0);
  life_time_factor_ = od.entry(kLifeTimeFactor, 0);
  if (od.entry(kProducerHeartbeat, 0)) {
    // A new period takes effect at once: first heartbeat one period after the write; 0 stops.
    od.add_observer(kProducerHeartbeat, 0, [this](OdEntry&, Origin) {
      next_heartbeat_ = status_.now + sim::milliseconds(heartbeat_period_ms());
    });
  }
  for (std::uint16_t idx : {kGuardTime, kLifeTimeFactor}) {
    if (od.entry(idx, 0)) {
      od.add_observer(idx, 0, [this](OdEntry&, Origin) {
        if (life_time_ms() == 0) armed_ = false;
      });
    }
  }
}

std::uint32_t ErrorControl::life_time_ms() const {
  if (!guard_time_ || !life_time_factor_) return 0;
  return guard_time_->as<std::uint32_t>() * life_time_factor_->as<std::uint32_t>();
}

void ErrorControl::reset_communication(sim::Time now) {
  toggle_ = false;
  armed_ = false;
  in_error_ = false;
  next_heartbeat_ = now + sim::milliseconds(heartbeat_period_ms());
}

void ErrorControl::on_frame(const sim::CanFrame& frame, sim::Time now) {
  if (!frame.rtr) return;  // only remote frames are guard requests
  if (heartbeat_period_ms() != 0 && !policy_.guard_while_heartbeat) return;
  const auto state = static_cast<std::uint8_t>(status_.nmt_state);
  sender_.send(sim::CanFrame::data_frame(0x700u + status_.node_id,
                                       {static_cast<std::uint8_t>((toggle_ ? 0x80 : 0x00) | state)}));
  toggle_ = !toggle_;
  last_guard_ = now;
  if (life_time_ms() != 0) armed_ = true;
  if (in_error_) {
    in_error_ = false;
    events_.communication_recovered(CommError::LifeGuarding);
  }
}

void ErrorControl::process(sim::Time now) {
  const std::uint16_t period = heartbeat_period_ms();
  if (period != 0) {
    if (!policy_.guard_while_heartbeat) armed_ = false;  // heartbeat replaces guarding
    if (now >= next_heartbeat_) {
      sender_.send(sim::CanFrame::data_frame(0x700u + status_.node_id, {static_cast<std::uint8_t>(status_.nmt_state)}));
      next_heartbeat_ += sim::milliseconds(period);
      if (next_heartbeat_ <= now) next_heartbeat_ = now + sim::milliseconds(period);
    }
  }
  if (!armed_ || in_error_) return;  // the life time is read only while guarding is armed
  const std::uint32_t life = life_time_ms();
  if (life != 0 && now - last_guard_ > sim::milliseconds(life)) {
    in_error_ = true;
    events_.communication_error(CommError::LifeGuarding, life);
  }
}

}  // namespace canopen
