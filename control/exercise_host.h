// The exercise a plant's trainee works on (docs/exercises.md): the control plane owns one, the
// HTTP endpoints select and read it, and the run checks its goals between ticks. Selection and
// reading run as bridge commands (between ticks), so the checker lives on the scheduler's thread
// only; every tick costs one goal test and no allocation. A classroom mounts one control plane per
// seat, and with it one ExerciseHost.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "control/sim_bridge.h"
#include "engine/loading/exercise.h"
#include "engine/running/exercise_checker.h"

namespace sim {
class Scheduler;
}
namespace control {

namespace http {
class Router;
}

class ExerciseHost {
 public:
  /// `dir`: the folder of exercise files ("" = none); `initial`: the exercise selected at attach
  /// ("" = none).
  ExerciseHost(SimBridge& bridge, std::string dir, std::string initial);
  ~ExerciseHost();
  ExerciseHost(const ExerciseHost&) = delete;
  ExerciseHost& operator=(const ExerciseHost&) = delete;

  // ---- scheduler thread ----------------------------------------------------------------------
  /// Taps every bus and selects the initial exercise; throws LoadError when it cannot be read or
  /// bound. Called again after a restart (a new world), it binds the selected exercise anew.
  void attach(const scenario::RunContext& context);
  /// Before every tick: checks the current step's goal.
  void check();

  // ---- any thread ----------------------------------------------------------------------------
  /// GET /api/exercises, POST /api/exercise, GET /api/exercise (control/exercise_endpoints.cpp).
  void add_routes(http::Router& router);
  const std::string& dir() const { return dir_; }
  /// Counts the changes the stream's `exercise` event reports: a selection (also the one a
  /// restart binds anew) and every step that became done.
  std::uint64_t version() const { return version_.load(std::memory_order_acquire); }
  /// The selection and its progress as GET /api/exercise answers it, read between ticks; "" when
  /// the scheduler did not answer within `wait` (the event hub asks again later).
  std::string state_json(std::chrono::milliseconds wait);

  /// A copy of the selection and its progress, taken between ticks.
  struct View {
    std::shared_ptr<const scenario::Exercise> exercise;  ///< null: none selected
    std::vector<scenario::ExerciseChecker::Progress> progress;
    std::size_t current = 0;
  };

 private:
  class Tap;
  /// Scheduler thread: makes `exercise` the selection (progress from the start).
  void select(std::shared_ptr<const scenario::Exercise> exercise, scenario::World& world);
  View view() const;

  SimBridge& bridge_;
  std::string dir_;
  std::string initial_;
  sim::Scheduler* scheduler_ = nullptr;
  std::vector<std::unique_ptr<Tap>> taps_;
  std::shared_ptr<const scenario::Exercise> exercise_;
  std::unique_ptr<scenario::ExerciseChecker> checker_;
  std::atomic<std::uint64_t> version_{0};
};

}  // namespace control
