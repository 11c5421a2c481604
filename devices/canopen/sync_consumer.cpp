#include "devices/canopen/sync_consumer.h"


namespace canopen {

namespace {
constexpr std::uint16_t kCobIdSync = 0x1005, kCommunicationCyclePeriod = 0x1006, kCounterOverflow = 0x1019;
constexpr std::uint16_t kEmcySyncLength = 0x8240;  // CiA 301: unexpected SYNC data length
}

void SyncConsumer::bind_objects() {
  auto& od = od_;
  if (!od.entry(kCobIdSync, 0)) return;
  od.add_check(kCobIdSync, 0, [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = static_cast<std::uint32_t>(decode_unsigned(data));
    if (v & 0x40000000u) return policy_.sync_producer_refused;
    if (!(v & 0x20000000u) && (v & 0x1FFFF800u)) return SdoAbort::InvalidValue;
    return SdoAbort::None;
  });
  od.add_observer(kCobIdSync, 0, [this](OdEntry&, Origin) { routes_.rebuild_dispatch(); });
  bind_counter_overflow();
}

void SyncConsumer::bind_counter_overflow() {
  auto& od = od_;
  overflow_ = od.entry(kCounterOverflow, 0);
  if (!overflow_ || !overflow_->writable()) return;
  // CiA 301 §7.5.2.22: 1 and 241..255 are reserved; the value may change only while the
  // communication cycle period (0x1006, if present) is 0, i.e. while this node produces no SYNC.
  od.add_check(kCounterOverflow, 0, [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    if (data[0] == 1 || data[0] > 240) return SdoAbort::InvalidValue;
    const auto* period = od_.entry(kCommunicationCyclePeriod, 0);
    if (period && period->as<std::uint32_t>() != 0) return SdoAbort::DataDeviceState;
    return SdoAbort::None;
  });
}

std::uint32_t SyncConsumer::cob_id() const {
  const auto* e = od_.entry(kCobIdSync, 0);
  const std::uint32_t v = e ? e->as<std::uint32_t>() : 0x80u;
  return v & ((v & 0x20000000u) ? 0x1FFFFFFFu : 0x7FFu);
}

bool SyncConsumer::extended() const {
  const auto* e = od_.entry(kCobIdSync, 0);
  return e && (e->as<std::uint32_t>() & 0x20000000u);
}

void SyncConsumer::on_frame(const sim::CanFrame& frame, sim::Time now) {
  if (frame.rtr || !sync_allowed(status_.nmt_state)) return;
  if (policy_.sync_requires_dlc0 && frame.dlc != 0) return;
  std::uint8_t pdo_counter = 0;  // 0: no counter for the TPDOs' start values
  if (overflow_) {
    const std::uint8_t overflow = overflow_->as<std::uint8_t>();
    if (frame.dlc != (overflow == 0 ? 0 : 1)) {
      emcy_.raise_emcy(kEmcySyncLength);
      return;
    }
    emcy_.clear_emcy(kEmcySyncLength);
    if (overflow != 0) pdo_counter = frame.data[0];
  }
  const std::uint8_t counter = frame.dlc >= 1 ? frame.data[0] : 0;
  ++count_;
  events_.sync_received(pdo_counter, counter, now);
}

}  // namespace canopen
