#include "devices/canopen/pdo_service.h"

#include <algorithm>


namespace canopen {

namespace {
constexpr std::uint16_t kRpdoComm = 0x1400, kRpdoMap = 0x1600, kTpdoComm = 0x1800, kTpdoMap = 0x1A00;
constexpr int kMaxPdos = 512;
constexpr std::uint32_t kInvalid = 0x80000000u, kNoRtr = 0x40000000u, kExtended = 0x20000000u;
constexpr std::uint16_t kEmcyRpdoShort = 0x8210, kEmcyRpdoLong = 0x8220, kEmcyRpdoTimeout = 0x8250;

bool external(Origin o) { return o == Origin::Sdo; }

}  // namespace

PdoService::PdoService(ObjectDictionary& od, const PdoPolicy& policy, const NodeStatus& status, FrameSender& sender,
                       PdoEvents& events, EmcyRequests& emcy, RoutesChanged& routes)
    : od_(od), policy_(policy), status_(status), sender_(sender), events_(events), emcy_(emcy), routes_(routes) {}

MappingRules PdoService::rules() const {
  const auto& p = policy_;
  return MappingRules{p.dummy_mapping, p.width_conversion, p.mapping_length_mismatch};
}

void PdoService::bind_objects() {
  auto& od = od_;
  rpdos_.clear();
  tpdos_.clear();
  for (int i = 0; i < kMaxPdos; ++i) {
    const auto comm = static_cast<std::uint16_t>(kRpdoComm + i), map = static_cast<std::uint16_t>(kRpdoMap + i);
    if (od.object(comm) && od.object(map)) {
      Rpdo r;
      r.number = i + 1;
      r.comm_index = comm;
      r.map_index = map;
      bind_timers(r);
      rpdos_.push_back(r);
      install_checks(comm, map, PdoDirection::Receive);
    }
  }
  for (int i = 0; i < kMaxPdos; ++i) {
    const auto comm = static_cast<std::uint16_t>(kTpdoComm + i), map = static_cast<std::uint16_t>(kTpdoMap + i);
    if (od.object(comm) && od.object(map)) {
      Tpdo t;
      t.number = i + 1;
      t.comm_index = comm;
      t.map_index = map;
      bind_timers(t);
      tpdos_.push_back(t);
      install_checks(comm, map, PdoDirection::Transmit);
    }
  }
  rebuild_lists();
  layout_ = od.layout();
}

void PdoService::bind_timers(Pdo& p) {
  p.inhibit_time = EntryRef<std::uint16_t>::optional(od_, p.comm_index, 3);
  p.event_timer = EntryRef<std::uint16_t>::optional(od_, p.comm_index, 5);
}

void PdoService::relink() {
  for (auto& r : rpdos_) {
    bind_timers(r);
    resolve(r, PdoDirection::Receive);
  }
  for (auto& t : tpdos_) {
    bind_timers(t);
    resolve(t, PdoDirection::Transmit);
  }
  rebuild_lists();
  layout_ = od_.layout();
}

void PdoService::rebuild_lists() {
  sync_tpdos_.clear();
  async_tpdos_.clear();
  for (std::size_t i = 0; i < tpdos_.size(); ++i) {
    const Tpdo& t = tpdos_[i];
    if (!t.valid || t.mapping.length == 0) continue;
    if (t.type <= 240 || t.type == 252) sync_tpdos_.push_back(static_cast<std::uint16_t>(i));
    if (t.type >= 254) async_tpdos_.push_back(static_cast<std::uint16_t>(i));
  }
  ++lists_version_;
}

template <typename Visit>
void PdoService::walk(const std::vector<std::uint16_t>& list, Visit&& visit) {
  // `visit` re-checks the conditions, so when a visit rebuilt the lists (a device reacting to
  // a sample or an RPDO by remapping), the walk goes on over every later TPDO as the plain loop did.
  const std::uint32_t version = lists_version_;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::size_t i = list[k];
    visit(tpdos_[i]);
    if (lists_version_ != version) {
      for (std::size_t j = i + 1; j < tpdos_.size(); ++j) visit(tpdos_[j]);
      return;
    }
  }
}

