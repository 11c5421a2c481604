#include "engine/wire_fault_filter.h"

namespace scenario {

int WireFaultFilter::add(const WireFault& fault) {
  rules_.push_back(Rule{fault, true, 0});
  return static_cast<int>(rules_.size()) - 1;
}

void WireFaultFilter::remove(int handle) {
  if (handle >= 0 && handle < static_cast<int>(rules_.size())) rules_[static_cast<std::size_t>(handle)].active = false;
}

sim::FrameFilter::Verdict WireFaultFilter::on_send(sim::CanFrame& frame, int, sim::Time) {
  Verdict v;
  for (auto& r : rules_) {
    if (!r.active || r.fault.kind == WireFault::Kind::TxError || !r.fault.match.matches(frame)) continue;
    if (r.fault.count != 0 && r.affected >= r.fault.count) continue;
    if (r.fault.probability < 1.0 && random_->uniform() >= r.fault.probability) continue;
    ++r.affected;
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
  for (auto& r : rules_) {
    if (!r.active || r.fault.kind != WireFault::Kind::TxError || r.fault.endpoint != from_endpoint) continue;
    if (r.fault.count != 0 && r.affected >= r.fault.count) continue;
    if (r.fault.probability < 1.0 && random_->uniform() >= r.fault.probability) continue;
    ++r.affected;
    destroyed = true;
  }
  return destroyed;
}

}  // namespace scenario
