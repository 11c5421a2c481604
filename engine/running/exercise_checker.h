// Checks an exercise's goals live, between ticks: the steps are done in order, and a step's done
// time is the virtual time its goal first held after it became current (a transition: the time
// the device recorded; a frame: the time it crossed the bus; a condition: the tick boundary it was
// seen at). Binding resolves every goal against the world once, so checking allocates nothing
// and costs one goal's test per tick (docs/exercises.md).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "devices/transition_log.h"
#include "engine/loading/exercise.h"
#include "engine/running/signal_source.h"
#include "sim/can_frame.h"

namespace scenario {

class World;

/// What goals are bound to: a World (GoalBinding::of), or a test's own signals and logs. Each
/// throws LoadError at the goal when the name is unknown.
struct GoalBinding {
  std::function<Signal(const SignalExpr&)> signal;
  std::function<int(const ExerciseGoal&)> bus;
  std::function<const devices::TransitionLog*(const ExerciseGoal&)> log;

  static GoalBinding of(World& world);
};

class ExerciseChecker {
 public:
  struct Progress {
    bool done = false;
    std::int64_t t_us = -1;  ///< -1 until done
  };

  /// Binds the goals (the first step becomes current); throws LoadError at a goal naming an
  /// unknown node, bus or signal. `exercise` must outlive the checker.
  ExerciseChecker(const Exercise& exercise, World& world) : ExerciseChecker(exercise, GoalBinding::of(world)) {}
  ExerciseChecker(const Exercise& exercise, const GoalBinding& binding);

  /// Scheduler thread, between ticks: completes the current step (and the ones after it) whose
  /// goal holds. Never allocates.
  void check(std::int64_t now_us);
  /// Scheduler thread: a frame crossed bus `bus` (a tap on every bus calls it).
  void on_frame(int bus, const sim::CanFrame& frame, std::int64_t now_us);

  /// Index of the current step; steps().size() once every step is done.
  std::size_t current() const { return current_; }
  const std::vector<Progress>& progress() const { return progress_; }

 private:
  struct Bound {
    ExerciseGoal::Kind kind = ExerciseGoal::Kind::Condition;
    const ExerciseGoal* goal = nullptr;  ///< into the exercise (kept alive by the caller)
    std::optional<Signal> signal;
    int bus = 0;
    const devices::TransitionLog* log = nullptr;
  };
  void make_current(std::size_t step, std::uint64_t carried_seq, const devices::TransitionLog* carried_log);
  void complete(std::int64_t t_us, std::uint64_t seq);

  std::vector<Bound> bound_;
  std::vector<Progress> progress_;
  std::size_t current_ = 0;
  std::uint64_t after_seq_ = 0;         ///< current transition goal: entries after this one count
  std::int64_t frame_seen_us_ = -1;     ///< current frame goal: when a matching frame crossed
};

}  // namespace scenario