void PdoService::install_checks(std::uint16_t comm_index, std::uint16_t map_index, PdoDirection dir) {
  auto& od = od_;
  auto preop_only = [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
    if (external(origin) && policy_.parameters_preop_only && status_.nmt_state == NmtState::Operational) {
      return SdoAbort::DataDeviceState;
    }
    return SdoAbort::None;
  };
  auto pdo_valid = [&od, comm_index]() {
    const auto* e = od.entry(comm_index, 1);
    return e && !(e->as<std::uint32_t>() & kInvalid);
  };
  auto reload_all = [this](OdEntry&, Origin) {
    reload();
    routes_.rebuild_dispatch();
  };

  for (auto& [sub, e] : od.object(comm_index)->entries) {
    if (sub == 0 || !e.writable()) continue;
    od.add_check(comm_index, sub, preop_only, CheckStage::State);
    od.add_observer(comm_index, sub, reload_all);
  }
  if (dir == PdoDirection::Transmit && od.entry(comm_index, 5) && od.entry(comm_index, 5)->writable()) {
    od.add_observer(comm_index, 5, [this, comm_index](OdEntry&, Origin) {
      if (!policy_.event_timer_restart_on_write) return;
      for (auto& t : tpdos_) {
        if (t.comm_index == comm_index) t.next_timer = status_.now + sim::milliseconds(event_timer_ms(t));
      }
    });
  }
  if (od.entry(comm_index, 1) && od.entry(comm_index, 1)->writable()) {
    od.add_check(comm_index, 1, [this, &od, comm_index](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
      if (!external(origin)) return SdoAbort::None;
      const auto now_value = e.as<std::uint32_t>();
      const auto new_value = static_cast<std::uint32_t>(decode_unsigned(data));
      const bool new_valid = !(new_value & kInvalid);
      if (new_valid && !(new_value & kExtended) && (new_value & 0x1FFFF800u)) return SdoAbort::InvalidValue;
      if (policy_.cobid_change_requires_invalid && !(now_value & kInvalid) && new_valid &&
          ((now_value ^ new_value) & 0x3FFFFFFFu) != 0) {
        return SdoAbort::InvalidValue;  // CiA 301: change the identifier only while the PDO is invalid
      }
      (void)od;
      (void)comm_index;
      return SdoAbort::None;
    });
  }
  if (od.entry(comm_index, 2) && od.entry(comm_index, 2)->writable()) {
    od.add_check(comm_index, 2, [this, dir](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
      if (!external(origin)) return SdoAbort::None;
      const auto& p = policy_;
      const auto& allowed = dir == PdoDirection::Receive ? p.rpdo_types : p.tpdo_types;
      return allowed.test(data[0]) ? SdoAbort::None : p.bad_transmission_type;
    });
  }
  if (dir == PdoDirection::Transmit && od.entry(comm_index, 6) && od.entry(comm_index, 6)->writable()) {
    // CiA 301: SYNC start value 0..240, changed only while the PDO is invalid.
    od.add_check(comm_index, 6, [pdo_valid](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
      if (!external(origin)) return SdoAbort::None;
      if (data[0] > 240) return SdoAbort::ValueTooHigh;
      return pdo_valid() ? SdoAbort::InvalidValue : SdoAbort::None;
    });
  }

  auto* map = od.object(map_index);
  for (auto& [sub, e] : map->entries) {
    if (!e.writable()) continue;
    od.add_check(map_index, sub, preop_only, CheckStage::State);
    od.add_check(
        map_index, sub,
        [this, pdo_valid, &od, map_index, s = sub](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
          if (!external(origin)) return SdoAbort::None;
          const auto& p = policy_;
          if (p.mapping_requires_invalid && pdo_valid()) return SdoAbort::DataDeviceState;
          if (s != 0 && p.mapping_entry_requires_sub0_zero) {
            const auto* count = od.entry(map_index, 0);
            if (count && count->as<std::uint32_t>() != 0) return SdoAbort::DataDeviceState;
          }
          return SdoAbort::None;
        },
        CheckStage::State);
    if (sub == 0) {
      od.add_check(map_index, 0, [this, &od, map_index, dir](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        if (!external(origin)) return SdoAbort::None;
        PdoMapping probe;
        return resolve_mapping(od, map_index, data[0], dir, rules(), probe);
      });
    } else {
      od.add_check(map_index, sub, [this, &od, dir](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        if (!external(origin)) return SdoAbort::None;
        const auto v = static_cast<std::uint32_t>(decode_unsigned(data));
        if (v == 0) return SdoAbort::None;  // clearing an entry is always allowed
        MappedObject m;
        return resolve_mapping_entry(od, v, dir, rules(), m);
      });
    }
    od.add_observer(map_index, sub, reload_all);
  }
}

