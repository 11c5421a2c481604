// The master monitor's findings: bounded storage filled on the scheduler's thread without
// allocating (fixed text, up to three frames as evidence), readable from another thread while
// the run goes on (entries are written once, then published by the count), and its JSON.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/can_frame.h"
#include "sim/time.h"
#include "engine/loading/master_rules.h"

namespace scenario {

/// A frame the finding rests on, as the bus carried it.
struct Evidence {
  sim::Time t{};
  sim::CanFrame frame;
  bool from_master = false;
};

struct Finding {
  static constexpr std::size_t kTextSize = 224;
  static constexpr std::size_t kMaxEvidence = 3;
  MasterRule rule = MasterRule::BeforeBootUp;
  Severity severity = Severity::Error;
  sim::Time t{};
  int bus = 0;
  int node = 0;  ///< node-ID the finding is about (0: the bus as a whole)
  std::array<char, kTextSize> text{};
  std::array<Evidence, kMaxEvidence> evidence{};
  std::uint8_t evidence_count = 0;
};

class FindingLog {
 public:
  explicit FindingLog(std::size_t capacity) : entries_(capacity) {}
  FindingLog(const FindingLog&) = delete;
  FindingLog& operator=(const FindingLog&) = delete;

  /// The slot for the next finding, or nullptr when full (the finding is counted as dropped);
  /// publish() makes it visible. Scheduler thread only.
  Finding* claim() {
    const std::size_t n = published_.load(std::memory_order_relaxed);
    if (n < entries_.size()) return &entries_[n];
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return nullptr;
  }
  void publish() { published_.fetch_add(1, std::memory_order_release); }
  /// Counts a finding of `rule` (stored or dropped).
  void count(MasterRule rule) { counts_[static_cast<std::size_t>(rule)].fetch_add(1, std::memory_order_relaxed); }

  // Any thread.
  std::size_t size() const { return published_.load(std::memory_order_acquire); }
  const Finding& operator[](std::size_t i) const { return entries_[i]; }
  std::size_t dropped() const { return dropped_.load(std::memory_order_relaxed); }
  std::size_t count_of(MasterRule rule) const { return counts_[static_cast<std::size_t>(rule)].load(std::memory_order_relaxed); }
  std::size_t capacity() const { return entries_.size(); }

 private:
  std::vector<Finding> entries_;
  std::atomic<std::size_t> published_{0};
  std::atomic<std::size_t> dropped_{0};
  std::array<std::atomic<std::size_t>, kMasterRuleCount> counts_{};
};

/// `{"findings": [...], "dropped": N, "rules": {...}}`: the published findings from `first` on,
/// at most `limit` of them, with their frames (candump text), and per rule its severity and
/// count. `bus_names` by bus index.
std::string findings_json(const FindingLog& log, const MasterRuleSettings& rules, const std::vector<std::string>& bus_names,
                          std::size_t first = 0, std::size_t limit = SIZE_MAX);
/// One finding as a line of the run summary: "sdo-abort (warning) at 1.234 s, bus main, node 2: text".
std::string finding_line(const Finding& f, const std::vector<std::string>& bus_names);

}  // namespace scenario
