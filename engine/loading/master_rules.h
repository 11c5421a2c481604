// The rules the master monitor (master_monitor.h) judges the master under test by: their names
// (one vocabulary for the scenario key `master_rules:`, the JSON report, JUnit and HTTP), their
// default severities, and a scenario's choice of severity per rule.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "engine/loading/source_mark.h"

namespace scenario {

enum class MasterRule : std::uint8_t {
  BeforeBootUp,
  SdoAbort,
  SdoNoAnswer,
  SdoProtocol,
  NmtUnknownNode,
  PdoConfigWhileValid,
  RpdoLength,
  DeviceFault,
  HeartbeatMissing,
  GuardingTimeout,
  SyncJitter,
};
inline constexpr std::size_t kMasterRuleCount = 11;

enum class Severity : std::uint8_t { Off, Warning, Error };

std::string_view rule_name(MasterRule rule);
std::optional<MasterRule> rule_by_name(std::string_view name);
/// "before-boot-up, sdo-abort, ..." for error messages.
std::string rule_names();
Severity default_severity(MasterRule rule);
std::string_view severity_name(Severity severity);
std::optional<Severity> severity_by_name(std::string_view name);

/// A scenario's `master_rules:`: each rule's severity (the defaults unless the file sets it).
struct MasterRuleSettings {
  std::array<Severity, kMasterRuleCount> severity{};
  SourceMark mark;  ///< the key in the file (line 0 when absent)

  MasterRuleSettings() {
    for (std::size_t i = 0; i < kMasterRuleCount; ++i) severity[i] = default_severity(static_cast<MasterRule>(i));
  }
  Severity of(MasterRule rule) const { return severity[static_cast<std::size_t>(rule)]; }
};

}  // namespace scenario
