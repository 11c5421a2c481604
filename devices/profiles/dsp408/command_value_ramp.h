// Command value ramp of CiA DSP 408 ("dvg ramp"): a linear ramp with separate times for the four
// quadrants. A time is the time for a change of the full scale (0 ↔ ±100 %); 0 means a step.
//
//   output r ≥ 0, target above r  → A up       output r > 0, target below r → A down (to 0 first)
//   output r ≤ 0, target below r  → B up       output r < 0, target above r → B down (to 0 first)
//
// A zero crossing costs the down-time to 0 plus the up-time from 0, each in proportion to its
// share of the full scale; both happen inside one step() when dt covers them, so the ramp ends
// within one control cycle of the exact time.
#pragma once

namespace dsp408 {

class CommandValueRamp {
 public:
  struct Times {
    double a_up = 0;    ///< s per full scale, positive side rising
    double a_down = 0;  ///< positive side falling toward 0
    double b_up = 0;    ///< negative side rising in magnitude
    double b_down = 0;  ///< negative side falling toward 0
  };

  void set_full_scale(double full_scale) { full_scale_ = full_scale; }
  void set_times(const Times& t) { times_ = t; }
  /// Disabled: the output follows the target at once.
  void set_enabled(bool enabled) { enabled_ = enabled; }

  /// Advances by `dt` seconds toward `target`; returns the new output.
  double step(double target, double dt);
  /// Sets the output (e.g. 0 when outputs are switched off).
  void reset(double value = 0) { output_ = value; }

  double output() const { return output_; }
  /// "Ramp running" (status bit 9): the output has not reached the target and will take time
  /// to (a quadrant with time 0 is a step, not a running ramp).
  bool running(double target) const { return enabled_ && output_ != target && time_to(target) > 0; }
  /// Seconds the ramp needs from its output to `target`.
  double time_to(double target) const;

 private:
  double rate(double seconds) const;  // units per second; 0 = step

  double full_scale_ = 16384;
  Times times_;
  bool enabled_ = true;
  double output_ = 0;
};

/// Rate limitation of a set point (DSP 408 "speed" for the axis modes): rising by at most
/// `rise` units per second, falling by at most `fall`; 0 = no limitation.
class RateLimiter {
 public:
  void set_rates(double rise, double fall) {
    rise_ = rise;
    fall_ = fall;
  }
  double step(double target, double dt);
  void reset(double value) { output_ = value; }
  double output() const { return output_; }

 private:
  double rise_ = 0, fall_ = 0;
  double output_ = 0;
};

}  // namespace dsp408
