#include "engine/running/master_monitor.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "devices/canopen/error_control.h"
#include "devices/canopen/heartbeat_consumer.h"
#include "devices/canopen/node.h"
#include "devices/canopen/pdo_service.h"
#include "devices/canopen/sdo_abort.h"
#include "devices/device.h"
#include "engine/running/fault_injector.h"
#include "engine/running/world.h"

namespace scenario {

namespace {

std::uint32_t le32(const sim::CanFrame& f, int at) {
  return static_cast<std::uint32_t>(f.data[at]) | static_cast<std::uint32_t>(f.data[at + 1]) << 8 |
         static_cast<std::uint32_t>(f.data[at + 2]) << 16 | static_cast<std::uint32_t>(f.data[at + 3]) << 24;
}
std::uint16_t sdo_index(const sim::CanFrame& f) { return static_cast<std::uint16_t>(f.data[1] | f.data[2] << 8); }

const char* nmt_word(std::uint8_t cs) {
  switch (cs) {
    case 0x01: return "start";
    case 0x02: return "stop";
    case 0x80: return "pre_operational";
    case 0x81: return "reset_node";
    case 0x82: return "reset_communication";
    default: return "unknown command";
  }
}
bool nmt_reset(std::uint8_t cs) { return cs == 0x81 || cs == 0x82; }

/// What a master frame asks, in words ("NMT stop to node 3", "SDO download 6040h:00").
void describe_request(const sim::CanFrame& f, char* out, std::size_t size) {
  if (!f.extended && f.id == 0 && f.dlc >= 2) {
    if (f.data[1] == 0) std::snprintf(out, size, "NMT %s to all nodes", nmt_word(f.data[0]));
    else std::snprintf(out, size, "NMT %s to node %u", nmt_word(f.data[0]), f.data[1]);
  } else if (!f.extended && f.id > 0x600 && f.id < 0x680 && !f.rtr) {
    const int ccs = f.data[0] >> 5;
    if (ccs == 1) std::snprintf(out, size, "SDO download of %04Xh:%02X", sdo_index(f), f.data[3]);
    else if (ccs == 2) std::snprintf(out, size, "SDO upload of %04Xh:%02X", sdo_index(f), f.data[3]);
    else std::snprintf(out, size, "SDO request (byte 0 = %02Xh)", f.data[0]);
  } else if (!f.extended && f.id > 0x700 && f.id < 0x780 && f.rtr) {
    std::snprintf(out, size, "node guarding request");
  } else {
    std::snprintf(out, size, "%s %0*Xh (%u bytes)", f.rtr ? "remote request" : "PDO", f.extended ? 8 : 3, f.id, f.dlc);
  }
}

}  // namespace

class MasterMonitor::Tap final : public sim::FrameTap {
 public:
  Tap(MasterMonitor& monitor, int bus) : monitor_(monitor), bus_(bus) {}
  void on_bus_frame(std::string_view, const sim::CanFrame& f, sim::Time now) override { monitor_.on_frame(bus_, f, now); }

