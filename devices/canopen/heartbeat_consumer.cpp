#include "devices/canopen/heartbeat_consumer.h"

#include <algorithm>

namespace canopen {

namespace {
constexpr std::uint16_t kConsumerHeartbeat = 0x1016;
}

void HeartbeatConsumer::bind_objects() {
  auto* obj = od_.object(kConsumerHeartbeat);
  if (!obj) return;
  for (auto& [sub, e] : obj->entries) {
    if (sub == 0) continue;
    od_.add_check(kConsumerHeartbeat, sub, [this, s = sub](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
      const SdoAbort refuse = policy_.duplicate_consumer;
      if (origin != Origin::Sdo || refuse == SdoAbort::None) return SdoAbort::None;
      const auto v = static_cast<std::uint32_t>(decode_unsigned(data));
      const auto producer = (v >> 16) & 0xFF;
      if (producer == 0 || producer > 127 || (v & 0xFFFF) == 0) return SdoAbort::None;  // entry unused
      for (const auto& [other, entry] : od_.object(kConsumerHeartbeat)->entries) {
        if (other == 0 || other == s) continue;
        const auto w = entry.as<std::uint32_t>();
        if (((w >> 16) & 0xFF) == producer && (w & 0xFFFF) != 0) return refuse;
      }
      return SdoAbort::None;
    });
    od_.add_observer(kConsumerHeartbeat, sub, [this](OdEntry&, Origin) {
      reload();
      routes_.rebuild_dispatch();
    });
  }
}

void HeartbeatConsumer::reload() {
  watches_.clear();
  const auto* obj = od_.object(kConsumerHeartbeat);
  if (!obj) return;
  for (const auto& [sub, e] : obj->entries) {
    if (sub == 0) continue;
    const auto v = e.as<std::uint32_t>();
    const auto producer = static_cast<std::uint8_t>((v >> 16) & 0xFF);
    const auto time_ms = static_cast<std::uint16_t>(v & 0xFFFF);
    if (producer == 0 || producer > 127 || time_ms == 0) continue;  // entry unused
    watches_.push_back(Watch{producer, time_ms});
  }
}

std::vector<std::uint8_t> HeartbeatConsumer::producers() const {
  std::vector<std::uint8_t> ids;
  for (const auto& w : watches_) ids.push_back(w.producer);
  return ids;
}

void HeartbeatConsumer::on_frame(const sim::CanFrame& frame, sim::Time now) {
  if (frame.rtr || frame.dlc < 1) return;
  const auto producer = static_cast<std::uint8_t>(frame.id - 0x700);
  for (auto& w : watches_) {
    if (w.producer != producer) continue;
    w.monitoring = true;
    w.last_seen = now;
    if (w.timed_out) {
      w.timed_out = false;
      events_.communication_recovered(CommError::HeartbeatConsumer);
    }
  }
}

void HeartbeatConsumer::process(sim::Time now) {
  for (auto& w : watches_) {
    if (!w.monitoring || w.timed_out) continue;
    if (now - w.last_seen > sim::milliseconds(w.time_ms)) {
      w.timed_out = true;
      events_.communication_error(CommError::HeartbeatConsumer, w.producer);
    }
  }
}

bool HeartbeatConsumer::timed_out(std::uint8_t producer) const {
  return std::any_of(watches_.begin(), watches_.end(),
                     [producer](const Watch& w) { return w.producer == producer && w.timed_out; });
}

bool HeartbeatConsumer::any_timed_out() const {
  return std::any_of(watches_.begin(), watches_.end(), [](const Watch& w) { return w.timed_out; });
}

}  // namespace canopen
