#include "devices/canopen/sync_consumer.h"

#include "devices/canopen/node.h"
#include "devices/canopen/pdo_service.h"

namespace canopen {

namespace {
constexpr std::uint16_t kCobIdSync = 0x1005;
}

void SyncConsumer::bind_objects() {
  auto& od = node_.od();
  if (!od.entry(kCobIdSync, 0)) return;
  od.add_check(kCobIdSync, 0, [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = static_cast<std::uint32_t>(decode_unsigned(data));
    if (v & 0x40000000u) return node_.policy().pdo.sync_producer_refused;
    if (!(v & 0x20000000u) && (v & 0x1FFFF800u)) return SdoAbort::InvalidValue;
    return SdoAbort::None;
  });
  od.add_observer(kCobIdSync, 0, [this](OdEntry&, Origin) { node_.rebuild_dispatch(); });
}

std::uint32_t SyncConsumer::cob_id() const {
  const auto* e = node_.od().entry(kCobIdSync, 0);
  const std::uint32_t v = e ? e->as<std::uint32_t>() : 0x80u;
  return v & ((v & 0x20000000u) ? 0x1FFFFFFFu : 0x7FFu);
}

bool SyncConsumer::extended() const {
  const auto* e = node_.od().entry(kCobIdSync, 0);
  return e && (e->as<std::uint32_t>() & 0x20000000u);
}

void SyncConsumer::on_frame(const sim::CanFrame& frame, sim::Time now) {
  if (frame.rtr || !sync_allowed(node_.nmt_state())) return;
  if (node_.policy().pdo.sync_requires_dlc0 && frame.dlc != 0) return;
  const std::uint8_t counter = frame.dlc >= 1 ? frame.data[0] : 0;
  ++count_;
  node_.pdo().on_sync(counter, now);
  node_.app().on_sync(counter);
}

}  // namespace canopen
