#include "devices/canopen/lss_slave.h"


namespace canopen {

namespace {
std::uint32_t u32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
}  // namespace

unsigned lss_bit_rate_kbit(std::uint8_t table_index) {
  static constexpr unsigned kTable[] = {1000, 800, 500, 250, 125, 100, 50, 20, 10};
  return table_index < 9 ? kTable[table_index] : 0;
}

bool LssSlave::unconfigured() const { return status_.node_id == kUnconfiguredNodeId; }

std::uint32_t LssSlave::identity(int sub) const {
  const auto* e = od_.entry(0x1018, static_cast<std::uint8_t>(sub));
  return e ? e->as<std::uint32_t>() : 0;
}

void LssSlave::power_on() {
  state_ = State::Waiting;
  selective_step_ = identify_step_ = fastscan_position_ = 0;
  switching_ = false;
  held_answer_.reset();
  stored_since_configure_ = false;
  const auto& nv = memory_;
  if (const auto* id = nv.find(kNvIndex, 1); id && id->bytes.size() == 1) events_.set_pending_node_id(id->bytes[0]);
  if (const auto* br = nv.find(kNvIndex, 2); br && br->bytes.size() == 1) {
    active_bit_rate_ = br->bytes[0];
  } else {
    active_bit_rate_ = default_bit_rate_;
  }
  pending_bit_rate_ = active_bit_rate_;
  pending_node_id_ = status_.pending_node_id;
}

sim::CanFrame LssSlave::answer(std::initializer_list<std::uint8_t> bytes) {
  sim::CanFrame f;
  f.id = kSlaveToMaster;
  f.dlc = 8;
  std::size_t i = 0;
  for (auto b : bytes) f.data[i++] = b;
  return f;
}

void LssSlave::reply(std::initializer_list<std::uint8_t> bytes) { sender_.send(answer(bytes)); }

void LssSlave::on_frame(const sim::CanFrame& frame, sim::Time now) {
  if (frame.rtr || switching_) return;
  if (frame.dlc < 8 && (!policy_.pad_short_frames || frame.dlc == 0)) return;
  if (!policy_.in_operational && status_.nmt_state == NmtState::Operational) return;
  std::uint8_t d[8] = {};
  for (int i = 0; i < frame.dlc && i < 8; ++i) d[i] = frame.data[i];
  const std::uint8_t cs = d[0];
  const bool config = state_ == State::Configuration;
  switch (cs) {
    case 0x04: switch_global(d[1]); break;
    case 0x40: case 0x41: case 0x42: case 0x43:
      if (!config) switch_selective(cs, u32(d + 1));
      break;
    case 0x11:  // configure node-ID
      if (config) reply({0x11, configure_node_id(d[1]), 0x00});
      break;
    case 0x13:  // configure bit timing
      if (config) reply({0x13, d[1] == 0 ? configure_bit_rate(d[2]) : std::uint8_t{0x01}, 0x00});
      break;
    case 0x15:  // activate bit timing: silent for the delay, switch, silent for the delay again
      if (!config || !policy_.activate_bit_timing) break;
      {
        const auto delay = sim::milliseconds(d[1] | d[2] << 8);
        switching_ = true;
        switch_at_ = now + delay;
        resume_at_ = now + delay + delay;
        silence_.go_silent_until(resume_at_);
      }
      break;
    case 0x17:  // store configuration
      if (!config) break;
      if (!store_configuration()) {
        reply({0x17, policy_.store_error_code, policy_.store_error_specific});
      } else if (policy_.store_answer_delay.count() > 0) {
        held_answer_ = answer({0x17, 0x00, 0x00});
        silence_.go_silent_until(now + policy_.store_answer_delay);
      } else {
        reply({0x17, 0x00, 0x00});
      }
      break;
    case 0x5A: case 0x5B: case 0x5C: case 0x5D:
      if (config || policy_.inquire_in_waiting) {
        const std::uint32_t v = identity(cs - 0x5A + 1);
        reply({cs, static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v >> 16),
               static_cast<std::uint8_t>(v >> 24)});
      }
      break;
    case 0x5E:
      if (config || policy_.inquire_in_waiting) reply({0x5E, status_.node_id});
      break;
    case 0x46: case 0x47: case 0x48: case 0x49: case 0x4A: case 0x4B: identify_remote(cs, u32(d + 1)); break;
    case 0x4C:
      if (unconfigured()) reply({0x50});
      break;
    case 0x51:
      if (policy_.fastscan && !config && (!policy_.fastscan_only_unconfigured || unconfigured())) fastscan(d);
      break;
    default: break;  // unknown LSS services are ignored (CiA 305)
  }
}

