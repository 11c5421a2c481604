// Opt-in split of where a tick's time goes, for the benchmarks (tools/bench): the plant, ODE
// within it, the nodes and bus delivery. Off unless a benchmark installs a TickProfile; off, a
// probe costs one load and a branch not taken. On, each probe reads the monotonic clock (vDSO)
// twice, so a benchmark measures its headline figure in a run without the profile and the split
// in a second run with it.
#pragma once

#include <time.h>

#include <array>
#include <cstdint>

namespace sim {

enum class TickPart { Plant, Ode, Nodes, Bus };
inline constexpr std::size_t kTickParts = 4;

struct TickProfile {
  std::array<std::int64_t, kTickParts> ns{};  ///< monotonic nanoseconds spent in each part
  std::array<std::uint64_t, kTickParts> calls{};

  /// The profile the probes add to, or nullptr (the default: no probe measures anything).
  /// Set it before the run starts, from the thread that runs it.
  inline static TickProfile* active = nullptr;

  /// Monotonic ns one probe adds to the run it measures (two clock reads and the bookkeeping),
  /// measured on a scratch profile; a benchmark subtracts calls * overhead from its figures.
  static double probe_overhead_ns();
  /// A profiled run's `ns` less the probes' own time (each probe's overhead counts in full in the
  /// run, half inside the part it measures).
  double run_ns_without_probes(std::int64_t ns, double overhead) const {
    std::uint64_t n = 0;
    for (auto c : calls) n += c;
    return static_cast<double>(ns) - static_cast<double>(n) * overhead;
  }
  /// A part's time less the probes' own; the ODE probe sits inside the plant's, so its overhead
  /// is taken from the plant's part in full.
  double part_ns(TickPart part, double overhead) const {
    const auto i = static_cast<std::size_t>(part);
    double own = static_cast<double>(ns[i]) - 0.5 * static_cast<double>(calls[i]) * overhead;
    if (part == TickPart::Plant) own -= static_cast<double>(calls[static_cast<std::size_t>(TickPart::Ode)]) * overhead;
    return own;
  }

  static std::int64_t now_ns() {
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
  }
};

/// Adds the time from its construction to its destruction to one part of the active profile.
class TickProbe {
 public:
  explicit TickProbe(TickPart part) : profile_(TickProfile::active) {
    if (profile_ != nullptr) [[unlikely]] {
      part_ = static_cast<std::size_t>(part);
      start_ = TickProfile::now_ns();
    }
  }
  ~TickProbe() {
    if (profile_ != nullptr) [[unlikely]] {
      profile_->ns[part_] += TickProfile::now_ns() - start_;
      ++profile_->calls[part_];
    }
  }
  TickProbe(const TickProbe&) = delete;
  TickProbe& operator=(const TickProbe&) = delete;

 private:
  TickProfile* profile_;
  std::size_t part_ = 0;
  std::int64_t start_ = 0;
};

inline double TickProfile::probe_overhead_ns() {
  TickProfile scratch;
  TickProfile* const saved = active;
  active = &scratch;
  constexpr int kProbes = 20000;
  const std::int64_t t0 = now_ns();
  for (int i = 0; i < kProbes; ++i) {
    const TickProbe probe(TickPart::Bus);
  }
  const std::int64_t t1 = now_ns();
  active = saved;
  return static_cast<double>(t1 - t0) / kProbes;
}

}  // namespace sim
