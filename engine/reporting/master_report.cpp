#include "engine/reporting/master_report.h"

#include <cerrno>
#include <cstring>

#include "engine/running/master_monitor.h"

namespace scenario {

namespace {

constexpr std::size_t kSummaryLines = 10;

}  // namespace

std::string write_master_report(const std::string& path, const MasterMonitor& monitor) {
  const std::string json = findings_json(monitor.findings(), monitor.rules(), monitor.bus_names());
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return "cannot write '" + path + "': " + std::strerror(errno);
  const bool written = std::fwrite(json.data(), 1, json.size(), f) == json.size();
  const int error = errno;
  if (std::fclose(f) != 0 || !written) return "cannot write '" + path + "': " + std::strerror(written ? errno : error);
  return {};
}

void add_rule_outcomes(const MasterMonitor& monitor, const SourceMark& mark, sim::Time end, Verdicts& verdicts) {
  const FindingLog& log = monitor.findings();
  for (std::size_t r = 0; r < kMasterRuleCount; ++r) {
    const auto rule = static_cast<MasterRule>(r);
    const Severity severity = monitor.rules().of(rule);
    if (severity == Severity::Off) continue;
    const std::string name = "master rule " + std::string(rule_name(rule));
    const std::size_t count = log.count_of(rule);
    if (count == 0 || severity == Severity::Warning) {
      verdicts.pass(name, mark, end);
      continue;
    }
    std::string actual = std::to_string(count) + " finding(s)";
    for (std::size_t i = 0; i < log.size(); ++i) {
      if (log[i].rule != rule) continue;
      actual += "; first: " + finding_line(log[i], monitor.bus_names());
      verdicts.fail(name, mark, log[i].t, "no findings", actual);
      actual.clear();
      break;
    }
    if (!actual.empty()) verdicts.fail(name, mark, end, "no findings", actual + " (not stored: the log was full)");
  }
}

void print_findings(std::FILE* out, const MasterMonitor& monitor, bool always) {
  const FindingLog& log = monitor.findings();
  std::size_t total = 0, errors = 0;
  for (std::size_t r = 0; r < kMasterRuleCount; ++r) {
    const auto rule = static_cast<MasterRule>(r);
    total += log.count_of(rule);
    if (monitor.rules().of(rule) == Severity::Error) errors += log.count_of(rule);
  }
  if (total == 0 && !always) return;
  std::fprintf(out, "  master findings: %zu (%zu errors, %zu warnings)", total, errors, total - errors);
  if (log.dropped()) std::fprintf(out, ", %zu not stored (the log holds %zu)", log.dropped(), log.capacity());
  std::fputc('\n', out);
  for (std::size_t i = 0; i < log.size() && i < kSummaryLines; ++i)
    std::fprintf(out, "    %s\n", finding_line(log[i], monitor.bus_names()).c_str());
  if (log.size() > kSummaryLines) std::fprintf(out, "    ... %zu more (--master-report FILE lists them all)\n", log.size() - kSummaryLines);
}

}  // namespace scenario