std::uint8_t LssSlave::configure_node_id(std::uint8_t id) {
  const bool valid = (id >= 1 && id <= 127) || (id == kUnconfiguredNodeId && policy_.accept_unconfigured_node_id);
  if (!valid) return 0x01;
  pending_node_id_ = id;
  events_.set_pending_node_id(id);
  stored_since_configure_ = false;
  return 0x00;
}

std::uint8_t LssSlave::configure_bit_rate(std::uint8_t table_index) {
  if (table_index >= policy_.bit_rates.size() || !policy_.bit_rates.test(table_index)) return 0x01;
  pending_bit_rate_ = table_index;
  return 0x00;
}

bool LssSlave::store_configuration() {
  if (memory_.failing()) return false;
  auto& nv = memory_;
  nv.put(kNvIndex, 1, ParameterStore::Value{false, {pending_node_id_}});
  nv.put(kNvIndex, 2, ParameterStore::Value{false, {pending_bit_rate_}});
  std::string error;
  if (!nv.save(error)) return false;
  stored_since_configure_ = true;
  return true;
}

void LssSlave::switch_global(std::uint8_t mode) {
  if (mode == 1) {
    state_ = State::Configuration;
    return;
  }
  if (mode != 0) return;
  const bool was_config = state_ == State::Configuration;
  state_ = State::Waiting;
  selective_step_ = 0;
  // Transition 4: an unconfigured node that got a valid node-ID (stored, if required) leaves
  // LSS-only operation and boots with it.
  if (was_config && unconfigured() && pending_node_id_ >= 1 && pending_node_id_ <= 127 &&
      (stored_since_configure_ || !policy_.transition4_requires_store)) {
    events_.apply_pending_node_id();
  }
}

void LssSlave::switch_selective(std::uint8_t cs, std::uint32_t value) {
  const int step = cs - 0x40;
  if (step == 0) {
    selective_step_ = 0;  // a vendor-ID restarts the sequence
  } else if (step != selective_step_) {
    selective_step_ = 0;
    return;
  }
  if (value != identity(step + 1)) {
    selective_step_ = 0;
    return;
  }
  selective_step_ = step + 1;
  if (selective_step_ == 4) {
    selective_step_ = 0;
    state_ = State::Configuration;
    reply({0x44, policy_.selective_response_mode});
  }
}

void LssSlave::identify_remote(std::uint8_t cs, std::uint32_t value) {
  const int step = cs - 0x46;  // 0 vendor, 1 product, 2 rev low, 3 rev high, 4 serial low, 5 serial high
  if (step == 0) {
    identify_step_ = 0;
    identify_match_ = true;
  } else if (step != identify_step_) {
    identify_step_ = 0;
    return;
  }
  switch (step) {
    case 0: identify_match_ = value == identity(1); break;
    case 1: identify_match_ = identify_match_ && value == identity(2); break;
    case 2: identify_low_ = value; break;
    case 3: identify_match_ = identify_match_ && identify_low_ <= identity(3) && identity(3) <= value; break;
    case 4: identify_low_ = value; break;
    case 5: identify_match_ = identify_match_ && identify_low_ <= identity(4) && identity(4) <= value; break;
    default: break;
  }
  identify_step_ = step + 1;
  if (identify_step_ == 6) {
    identify_step_ = 0;
    if (identify_match_) reply({0x4F});
  }
}

void LssSlave::fastscan(const std::uint8_t* d) {
  const std::uint32_t id = u32(d + 1);
  const std::uint8_t bit_check = d[5];
  const std::uint8_t sub = d[6];
  const std::uint8_t next = d[7];
  if (bit_check == 0x80) {
    fastscan_position_ = 0;
    reply({0x4F});
    return;
  }
  if (bit_check > 31 || sub > 3 || next > 3 || sub != fastscan_position_) return;
  const std::uint32_t mask = bit_check == 0 ? 0xFFFFFFFFu : (0xFFFFFFFFu << bit_check);
  if (((id ^ identity(sub + 1)) & mask) != 0) return;
  reply({0x4F});
  if (bit_check == 0) {
    fastscan_position_ = next;
    if (next < sub) state_ = State::Configuration;  // all four LSS address parts matched
  }
}

void LssSlave::process(sim::Time now) {
  if (held_answer_ && !status_.silent()) {
    sender_.send(*held_answer_);
    held_answer_.reset();
  }
  if (!switching_) return;
  if (now >= switch_at_) active_bit_rate_ = pending_bit_rate_;
  if (now >= resume_at_) switching_ = false;
}

}  // namespace canopen
