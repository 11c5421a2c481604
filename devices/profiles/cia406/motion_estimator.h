// Speed, acceleration and jerk of a position sampled every internal cycle, as differences over
// a sliding window (CiA 406 6030h/6040h/6050h; the window is the device's integration time):
// v = (S(t) − S(t−T)) / T, a = (v(t) − v(t−T)) / T, j = (a(t) − a(t−T)) / T.
// The window buffers are sized by configure() (a parameter write), never per sample.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cia406 {

class MotionEstimator {
 public:
  MotionEstimator() { configure(1, 0.001); }
  /// `window` samples of `period_s` seconds each (window ≥ 1). Restarts from standstill at the
  /// last position.
  void configure(std::size_t window, double period_s);
  /// Standstill at `position` (power-on: no history yet, so no speed).
  void reset(std::int64_t position);
  /// One sample per internal cycle.
  void push(std::int64_t position);

  double speed() const { return speed_; }          ///< units per second
  double acceleration() const { return accel_; }   ///< units per second²
  double jerk() const { return jerk_; }            ///< units per second³
  std::size_t window() const { return window_; }

 private:
  std::size_t window_ = 1;
  double span_s_ = 0.001;
  std::size_t next_ = 0;
  std::vector<std::int64_t> positions_;
  std::vector<double> speeds_, accels_;
  std::int64_t last_ = 0;
  double speed_ = 0, accel_ = 0, jerk_ = 0;
};

}  // namespace cia406
