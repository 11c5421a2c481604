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

}  // namespace sim
