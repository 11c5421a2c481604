#include "engine/running/scripted_master.h"

#include <cmath>
#include <cstdio>

#include "devices/canopen/object_dictionary.h"
#include "engine/running/rpdo_frame.h"
#include "engine/loading/value_codec.h"

namespace scenario {

/// Sends for the master on one bus and forwards everything the bus carries to it.
struct ScriptedMaster::Endpoint final : sim::FrameReceiver, sim::FrameTap {
  ScriptedMaster* master = nullptr;
  int bus = 0;
  int id = -1;
  void on_frame(const sim::CanFrame&, sim::Time) override {}  // observed through the tap
  void on_bus_frame(std::string_view, const sim::CanFrame& f, sim::Time now) override { master->on_frame(bus, f, now); }
};

ScriptedMaster::ScriptedMaster(World& world, FaultInjector& faults, Verdicts& verdicts, Log log)
    : world_(world),
      faults_(faults),
      verdicts_(verdicts),
      log_(std::move(log)),
      monitor_(verdicts),
      sdo_([this](const sim::CanFrame& f) { send(sdo_bus_, f, now_); }) {
  for (std::size_t i = 0; i < world_.buses().size(); ++i) {
    auto ep = std::make_unique<Endpoint>();
    ep->master = this;
    ep->bus = static_cast<int>(i);
    ep->id = world_.buses()[i]->attach(ep.get());
    world_.buses()[i]->add_tap(ep.get());
    endpoints_.push_back(std::move(ep));
  }
  sync_.resize(world_.buses().size());
  steps_.reserve(world_.scenario().script.size());
  for (const auto& s : world_.scenario().script) {
    Bound b;
    b.step = &s;
    b.name = s.name.empty() ? s.summary : s.name;
    bind(b);
    steps_.push_back(std::move(b));
  }
}

ScriptedMaster::~ScriptedMaster() = default;

void ScriptedMaster::bind(Bound& b) {
  const Step& s = *b.step;
  b.bus = world_.bus_index(s.bus);
  if (b.bus < 0) throw LoadError(s.mark, "unknown bus '" + s.bus + "'");
  const auto bind_node = [&](const NodeRef& ref) {
    if (!ref.name.empty()) {
      b.node = world_.find_node(ref.name);
      if (!b.node) throw LoadError(s.mark, "no node '" + ref.name + "' in the scenario");
      if (!s.bus.empty() && b.node->bus != b.bus) throw LoadError(s.mark, "node '" + ref.name + "' is not on bus '" + s.bus + "'");
      b.bus = b.node->bus;
      b.node_id = b.node->node_id;
    } else {
      b.node_id = ref.node_id;
      b.node = ref.node_id ? world_.find_node(b.bus, ref.node_id) : nullptr;
    }
  };
  const auto bind_type = [&](const SdoTarget& t) {
    if (!t.type.empty()) {
      if (auto ty = type_from_name(t.type)) {
        b.typed = true;
        b.type = *ty;
      }
      return;
    }
    if (b.node) {
      if (const auto* e = b.node->device->node().od().entry(t.index, t.sub)) {
        b.typed = true;
        b.type = e->type;
      }
    }
  };
  std::visit(
      [&](const auto& a) {
        using T = std::decay_t<decltype(a)>;
        if constexpr (std::is_same_v<T, NmtStep>) {
          bind_node(a.node);
        } else if constexpr (std::is_same_v<T, SdoReadStep>) {
          bind_node(a.target.node);
          bind_type(a.target);
          if (a.expect && a.expect->kind != Literal::Kind::Text && b.typed && canopen::is_variable_length(b.type))
            throw LoadError(a.expect->mark, "expect: " + object_address(a.target.index, a.target.sub) + " is a string; quote the text");
        } else if constexpr (std::is_same_v<T, SdoWriteStep>) {
          bind_node(a.target.node);
          bind_type(a.target);
          if (a.data) {
            b.bytes = *a.data;
          } else if (!b.typed) {
            throw LoadError(s.mark, "sdo_write " + object_address(a.target.index, a.target.sub) +
                                        ": the type is unknown (not an object of an in-process node); give 'type:' or 'data:'");
          } else if (auto err = encode_literal(b.type, *a.value, b.bytes); !err.empty()) {
            throw LoadError(a.value->mark, object_address(a.target.index, a.target.sub) + ": " + err);
          }
        } else if constexpr (std::is_same_v<T, RpdoStep>) {
          bind_node(NodeRef{a.node, 0});
        } else if constexpr (std::is_same_v<T, WaitUntilStep>) {
          b.signals.push_back(world_.resolve(a.condition.signal));
        } else if constexpr (std::is_same_v<T, ExpectStep>) {
          b.signals.push_back(world_.resolve(a.condition.signal));
        } else if constexpr (std::is_same_v<T, FaultStep>) {
          faults_.check(a.fault);
        }
      },
      s.action);
}

void ScriptedMaster::send(int bus, const sim::CanFrame& f, sim::Time now) {
  ++frames_sent_;
  world_.buses()[static_cast<std::size_t>(bus)]->send(endpoints_[static_cast<std::size_t>(bus)]->id, f, now);
}

void ScriptedMaster::on_frame(int bus, const sim::CanFrame& f, sim::Time now) {
  world_.frame_fields().on_frame(bus, f);
  monitor_.on_frame(bus, f, now);
  if (pc_ >= steps_.size() || !started_) return;
  Bound& b = steps_[pc_];
  if (b.bus != bus) return;
  if (const auto* w = std::get_if<WaitFrameStep>(&b.step->action)) {
    if (!frame_matched_ && w->pattern.matches(f)) frame_matched_ = true;
  } else if (sdo_.busy()) {
    sdo_.on_frame(f, now);
  }
}

void ScriptedMaster::step(sim::Time now, sim::Duration) {
  now_ = now;
  monitor_.step(now);
  sdo_.poll(now);
  while (pc_ < steps_.size()) {
    Bound& b = steps_[pc_];
    if (!started_) {
      if (b.step->at && now.time_since_epoch() < *b.step->at) break;
      started_ = true;
      started_at_ = now;
      frame_matched_ = false;
      if (!start(b, now)) break;
    } else if (!poll(b, now)) {
      break;
    }
    started_ = false;
    ++pc_;
  }
  // SYNC after the script, so a `sync` step's first SYNC goes out in the same tick and a
  // `sync: off` stops the very next one.
  for (std::size_t i = 0; i < sync_.size(); ++i)
    if (const auto f = sync_[i].due(now)) send(static_cast<int>(i), *f, now);
}

bool ScriptedMaster::start(Bound& b, sim::Time now) {
  const Step& s = *b.step;
  return std::visit(
      [&](const auto& a) -> bool {
        using T = std::decay_t<decltype(a)>;
        if constexpr (std::is_same_v<T, NmtStep>) {
          send(b.bus, sim::CanFrame::data_frame(0x000, {static_cast<std::uint8_t>(a.command), b.node_id}), now);
          return true;
        } else if constexpr (std::is_same_v<T, SyncStep>) {
          sync_[static_cast<std::size_t>(b.bus)].start(a.period, a.counter_overflow, now);
          return true;
        } else if constexpr (std::is_same_v<T, SdoReadStep>) {
          sdo_bus_ = b.bus;
          sdo_.start_upload(b.node_id, a.target.index, a.target.sub, now, a.timeout);
          return false;
        } else if constexpr (std::is_same_v<T, SdoWriteStep>) {
          sdo_bus_ = b.bus;
          sdo_.start_download(b.node_id, a.target.index, a.target.sub, b.bytes, now, a.timeout);
          return false;
        } else if constexpr (std::is_same_v<T, SendStep>) {
          send(b.bus, a.frame, now);
          return true;
        } else if constexpr (std::is_same_v<T, RpdoStep>) {
          return send_rpdo(b, a, now);
        } else if constexpr (std::is_same_v<T, WaitStep>) {
          return a.duration.count() == 0;
        } else if constexpr (std::is_same_v<T, WaitFrameStep> || std::is_same_v<T, WaitUntilStep>) {
          return poll(b, now);
        } else if constexpr (std::is_same_v<T, ExpectStep>) {
          monitor_.expect(a, b.signals.front(), b.name, s.mark, now);
          return true;
        } else if constexpr (std::is_same_v<T, ExpectFramesStep>) {
          monitor_.expect_frames(a, b.bus, b.name, s.mark, now);
          return true;
        } else if constexpr (std::is_same_v<T, FaultStep>) {
          faults_.apply(a.fault, now);
          return true;
        } else {
          if (log_) log_(now, a.message);
          return true;
        }
      },
      s.action);
}

bool ScriptedMaster::poll(Bound& b, sim::Time now) {
  const Step& s = *b.step;
  if (const auto* w = std::get_if<WaitStep>(&s.action)) return now >= started_at_ + w->duration;
  if (const auto* w = std::get_if<WaitFrameStep>(&s.action)) {
    if (frame_matched_) {
      verdicts_.pass(b.name, s.mark, now);
      return true;
    }
    if (now >= started_at_ + w->timeout) {
      verdicts_.fail(b.name, s.mark, now, "a frame " + w->pattern.describe() + " within " + format_value(sim::seconds(w->timeout)) + " s",
                     "none");
      return true;
    }
    return false;
  }
  if (const auto* w = std::get_if<WaitUntilStep>(&s.action)) {
    const double v = b.signals.front().value();
    if (w->condition.holds(v)) {
      verdicts_.pass(b.name, s.mark, now);
      return true;
    }
    if (now >= started_at_ + w->timeout) {
      verdicts_.fail(b.name, s.mark, now, w->condition.describe() + " within " + format_value(sim::seconds(w->timeout)) + " s",
                     format_value(v));
      return true;
    }
    return false;
  }
  if (std::holds_alternative<SdoReadStep>(s.action) || std::holds_alternative<SdoWriteStep>(s.action)) {
    if (sdo_.busy()) return false;
    finish_sdo(b, now);
    sdo_.reset();
    return true;
  }
  return true;
}

void ScriptedMaster::finish_sdo(Bound& b, sim::Time now) {
  const Step& s = *b.step;
  const auto* rd = std::get_if<SdoReadStep>(&s.action);
  const auto* wr = std::get_if<SdoWriteStep>(&s.action);
  const auto& target = rd ? rd->target : wr->target;
  const auto expect_abort = rd ? rd->expect_abort : wr->expect_abort;
  const std::string where = object_address(target.index, target.sub);
  if (sdo_.state() == SdoClient::State::Failed) {
    // The client's own abort (e.g. 0x05040000 on a timeout) satisfies an expected abort too.
    if (expect_abort && *expect_abort == sdo_.abort_code()) {
      verdicts_.pass(b.name, s.mark, now);
      return;
    }
    verdicts_.fail(b.name, s.mark, now, expect_abort ? "abort " + hex32(*expect_abort) : "a response", sdo_.error());
    return;
  }
  if (sdo_.state() == SdoClient::State::Aborted) {
    if (expect_abort && *expect_abort == sdo_.abort_code()) verdicts_.pass(b.name, s.mark, now);
    else verdicts_.fail(b.name, s.mark, now, expect_abort ? "abort " + hex32(*expect_abort) : "success", "abort " + hex32(sdo_.abort_code()));
    return;
  }
  if (expect_abort) {
    verdicts_.fail(b.name, s.mark, now, "abort " + hex32(*expect_abort), "success" + (rd ? ": " + hex_bytes(sdo_.data()) : std::string()));
    return;
  }
  if (wr) {
    verdicts_.pass(b.name, s.mark, now);
    return;
  }
  const auto& data = sdo_.data();
  const auto shown = b.typed ? describe_bytes(b.type, data) : hex_bytes(data);
  if (rd->expect_data && *rd->expect_data != data) {
    verdicts_.fail(b.name, s.mark, now, where + " = " + hex_bytes(*rd->expect_data), hex_bytes(data));
    return;
  }
  if (rd->expect) {
    const auto& e = *rd->expect;
    bool ok;
    std::string expected = where + " = " + e.text;
    if (e.kind == Literal::Kind::Text) {
      ok = std::string(data.begin(), data.end()) == e.text;
    } else {
      double v;
      if (b.typed && !canopen::is_variable_length(b.type) && data.size() == canopen::type_size(b.type)) {
        v = decode_number(b.type, data);
      } else if (!b.typed && data.size() <= 8) {
        v = static_cast<double>(canopen::decode_unsigned(data));
      } else {
        v = std::nan("");
      }
      if (e.kind == Literal::Kind::Integer && rd->tolerance == 0 && b.typed && !canopen::is_real(b.type)) {
        // Exact comparison of the bit pattern (hex literals of negative values work too).
        std::vector<std::uint8_t> want;
        ok = encode_literal(b.type, e, want).empty() && want == data;
      } else {
        ok = std::fabs(v - e.as_double()) <= rd->tolerance;
      }
      if (rd->tolerance > 0) expected += " ± " + format_value(rd->tolerance);
    }
    if (!ok) {
      verdicts_.fail(b.name, s.mark, now, expected, shown);
      return;
    }
  }
  verdicts_.pass(b.name, s.mark, now);
}

bool ScriptedMaster::send_rpdo(Bound& b, const RpdoStep& s, sim::Time now) {
  // The master knows the node's configuration (as from its EDS/DCF): the RPDO's COB-ID and
  // mapping are read from the node as they are now.
  const auto r = build_rpdo(b.node->device->node().od(), s.node, s.pdo, s.values);
  if (!r.frame) {
    verdicts_.fail(b.name, r.value ? s.values[*r.value].mark : b.step->mark, now, r.expected, r.actual);
    return true;
  }
  send(b.bus, *r.frame, now);
  return true;
}

void ScriptedMaster::finish(sim::Time end) {
  if (pc_ < steps_.size()) {
    const Bound& b = steps_[pc_];
    const auto left = steps_.size() - pc_ - 1;
    verdicts_.fail(b.name, b.step->mark, end, started_ ? "the step to complete" : "the step to start",
                   "the run ended" + (left ? " (" + std::to_string(left) + " later steps not run)" : std::string()));
    pc_ = steps_.size();
  }
  monitor_.finish(end);
}

}  // namespace scenario