void PdoService::load(Pdo& p, PdoDirection dir) {
  auto& od = od_;
  const auto* cob = od.entry(p.comm_index, 1);
  const std::uint32_t v = cob ? cob->as<std::uint32_t>() : kInvalid;
  p.cob_id = v & ((v & kExtended) ? 0x1FFFFFFFu : 0x7FFu);
  p.extended = (v & kExtended) != 0;
  p.rtr_allowed = !(v & kNoRtr);
  const auto* type = od.entry(p.comm_index, 2);
  p.type = type ? type->as<std::uint8_t>() : 255;
  p.valid = !(v & kInvalid) && !p.device_disabled;
  resolve(p, dir);
}

void PdoService::resolve(Pdo& p, PdoDirection dir) {
  const auto* count = od_.entry(p.map_index, 0);
  const std::uint8_t n = count ? count->as<std::uint8_t>() : 0;
  if (resolve_mapping(od_, p.map_index, n, dir, rules(), p.mapping) != SdoAbort::None) {
    p.mapping = PdoMapping{};  // an invalid stored mapping makes the PDO send/accept nothing
  }
}

void PdoService::load(Tpdo& t) {
  const bool was_valid = t.valid;
  load(t, PdoDirection::Transmit);
  const auto* start = od_.entry(t.comm_index, 6);
  t.sync_start = start ? start->as<std::uint8_t>() : 0;
  if (t.valid && !was_valid) {  // a PDO made valid again starts its SYNC counting afresh
    t.sync_count = 0;
    t.awaiting_start = true;
  }
}

void PdoService::reload() {
  for (auto& r : rpdos_) {
    bind_timers(r);
    load(r, PdoDirection::Receive);
    r.latched = false;
  }
  for (auto& t : tpdos_) {
    bind_timers(t);
    load(t);
  }
  rebuild_lists();
  layout_ = od_.layout();  // everything resolved afresh: objects a product added after bind_objects() included
}

std::vector<PdoService::Route> PdoService::rpdo_routes() const {
  std::vector<Route> routes;
  for (const auto& r : rpdos_)
    if (r.valid) routes.push_back(Route{r.cob_id, r.extended, r.number});
  return routes;
}

std::vector<PdoService::Route> PdoService::tpdo_routes() const {
  std::vector<Route> routes;
  for (const auto& t : tpdos_)
    if (t.valid && t.rtr_allowed) routes.push_back(Route{t.cob_id, t.extended, t.number});
  return routes;
}

int PdoService::tpdo_length(int number) const {
  for (const auto& t : tpdos_)
    if (t.number == number) return t.mapping.length;
  return -1;
}

int PdoService::rpdo_length(int number) const {
  for (const auto& r : rpdos_)
    if (r.number == number) return r.mapping.length;
  return -1;
}

std::uint16_t PdoService::event_timer_ms(const Pdo& p) const { return p.event_timer.get(); }

