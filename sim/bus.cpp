#include "sim/bus.h"

#include <algorithm>
#include <bit>
#include <limits>

#include "sim/can_bit_timing.h"
#include "sim/log.h"

namespace sim {

namespace {
// A tick in which more than this many frames are delivered is a runaway feedback loop between
// endpoints (e.g. two nodes answering each other); stop it rather than hang the scheduler.
constexpr std::size_t kMaxFramesPerDelivery = 100000;
// ISO 11898-1 fault confinement.
constexpr unsigned kPassiveLimit = 128;
constexpr unsigned kBusOffLimit = 255;
constexpr unsigned kRecoverySequences = 128;
constexpr unsigned kSuspendTransmissionBits = 8;
constexpr unsigned kRecAfterPassiveSuccess = 119;  // "a value between 119 and 127"

std::int64_t ns_of(Time t) { return t.time_since_epoch().count() * 1000; }
Time time_of(std::int64_t ns) { return Time{Duration{ns / 1000}}; }

// CanFrame::operator== inline: the transmit queue's head is checked against every frame sent.
bool same_frame(const CanFrame& a, const CanFrame& b) {
  if (a.id != b.id || a.dlc != b.dlc || a.extended != b.extended || a.rtr != b.rtr) return false;
  if (a.rtr) return true;
  const unsigned n = a.dlc > 8 ? 8u : a.dlc;
  for (unsigned i = 0; i < n; ++i)
    if (a.data[i] != b.data[i]) return false;
  return true;
}
}  // namespace

Bus::Bus(std::string name)
    : name_(std::move(name)), load_(static_cast<std::size_t>(kLoadBuckets)), std_traffic_(CanFrame::kMaxStdId + 1) {}

void Bus::set_timing(BusTiming timing, std::uint32_t bit_rate) {
  timing_ = timing;
  timing_rate_ = bit_rate == 0 ? 500000 : bit_rate;
  bit_ns_ = 1000000000LL / timing_rate_;
  unsettle();
}

int Bus::attach(FrameReceiver* receiver) {
  unsettle();
  endpoints_.emplace_back();
  endpoints_.back().receiver = receiver;
  tx_pending_.resize((endpoints_.size() + 63) / 64);
  rx_list_.reserve(endpoints_.size());
  refresh_receiver(static_cast<int>(endpoints_.size()) - 1);
  return static_cast<int>(endpoints_.size()) - 1;
}

void Bus::set_online(int endpoint, bool online) {
  if (endpoint < 0 || endpoint >= static_cast<int>(endpoints_.size())) return;
  unsettle();
  auto& ep = endpoints_[static_cast<std::size_t>(endpoint)];
  ep.online = online;
  if (!online) tx_clear(endpoint);  // the controller is off: what it had queued is gone
  refresh_receiver(endpoint);
}

bool Bus::online(int endpoint) const {
  return endpoint >= 0 && endpoint < static_cast<int>(endpoints_.size()) && endpoints_[endpoint].online;
}

bool Bus::participates(int index) const {
  const auto& ep = endpoints_[static_cast<std::size_t>(index)];
  return ep.online && ep.counters.state != ErrorState::BusOff;
}

const ErrorCounters& Bus::counters(int endpoint) const {
  if (endpoint < 0 || endpoint >= static_cast<int>(endpoints_.size())) return wire_counters_;
  return endpoints_[static_cast<std::size_t>(endpoint)].counters;
}

void Bus::send(int from_endpoint, const CanFrame& frame, Time now) { send_tagged(from_endpoint, frame, now, 0); }

void Bus::send_tagged(int from_endpoint, const CanFrame& frame, Time now, std::uint32_t wire_tag) {
  unsettle();
  if (from_endpoint != kWire && !participates(from_endpoint)) return;
  Pending p{frame, from_endpoint};
  if (filter_) {
    const auto verdict = filter_->on_send(p.frame, from_endpoint, now);
    if (verdict.drop) {
      ++stats_.dropped_by_filter;
      if (wire_tag != 0 && transport_) transport_->wire_result(wire_tag, p.frame, Transport::WireResult::Lost);
      return;
    }
    if (verdict.delay.count() > 0) {
      delayed_.push_back(Delayed{p, now + verdict.delay, wire_tag});
      return;
    }
  }
  if (timing_ == BusTiming::Ideal) {
    queue_.push(p);
    if (from_endpoint == kWire) wire_tags_.push(WireTag{wire_tag, p.frame});
    return;
  }
  auto* ep = endpoint_of(from_endpoint);
  if (ep->tx.size() >= tx_depth_) {
    ++stats_.tx_queue_overflow;
    ++ep->counters.tx_queue_overflow;
    wire_refused(wire_tag, p.frame);
    return;
  }
  tx_push(from_endpoint, Queued{p.frame, ns_of(now)});
  if (from_endpoint == kWire) wire_tags_.push(WireTag{wire_tag, p.frame});
}

void Bus::wire_done(Transport::WireResult result) {
  if (wire_tags_.empty()) return;
  const WireTag done = wire_tags_.front();
  wire_tags_.pop();
  if (done.tag != 0 && transport_) transport_->wire_result(done.tag, done.frame, result);
}

void Bus::refresh_head(Endpoint& ep) {
  const Queued& head = ep.tx.front();
  ep.head_ready_ns = std::max(head.ready_ns, ep.suspend_until_ns);
  ep.head_key = arbitration_key(head.frame);
}

void Bus::tx_push(int from, const Queued& q) {
  Endpoint* ep = endpoint_of(from);
  const bool was_empty = ep->tx.empty();
  ep->tx.push(q);
  if (!was_empty) return;  // the queue's head, and so the earliest ready head, is unchanged
  refresh_head(*ep);
  if (from != kWire) tx_pending_[static_cast<std::size_t>(from) >> 6] |= 1ull << (from & 63);
  ready_floor_ns_ = std::min(ready_floor_ns_, q.ready_ns);
}

void Bus::tx_pop(int from) {
  Endpoint* ep = endpoint_of(from);
  ep->tx.pop();
  if (!ep->tx.empty()) {
    refresh_head(*ep);
    ready_floor_ns_ = std::min(ready_floor_ns_, ep->tx.front().ready_ns);
  } else if (from != kWire) {
    tx_pending_[static_cast<std::size_t>(from) >> 6] &= ~(1ull << (from & 63));
  }
}

void Bus::tx_clear(int index) {
  endpoints_[static_cast<std::size_t>(index)].tx.clear();
  tx_pending_[static_cast<std::size_t>(index) >> 6] &= ~(1ull << (index & 63));
  if (in_flight_.active && in_flight_.from == index) in_flight_.head = false;
}

void Bus::refresh_receiver(int index) {
  auto& ep = endpoints_[static_cast<std::size_t>(index)];
  const bool receives = participates(index) && ep.receiver != nullptr;
  if (receives == ep.receives) return;
  ep.receives = receives;
  rx_list_.clear();
  for (std::size_t i = 0; i < endpoints_.size(); ++i)
    if (endpoints_[i].receives) rx_list_.push_back(Rx{endpoints_[i].receiver, static_cast<int>(i)});
  ++rx_version_;
}

void Bus::release_delayed(Time now) {
  // Release due delayed frames in the order they were delayed (stable for determinism).
  auto due_end = std::stable_partition(delayed_.begin(), delayed_.end(),
                                       [now](const Delayed& d) { return d.due <= now; });
  for (auto it = delayed_.begin(); it != due_end; ++it) {
    const bool wire = it->pending.from == kWire;
    if (timing_ == BusTiming::Ideal) {
      queue_.push(it->pending);
      if (wire) wire_tags_.push(WireTag{it->wire_tag, it->pending.frame});
    } else if (wire || participates(it->pending.from)) {
      auto* ep = endpoint_of(it->pending.from);
      if (ep->tx.size() < tx_depth_) {
        tx_push(it->pending.from, Queued{it->pending.frame, ns_of(it->due)});
        if (wire) wire_tags_.push(WireTag{it->wire_tag, it->pending.frame});
      } else {
        ++stats_.tx_queue_overflow;
        ++ep->counters.tx_queue_overflow;
        if (wire) wire_refused(it->wire_tag, it->pending.frame);
      }
    }
  }
  delayed_.erase(delayed_.begin(), due_end);
}

std::size_t Bus::deliver_due(Time now) {
  unsettle();
  const std::int64_t now_ns = ns_of(now);
  now_ns_ = std::max(now_ns_, now_ns);
  if (!delayed_.empty()) release_delayed(now);
  std::size_t n = 0;
  if (timing_ == BusTiming::Bit) {
    deliver_timed(now, n);
  } else {
    while (!queue_.empty()) {
      const Pending p = queue_.front();
      queue_.pop();
      deliver_one(p, now);
      if (++n >= kMaxFramesPerDelivery) {
        ++stats_.delivery_overflow;
        log(LogLevel::Warn, "bus {}: more than {} frames in one tick; dropping {} queued frames", name_,
            kMaxFramesPerDelivery, queue_.size());
        queue_.clear();
        while (!wire_tags_.empty()) wire_done(Transport::WireResult::Refused);
        break;
      }
    }
  }
  idle_until(now_ns, now);
  if (transport_) transport_->service(now);
  return n;
}

// ---- ideal timing -------------------------------------------------------------------------------

void Bus::deliver_one(const Pending& p, Time now) {
  const std::int64_t at_ns = std::max(ns_of(now), idle_ns_);
  const FrameBits bits = bits_cache_.get(p.frame);
  // Attempts at zero duration: each destroyed one costs an error frame and counts.
  if (filter_ && p.from != kWire) {
    while (filter_->on_transmit(p.frame, p.from, now)) {
      account(nullptr, bits.stuffed_region + bits.stuff_bits + 3 + kErrorFrameBits, at_ns);
      ++stats_.error_frames;
      transmit_error(p.from, now);
      receive_result(p.from, true, now);
      recessive_sequences(1, now);
      if (!participates(p.from)) return;  // bus-off: the frame is gone with the queue
    }
  }
  account(&p.frame, bits.total(), at_ns);
  ++stats_.frames;
  if (p.from == kWire) ++stats_.from_wire;
  const std::string_view wire_name = transport_ ? transport_->name() : std::string_view(name_);
  tap_sender_ = p.from;
  for (auto* tap : taps_) tap->on_bus_frame(wire_name, p.frame, now);
  if (transport_) {
    if (p.from != kWire) transport_->send(p.frame);
    else wire_done(Transport::WireResult::Delivered);
  }
  transmit_success(p.from, now);
  receive_result(p.from, false, now);
  recessive_sequences(1, now);
  deliver_to_receivers(p.frame, p.from, now);
}

// ---- bit timing ---------------------------------------------------------------------------------

void Bus::deliver_timed(Time now, std::size_t& n) {
  const std::int64_t now_ns = ns_of(now);
  for (;;) {
    if (in_flight_.active) {
      if (in_flight_.deliver_ns > now_ns) break;
      const bool delivered = !in_flight_.error;
      complete(time_of(in_flight_.deliver_ns));
      if (delivered) ++n;
      continue;
    }
    if (!start_next(now_ns)) break;
  }
}

bool Bus::start_next(std::int64_t now_ns) {
  // Nothing can start before now: the common case between frames, decided without the queues.
  if (std::max(idle_ns_, ready_floor_ns_) >= now_ns) return false;
  // The next frame starts at start = max(idle, earliest ready head); the heads ready by then
  // arbitrate (lowest key wins; on equal keys the lower endpoint, the wire last). In one pass:
  // the least (max(ready, idle), key), first found on ties.
  std::int64_t earliest = std::numeric_limits<std::int64_t>::max();
  std::int64_t start = earliest;
  std::uint64_t best = 0;
  int winner = kWire - 1;
  for (std::size_t w = 0; w < tx_pending_.size(); ++w) {
    for (std::uint64_t bits = tx_pending_[w]; bits != 0; bits &= bits - 1) {
      const int i = static_cast<int>(w * 64) + std::countr_zero(bits);
      if (!participates(i)) continue;
      const Endpoint& ep = endpoints_[static_cast<std::size_t>(i)];
      earliest = std::min(earliest, ep.head_ready_ns);
      const std::int64_t at = std::max(ep.head_ready_ns, idle_ns_);
      if (at < start || (at == start && ep.head_key < best)) {
        winner = i;
        start = at;
        best = ep.head_key;
      }
    }
  }
  if (!wire_.tx.empty()) {
    earliest = std::min(earliest, wire_.head_ready_ns);
    const std::int64_t at = std::max(wire_.head_ready_ns, idle_ns_);
    if (at < start || (at == start && wire_.head_key < best)) {
      winner = kWire;
      start = at;
    }
  }
  ready_floor_ns_ = earliest;
  if (winner == kWire - 1) return false;
  // Everything sent at `start` must be known before it is decided: only instants before now.
  if (start >= now_ns) return false;
  const Time start_time = time_of(start);
  idle_until(start, start_time);
  // The SOF ends every recessive sequence (only bus-off endpoints count them).
  if (bus_off_count_ > 0)
    for (auto& ep : endpoints_) ep.recessive_ns = 0;

  const CanFrame& frame = endpoint_of(winner)->tx.front().frame;
  const FrameBits bits = bits_cache_.get(frame);
  // Built in place: in_flight_ is inactive, nothing reads it until this returns.
  InFlight& f = in_flight_;
  f.from = winner;
  f.frame = frame;
  f.start_ns = start;
  f.head = true;
  f.error = filter_ && winner != kWire && filter_->on_transmit(frame, winner, start_time);
  if (f.error) {
    // Receivers find the CRC error at the CRC delimiter; the error flag starts after the ACK
    // delimiter.
    f.bits = bits.stuffed_region + bits.stuff_bits + 3 + kErrorFrameBits;
    f.deliver_ns = start + static_cast<std::int64_t>(f.bits - 3) * bit_ns();
  } else {
    f.bits = bits.total();
    f.deliver_ns = start + static_cast<std::int64_t>(bits.until_eof()) * bit_ns();
  }
  f.end_ns = start + static_cast<std::int64_t>(f.bits) * bit_ns();
  f.active = true;
  // Counted when it starts: the load window then sees the bus busy while the frame is on it.
  account(f.error ? nullptr : &f.frame, f.bits, f.start_ns);
  return true;
}

void Bus::complete(Time at) {
  const InFlight f = in_flight_;
  in_flight_.active = false;
  idle_ns_ = f.end_ns;
  idle_accounted_ns_ = std::max(idle_accounted_ns_, f.end_ns);
  Endpoint* sender = endpoint_of(f.from);
  if (f.error) {
    ++stats_.error_frames;
    transmit_error(f.from, at);
    receive_result(f.from, true, at);
  } else {
    // The frame leaves the queue only now: a destroyed one is retransmitted automatically.
    // Still the head unless the queue was cleared meanwhile; then the original test: the head
    // equal to the frame.
    if (!sender->tx.empty() && (f.head || same_frame(sender->tx.front().frame, f.frame))) tx_pop(f.from);
    ++stats_.frames;
    if (f.from == kWire) ++stats_.from_wire;
    if (!taps_.empty()) {
      const std::string_view wire_name = transport_ ? transport_->name() : std::string_view(name_);
      tap_sender_ = f.from;
      for (auto* tap : taps_) tap->on_bus_frame(wire_name, f.frame, at);
    }
    if (transport_) {
      if (f.from != kWire) transport_->send(f.frame);
      else wire_done(Transport::WireResult::Delivered);
    }
    transmit_success(f.from, at);
    // A success changes nothing while every REC is 0 (the state follows the counters).
    if (rec_nonzero_count_ != 0) receive_result(f.from, false, at);
  }
  if (f.from != kWire && sender->counters.state == ErrorState::Passive) {
    sender->suspend_until_ns = f.end_ns + static_cast<std::int64_t>(kSuspendTransmissionBits) * bit_ns();
    if (!sender->tx.empty()) refresh_head(*sender);
  }
  // ACK delimiter + EOF + intermission, or error delimiter + intermission (only bus-off
  // endpoints count them).
  if (bus_off_count_ > 0) recessive_sequences(1, at);
  if (f.error) return;
  deliver_to_receivers(f.frame, f.from, at);
}

void Bus::deliver_to_receivers(const CanFrame& frame, int from, Time at) {
  // Every endpoint that takes frames, in order. A receiver may take another endpoint off the bus
  // (or attach one): then the rest goes by the endpoints' flags, read as the loop goes.
  const std::uint64_t version = rx_version_;
  for (std::size_t k = 0; k < rx_list_.size(); ++k) {
    const Rx rx = rx_list_[k];
    if (rx.index == from) continue;
    rx.receiver->on_frame(frame, at);
    if (rx_version_ == version) continue;
    for (auto i = static_cast<std::size_t>(rx.index) + 1; i < endpoints_.size(); ++i) {
      const Endpoint& ep = endpoints_[i];
      if (ep.receives && static_cast<int>(i) != from) ep.receiver->on_frame(frame, at);
    }
    return;
  }
}

// ---- fault confinement --------------------------------------------------------------------------

void Bus::transmit_error(int from, Time at) {
  if (from == kWire) return;
  endpoints_[static_cast<std::size_t>(from)].counters.tec += 8;
  update_state(from, at);
}

void Bus::transmit_success(int from, Time at) {
  if (from == kWire) return;
  auto& c = endpoints_[static_cast<std::size_t>(from)].counters;
  if (c.tec == 0) return;  // the state follows the counters: unchanged counters, unchanged state
  --c.tec;
  update_state(from, at);
}

void Bus::receive_result(int from, bool error, Time at) {
  // A success changes nothing while every REC is 0 (the state follows the counters).
  if (!error && rec_nonzero_count_ == 0) return;
  for (int i = 0; i < static_cast<int>(endpoints_.size()); ++i) {
    if (i == from || !participates(i)) continue;
    auto& c = endpoints_[static_cast<std::size_t>(i)].counters;
    if (error) {
      if (c.rec++ == 0) ++rec_nonzero_count_;
    } else if (c.rec >= kPassiveLimit) {
      c.rec = kRecAfterPassiveSuccess;
    } else if (c.rec > 0) {
      if (--c.rec == 0) --rec_nonzero_count_;
    } else {
      continue;  // unchanged counters, unchanged state
    }
    update_state(i, at);
  }
}

void Bus::update_state(int index, Time at) {
  auto& ep = endpoints_[static_cast<std::size_t>(index)];
  auto& c = ep.counters;
  if (c.state == ErrorState::BusOff) return;  // only the recovery sequence ends it
  ErrorState next = ErrorState::Active;
  if (c.tec > kBusOffLimit) next = ErrorState::BusOff;
  else if (c.tec >= kPassiveLimit || c.rec >= kPassiveLimit) next = ErrorState::Passive;
  if (next == c.state) return;
  c.state = next;
  if (next == ErrorState::BusOff) {
    ++c.bus_off_events;
    ++bus_off_count_;
    tx_clear(index);
    refresh_receiver(index);
    ep.recessive_ns = 0;
    ep.recovery_sequences = 0;
  }
  notify(index, next, at);
}

void Bus::recessive_sequences(unsigned count, Time at) {
  if (bus_off_count_ == 0) return;
  for (int i = 0; i < static_cast<int>(endpoints_.size()); ++i) add_recovery(i, count, at);
}

void Bus::add_recovery(int index, unsigned sequences, Time at) {
  auto& ep = endpoints_[static_cast<std::size_t>(index)];
  if (ep.counters.state != ErrorState::BusOff || sequences == 0) return;
  ep.recovery_sequences += sequences;
  if (ep.recovery_sequences < kRecoverySequences) return;
  ep.counters.tec = 0;
  if (ep.counters.rec > 0) --rec_nonzero_count_;
  ep.counters.rec = 0;
  ep.counters.state = ErrorState::Active;
  --bus_off_count_;
  refresh_receiver(index);
  ep.recovery_sequences = 0;
  ep.recessive_ns = 0;
  notify(index, ErrorState::Active, at);
}

void Bus::idle_until(std::int64_t until_ns, Time at) {
  if (in_flight_.active) return;
  const std::int64_t from = std::max(idle_ns_, idle_accounted_ns_);
  if (until_ns <= from) return;
  idle_accounted_ns_ = until_ns;
  if (bus_off_count_ > 0) count_idle(from, until_ns, at);
}

void Bus::count_idle(std::int64_t from, std::int64_t until_ns, Time at) {
  const std::int64_t sequence_ns = static_cast<std::int64_t>(kFrameTailBits) * bit_ns();
  for (int i = 0; i < static_cast<int>(endpoints_.size()); ++i) {
    auto& ep = endpoints_[static_cast<std::size_t>(i)];
    if (ep.counters.state != ErrorState::BusOff) continue;
    ep.recessive_ns += until_ns - from;
    const auto sequences = static_cast<unsigned>(ep.recessive_ns / sequence_ns);
    ep.recessive_ns %= sequence_ns;
    add_recovery(i, sequences, at);
  }
}

void Bus::notify(int index, ErrorState state, Time at) {
  auto* receiver = endpoints_[static_cast<std::size_t>(index)].receiver;
  if (receiver) receiver->on_error_state(state, at);
}

// ---- load ---------------------------------------------------------------------------------------

void Bus::account(const CanFrame* frame, unsigned bits, std::int64_t start_ns) {
  stats_.busy_bits += bits;
  const std::int64_t duration = static_cast<std::int64_t>(bits) * bit_ns();
  busy_ns_ += static_cast<std::uint64_t>(duration);
  if (timing_ == BusTiming::Ideal) idle_ns_ = std::max(idle_ns_, start_ns + duration);
  const std::int64_t end = start_ns + duration;
  if (start_ns >= load_lo_ns_ && end <= load_lo_ns_ + 1000000) {
    // Within the bucket the last frame ended in (most frames): no division.
    load_[load_index_].busy_ns += duration;
  } else {
    // Split the occupancy over the millisecond buckets it covers.
    std::int64_t t = start_ns;
    while (t < end) {
      const std::int64_t ms = t / 1000000;
      const std::int64_t bucket_end = std::min(end, (ms + 1) * 1000000);
      load_index_ = static_cast<std::size_t>(ms % kLoadBuckets);
      load_lo_ns_ = ms * 1000000;
      auto& b = load_[load_index_];
      if (b.ms != ms) b = LoadBucket{ms, 0};
      b.busy_ns += bucket_end - t;
      t = bucket_end;
    }
  }
  if (!frame) return;
  IdTraffic* entry = nullptr;
  if (!frame->extended) {
    entry = &std_traffic_[frame->id & CanFrame::kMaxStdId];
    if (entry->frames == 0) {
      entry->id = frame->id & CanFrame::kMaxStdId;
      std_order_.push_back(static_cast<std::uint16_t>(entry->id));
    }
  } else {
    for (auto& e : ext_traffic_)
      if (e.id == frame->id) entry = &e;
    if (!entry) {  // allocates only for an identifier not seen before
      ext_traffic_.push_back(IdTraffic{frame->id, true, 0, 0});
      entry = &ext_traffic_.back();
    }
  }
  ++entry->frames;
  entry->bits += bits;
}

double Bus::load() const {
  // The last kLoadWindowMs whole milliseconds before now (the one now is in has not happened).
  const std::int64_t now_ms = now_ns_ / 1000000;
  std::int64_t busy = 0;
  for (const auto& b : load_)
    if (b.ms >= now_ms - kLoadWindowMs && b.ms < now_ms) busy += b.busy_ns;
  return std::min(1.0, static_cast<double>(busy) / (static_cast<double>(kLoadWindowMs) * 1e6));
}

double Bus::mean_load() const {
  if (now_ns_ <= 0) return 0.0;
  return std::min(1.0, static_cast<double>(busy_ns_) / static_cast<double>(now_ns_));
}

std::vector<IdTraffic> Bus::traffic() const {
  std::vector<IdTraffic> out;
  out.reserve(std_order_.size() + ext_traffic_.size());
  for (auto id : std_order_) out.push_back(std_traffic_[id]);
  out.insert(out.end(), ext_traffic_.begin(), ext_traffic_.end());
  return out;
}

std::size_t Bus::pending_frames() const {
  std::size_t n = wire_.tx.size() + queue_.size() + delayed_.size();
  for (const auto& ep : endpoints_) n += ep.tx.size();
  return n;
}

// ---- transport ----------------------------------------------------------------------------------

std::size_t Bus::poll_transport(Time now) {
  if (!transport_) return 0;
  std::size_t n = 0;
  CanFrame f;
  std::uint32_t tag = 0;
  while (transport_->receive_tagged(f, tag)) {
    send_tagged(kWire, f, now, tag);
    ++n;
  }
  return n;
}

}  // namespace sim
