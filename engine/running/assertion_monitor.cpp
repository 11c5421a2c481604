#include "engine/running/assertion_monitor.h"

#include <cmath>

#include "engine/loading/value_codec.h"

namespace scenario {

namespace {

std::string seconds_text(sim::Duration d) { return format_value(sim::seconds(d)) + " s"; }

// The value that came closest to satisfying the condition (what a failure reports).
bool closer(const Condition& c, double candidate, double best) {
  if (std::isnan(best)) return !std::isnan(candidate);
  if (std::isnan(candidate)) return false;
  switch (c.op) {
    case Condition::Op::Above: return candidate > best;
    case Condition::Op::Below: return candidate < best;
    case Condition::Op::Near: return std::fabs(candidate - c.a) < std::fabs(best - c.a);
    case Condition::Op::Between: {
      auto dist = [&](double v) { return v < c.a ? c.a - v : (v > c.b ? v - c.b : 0.0); };
      return dist(candidate) < dist(best);
    }
    case Condition::Op::Outside: {
      auto depth = [&](double v) { return std::min(std::fabs(v - c.a), std::fabs(v - c.b)); };
      return depth(candidate) > depth(best);
    }
  }
  return false;
}

}  // namespace

void AssertionMonitor::expect(const ExpectStep& e, Signal signal, const std::string& name, const SourceMark& mark,
                              sim::Time now) {
  if (e.mode == ExpectStep::Mode::Now) {
    const double v = signal.value();
    if (e.condition.holds(v)) verdicts_.pass(name, mark, now);
    else verdicts_.fail(name, mark, now, e.condition.describe(), format_value(v));
    return;
  }
  SignalWatch w{e, std::move(signal), name, mark, now, now + e.window};
  w.first = w.signal.value();
  w.extreme = w.first;
  w.last = w.first;
  signals_.push_back(std::move(w));
}

void AssertionMonitor::expect_frames(const ExpectFramesStep& e, int bus, const std::string& name, const SourceMark& mark,
                                     sim::Time now) {
  FrameWatch w;
  w.spec = e;
  w.bus = bus;
  w.name = name;
  w.mark = mark;
  w.start = now;
  w.end = now + e.window;
  frames_.push_back(std::move(w));
}

void AssertionMonitor::on_frame(int bus, const sim::CanFrame& f, sim::Time now) {
  for (auto& w : frames_) {
    if (w.done || w.bus != bus || now < w.start || now >= w.end || !w.spec.select.matches_id(f)) continue;
    if (w.spec.content && !w.spec.content->matches_data(f) && w.violation.empty()) {
      w.violation = "frame " + sim::to_candump(f) + " does not match " + w.spec.content->describe();
      w.violation_time = now;
    }
    if (w.spec.period && w.count > 0 && w.violation.empty()) {
      const auto interval = now - w.last_time;
      if (interval < *w.spec.period - w.spec.period_tolerance || interval > *w.spec.period + w.spec.period_tolerance) {
        w.violation = "interval " + seconds_text(interval) + " between frames";
        w.violation_time = now;
      }
    }
    ++w.count;
    w.last_time = now;
  }
}

void AssertionMonitor::decide(SignalWatch& w, sim::Time now, bool at_end) {
  const auto& c = w.spec.condition;
  switch (w.spec.mode) {
    case ExpectStep::Mode::Within:
      if (c.holds(w.last)) {
        verdicts_.pass(w.name, w.mark, now);
        w.done = true;
      } else if (now >= w.end || at_end) {
        verdicts_.fail(w.name, w.mark, now, c.describe() + " within " + seconds_text(w.spec.window),
                       (at_end && now < w.end ? "run ended; " : "") + std::string("closest ") + format_value(w.extreme) +
                           ", last " + format_value(w.last));
        w.done = true;
      }
      break;
    case ExpectStep::Mode::During:
    case ExpectStep::Mode::UntilEnd:
      if (!c.holds(w.last)) {
        verdicts_.fail(w.name, w.mark, now, c.describe() + " throughout", format_value(w.last));
        w.done = true;
      } else if ((w.spec.mode == ExpectStep::Mode::During && now >= w.end) || at_end) {
        if (w.spec.mode == ExpectStep::Mode::During && now < w.end) {
          verdicts_.fail(w.name, w.mark, now, c.describe() + " during " + seconds_text(w.spec.window),
                         "run ended after " + seconds_text(now - w.start));
        } else {
          verdicts_.pass(w.name, w.mark, now);
        }
        w.done = true;
      }
      break;
    case ExpectStep::Mode::Slope:
      if (now >= w.end || at_end) {
        const double dt = sim::seconds(now - w.start);
        const double slope = dt > 0 ? (w.last - w.first) / dt : std::nan("");
        const std::string expected = "slope of " + c.signal.text + " = " + format_value(c.a) + " ± " + format_value(c.b) + " /s";
        if (now < w.end) verdicts_.fail(w.name, w.mark, now, expected, "run ended before the window closed");
        else if (c.holds(slope)) verdicts_.pass(w.name, w.mark, now);
        else verdicts_.fail(w.name, w.mark, now, expected, format_value(slope) + " /s (" + format_value(w.first) + " → " + format_value(w.last) + ")");
        w.done = true;
      }
      break;
    case ExpectStep::Mode::Now:
      break;
  }
}

void AssertionMonitor::decide(FrameWatch& w, sim::Time now) {
  w.done = true;
  const auto& s = w.spec;
  std::string expected = s.select.describe();
  if (!w.violation.empty()) {
    verdicts_.fail(w.name, w.mark, w.violation_time,
                   expected + (s.content ? " with data " + s.content->describe() : "") +
                       (s.period ? " every " + seconds_text(*s.period) + " ± " + seconds_text(s.period_tolerance) : ""),
                   w.violation);
    return;
  }
  const bool low = s.min_count && w.count < *s.min_count;
  const bool high = s.max_count && w.count > *s.max_count;
  if (low || high) {
    std::string range = s.min_count && s.max_count && *s.min_count == *s.max_count
                            ? std::to_string(*s.min_count)
                            : "[" + (s.min_count ? std::to_string(*s.min_count) : "0") + ", " +
                                  (s.max_count ? std::to_string(*s.max_count) : "∞") + "]";
    verdicts_.fail(w.name, w.mark, now, range + " frames " + expected + " in " + seconds_text(s.window),
                   std::to_string(w.count) + " frames" + (now < w.end ? " (run ended early)" : ""));
    return;
  }
  if (now < w.end) {
    verdicts_.fail(w.name, w.mark, now, "a window of " + seconds_text(s.window), "run ended after " + seconds_text(now - w.start));
    return;
  }
  verdicts_.pass(w.name, w.mark, now);
}

void AssertionMonitor::step(sim::Time now) {
  for (auto& w : signals_) {
    if (w.done) continue;
    w.last = w.signal.value();
    if (closer(w.spec.condition, w.last, w.extreme)) w.extreme = w.last;
    decide(w, now, false);
  }
  for (auto& w : frames_)
    if (!w.done && now >= w.end) decide(w, now);
  // Forget what is decided (keeps the per-tick loops short on long runs).
  std::erase_if(signals_, [](const SignalWatch& w) { return w.done; });
  std::erase_if(frames_, [](const FrameWatch& w) { return w.done; });
}

void AssertionMonitor::finish(sim::Time end) {
  for (auto& w : signals_)
    if (!w.done) decide(w, end, true);
  for (auto& w : frames_)
    if (!w.done) decide(w, end);
  signals_.clear();
  frames_.clear();
}

bool AssertionMonitor::pending() const {
  for (const auto& w : signals_)
    if (!w.done && w.spec.mode != ExpectStep::Mode::UntilEnd) return true;
  for (const auto& w : frames_)
    if (!w.done) return true;
  return false;
}

}  // namespace scenario