std::uint16_t PdoService::inhibit_100us(const Pdo& p) const { return p.inhibit_time.get(); }

// ---- receive ------------------------------------------------------------------------------------

void PdoService::on_rpdo(int number, const sim::CanFrame& frame, sim::Time now) {
  follow_layout();
  if (!pdo_allowed(status_.nmt_state) || frame.rtr) return;
  auto it = std::find_if(rpdos_.begin(), rpdos_.end(), [number](const Rpdo& r) { return r.number == number; });
  if (it == rpdos_.end() || !it->valid) return;
  Rpdo& r = *it;
  const auto& policy = policy_;
  if (frame.dlc < r.mapping.length) {
    if (policy.rpdo_length_emcy) emcy_.raise_emcy(kEmcyRpdoShort);
    return;
  }
  if (policy.rpdo_length_emcy) {
    if (frame.dlc > r.mapping.length && policy.rpdo_too_long_is_error) {
      emcy_.raise_emcy(kEmcyRpdoLong);
    } else {
      emcy_.clear_emcy(kEmcyRpdoShort);
      emcy_.clear_emcy(kEmcyRpdoLong);
    }
  }
  if (event_timer_ms(r) != 0) {
    r.deadline_armed = true;
    any_deadline_armed_ = true;
    r.last_rx = now;
    emcy_.clear_emcy(kEmcyRpdoTimeout);
  }
  std::copy(frame.data.begin(), frame.data.end(), r.buffer.begin());
  if (r.type <= 240) {
    r.latched = true;  // synchronous: takes effect at the next SYNC
    any_latched_ = true;
    return;
  }
  apply_rpdo(r);
}

void PdoService::apply_rpdo(Rpdo& r) {
  auto& od = od_;
  std::size_t pos = 0;
  for (const auto& m : r.mapping.objects) {
    if (m.entry) {
      const std::span<const std::uint8_t> slot(r.buffer.data() + pos, m.bytes);
      if (m.bytes == m.entry->size()) {
        (void)od.write(*m.entry, slot, Origin::Pdo);  // a refused PDO value is dropped silently
      } else if (m.entry->size() <= 8) {
        std::array<std::uint8_t, 8> widened{};  // width conversion without allocating per frame
        const std::span<std::uint8_t> out(widened.data(), m.entry->size());
        resize_value_into(m.entry->type, slot, out);
        (void)od.write(*m.entry, out, Origin::Pdo);
      } else {
        const Bytes widened = resize_value(m.entry->type, slot, m.entry->size());
        (void)od.write(*m.entry, widened, Origin::Pdo);
      }
    }
    pos += m.bytes;
  }
  r.latched = false;
  events_.rpdo_received(r.number);
  for (auto& t : tpdos_) {
    if (t.number != r.number) continue;
    const auto* trig = async_triggers(t);
    if (trig && trig->after_rpdo) {
      t.event_pending = true;
      try_send_event(t, status_.now);
    }
  }
}

// ---- transmit -----------------------------------------------------------------------------------

const PdoPolicy::AsyncTriggers* PdoService::async_triggers(const Tpdo& t) const {
  if (t.type == 254) return &policy_.type254;
  if (t.type == 255) return &policy_.type255;
  return nullptr;
}

void PdoService::sample(Tpdo& t, std::array<std::uint8_t, 8>& out) {
  events_.before_tpdo(t.number);
  for (const auto& m : t.mapping.objects) {
    // read() only checks access and runs the hooks: without hooks it does nothing.
    if (m.entry && !m.entry->read_hooks.empty()) (void)od_.read(*m.entry, Origin::Pdo);
  }
  pack_pdo(t.mapping, out);
}

std::uint8_t PdoService::wire_length(const Tpdo& t) const {
  return policy_.pad_tpdo_to_8 ? 8 : static_cast<std::uint8_t>(t.mapping.length);
}

