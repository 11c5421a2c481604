#include "engine/running/master_findings.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>


namespace scenario {

namespace {

void append_json_string(std::string& out, std::string_view s) {
  out += '"';
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  out += '"';
}

std::string_view bus_name(const std::vector<std::string>& names, int bus) {
  return bus >= 0 && static_cast<std::size_t>(bus) < names.size() ? std::string_view(names[static_cast<std::size_t>(bus)]) : "?";
}

}  // namespace

std::string findings_json(const FindingLog& log, const MasterRuleSettings& rules, const std::vector<std::string>& bus_names,
                          std::size_t first, std::size_t limit) {
  std::string out = "{\"findings\": [";
  const std::size_t size = log.size();
  const std::size_t begin = std::min(first, size);
  const std::size_t n = std::min(size - begin, limit);
  for (std::size_t i = begin; i < begin + n; ++i) {
    const Finding& f = log[i];
    out += i > begin ? ",\n  {" : "\n  {";
    out += "\"rule\": ";
    append_json_string(out, rule_name(f.rule));
    out += ", \"severity\": ";
    append_json_string(out, severity_name(f.severity));
    out += ", \"t_us\": " + std::to_string(f.t.time_since_epoch().count());
    out += ", \"bus\": ";
    append_json_string(out, bus_name(bus_names, f.bus));
    out += ", \"node\": " + std::to_string(f.node) + ", \"text\": ";
    append_json_string(out, f.text.data());
    out += ", \"frames\": [";
    for (std::size_t k = 0; k < f.evidence_count; ++k) {
      const Evidence& e = f.evidence[k];
      out += k ? ", {" : "{";
      out += "\"t_us\": " + std::to_string(e.t.time_since_epoch().count());
      out += ", \"from\": ";
      append_json_string(out, e.from_master ? "master" : "node");
      out += ", \"frame\": ";
      append_json_string(out, sim::to_candump(e.frame));
      out += '}';
    }
    out += "]}";
  }
  out += n ? "\n], \"next\": " : "], \"next\": ";
  out += std::to_string(begin + n) + ", \"total\": " + std::to_string(size) + ", \"dropped\": ";
  out += std::to_string(log.dropped()) + ", \"rules\": {";
  for (std::size_t r = 0; r < kMasterRuleCount; ++r) {
    const auto rule = static_cast<MasterRule>(r);
    out += r ? ", " : "";
    append_json_string(out, rule_name(rule));
    out += ": {\"severity\": ";
    append_json_string(out, severity_name(rules.of(rule)));
    out += ", \"count\": " + std::to_string(log.count_of(rule)) + "}";
  }
  out += "}}\n";
  return out;
}

std::string finding_line(const Finding& f, const std::vector<std::string>& bus_names) {
  char head[128];
  std::snprintf(head, sizeof head, "%s (%s) at %.3f s, bus %.*s", std::string(rule_name(f.rule)).c_str(),
                std::string(severity_name(f.severity)).c_str(), sim::seconds(f.t),
                static_cast<int>(bus_name(bus_names, f.bus).size()), bus_name(bus_names, f.bus).data());
  std::string line = head;
  if (f.node) line += ", node " + std::to_string(f.node);
  return line + ": " + f.text.data();
}

}  // namespace scenario
