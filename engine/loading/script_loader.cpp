#include "engine/loading/script_loader.h"

#include <cstdio>

#include "devices/canopen/nmt_command.h"
#include "engine/loading/fault_codec.h"

namespace scenario {

namespace {

std::string hex(std::uint32_t v, int digits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%0*X", digits, v);
  return buf;
}

NodeRef read_node_ref(const YAML::Node& n, const std::string& file, bool allow_all) {
  NodeRef ref;
  const auto text = read_string(n, file, "node");
  if (allow_all && text == "all") return ref;
  if (auto id = parse_integer(text)) {
    if (*id < 1 || *id > 127) throw LoadError(mark_of(n, file), "node: value " + text + " out of range [1, 127]");
    ref.node_id = static_cast<std::uint8_t>(*id);
    return ref;
  }
  ref.name = read_name(n, file, "node");
  return ref;
}

std::string describe(const NodeRef& r) {
  if (!r.name.empty()) return r.name;
  if (r.node_id == 0) return "all";
  return "node " + std::to_string(r.node_id);
}

std::uint32_t read_abort(const YAML::Node& n, const std::string& file) {
  return static_cast<std::uint32_t>(read_integer(n, file, "expect_abort", 1, 0xFFFFFFFF));
}

void read_sdo_target(MapReader& r, const std::string& file, SdoTarget& t) {
  t.node = read_node_ref(r.require("node"), file, false);
  t.index = static_cast<std::uint16_t>(read_integer(r.require("index"), file, "index", 0, 0xFFFF));
  if (auto s = r.get("sub")) t.sub = static_cast<std::uint8_t>(read_integer(s, file, "sub", 0, 255));
  if (auto ty = r.get("type")) {
    static const char* kTypes[] = {"u8", "u16", "u24", "u32", "u40", "u48", "u56", "u64", "i8", "i16", "i24", "i32",
                                   "i40", "i48", "i56", "i64", "f32", "f64", "bool", "string", "bytes"};
    t.type = read_string(ty, file, "type");
    bool ok = false;
    for (const char* k : kTypes) ok |= t.type == k;
    if (!ok) throw LoadError(mark_of(ty, file), "type: '" + t.type + "' is not one of u8..u64, i8..i64, f32, f64, bool, string, bytes");
  }
}

std::string where(const SdoTarget& t) { return describe(t.node) + " " + hex(t.index, 4) + ":" + hex(t.sub, 2).substr(2); }

StepAction read_action(const std::string& kind, const YAML::Node& v, const std::string& file, std::string& summary,
                       MapReader& step) {
  if (kind == "nmt") {
    NmtStep s;
    std::string cmd;
    if (v.IsMap()) {
      MapReader r(v, file, "nmt");
      cmd = read_string(r.require("command"), file, "command");
      if (auto n = r.get("node")) s.node = read_node_ref(n, file, true);
      r.finish();
    } else {
      cmd = read_string(v, file, "nmt");
    }
    const auto command = canopen::parse_nmt_command(cmd);
    if (!command) throw LoadError(mark_of(v, file), "nmt: '" + cmd + "' is not " + std::string(canopen::kNmtCommandWords));
    s.command = *command;
    summary = "nmt " + cmd + " " + describe(s.node);
    return s;
  }
  if (kind == "sync") {
    SyncStep s;
    if (v.IsMap()) {
      MapReader r(v, file, "sync");
      s.period = read_duration(r.require("period"), file, "period");
      if (auto c = r.get("counter")) s.counter_overflow = static_cast<std::uint8_t>(read_integer(c, file, "counter", 2, 240));
      r.finish();
    } else if (v.IsScalar() && v.Scalar() == "off") {
      s.period = sim::Duration{0};
    } else {
      s.period = read_duration(v, file, "sync");
      if (s.period.count() == 0) throw LoadError(mark_of(v, file), "sync: a period > 0, or 'off'");
    }
    summary = s.period.count() ? "sync every " + format_value(sim::seconds(s.period) * 1e3) + " ms" : "sync off";
    return s;
  }
  if (kind == "sdo_read") {
    MapReader r(v, file, "sdo_read");
    SdoReadStep s;
    read_sdo_target(r, file, s.target);
    if (auto e = r.get("expect")) s.expect = read_literal(e, file, "expect");
    if (auto t = r.get("tolerance")) s.tolerance = read_number(t, file, "tolerance", 0.0, 1e300);
    if (auto d = r.get("expect_data")) s.expect_data = read_bytes(d, file, "expect_data");
    if (auto a = r.get("expect_abort")) s.expect_abort = read_abort(a, file);
    if (auto t = r.get("timeout")) s.timeout = read_duration(t, file, "timeout");
    if (s.expect_abort && (s.expect || s.expect_data))
      throw LoadError(r.key_mark("expect_abort"), "sdo_read: expect_abort excludes expect/expect_data");
    r.finish();
    summary = "sdo_read " + where(s.target);
    if (s.expect) summary += " expect " + s.expect->text;
    if (s.expect_abort) summary += " expect abort " + hex(*s.expect_abort, 8);
    return s;
  }
  if (kind == "sdo_write") {
    MapReader r(v, file, "sdo_write");
    SdoWriteStep s;
    read_sdo_target(r, file, s.target);
    const auto which = r.one_of({"value", "data"});
    if (which == "value") s.value = read_literal(r.get("value"), file, "value");
    else s.data = read_bytes(r.get("data"), file, "data");
    if (auto a = r.get("expect_abort")) s.expect_abort = read_abort(a, file);
    if (auto t = r.get("timeout")) s.timeout = read_duration(t, file, "timeout");
    r.finish();
    summary = "sdo_write " + where(s.target) + " = " + (s.value ? s.value->text : std::string("<data>"));
    if (s.expect_abort) summary += " expect abort " + hex(*s.expect_abort, 8);
    return s;
  }
  if (kind == "send" || (kind == "rpdo" && v.IsMap() && MapReader(v, file, "rpdo").has("id"))) {
    MapReader r(v, file, kind);
    SendStep s;
    const auto id = read_integer(r.require("id"), file, "id", 0, 0x1FFFFFFF);
    // The payload first, then the flags: building the data frame must not reset an explicit
    // `extended` (an 11-bit ID sent as a 29-bit frame) or `rtr`.
    if (auto d = r.get("data")) {
      const auto bytes = read_bytes(d, file, "data");
      if (bytes.size() > 8) throw LoadError(mark_of(d, file), "data: at most 8 bytes");
      s.frame = sim::CanFrame::data_frame(static_cast<std::uint32_t>(id), bytes);
    }
    s.frame.id = static_cast<std::uint32_t>(id);
    s.frame.extended = id > 0x7FF;
    if (auto e = r.get("extended")) {
      s.frame.extended = read_bool(e, file, "extended");
      if (!s.frame.extended && id > 0x7FF)
        throw LoadError(mark_of(e, file), "extended: false with an ID above 0x7FF");
    }
    if (auto rtr = r.get("rtr")) {
      if (r.has("data"))
        throw LoadError(r.key_mark("rtr"), "rtr: a remote frame carries no data (give rtr or data)");
      s.frame.rtr = true;
      s.frame.dlc = static_cast<std::uint8_t>(read_integer(rtr, file, "rtr", 0, 8));
    }
    r.finish();
    summary = kind + " " + sim::to_candump(s.frame);
    return s;
  }
  if (kind == "rpdo") {
    MapReader r(v, file, "rpdo");
    RpdoStep s;
    s.node = read_name(r.require("node"), file, "node");
    if (auto p = r.get("pdo")) s.pdo = static_cast<int>(read_integer(p, file, "pdo", 1, 512));
    const auto values = r.require("values");
    MapReader vr(values, file, "rpdo values");
    for (const auto& kv : values) {
      vr.get(kv.first.Scalar());
      ParameterOverride o;
      o.mark = mark_of(kv.first, file);
      parse_object_address(kv.first.Scalar(), o.mark, o.index, o.sub);
      o.value = read_literal(kv.second, file, "value");
      s.values.push_back(o);
    }
    vr.finish();
    r.finish();
    summary = "rpdo " + std::to_string(s.pdo) + " of " + s.node;
    return s;
  }
  if (kind == "wait") {
    WaitStep s{read_duration(v, file, "wait")};
    summary = "wait " + format_value(sim::seconds(s.duration)) + " s";
    return s;
  }
  if (kind == "wait_frame") {
    MapReader r(v, file, "wait_frame");
    WaitFrameStep s;
    s.pattern = read_pattern(r, file, "data");
    s.timeout = read_duration(r.require("timeout"), file, "timeout");
    r.finish();
    summary = "wait_frame " + s.pattern.describe();
    return s;
  }
  if (kind == "wait_until") {
    MapReader r(v, file, "wait_until");
    WaitUntilStep s;
    s.condition = read_condition(r, file);
    s.timeout = read_duration(r.require("timeout"), file, "timeout");
    r.finish();
    summary = "wait_until " + s.condition.describe();
    return s;
  }
  if (kind == "expect") {
    MapReader r(v, file, "expect");
    ExpectStep s;
    if (r.has("slope")) {
      s.mode = ExpectStep::Mode::Slope;
      const auto sig = r.require("signal");
      s.condition.signal = parse_signal(read_string(sig, file, "signal"), mark_of(sig, file));
      s.condition.op = Condition::Op::Near;
      s.condition.a = read_number(r.require("slope"), file, "slope");
      s.condition.b = read_number(r.require("tolerance"), file, "tolerance", 0.0, 1e300);
      s.window = read_duration(r.require("over"), file, "over");
      if (s.window.count() <= 0) throw LoadError(r.key_mark("over"), "over: must be greater than zero");
      summary = "expect slope of " + s.condition.signal.text + " = " + format_value(s.condition.a) + " ± " +
                format_value(s.condition.b) + " /s";
    } else {
      s.condition = read_condition(r, file);
      if (r.has("within") && r.has("during"))
        throw LoadError(r.key_mark("during"), "expect: 'within' and 'during' cannot be combined");
      if (auto w = r.get("within")) {
        s.mode = ExpectStep::Mode::Within;
        s.window = read_duration(w, file, "within");
        summary = "expect " + s.condition.describe() + " within " + format_value(sim::seconds(s.window)) + " s";
      } else if (auto d = r.get("during")) {
        if (d.IsScalar() && d.Scalar() == "end") {
          s.mode = ExpectStep::Mode::UntilEnd;
          summary = "expect " + s.condition.describe() + " until the end";
        } else {
          s.mode = ExpectStep::Mode::During;
          s.window = read_duration(d, file, "during");
          summary = "expect " + s.condition.describe() + " during " + format_value(sim::seconds(s.window)) + " s";
        }
      } else {
        summary = "expect " + s.condition.describe();
      }
    }
    r.finish();
    return s;
  }
  if (kind == "expect_frames") {
    MapReader r(v, file, "expect_frames");
    ExpectFramesStep s;
    s.select = read_pattern(r, file, nullptr);
    if (auto d = r.get("data")) {
      FramePattern content = s.select;
      const auto err = parse_data_pattern(read_string(d, file, "data"), content);
      if (!err.empty()) throw LoadError(mark_of(d, file), "data: " + err);
      s.content = content;
    }
    s.window = read_duration(r.require("during"), file, "during");
    if (s.window.count() <= 0) throw LoadError(r.key_mark("during"), "during: must be greater than zero");
    if (auto c = r.get("count")) {
      if (c.IsMap()) {
        MapReader cr(c, file, "count");
        if (auto mn = cr.get("min")) s.min_count = static_cast<std::uint64_t>(read_integer(mn, file, "min", 0, INT64_MAX));
        if (auto mx = cr.get("max")) s.max_count = static_cast<std::uint64_t>(read_integer(mx, file, "max", 0, INT64_MAX));
        cr.finish();
        if (s.min_count && s.max_count && *s.max_count < *s.min_count)
          throw LoadError(mark_of(c, file), "count: max is below min");
      } else {
        s.min_count = s.max_count = static_cast<std::uint64_t>(read_integer(c, file, "count", 0, INT64_MAX));
      }
    }
    if (auto p = r.get("period")) {
      s.period = read_duration(p, file, "period");
      if (auto t = r.get("period_tolerance")) s.period_tolerance = read_duration(t, file, "period_tolerance");
    }
    r.finish();
    summary = "expect_frames " + s.select.describe() + " during " + format_value(sim::seconds(s.window)) + " s";
    return s;
  }
  if (kind == "fault") {
    FaultStep s{read_fault(v, file, FaultTiming::Now)};
    summary = "fault " + s.fault.summary;
    return s;
  }
  LogStep s{read_string(v, file, "log")};
  summary = "log";
  (void)step;
  return s;
}

}  // namespace

Condition read_condition(MapReader& r, const std::string& file) {
  Condition c;
  const auto s = r.require("signal");
  c.signal = parse_signal(read_string(s, file, "signal"), mark_of(s, file));
  const auto op = r.one_of({"above", "below", "between", "outside", "value"});
  const auto v = r.get(op);
  if (op == "above" || op == "below") {
    c.op = op == "above" ? Condition::Op::Above : Condition::Op::Below;
    c.a = read_number(v, file, op);
  } else if (op == "between" || op == "outside") {
    c.op = op == "between" ? Condition::Op::Between : Condition::Op::Outside;
    if (!v.IsSequence() || v.size() != 2) throw LoadError(mark_of(v, file), op + ": expected [low, high]");
    c.a = read_number(v[0], file, op);
    c.b = read_number(v[1], file, op);
    if (c.b < c.a) throw LoadError(mark_of(v, file), op + ": high is below low");
  } else {
    c.op = Condition::Op::Near;
    c.a = read_number(v, file, "value");
    const auto t = r.require("tolerance");
    c.b = read_number(t, file, "tolerance", 0.0, 1e300);
  }
  return c;
}

/// Reads id / mask / data (/ extended) of a frame pattern from `r`.
FramePattern read_pattern(MapReader& r, const std::string& file, const char* data_key) {
  FramePattern p;
  const auto id = r.require("id");
  const auto v = read_integer(id, file, "id", 0, 0x1FFFFFFF);
  p.id = static_cast<std::uint32_t>(v);
  p.extended = v > 0x7FF;
  if (auto e = r.get("extended")) p.extended = read_bool(e, file, "extended");
  p.mask = p.extended ? 0x1FFFFFFF : 0x7FF;
  if (auto m = r.get("mask")) p.mask = static_cast<std::uint32_t>(read_integer(m, file, "mask", 0, p.mask));
  p.id &= p.mask;
  if (data_key) {
    if (auto d = r.get(data_key)) {
      const auto err = parse_data_pattern(read_string(d, file, data_key), p);
      if (!err.empty()) throw LoadError(mark_of(d, file), std::string(data_key) + ": " + err);
    }
  }
  return p;
}

void parse_object_address(const std::string& text, const SourceMark& mark, std::uint16_t& index, std::uint8_t& sub) {
  const auto colon = text.find(':');
  const auto idx = parse_integer(text.substr(0, colon));
  if (!idx || *idx < 0 || *idx > 0xFFFF || text.rfind("0x", 0) != 0)
    throw LoadError(mark, "'" + text + "' is not an object address (0xINDEX or 0xINDEX:SUB)");
  index = static_cast<std::uint16_t>(*idx);
  sub = 0;
  if (colon != std::string::npos) {
    const auto s = parse_integer(text.substr(colon + 1));
    if (!s || *s < 0 || *s > 255) throw LoadError(mark, "'" + text + "': sub-index out of range [0, 255]");
    sub = static_cast<std::uint8_t>(*s);
  }
}

std::vector<Step> read_script(const YAML::Node& seq, const std::string& file) {
  if (!seq.IsSequence()) throw LoadError(mark_of(seq, file), "script: expected a list of steps");
  std::vector<Step> steps;
  for (const auto& item : seq) {
    MapReader r(item, file, "script step");
    Step s;
    s.mark = r.mark();
    if (auto a = r.get("at")) s.at = read_duration(a, file, "at");
    if (auto n = r.get("name")) s.name = read_string(n, file, "name");
    if (auto b = r.get("bus")) s.bus = read_name(b, file, "bus");
    const auto kind = r.one_of({"nmt", "sync", "sdo_read", "sdo_write", "send", "rpdo", "wait", "wait_frame",
                                "wait_until", "expect", "expect_frames", "fault", "log"});
    s.action = read_action(kind, r.get(kind), file, s.summary, r);
    r.finish();
    steps.push_back(std::move(s));
  }
  return steps;
}

std::vector<FaultSpec> read_faults(const YAML::Node& seq, const std::string& file) {
  if (!seq.IsSequence()) throw LoadError(mark_of(seq, file), "faults: expected a list of faults");
  std::vector<FaultSpec> faults;
  for (const auto& item : seq) faults.push_back(read_fault(item, file, FaultTiming::Scheduled));
  return faults;
}

}  // namespace scenario
