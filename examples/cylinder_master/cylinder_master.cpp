#include "cylinder_master.h"

#include <cstdio>

namespace example {

namespace {

std::uint16_t u16(const vplant::Frame& f, int at) {
  return static_cast<std::uint16_t>(f.data[at] | f.data[at + 1] << 8);
}
std::int32_t i32(const vplant::Frame& f, int at) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(f.data[at]) | static_cast<std::uint32_t>(f.data[at + 1]) << 8 |
                                   static_cast<std::uint32_t>(f.data[at + 2]) << 16 |
                                   static_cast<std::uint32_t>(f.data[at + 3]) << 24);
}
std::uint8_t byte(std::uint32_t v, int n) { return static_cast<std::uint8_t>(v >> (8 * n)); }

constexpr std::uint16_t kAngleCommand = 0x2C72;

}  // namespace

CylinderMaster::CylinderMaster(vplant::Simulation& sim, Config config) : config_(config) {
  bus_ = &sim.attach("", [this](const vplant::Frame& f, vplant::Time now) { on_frame(f, now); });
  sim.add_step([this](vplant::Time now, vplant::Duration) { step(now); });
}

void CylinderMaster::fail(std::string why) {
  phase_ = Phase::Failed;
  failure_ = std::move(why);
}

void CylinderMaster::step(vplant::Time now) {
  if (next_sync_.count() >= 0 && now >= next_sync_) {
    bus_->send(vplant::Frame::make(0x080, {}));
    next_sync_ += config_.sync_period;
  }
  switch (phase_) {
    case Phase::Booting:
      if (now < config_.boot_wait) break;
      bus_->send(vplant::Frame::make(0x000, {0x01, 0x00}));  // NMT Start, all nodes
      next_sync_ = now + config_.sync_period;
      {
        const auto angle = static_cast<std::uint32_t>(config_.pump_angle);
        // Expedited download, 4 bytes: 0x23 index sub data.
        bus_->send(vplant::Frame::make(0x600u + config_.pump_node,
                                       {0x23, byte(kAngleCommand, 0), byte(kAngleCommand, 1), 0x00, byte(angle, 0),
                                        byte(angle, 1), byte(angle, 2), byte(angle, 3)}));
      }
      phase_ = Phase::CommandingPump;
      break;
    case Phase::PumpSettling:
      if (now < settle_until_) break;
      {
        const auto sp = static_cast<std::uint16_t>(config_.valve_set_point);
        bus_->send(vplant::Frame::make(0x200u + config_.valve_node, {0x07, 0x00, byte(sp, 0), byte(sp, 1)}));
      }
      phase_ = Phase::EnablingValve;
      break;
    default:
      break;
  }
}

void CylinderMaster::on_frame(const vplant::Frame& f, vplant::Time now) {
  if (f.extended || f.rtr) return;
  if (f.id == 0x580u + config_.pump_node && phase_ == Phase::CommandingPump && f.dlc == 8 && u16(f, 1) == kAngleCommand) {
    if (f.data[0] == 0x60) {
      phase_ = Phase::PumpSettling;
      settle_until_ = now + config_.pump_settle;
    } else if (f.data[0] == 0x80) {
      char text[64];
      std::snprintf(text, sizeof text, "pump: SDO abort 0x%08X", static_cast<unsigned>(i32(f, 4)));
      fail(text);
    }
  } else if (f.id == 0x180u + config_.valve_node && phase_ == Phase::EnablingValve && f.dlc >= 2) {
    if ((u16(f, 0) & 0x000F) == 0x000F) {  // DEVICE_MODE_ACTIVE
      phase_ = Phase::Extending;
      active_at_ = now;
    }
  } else if (f.id == 0x280u + config_.sensor_node && f.dlc >= 4) {
    position_ = i32(f, 0);
    if (phase_ == Phase::Extending && position_ >= config_.target_steps) {
      phase_ = Phase::Reached;
      reached_at_ = now;
    }
  }
}

}  // namespace example
