#include "engine/running/exercise_checker.h"

#include "engine/running/world.h"

namespace scenario {

namespace {

bool matches(const TransitionGoal& g, const devices::Transition& t) {
  if (!g.machine.empty() && t.machine != g.machine) return false;
  if (!g.from.empty() && t.from != g.from) return false;
  if (!g.to.empty() && t.to != g.to) return false;
  if (!g.transition.empty() && t.transition != g.transition) return false;
  return true;
}

}  // namespace

GoalBinding GoalBinding::of(World& world) {
  GoalBinding b;
  b.signal = [&world](const SignalExpr& e) { return world.resolve(e); };
  b.bus = [&world](const ExerciseGoal& g) {
    const int bus = world.bus_index(g.bus);
    if (bus < 0) throw LoadError(g.mark, "frame: no bus '" + g.bus + "' in this scenario");
    return bus;
  };
  b.log = [&world](const ExerciseGoal& g) {
    auto* n = world.find_node(g.transition.node);
    if (!n) throw LoadError(g.mark, "transition: no node '" + g.transition.node + "' in this scenario");
    return &n->device->transition_log();
  };
  return b;
}

ExerciseChecker::ExerciseChecker(const Exercise& exercise, const GoalBinding& binding) {
  bound_.reserve(exercise.steps.size());
  for (const auto& step : exercise.steps) {
    const auto& g = step.goal;
    Bound b;
    b.kind = g.kind;
    b.goal = &g;
    switch (g.kind) {
      case ExerciseGoal::Kind::Condition: b.signal = binding.signal(g.condition.signal); break;
      case ExerciseGoal::Kind::Frame: b.bus = binding.bus(g); break;
      case ExerciseGoal::Kind::Transition: b.log = binding.log(g); break;
    }
    bound_.push_back(std::move(b));
  }
  progress_.assign(bound_.size(), Progress{});
  if (!bound_.empty()) make_current(0, 0, nullptr);
}

void ExerciseChecker::make_current(std::size_t step, std::uint64_t carried_seq, const devices::TransitionLog* carried_log) {
  current_ = step;
  frame_seen_us_ = -1;
  if (step >= bound_.size()) return;
  const auto& b = bound_[step];
  // A chain recorded in one tick (TR_5, TR_6, TR_7) can complete several steps: the next step on
  // the same log looks at the entries after the one that completed this step.
  if (b.log) after_seq_ = b.log == carried_log ? carried_seq : b.log->last_seq();
}

void ExerciseChecker::complete(std::int64_t t_us, std::uint64_t seq) {
  progress_[current_] = Progress{true, t_us};
  const auto* log = bound_[current_].log;
  make_current(current_ + 1, seq, log);
}

void ExerciseChecker::on_frame(int bus, const sim::CanFrame& frame, std::int64_t now_us) {
  if (current_ >= bound_.size() || frame_seen_us_ >= 0) return;
  const auto& b = bound_[current_];
  if (b.kind == ExerciseGoal::Kind::Frame && b.bus == bus && b.goal->frame.matches(frame)) frame_seen_us_ = now_us;
}

void ExerciseChecker::check(std::int64_t now_us) {
  while (current_ < bound_.size()) {
    const auto& b = bound_[current_];
    switch (b.kind) {
      case ExerciseGoal::Kind::Condition:
        if (!b.goal->condition.holds(b.signal->value())) return;
        complete(now_us, 0);
        break;
      case ExerciseGoal::Kind::Frame:
        if (frame_seen_us_ < 0) return;
        complete(frame_seen_us_, 0);
        break;
      case ExerciseGoal::Kind::Transition: {
        const devices::Transition* hit = nullptr;
        b.log->for_each_after(after_seq_, [&](const devices::Transition& t) {
          if (!hit && matches(b.goal->transition, t)) hit = &t;
        });
        if (!hit) {
          after_seq_ = b.log->last_seq();  // seen: not looked at again
          return;
        }
        complete(static_cast<std::int64_t>(hit->t_us), hit->seq);
        break;
      }
    }
  }
}

}  // namespace scenario