void PdoService::transmit(Tpdo& t, const std::array<std::uint8_t, 8>& data, sim::Time now) {
  sim::CanFrame f;
  f.id = t.cob_id;
  f.extended = t.extended;
  f.dlc = wire_length(t);
  f.data = data;
  sender_.send(f);
  t.last_sent = data;
  t.sent_once = true;
  t.event_pending = false;
  t.inhibit_until = now + std::max(sim::microseconds(static_cast<std::int64_t>(inhibit_100us(t)) * 100), t.min_spacing);
  const auto et = event_timer_ms(t);
  if (et != 0) t.next_timer = now + sim::milliseconds(et);
}

void PdoService::try_send_event(Tpdo& t, sim::Time now) {
  if (!pdo_allowed(status_.nmt_state) || !t.valid || t.mapping.length == 0) return;
  if (!t.event_pending || now < t.inhibit_until) return;
  if (t.type == 255 && policy_.type255_off_without_timer && event_timer_ms(t) == 0) {
    t.event_pending = false;
    return;
  }
  std::array<std::uint8_t, 8> data{};
  sample(t, data);
  transmit(t, data, now);
}

void PdoService::set_active(PdoDirection dir, int number, bool active) {
  if (dir == PdoDirection::Receive) {
    for (auto& r : rpdos_) {
      if (r.number != number) continue;
      r.device_disabled = !active;
      load(r, dir);
      r.latched = false;
    }
  } else {
    for (auto& t : tpdos_) {
      if (t.number != number) continue;
      t.device_disabled = !active;
      load(t);
      t.event_pending = false;
    }
  }
  rebuild_lists();
  routes_.rebuild_dispatch();
}

bool PdoService::active(PdoDirection dir, int number) const {
  if (dir == PdoDirection::Receive) {
    for (const auto& r : rpdos_)
      if (r.number == number) return !r.device_disabled;
  } else {
    for (const auto& t : tpdos_)
      if (t.number == number) return !t.device_disabled;
  }
  return false;
}

void PdoService::request_tpdo(int number) {
  follow_layout();
  for (auto& t : tpdos_) {
    if (t.number != number) continue;
    t.event_pending = true;
    if (t.type >= 254) try_send_event(t, status_.now);
  }
}

void PdoService::restart_event_timer(int number) {
  follow_layout();
  for (auto& t : tpdos_) {
    if (t.number != number) continue;
    const auto et = event_timer_ms(t);
    t.next_timer = status_.now + sim::milliseconds(et);
  }
}

void PdoService::set_min_spacing(int number, sim::Duration spacing) {
  for (auto& t : tpdos_)
    if (t.number == number) t.min_spacing = spacing;
}

void PdoService::on_tpdo_rtr(int number, const sim::CanFrame& frame, sim::Time now) {
  follow_layout();
  if (!pdo_allowed(status_.nmt_state) || !frame.rtr || !policy_.tpdo_remote_requests) return;
  auto it = std::find_if(tpdos_.begin(), tpdos_.end(), [number](const Tpdo& t) { return t.number == number; });
  if (it == tpdos_.end() || !it->valid || !it->rtr_allowed || it->mapping.length == 0) return;
  Tpdo& t = *it;
  if (frame.dlc != wire_length(t)) {
    switch (policy_.rtr_dlc_mismatch) {
      case PdoPolicy::RtrDlcMismatch::Ignore: return;
      case PdoPolicy::RtrDlcMismatch::EmptyFrame: {
        sim::CanFrame empty;
        empty.id = t.cob_id;
        empty.extended = t.extended;
        sender_.send(empty);
        return;
      }
      case PdoPolicy::RtrDlcMismatch::Answer: break;
    }
  }
  std::array<std::uint8_t, 8> data{};
  if (t.type == 252 && t.has_sample) {
    data = t.sampled;
  } else {
    sample(t, data);
  }
  transmit(t, data, now);
}

