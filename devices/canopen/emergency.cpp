#include "devices/canopen/emergency.h"

#include <algorithm>


namespace canopen {

namespace {
constexpr std::uint16_t kErrorRegister = 0x1001;
constexpr std::uint16_t kErrorHistory = 0x1003;
constexpr std::uint16_t kCobIdEmcy = 0x1014;
constexpr std::uint16_t kInhibitEmcy = 0x1015;
}  // namespace

bool Emergency::may_send() const {
  const NmtState state = status_.nmt_state;
  if (!emcy_allowed(state)) return false;
  return state != NmtState::PreOperational || policy_.send_in_preoperational;
}

void Emergency::bind_objects() {
  auto& od = od_;
  const auto& policy = policy_;
  if (od.entry(kErrorHistory, 0) && policy.history_depth > 0) {
    od.add_check(kErrorHistory, 0, [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
      if (origin == Origin::Restore || origin == Origin::Internal) return SdoAbort::None;
      if (decode_unsigned(data) != 0) return policy_.history_write_nonzero;
      return SdoAbort::None;
    });
    od.add_observer(kErrorHistory, 0, [this](OdEntry&, Origin origin) {
      if (origin == Origin::Sdo || origin == Origin::Pdo) clear_history();
    });
    for (auto& [sub, e] : od.object(kErrorHistory)->entries) {
      if (sub == 0) continue;
      od.add_read_hook(kErrorHistory, sub, [this, s = sub](OdEntry&, Origin) {
        return s > history_.size() ? policy_.history_read_beyond : SdoAbort::None;
      });
    }
  }
}

std::uint8_t Emergency::error_register() const {
  std::uint8_t r = extra_bits_;
  for (const auto& e : active_) r |= e.bits;
  return r;
}

void Emergency::set_extra_register_bits(std::uint8_t bits) {
  extra_bits_ = bits;
  update_register();
}

void Emergency::update_register() {
  if (od_.entry(kErrorRegister, 0)) od_.set<std::uint8_t>(kErrorRegister, 0, error_register());
}

void Emergency::raise(std::uint16_t code, std::uint8_t register_bits, Info info) {
  if (active(code)) return;
  active_.push_back(ActiveError{code, register_bits});
  update_register();
  record(code, info);
  enqueue(code, info);
}

void Emergency::signal(std::uint16_t code, std::uint8_t register_bits, Info info) {
  // An event without a lasting condition: the register shows its bits only in this frame.
  record(code, info);
  const std::uint8_t saved = extra_bits_;
  extra_bits_ |= register_bits;
  enqueue(code, info);
  extra_bits_ = saved;
}

void Emergency::clear(std::uint16_t code) {
  const auto it = std::find_if(active_.begin(), active_.end(), [code](const ActiveError& e) { return e.code == code; });
  if (it == active_.end()) return;
  active_.erase(it);
  update_register();
  if (policy_.history == EmcyPolicy::History::PresentErrors) {
    history_.erase(std::remove_if(history_.begin(), history_.end(),
                                  [code](std::uint32_t e) { return (e & 0xFFFF) == code; }),
                   history_.end());
    publish_history();
  }
  if (active_.empty() && policy_.send_no_error) enqueue(0x0000, Info{});
}

void Emergency::clear_all() {
  if (active_.empty()) return;
  active_.clear();
  update_register();
  if (policy_.history == EmcyPolicy::History::PresentErrors) {
    history_.clear();
    publish_history();
  }
  if (policy_.send_no_error) enqueue(0x0000, Info{});
}

void Emergency::record(std::uint16_t code, const Info& info) {
  const auto& policy = policy_;
  if (policy.history_depth == 0 || code == 0) return;
  if (!policy.record_when_not_sent && !emcy_allowed(status_.nmt_state)) return;
  const std::uint32_t entry = (static_cast<std::uint32_t>(info[0]) | static_cast<std::uint32_t>(info[1]) << 8) << 16 | code;
  history_.insert(history_.begin(), entry);
  if (history_.size() > policy.history_depth) history_.resize(policy.history_depth);
  publish_history();
}

void Emergency::clear_history() {
  history_.clear();
  publish_history();
}

void Emergency::publish_history() {
  if (policy_.history_depth == 0) return;  // the device keeps 0x1003 itself
  auto& od = od_;
  auto* obj = od.object(kErrorHistory);
  if (!obj) return;
  for (auto& [sub, e] : obj->entries) {
    if (sub == 0) {
      e.assign<std::uint8_t>(static_cast<std::uint8_t>(history_.size()));
    } else {
      e.assign<std::uint32_t>(sub <= history_.size() ? history_[sub - 1] : 0);
    }
  }
}

void Emergency::send_frame(std::uint16_t code, std::uint8_t error_register, Info info) {
  const auto* cob = od_.entry(kCobIdEmcy, 0);
  const std::uint32_t cob_id = cob ? cob->as<std::uint32_t>() : 0x80u + status_.node_id;
  if (cob_id & 0x80000000u) return;  // EMCY disabled
  if (!may_send()) return;
  sim::CanFrame f;
  f.extended = (cob_id & 0x20000000u) != 0;
  f.id = cob_id & (f.extended ? 0x1FFFFFFFu : 0x7FFu);
  f.dlc = 8;
  f.data = {static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(code >> 8), error_register,
            info[0], info[1], info[2], info[3], info[4]};
  queue_.push(f);
  process(status_.now);
}

void Emergency::enqueue(std::uint16_t code, const Info& info) { send_frame(code, error_register(), info); }

void Emergency::process(sim::Time now) {
  while (!queue_.empty() && now >= next_allowed_) {
    if (!may_send()) {
      queue_.clear();  // EMCYs are never sent late from Stopped
      return;
    }
    sender_.send(queue_.front());
    queue_.pop();
    const auto* inhibit = od_.entry(kInhibitEmcy, 0);
    const auto units = inhibit ? inhibit->as<std::uint32_t>() : 0u;
    next_allowed_ = now + sim::microseconds(static_cast<std::int64_t>(units) * 100);
  }
}

void Emergency::reset_communication() {
  queue_.clear();
  next_allowed_ = sim::Time{};
  if (policy_.clear_history_on_reset_communication &&
      policy_.history == EmcyPolicy::History::Events) {
    history_.clear();
  }
  publish_history();
  update_register();
}

}  // namespace canopen
