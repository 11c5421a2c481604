#include "engine/loading/fault_codec.h"

#include "engine/loading/script_loader.h"
#include "engine/loading/yaml_fields.h"

namespace scenario {

namespace {

FaultAction read_fault_action(MapReader& r, const std::string& file, std::string& summary) {
  const auto kind = r.one_of({"drop", "delay", "corrupt", "tx_errors", "bus_off", "device_fault", "power_off",
                              "power_on", "power_cycle", "reset", "plant"});
  const auto v = r.get(kind);
  if (kind == "tx_errors") {
    MapReader wr(v, file, kind);
    WireFault w;
    w.kind = WireFault::Kind::TxError;
    w.node = read_name(wr.require("node"), file, "node");
    if (auto p = wr.get("probability")) w.probability = read_number(p, file, "probability", 0.0, 1.0);
    if (auto c = wr.get("count")) w.count = static_cast<std::uint64_t>(read_integer(c, file, "count", 1, INT64_MAX));
    wr.finish();
    summary = "tx_errors " + w.node + (w.count ? " x" + std::to_string(w.count) : "");
    return w;
  }
  if (kind == "drop" || kind == "delay" || kind == "corrupt") {
    MapReader wr(v, file, kind);
    WireFault w;
    if (auto b = wr.get("bus")) w.bus = read_name(b, file, "bus");
    w.match = read_pattern(wr, file, "data");
    if (auto p = wr.get("probability")) w.probability = read_number(p, file, "probability", 0.0, 1.0);
    if (auto c = wr.get("count")) w.count = static_cast<std::uint64_t>(read_integer(c, file, "count", 1, INT64_MAX));
    summary = kind + " " + w.match.describe();
    if (kind == "drop") {
      w.kind = WireFault::Kind::Drop;
    } else if (kind == "delay") {
      w.kind = WireFault::Kind::Delay;
      w.delay = read_duration(wr.require("by"), file, "by");
      summary += " by " + format_value(sim::seconds(w.delay)) + " s";
    } else {
      w.kind = WireFault::Kind::Corrupt;
      w.byte = static_cast<int>(read_integer(wr.require("byte"), file, "byte", 0, 7));
      const auto how = wr.one_of({"xor", "value", "random"});
      if (how == "xor") w.xor_mask = static_cast<std::uint8_t>(read_integer(wr.get("xor"), file, "xor", 1, 255));
      if (how == "value") w.set_value = static_cast<std::uint8_t>(read_integer(wr.get("value"), file, "value", 0, 255));
      if (how == "random") w.random_value = read_bool(wr.get("random"), file, "random");
      summary += " byte " + std::to_string(w.byte);
    }
    wr.finish();
    return w;
  }
  if (kind == "bus_off") {
    BusOff b{read_name(v, file, "bus_off")};
    summary = "bus_off " + b.node;
    return b;
  }
  if (kind == "device_fault") {
    MapReader dr(v, file, "device_fault");
    DeviceFault d;
    d.node = read_name(dr.require("node"), file, "node");
    d.fault = read_name(dr.require("fault"), file, "fault");
    if (auto a = dr.get("active")) d.active = read_bool(a, file, "active");
    dr.finish();
    summary = "device_fault " + d.node + " " + d.fault + (d.active ? " on" : " off");
    return d;
  }
  if (kind == "plant") {
    MapReader pr(v, file, "plant fault");
    PlantParameter p;
    p.name = read_string(pr.require("parameter"), file, "parameter");
    p.value = read_number(pr.require("value"), file, "value");
    pr.finish();
    summary = "plant " + p.name + " = " + format_value(p.value);
    return p;
  }
  Power p;
  if (kind == "power_cycle" && v.IsMap()) {
    MapReader pr(v, file, "power_cycle");
    p.node = read_name(pr.require("node"), file, "node");
    if (auto o = pr.get("off")) p.off_time = read_duration(o, file, "off");
    pr.finish();
  } else {
    p.node = read_name(v, file, kind);
  }
  p.kind = kind == "power_off" ? Power::Kind::Off
           : kind == "power_on" ? Power::Kind::On
           : kind == "reset"    ? Power::Kind::Reset
                                : Power::Kind::Cycle;
  summary = kind + " " + p.node;
  return p;
}

}  // namespace

FaultSpec read_fault(const YAML::Node& node, const std::string& file, FaultTiming timing) {
  MapReader r(node, file, "fault");
  FaultSpec f;
  f.mark = r.mark();
  if (auto n = r.get("name")) f.name = read_string(n, file, "name");
  if (timing == FaultTiming::Scheduled) {
    if (auto a = r.get("at")) f.at = read_duration(a, file, "at");
    if (auto w = r.get("when")) {
      MapReader wr(w, file, "when");
      f.when = read_condition(wr, file);
      wr.finish();
    }
    if (f.at.has_value() == f.when.has_value())
      throw LoadError(f.mark, "fault: give exactly one of 'at' (a time) or 'when' (a condition)");
  }
  if (auto d = r.get("for")) {
    f.duration = read_duration(d, file, "for");
    if (f.duration->count() <= 0) throw LoadError(mark_of(d, file), "for: must be greater than zero");
  }
  f.action = read_fault_action(r, file, f.summary);
  if (f.duration) {
    if (const auto* p = std::get_if<Power>(&f.action); p && p->kind != Power::Kind::Off)
      throw LoadError(r.key_mark("for"), "for: only power_off can be timed (power_cycle has 'off')");
  }
  r.finish();
  if (f.name.empty()) f.name = f.summary;
  return f;
}

FaultSpec parse_fault(std::string_view text, const std::string& name) {
  YAML::Node node;
  try {
    node = YAML::Load(std::string(text));
  } catch (const YAML::ParserException& e) {
    throw LoadError(SourceMark{name, e.mark.line + 1, e.mark.column + 1}, e.msg);
  }
  return read_fault(node, name, FaultTiming::Now);
}

}  // namespace scenario