void PdoService::on_sync(std::uint8_t counter, sim::Time now) {
  follow_layout();
  if (!pdo_allowed(status_.nmt_state)) return;
  if (any_latched_) {
    any_latched_ = false;  // an RPDO latched again while these are applied sets it anew
    for (auto& r : rpdos_) {
      if (!r.latched) continue;
      if (r.valid) {
        apply_rpdo(r);
      } else {
        any_latched_ = true;  // kept, as the plain loop kept it, should the PDO become valid
      }
    }
  }
  walk(sync_tpdos_, [this, counter, now](Tpdo& t) {
    if (!t.valid || t.mapping.length == 0) return;
    if (t.type == 0) {
      std::array<std::uint8_t, 8> data{};
      sample(t, data);
      if (t.event_pending || !t.sent_once || data != t.last_sent) transmit(t, data, now);
    } else if (t.type <= 240) {
      if (t.awaiting_start) {
        // CiA 301: with a SYNC counter and a start value, the SYNC carrying that value is the
        // first one counted; the PDO goes out on it and on every type-th SYNC after it.
        if (counter != 0 && t.sync_start != 0) {
          if (counter != t.sync_start) return;
          t.sync_count = static_cast<std::uint8_t>(t.type - 1);
        }
        t.awaiting_start = false;
      }
      if (++t.sync_count >= t.type) {
        t.sync_count = 0;
        std::array<std::uint8_t, 8> data{};
        sample(t, data);
        transmit(t, data, now);
      }
    } else if (t.type == 252) {
      sample(t, t.sampled);
      t.has_sample = true;
    }
  });
}

void PdoService::on_enter_operational(sim::Time now) {
  follow_layout();
  for (auto& r : rpdos_) {
    r.latched = false;
    r.deadline_armed = false;
  }
  for (auto& t : tpdos_) {
    t.sync_count = 0;
    t.awaiting_start = true;
    t.sent_once = false;
    t.has_sample = false;
    t.event_pending = false;
    t.inhibit_until = now;
    const auto et = event_timer_ms(t);
    t.next_timer = now + sim::milliseconds(et);
    if (policy_.send_async_on_operational && t.type >= 254) {
      t.event_pending = true;
      try_send_event(t, now);
    } else if (policy_.change_baseline_on_operational && t.type >= 254 && t.valid && t.mapping.length != 0) {
      sample(t, t.last_sent);
      t.sent_once = true;
    }
  }
}

void PdoService::process(sim::Time now) {
  follow_layout();
  if (!pdo_allowed(status_.nmt_state)) return;
  if (any_deadline_armed_) {
    any_deadline_armed_ = false;  // set again below for every deadline still running
    for (auto& r : rpdos_) {
      if (!r.deadline_armed) continue;
      if (!r.valid) {
        any_deadline_armed_ = true;  // still armed: checked again once the PDO is valid
        continue;
      }
      const auto et = event_timer_ms(r);
      if (et != 0 && now - r.last_rx > sim::milliseconds(et)) {
        r.deadline_armed = false;  // one EMCY per timeout; re-armed by the next reception
        emcy_.raise_emcy(kEmcyRpdoTimeout);
      } else {
        any_deadline_armed_ = true;
      }
    }
  }
  walk(async_tpdos_, [this, now](Tpdo& t) {
    const auto* trig = async_triggers(t);
    if (!trig || !t.valid || t.mapping.length == 0) return;
    if (trig->on_timer) {
      const auto et = event_timer_ms(t);
      if (et != 0 && now >= t.next_timer) {
        t.event_pending = true;
        t.next_timer = now + sim::milliseconds(et);
      }
    }
    if (trig->on_change && !t.event_pending) {
      std::array<std::uint8_t, 8> data{};
      sample(t, data);
      if (!t.sent_once || data != t.last_sent) t.event_pending = true;
    }
    // try_send_event() does nothing unless an event waits and the inhibit time has run out.
    if (t.event_pending && now >= t.inhibit_until) try_send_event(t, now);
  });
}

}  // namespace canopen
