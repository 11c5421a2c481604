#include "control/exercise_host.h"

#include "engine/running/world.h"
#include "sim/bus.h"
#include "sim/scheduler.h"

namespace control {

/// Hands the frames of one bus to the current checker (scheduler thread).
class ExerciseHost::Tap final : public sim::FrameTap {
 public:
  Tap(ExerciseHost& host, int bus) : host_(host), bus_(bus) {}
  void on_bus_frame(std::string_view, const sim::CanFrame& frame, sim::Time now) override {
    if (host_.checker_) host_.checker_->on_frame(bus_, frame, now.time_since_epoch().count());
  }

 private:
  ExerciseHost& host_;
  int bus_;
};

ExerciseHost::ExerciseHost(SimBridge& bridge, std::string dir, std::string initial)
    : bridge_(bridge), dir_(std::move(dir)), initial_(std::move(initial)) {}

ExerciseHost::~ExerciseHost() = default;

void ExerciseHost::attach(const scenario::RunContext& context) {
  scheduler_ = &context.scheduler;
  auto& buses = context.world.buses();
  taps_.clear();
  for (std::size_t b = 0; b < buses.size(); ++b) {
    taps_.push_back(std::make_unique<Tap>(*this, static_cast<int>(b)));
    buses[b]->add_tap(taps_.back().get());
  }
  if (exercise_) {
    select(exercise_, context.world);
  } else if (!initial_.empty()) {
    if (dir_.empty()) throw scenario::LoadError(scenario::SourceMark{"--exercise", 0, 0}, "no exercises folder (--exercises DIR)");
    select(std::make_shared<const scenario::Exercise>(scenario::load_exercise(dir_, initial_)), context.world);
  }
}

void ExerciseHost::select(std::shared_ptr<const scenario::Exercise> exercise, scenario::World& world) {
  auto checker = std::make_unique<scenario::ExerciseChecker>(*exercise, world);  // throws before anything changes
  checker_ = std::move(checker);
  exercise_ = std::move(exercise);
  version_.fetch_add(1, std::memory_order_release);
}

void ExerciseHost::check() {
  if (!checker_) return;
  const auto before = checker_->current();
  checker_->check(scheduler_->now().time_since_epoch().count());
  if (checker_->current() != before) version_.fetch_add(1, std::memory_order_release);  // a step is done
}

ExerciseHost::View ExerciseHost::view() const {
  View v;
  v.exercise = exercise_;
  if (checker_) {
    v.progress = checker_->progress();
    v.current = checker_->current();
  }
  return v;
}

}  // namespace control
