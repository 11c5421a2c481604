#include "engine/loading/master_rules.h"

namespace scenario {

namespace {

struct RuleInfo {
  std::string_view name;
  Severity severity;
};

// In MasterRule order. Warnings: what a careful master may still do on purpose (probe an object
// and take the abort, address a node that may be absent, a SYNC that is merely late).
constexpr std::array<RuleInfo, kMasterRuleCount> kRules{{
    {"before-boot-up", Severity::Error},
    {"sdo-abort", Severity::Warning},
    {"sdo-no-answer", Severity::Error},
    {"sdo-protocol", Severity::Error},
    {"nmt-unknown-node", Severity::Warning},
    {"pdo-config-while-valid", Severity::Error},
    {"rpdo-length", Severity::Error},
    {"device-fault", Severity::Error},
    {"heartbeat-missing", Severity::Error},
    {"guarding-timeout", Severity::Error},
    {"sync-jitter", Severity::Warning},
}};

}  // namespace

std::string_view rule_name(MasterRule rule) { return kRules[static_cast<std::size_t>(rule)].name; }

std::optional<MasterRule> rule_by_name(std::string_view name) {
  for (std::size_t i = 0; i < kRules.size(); ++i)
    if (kRules[i].name == name) return static_cast<MasterRule>(i);
  return std::nullopt;
}

std::string rule_names() {
  std::string s;
  for (const auto& r : kRules) s += (s.empty() ? "" : ", ") + std::string(r.name);
  return s;
}

Severity default_severity(MasterRule rule) { return kRules[static_cast<std::size_t>(rule)].severity; }

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::Off: return "off";
    case Severity::Warning: return "warning";
    case Severity::Error: break;
  }
  return "error";
}

std::optional<Severity> severity_by_name(std::string_view name) {
  if (name == "off") return Severity::Off;
  if (name == "warning") return Severity::Warning;
  if (name == "error") return Severity::Error;
  return std::nullopt;
}

}  // namespace scenario
