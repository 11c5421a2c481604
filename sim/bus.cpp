#include "sim/bus.h"

#include <algorithm>

#include "sim/log.h"

namespace sim {

namespace {
// A tick in which more than this many frames are delivered is a runaway feedback loop between
// endpoints (e.g. two nodes answering each other); stop it rather than hang the scheduler.
constexpr std::size_t kMaxFramesPerDelivery = 100000;
}  // namespace

Bus::Bus(std::string name) : name_(std::move(name)) {}

int Bus::attach(FrameReceiver* receiver) {
  endpoints_.push_back(Endpoint{receiver, true});
  return static_cast<int>(endpoints_.size()) - 1;
}

void Bus::set_online(int endpoint, bool online) {
  if (endpoint >= 0 && endpoint < static_cast<int>(endpoints_.size())) endpoints_[endpoint].online = online;
}

bool Bus::online(int endpoint) const {
  return endpoint >= 0 && endpoint < static_cast<int>(endpoints_.size()) && endpoints_[endpoint].online;
}

void Bus::send(int from_endpoint, const CanFrame& frame, Time now) {
  if (from_endpoint != kWire && !online(from_endpoint)) return;
  Pending p{frame, from_endpoint};
  if (filter_) {
    const auto verdict = filter_->on_send(p.frame, from_endpoint, now);
    if (verdict.drop) {
      ++stats_.dropped_by_filter;
      return;
    }
    if (verdict.delay.count() > 0) {
      delayed_.push_back(Delayed{p, now + verdict.delay});
      return;
    }
  }
  queue_.push(p);
}

std::size_t Bus::deliver(Time now) {
  if (!delayed_.empty()) {
    // Release due delayed frames in the order they were delayed (stable for determinism).
    auto due_end = std::stable_partition(delayed_.begin(), delayed_.end(),
                                         [now](const Delayed& d) { return d.due <= now; });
    for (auto it = delayed_.begin(); it != due_end; ++it) queue_.push(it->pending);
    delayed_.erase(delayed_.begin(), due_end);
  }
  std::size_t n = 0;
  while (!queue_.empty()) {
    const Pending p = queue_.front();
    queue_.pop();
    deliver_one(p, now);
    if (++n >= kMaxFramesPerDelivery) {
      ++stats_.delivery_overflow;
      log(LogLevel::Warn, "bus {}: more than {} frames in one tick; dropping {} queued frames", name_,
          kMaxFramesPerDelivery, queue_.size());
      queue_.clear();
      break;
    }
  }
  if (transport_) transport_->service(now);
  return n;
}

void Bus::deliver_one(const Pending& p, Time now) {
  ++stats_.frames;
  if (p.from == kWire) ++stats_.from_wire;
  const std::string_view wire_name = transport_ ? transport_->name() : std::string_view(name_);
  for (auto* tap : taps_) tap->on_bus_frame(wire_name, p.frame, now);
  if (transport_ && p.from != kWire) transport_->send(p.frame);
  for (std::size_t i = 0; i < endpoints_.size(); ++i) {
    const auto& ep = endpoints_[i];
    if (static_cast<int>(i) == p.from || !ep.online || ep.receiver == nullptr) continue;
    ep.receiver->on_frame(p.frame, now);
  }
}

std::size_t Bus::poll_transport(Time now) {
  if (!transport_) return 0;
  std::size_t n = 0;
  CanFrame f;
  while (transport_->receive(f)) {
    send(kWire, f, now);
    ++n;
  }
  return n;
}

}  // namespace sim