 private:
  MasterMonitor& monitor_;
  int bus_;
};

MasterMonitor::MasterMonitor(World& world, const MasterRuleSettings& rules, sim::Duration tick, const FaultInjector* faults,
                             std::size_t capacity)
    : world_(world), rules_(rules), tick_(tick), faults_(faults), log_(capacity) {
  auto& buses = world.buses();
  buses_.resize(buses.size());
  for (std::size_t i = 0; i < buses.size(); ++i) {
    BusWatch& b = buses_[i];
    b.bus = buses[i].get();
    bus_names_.push_back(b.bus->name());
    b.node_endpoint.assign(b.bus->endpoint_count(), 0);
    b.watch_of_endpoint.assign(b.bus->endpoint_count(), -1);
    b.watch_of_id.fill(-1);
  }
  for (auto& n : world.nodes()) {
    NodeWatch w;
    w.device = n.device.get();
    w.node = &n.device->node();
    w.bus = n.bus;
    w.id = w.node->node_id();
    w.channels = std::min(n.device->profile_channel_count(), static_cast<int>(w.state.size()) - 1);
    const int index = static_cast<int>(nodes_.size());
    BusWatch& b = buses_[static_cast<std::size_t>(n.bus)];
    const int ep = w.node->endpoint();
    if (ep >= 0 && static_cast<std::size_t>(ep) < b.node_endpoint.size()) {
      b.node_endpoint[static_cast<std::size_t>(ep)] = 1;
      b.watch_of_endpoint[static_cast<std::size_t>(ep)] = index;
    }
    if (w.id >= 1 && w.id <= 127) b.watch_of_id[w.id] = index;
    if (const auto* period = w.node->od().entry(0x1006, 0); period && period->size() == 4) b.cycle_periods.emplace_back(w.id, period);
    nodes_.push_back(w);
  }
  for (std::size_t i = 0; i < buses.size(); ++i) {
    taps_.push_back(std::make_unique<Tap>(*this, static_cast<int>(i)));
    buses[i]->add_tap(taps_.back().get());
  }
}

MasterMonitor::~MasterMonitor() = default;

Finding* MasterMonitor::report(MasterRule rule, sim::Time t, int bus, int node, std::initializer_list<const Evidence*> evidence,
                               const char* format, ...) {
  const Severity severity = rules_.of(rule);
  if (severity == Severity::Off) return nullptr;
  log_.count(rule);
  Finding* f = log_.claim();
  if (!f) return nullptr;
  f->rule = rule;
  f->severity = severity;
  f->t = t;
  f->bus = bus;
  f->node = node;
  va_list args;
  va_start(args, format);
  std::vsnprintf(f->text.data(), f->text.size(), format, args);
  va_end(args);
  f->evidence_count = 0;
  for (const Evidence* e : evidence)
    if (e && f->evidence_count < Finding::kMaxEvidence) f->evidence[f->evidence_count++] = *e;
  log_.publish();
  return f;
}

MasterMonitor::NodeWatch* MasterMonitor::watch_at(BusWatch& b, std::uint8_t id) {
  if (id < 1 || id > 127) return nullptr;
  const int w = b.watch_of_id[id];
  return w < 0 ? nullptr : &nodes_[static_cast<std::size_t>(w)];
}

// ---- frames -------------------------------------------------------------------------------------

void MasterMonitor::on_frame(int bus, const sim::CanFrame& f, sim::Time now) {
  BusWatch& b = buses_[static_cast<std::size_t>(bus)];
  const int sender = b.bus->tap_sender();
  if (sender < 0 || static_cast<std::size_t>(sender) >= b.node_endpoint.size() || !b.node_endpoint[static_cast<std::size_t>(sender)]) {
    on_master_frame(b, bus, f, now);
  } else if (f.id > 0x580 && f.id < 0x780 && !f.extended) {  // of a node's frames only SDO answers and boot-ups matter
    on_node_frame(b, bus, b.watch_of_endpoint[static_cast<std::size_t>(sender)], f, now);
  }
}

void MasterMonitor::on_master_frame(BusWatch& b, int bus, const sim::CanFrame& f, sim::Time now) {
  const Evidence e{now, f, true};
  if (f.extended) {
    master_rpdo(bus, e);
  } else if (f.id == 0) {
    master_nmt(b, bus, e);
  } else if (f.id == 0x80) {
    master_sync(b, bus, e);
  } else if (f.id > 0x600 && f.id < 0x680) {
    master_sdo(b, bus, static_cast<std::uint8_t>(f.id - 0x600), e);
  } else if (f.id > 0x700 && f.id < 0x780) {
    NodeWatch* w = watch_at(b, static_cast<std::uint8_t>(f.id - 0x700));
    if (w && f.rtr) early(*w, bus, e, "a node guarding request");
  } else {
    master_rpdo(bus, e);
  }
}

void MasterMonitor::on_node_frame(BusWatch& b, int bus, int watch, const sim::CanFrame& f, sim::Time now) {
  if (watch < 0 || f.extended || f.rtr) return;
  NodeWatch& w = nodes_[static_cast<std::size_t>(watch)];
  if (f.id > 0x700 && f.id < 0x780 && f.dlc >= 1 && f.data[0] == 0) {
    // Boot-up: the node is reachable again, under the node-ID its boot-up carries.
    const auto id = static_cast<std::uint8_t>(f.id - 0x700);
    if (id != w.id) {
      if (w.id >= 1 && w.id <= 127 && b.watch_of_id[w.id] == watch) b.watch_of_id[w.id] = -1;
      w.id = id;
      b.watch_of_id[id] = watch;
    }
    w.booted = true;
    w.early_reported = false;
  } else if (f.id > 0x580 && f.id < 0x600 && f.id - 0x580 == w.id) {
    server_sdo(b, bus, w.id, Evidence{now, f, false});
  }
}

void MasterMonitor::early(NodeWatch& w, int bus, const Evidence& e, const char* what) {
  if (w.booted || w.early_reported) return;
  w.early_reported = true;
  char since[96];
  if (w.reset.valid)
    std::snprintf(since, sizeof since, "the master reset it at %.3f s", sim::seconds(w.reset.frame.t));
  else
    std::snprintf(since, sizeof since, "it has not booted since power-on");
  report(MasterRule::BeforeBootUp, e.t, bus, w.id, {w.reset.valid ? &w.reset.frame : nullptr, &e},
         "%s to node %u (%s) before its boot-up message: %s; a node accepts requests only after its boot-up (CiA 301)", what,
         w.id, w.node->name().c_str(), since);
}

void MasterMonitor::master_nmt(BusWatch& b, int bus, const Evidence& e) {
  const sim::CanFrame& f = e.frame;
  if (f.dlc < 2 || f.rtr) return;
  const std::uint8_t cs = f.data[0], target = f.data[1];
  const auto apply = [&](NodeWatch& w) {
    w.command = Action{true, e};
    if (nmt_reset(cs)) {
      w.booted = false;
      w.early_reported = false;
      w.reset = Action{true, e};
    }
  };
  if (target == 0) {
    for (auto& w : nodes_)
      if (w.bus == bus) apply(w);
    return;
  }
  NodeWatch* w = watch_at(b, target);
  if (!w) {
    report(MasterRule::NmtUnknownNode, e.t, bus, target, {&e}, "NMT %s to node %u: there is no node %u on bus %s", nmt_word(cs),
           target, target, b.bus->name().c_str());
    return;
  }
  if (!nmt_reset(cs) && !w->booted) {
    char what[48];
    std::snprintf(what, sizeof what, "NMT %s", nmt_word(cs));
    early(*w, bus, e, what);
  }
  apply(*w);
}

void MasterMonitor::master_sdo(BusWatch& b, int bus, std::uint8_t id, const Evidence& e) {
  const sim::CanFrame& f = e.frame;
  SdoWatch& s = b.sdo[id];
  NodeWatch* w = watch_at(b, id);
  if (w) {
    w->command = Action{true, e};
    early(*w, bus, e, "an SDO request");
  }
  if (f.rtr) return;
  if (f.dlc != 8) {
    report(MasterRule::SdoProtocol, e.t, bus, id, {&e}, "SDO request to node %u with %u data bytes: CiA 301 SDO frames carry 8",
           id, f.dlc);
    return;
  }
  const int ccs = f.data[0] >> 5;
  const auto disarm = [&] {
    if (s.awaiting) --awaiting_;
    s.awaiting = false;
  };
  const auto arm = [&] {
    s.request = e;
    if (!s.awaiting) {
      s.awaiting = true;
      s.since = e.t;
      ++awaiting_;
    }
  };
  if (s.transfer == Transfer::Block) {
    // Sub-block segments carry any first byte: only an abort or the upload's end ends the block.
    if (ccs == 4 || (!s.block_download && f.data[0] == 0xA1)) {
      s.transfer = Transfer::Idle;
      disarm();
    }
    return;
  }
  const auto open_transfer = [&] {
    if (s.transfer != Transfer::Download && s.transfer != Transfer::Upload) return;
    report(MasterRule::SdoProtocol, e.t, bus, id, {&s.request, &e},
           "a new SDO transfer to node %u began while the segmented %s of %04Xh:%02X was still open (no abort)", id,
           s.transfer == Transfer::Download ? "download" : "upload", s.index, s.sub);
    s.transfer = Transfer::Idle;
  };
  switch (ccs) {
    case 4:  // abort by the client
      s.transfer = Transfer::Idle;
      disarm();
      return;
    case 1: {
      open_transfer();
      const bool expedited = f.data[0] & 0x02;
      s.index = sdo_index(f);
      s.sub = f.data[3];
      s.size_known = !expedited && (f.data[0] & 0x01);
      s.size = le32(f, 4);
      s.sent = 0;
      if (w) check_pdo_config(*w, bus, e, s.index, s.sub);
      arm();
      return;
    }
    case 2:
      open_transfer();
      s.index = sdo_index(f);
      s.sub = f.data[3];
      arm();
      return;
    case 0:
    case 3: {
      const bool download = ccs == 0;
      if (s.transfer != (download ? Transfer::Download : Transfer::Upload)) {
        report(MasterRule::SdoProtocol, e.t, bus, id, {&s.request, &e},
               "%s segment request to node %u without a segmented %s in progress (initiated and answered)",
               download ? "download" : "upload", id, download ? "download" : "upload");
      } else {
        const bool toggle = f.data[0] & 0x10;
        if (toggle != s.toggle)
          report(MasterRule::SdoProtocol, e.t, bus, id, {&s.request, &e},
                 "%s segment of %04Xh:%02X to node %u with toggle bit %d, expected %d (toggle not alternated)",
                 download ? "download" : "upload", s.index, s.sub, id, toggle ? 1 : 0, s.toggle ? 1 : 0);
        s.toggle = !toggle;
        if (download) {
          s.sent += 7u - ((f.data[0] >> 1) & 7u);
          if ((f.data[0] & 0x01) && s.size_known && s.sent != s.size)
            report(MasterRule::SdoProtocol, e.t, bus, id, {&s.request, &e},
                   "segmented download of %04Xh:%02X to node %u: the initiate indicated %u bytes, the segments carried %u",
                   s.index, s.sub, id, s.size, s.sent);
        }
      }
      arm();
      return;
    }
    case 5:
    case 6:
      open_transfer();
      s.index = sdo_index(f);
      s.sub = f.data[3];
      s.request = e;
      s.transfer = Transfer::Block;
      s.block_download = ccs == 6;
      disarm();
      return;
    default:
      report(MasterRule::SdoProtocol, e.t, bus, id, {&e}, "SDO request to node %u with command specifier 7 (byte 0 = %02Xh): not defined",
             id, f.data[0]);
      arm();
      return;
  }
}

void MasterMonitor::server_sdo(BusWatch& b, int bus, std::uint8_t id, const Evidence& e) {
  const sim::CanFrame& f = e.frame;
  SdoWatch& s = b.sdo[id];
  if (s.awaiting) --awaiting_;
  s.awaiting = false;
  if (f.data[0] == 0x80) {
    s.transfer = Transfer::Idle;
    const std::uint16_t index = sdo_index(f);
    const std::uint8_t sub = f.data[3];
    const std::uint32_t code = le32(f, 4);
    const NodeWatch* w = watch_at(b, id);
    const char* name = "";
    if (w) {
      if (const auto* entry = w->node->od().entry(index, sub)) name = entry->name.c_str();
      else if (const auto* object = w->node->od().object(index)) name = object->name.c_str();
    }
    const std::string_view text = canopen::describe(static_cast<canopen::SdoAbort>(code));
    char request[64];
    describe_request(s.request.frame, request, sizeof request);
    report(MasterRule::SdoAbort, e.t, bus, id, {&s.request, &e}, "node %u aborted the master's %s: %04Xh:%02X%s%s%s, abort code %08Xh (%.*s)",
           id, request, index, sub, *name ? " \"" : "", name, *name ? "\"" : "", code, static_cast<int>(text.size()), text.data());
    return;
  }
  const int scs = f.data[0] >> 5;
  const sim::CanFrame& q = s.request.frame;
  switch (s.transfer) {
    case Transfer::Block:
      if (s.block_download && f.data[0] == 0xA1) s.transfer = Transfer::Idle;  // end of block download confirmed
      return;
    case Transfer::Idle:
      if (scs == 3 && (q.data[0] >> 5) == 1 && !(q.data[0] & 0x02)) {
        s.transfer = Transfer::Download;
        s.toggle = false;
        s.sent = 0;
      } else if (scs == 2 && (q.data[0] >> 5) == 2 && !(f.data[0] & 0x02)) {
        s.transfer = Transfer::Upload;
        s.toggle = false;
      }
      return;
    case Transfer::Download:
      if (scs == 1 && (q.data[0] >> 5) == 0 && (q.data[0] & 0x01)) s.transfer = Transfer::Idle;
      return;
    case Transfer::Upload:
      if (scs == 0 && (f.data[0] & 0x01)) s.transfer = Transfer::Idle;
      return;
  }
}

void MasterMonitor::check_pdo_config(NodeWatch& w, int bus, const Evidence& e, std::uint16_t index, std::uint8_t sub) {
  const bool receive = index >= 0x1400 && index < 0x1800;
  const bool transmit = index >= 0x1800 && index < 0x1C00;
  if (!receive && !transmit) return;
  const std::uint16_t base = receive ? 0x1400 : 0x1800;
  const bool mapping = index - base >= 0x200;
  const int number = (index - base) % 0x200 + 1;
  const auto comm = static_cast<std::uint16_t>(base + number - 1);
  if (!mapping && sub != 1) return;
  const auto* target = w.node->od().entry(index, sub);
  if (!target || !target->writable()) return;  // the node refuses it anyway: its abort is the finding
  const auto* cob = w.node->od().entry(comm, 1);
  if (!cob || cob->size() < 4) return;
  const auto current = cob->as<std::uint32_t>();
  if (current & 0x80000000u) return;  // not valid: configuring is what CiA 301 asks for
  const char* kind = receive ? "RPDO" : "TPDO";
  const sim::CanFrame& f = e.frame;
  if (mapping) {
    report(MasterRule::PdoConfigWhileValid, e.t, bus, w.id, {&e},
           "writing %04Xh:%02X, the mapping of %s%d of node %u, while the PDO is valid (%04Xh:01 = %08Xh): set bit 31 of the "
           "COB-ID first, then 00h in sub-index 0 (CiA 301)",
           index, sub, kind, number, w.id, comm, current);
    return;
  }
  if (!(f.data[0] & 0x02)) return;  // segmented: the value is not in this frame
  const std::uint32_t value = le32(f, 4);
  if ((value & 0x80000000u) || value == current) return;
  report(MasterRule::PdoConfigWhileValid, e.t, bus, w.id, {&e},
         "changing the COB-ID of %s%d of node %u (%04Xh:01 %08Xh -> %08Xh) while the PDO is valid: set bit 31 first (CiA 301)",
         kind, number, w.id, comm, current, value);
}

void MasterMonitor::master_rpdo(int bus, const Evidence& e) {
  const sim::CanFrame& f = e.frame;
  if (f.rtr) return;
  for (auto& w : nodes_) {
    if (w.bus != bus) continue;
    const int number = w.node->rpdo_for(f.id, f.extended);
    if (number == 0) continue;
    w.rpdo = Action{true, e};
    if (!w.booted) {
      char what[32];
      std::snprintf(what, sizeof what, "RPDO%d", number);
      early(w, bus, e, what);
    }
    const int length = w.node->pdo().rpdo_length(number);
    if (length < 0 || f.dlc == length) continue;
    if (w.rpdo_finding_seen && e.t - w.last_rpdo_finding < sim::milliseconds(1000)) continue;  // one a second
    w.rpdo_finding_seen = true;
    w.last_rpdo_finding = e.t;
    report(MasterRule::RpdoLength, e.t, bus, w.id, {&e}, "RPDO%d of node %u (COB-ID %03Xh) carried %u byte(s), its mapping %d: %s",
           number, w.id, f.id, f.dlc, length,
           f.dlc < length ? "the node ignores it" : "longer than mapped (a node may ignore it or raise an EMCY)");
  }
}

void MasterMonitor::master_sync(BusWatch& b, int bus, const Evidence& e) {
  const Evidence previous = b.last_sync;
  const bool had = b.sync_seen;
  b.sync_seen = true;
  b.last_sync = e;
  if (!had) return;
  std::uint32_t period = 0;
  int node = 0;
  for (const auto& [id, entry] : b.cycle_periods) {
    period = entry->as<std::uint32_t>();
    node = id;
    if (period != 0) break;
  }
  if (period == 0) return;
  const std::int64_t interval = (e.t - previous.t).count();
  const std::int64_t tolerance = std::max<std::int64_t>(period / 10, tick_.count());
  if (std::abs(interval - static_cast<std::int64_t>(period)) <= tolerance) return;
  if (b.jitter_reported && e.t - b.last_jitter_finding < sim::milliseconds(1000)) return;  // one a second
  b.jitter_reported = true;
  b.last_jitter_finding = e.t;
  report(MasterRule::SyncJitter, e.t, bus, 0, {&previous, &e},
         "SYNC %.3f ms after the previous one; node %u's communication cycle period (1006h) is %.3f ms (tolerance %.3f ms)",
         static_cast<double>(interval) / 1000.0, node, period / 1000.0, static_cast<double>(tolerance) / 1000.0);
}

// ---- polling ------------------------------------------------------------------------------------

void MasterMonitor::step(sim::Time now, sim::Duration) {
  if (awaiting_) poll_sdo_timeouts(now);
  if (now < next_poll_) return;
  next_poll_ = now + kPollPeriod;
  poll_devices(now);
}

void MasterMonitor::poll_sdo_timeouts(sim::Time now) {
  for (std::size_t bi = 0; bi < buses_.size(); ++bi) {
    BusWatch& b = buses_[bi];
    for (int id = 1; id <= 127; ++id) {
      SdoWatch& s = b.sdo[static_cast<std::size_t>(id)];
      if (!s.awaiting || now - s.since < kSdoTimeout) continue;
      s.awaiting = false;
      --awaiting_;
      s.transfer = Transfer::Idle;
      char request[64];
      describe_request(s.request.frame, request, sizeof request);
      const auto ms = static_cast<long long>(kSdoTimeout.count() / 1000);
      const int bus = static_cast<int>(bi);
      if (watch_at(b, static_cast<std::uint8_t>(id)))
        report(MasterRule::SdoNoAnswer, now, bus, id, {&s.request}, "node %d did not answer the master's %s within %lld ms", id,
               request, ms);
      else
        report(MasterRule::SdoNoAnswer, now, bus, id, {&s.request},
               "the master's %s to node %d got no answer within %lld ms: there is no node %d on bus %s", request, id, ms, id,
               b.bus->name().c_str());
    }
  }
}

void MasterMonitor::poll_devices(sim::Time now) {
  const bool poll_states = ++polls_ >= kStatePollEvery;
  if (poll_states) polls_ = 0;
  if (faults_ && faults_->applied() != faults_seen_) {
    faults_seen_ = faults_->applied();
    last_fault_ = now;
    fault_seen_ = true;
  }
  for (auto& w : nodes_) {
    if (!w.node->powered()) {
      w.booted = false;  // a power cycle: the next boot-up makes it reachable again
      continue;
    }
    BusWatch& b = buses_[static_cast<std::size_t>(w.bus)];
    auto& consumer = w.node->heartbeat_consumer();
    const bool timed_out = !consumer.idle() && consumer.any_timed_out();
    if (timed_out && !w.heartbeat_timed_out) {
      for (int p = 1; p <= 127; ++p) {
        if (!consumer.timed_out(static_cast<std::uint8_t>(p)) || b.watch_of_id[static_cast<std::size_t>(p)] >= 0) continue;
        report(MasterRule::HeartbeatMissing, now, w.bus, w.id, {},
               "node %u (%s): its heartbeat consumer (1016h) timed out waiting for node %d, the master: the master's heartbeat "
               "stopped or is slower than the consumer time",
               w.id, w.node->name().c_str(), p);
        break;
      }
    }
    w.heartbeat_timed_out = timed_out;
    const bool guarding = w.node->error_control().life_guarding_error();
    if (guarding && !w.guarding_error) {
      const auto* guard = w.node->od().entry(0x100C, 0);
      const auto* factor = w.node->od().entry(0x100D, 0);
      report(MasterRule::GuardingTimeout, now, w.bus, w.id, {},
             "node %u (%s): life guarding expired (guard time 100Ch = %u ms, life time factor 100Dh = %u): the master's node "
             "guarding requests stopped or came too late",
             w.id, w.node->name().c_str(), guard ? guard->as<std::uint32_t>() : 0u, factor ? factor->as<std::uint32_t>() : 0u);
    }
    w.guarding_error = guarding;
    if (!poll_states) continue;
    if (w.channels == 0) {
      poll_device_state(w, 0, now);
    } else {
      for (int c = 1; c <= w.channels; ++c) poll_device_state(w, c, now);
    }
  }
}

void MasterMonitor::poll_device_state(NodeWatch& w, int channel, sim::Time now) {
  const devices::ProfileStatus ps = channel == 0 ? w.device->profile_status() : w.device->channel_profile_status(channel);
  if (ps.profile != devices::ProfileStatus::Profile::Dsp408 && ps.profile != devices::ProfileStatus::Profile::Vtvpcd) return;
  ChannelState& cs = w.state[static_cast<std::size_t>(channel)];
  const bool fault = ps.state.starts_with("FAULT");
  const bool entered = fault && !cs.fault;
  // The state before: the one seen at the last look, unless the profile names the last change.
  const std::string_view before = ps.transition_from.empty() || ps.transition_from.starts_with("FAULT") ? cs.state : ps.transition_from;
  cs.fault = fault;
  cs.state = ps.state;
  if (!entered) return;
  if (fault_seen_ && now - last_fault_ <= kActionWindow) return;  // the scenario injected a fault
  const Action* action = nullptr;
  if (w.command.valid && now - w.command.frame.t <= kActionWindow) action = &w.command;
  else if (w.rpdo.valid && now - w.rpdo.frame.t <= kActionWindow) action = &w.rpdo;
  char what[96];
  if (action) {
    char request[64];
    describe_request(action->frame.frame, request, sizeof request);
    std::snprintf(what, sizeof what, "the master's %s at %.3f s", request, sim::seconds(action->frame.t));
  } else if (w.heartbeat_timed_out || w.guarding_error) {
    std::snprintf(what, sizeof what, "the master's %s stopped", w.heartbeat_timed_out ? "heartbeat" : "node guarding");
  } else {
    return;  // nothing the master did
  }
  char where[24] = "";
  if (channel > 0) std::snprintf(where, sizeof where, " channel %d", channel);
  const int from_len = static_cast<int>(before.size());
  report(MasterRule::DeviceFault, now, w.bus, w.id, {action ? &action->frame : nullptr},
         "node %u (%s)%s entered %.*s%s%.*s after %s", w.id, w.node->name().c_str(), where, static_cast<int>(ps.state.size()),
         ps.state.data(), from_len ? " from " : "", from_len, before.data(), what);
}

}  // namespace scenario
