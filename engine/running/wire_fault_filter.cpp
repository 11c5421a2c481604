#include "engine/running/wire_fault_filter.h"

#include <algorithm>

namespace scenario {

int WireFaultFilter::add(const WireFault& fault) {
  rules_.push_back(Rule{fault, next_handle_, 0});
  return next_handle_++;
}

void WireFaultFilter::remove(int handle) {
  const auto it = std::find_if(rules_.begin(), rules_.end(), [handle](const Rule& r) { return r.handle == handle; });
  if (it != rules_.end()) rules_.erase(it);
}

std::size_t WireFaultFilter::active() const {
  return static_cast<std::size_t>(std::count_if(rules_.begin(), rules_.end(), [](const Rule& r) { return !r.spent(); }));
}

void WireFaultFilter::free_spent() {
  std::erase_if(rules_, [](const Rule& r) { return r.spent(); });
  spent_ = false;
}

sim::FrameFilter::Verdict WireFaultFilter::on_send(sim::CanFrame& frame, int, sim::Time) {
  Verdict v;
  if (spent_) free_spent();
  for (auto& r : rules_) {
    if (r.fault.kind == WireFault::Kind::TxError || !r.fault.match.matches(frame)) continue;
    if (r.spent()) continue;
    if (r.fault.probability < 1.0 && random_->uniform() >= r.fault.probability) continue;
    ++r.affected;
    spent_ |= r.spent();
    switch (r.fault.kind) {
      case WireFault::Kind::Drop:
        v.drop = true;
        return v;
      case WireFault::Kind::Delay:
        v.delay += r.fault.delay;
        break;
      case WireFault::Kind::TxError: break;
      case WireFault::Kind::Corrupt:
        if (r.fault.byte < frame.dlc && !frame.rtr) {
          auto& b = frame.data[static_cast<std::size_t>(r.fault.byte)];
          if (r.fault.set_value) b = *r.fault.set_value;
          else if (r.fault.random_value) b = static_cast<std::uint8_t>(random_->next() >> 56);
          else b ^= r.fault.xor_mask;
        }
        break;
    }
  }
  return v;
}

bool WireFaultFilter::on_transmit(const sim::CanFrame&, int from_endpoint, sim::Time) {
  bool destroyed = false;
  if (spent_) free_spent();
  for (auto& r : rules_) {
    if (r.fault.kind != WireFault::Kind::TxError || r.fault.endpoint != from_endpoint) continue;
    if (r.spent()) continue;
    if (r.fault.probability < 1.0 && random_->uniform() >= r.fault.probability) continue;
    ++r.affected;
    spent_ |= r.spent();
    destroyed = true;
  }
  return destroyed;
}

}  // namespace scenario
