// The exercise endpoints (docs/api.md, "Exercises"): GET /api/exercises (the names in the
// folder), POST /api/exercise {"name"} (select; progress starts again), GET /api/exercise (the
// selection with each step's instruction and whether and when it was done), and the same body
// for the stream's `exercise` event (ExerciseHost::state_json).
#include <nlohmann/json.hpp>

#include "control/exercise_host.h"
#include "control/http_server.h"
#include "control/request_body.h"

namespace control {

using nlohmann::json;

namespace {

constexpr auto kExerciseCommandTimeout = std::chrono::milliseconds(2000);

struct ExerciseError {
  int status;
  std::string reason;
};

void answer(http::Response& res, int status, const json& body) {
  res.status = status;
  res.type = "application/json";
  res.body = body.dump(-1, ' ', false, json::error_handler_t::replace);
}

/// Runs `f` between ticks; a run that has not started, has ended or does not answer is a 503.
template <typename R>
R between_ticks(SimBridge& bridge, std::function<R(const scenario::RunContext&)> f) {
  if (!bridge.attached()) throw ExerciseError{503, "the run is starting"};
  if (bridge.finished()) throw ExerciseError{503, "the run has ended"};
  SimBridge::Posted posted{};
  auto r = bridge.call<R>(std::move(f), kExerciseCommandTimeout, &posted);
  if (posted == SimBridge::Posted::Full) throw ExerciseError{429, "too many commands wait for the simulation: retry later"};
  if (!r) throw ExerciseError{503, "the simulation did not answer (the run has ended?)"};
  return std::move(*r);
}

http::Handler answering(std::function<void(const http::Request&, http::Response&)> h) {
  return [h = std::move(h)](http::Request& req, http::Response& res) {
    try {
      h(req, res);
    } catch (const ExerciseError& e) {
      answer(res, e.status, {{"error", e.reason}});
    } catch (const std::exception& e) {
      answer(res, 500, {{"error", std::string("internal error: ") + e.what()}});
    }
  };
}

json exercise_json(const ExerciseHost::View& v) {
  if (!v.exercise)
    return {{"name", nullptr}, {"title", ""}, {"introduction", ""}, {"steps", json::array()}, {"current", 0}, {"done", false}};
  const auto& e = *v.exercise;
  json steps = json::array();
  for (std::size_t i = 0; i < e.steps.size(); ++i) {
    const auto& s = e.steps[i];
    const auto p = i < v.progress.size() ? v.progress[i] : scenario::ExerciseChecker::Progress{};
    steps.push_back({{"title", s.title},
                     {"text", s.text},
                     {"hint", s.hint},
                     {"goal", s.goal.summary},
                     {"done", p.done},
                     {"t_us", p.done ? json(p.t_us) : json(nullptr)}});
  }
  return {{"name", e.name},
          {"title", e.title},
          {"introduction", e.introduction},
          {"steps", steps},
          {"current", v.current},
          {"done", v.current >= e.steps.size()}};
}

}  // namespace

std::string ExerciseHost::state_json(std::chrono::milliseconds wait) {
  if (!bridge_.attached() || bridge_.finished()) return {};
  auto v = bridge_.call<View>([this](const scenario::RunContext&) { return view(); }, wait);
  return v ? exercise_json(*v).dump(-1, ' ', false, json::error_handler_t::replace) : std::string();
}

void ExerciseHost::add_routes(http::Router& router) {
  router.add("GET", "/api/exercises", answering([this](const http::Request&, http::Response& res) {
    answer(res, 200, scenario::list_exercises(dir_));
  }));
  router.add("GET", "/api/exercise", answering([this](const http::Request&, http::Response& res) {
    answer(res, 200, exercise_json(between_ticks<View>(bridge_, [this](const scenario::RunContext&) { return view(); })));
  }));
  router.add("POST", "/api/exercise", answering([this](const http::Request& req, http::Response& res) {
    const auto name = [&] {
      try {
        RequestBody body(req.body, "the exercise choice");
        auto n = body.text("name");
        body.finish();
        return n;
      } catch (const BodyError& e) {
        throw ExerciseError{400, e.reason};
      }
    }();
    if (!scenario::valid_exercise_name(name))
      throw ExerciseError{400, "'" + name + "' is not an exercise name (letters, digits, '_', '-', at most 64)"};
    if (dir_.empty()) throw ExerciseError{404, "no exercise '" + name + "': this plant has no exercises folder (--exercises DIR)"};
    const auto names = scenario::list_exercises(dir_);
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw ExerciseError{404, "no exercise '" + name + "' (see GET /api/exercises)"};
    std::shared_ptr<const scenario::Exercise> exercise;
    try {  // read on this thread: no file is read between ticks
      exercise = std::make_shared<const scenario::Exercise>(scenario::load_exercise(dir_, name));
    } catch (const scenario::LoadError& e) {
      throw ExerciseError{400, e.what()};
    }
    const auto error = between_ticks<std::string>(bridge_, [this, exercise](const scenario::RunContext& c) {
      try {
        select(exercise, c.world);
        return std::string();
      } catch (const scenario::LoadError& e) {  // a goal names what this scenario does not have
        return std::string(e.what());
      }
    });
    if (!error.empty()) throw ExerciseError{400, error};
    answer(res, 200, exercise_json(between_ticks<View>(bridge_, [this](const scenario::RunContext&) { return view(); })));
  }));
}

}  // namespace control
