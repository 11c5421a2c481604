// The live control plane's scheduler side allocates nothing per tick or frame: the SimBridge as
// the reference plant's RunExtension, with a stream listening (frames captured, signals sampled,
// PDO mappings re-read) and a node snapshot asked for every tick, makes no heap allocation in
// before_tick, and a tick with it makes exactly as many as the same tick without it.
// (tests/support/counting_allocator.h says what is counted; no server thread runs here.)
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "control/sim_bridge.h"
#include "engine/running/environment.h"
#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"
#include "tests/support/counting_allocator.h"

namespace {

constexpr std::uint64_t kWarmUp = 500;   // boot, first snapshots, rings sized
constexpr std::uint64_t kMeasured = 3000;

/// Counts the allocations of each measured tick (between two before_tick calls) and of the
/// bridge's before_tick; with a bridge, drains its frame ring on every other tick so both the
/// capture and the ring-full path run.
class Counting final : public scenario::RunExtension {
 public:
  explicit Counting(control::SimBridge* bridge) : bridge_(bridge) { per_tick.reserve(kMeasured); }
  void attach(const scenario::RunContext& c) override {
    if (bridge_) bridge_->attach(c);
  }
  bool before_tick(bool end) override {
    const long at_entry = vtest::allocation_count();
    const bool measuring = ticks_ >= kWarmUp && ticks_ < kWarmUp + kMeasured;
    if (measuring && ticks_ > kWarmUp) per_tick.push_back(at_entry - tick_start_);
    if (end || ticks_ >= kWarmUp + kMeasured) return false;
    bool go = true;
    if (bridge_) {
      bridge_->request_snapshot();
      control::CapturedFrame f;
      if (ticks_ % 2 == 0)
        while (bridge_->frames().pop(f)) ++frames_seen;
      const long before = vtest::allocation_count();
      go = bridge_->before_tick(end);
      if (measuring) in_bridge += vtest::allocation_count() - before;
      if (ticks_ % 2 == 0) row_pops += bridge_->signal_rows().pop(row_) ? 1 : 0;
    }
    ++ticks_;
    tick_start_ = vtest::allocation_count();
    return go;
  }
  void detach() override {
    if (bridge_) bridge_->detach();
  }

  std::vector<long> per_tick;
  long in_bridge = 0;
  long frames_seen = 0;
  long row_pops = 0;

 private:
  control::SimBridge* bridge_;
  std::uint64_t ticks_ = 0;
  long tick_start_ = 0;
  control::SignalRow row_;
};

std::vector<long> run(Counting& counting) {
  auto s = scenario::load_scenario_file(VPLANT_REFERENCE_PLANT);
  s.outputs = {};
  scenario::RunOptions o;
  o.quiet = true;
  std::FILE* sink = std::tmpfile();
  o.out = sink;
  o.extension = &counting;
  {
    scenario::Runner runner(s, scenario::default_environment(), o);
    runner.run();
  }
  std::fclose(sink);
  return counting.per_tick;
}

TEST(BridgeAllocation, TicksWithTheBridgeAllocateNothingMore) {
  Counting off(nullptr);
  const auto without = run(off);

  control::ClockOptions clock;
  clock.start_paused = false;
  clock.speed = 0;
  control::SimBridge bridge(clock);
  bridge.add_listener();  // a stream listens: capture, sampling and PDO re-reads run
  Counting on(&bridge);
  const auto with = run(on);

  ASSERT_EQ(with.size(), kMeasured - 1);
  ASSERT_EQ(without.size(), with.size());
  EXPECT_EQ(on.in_bridge, 0) << "SimBridge::before_tick allocated";
  long extra = 0;
  for (std::size_t k = 0; k < with.size(); ++k) extra += with[k] - without[k];
  EXPECT_EQ(extra, 0) << "ticks with the bridge (its frame taps) allocated more than without";
  EXPECT_GT(on.frames_seen, 1000) << "the capture must have run";
  EXPECT_GT(on.row_pops, 10) << "signal sampling must have run";
  EXPECT_GT(bridge.node_version(), 1u) << "snapshots must have been published";
}

}  // namespace
