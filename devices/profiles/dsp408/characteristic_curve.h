// A characteristic curve through up to 11 points (x: demand 0..1, y: fraction of the Imin..Imax
// span), interpolated linearly, flat beyond the last point: the DSV's "characteristic
// optimisation". The factory points make it the identity.
#pragma once

#include <array>
#include <cstddef>

namespace dsp408 {

class CharacteristicCurve {
 public:
  static constexpr std::size_t kPoints = 11;
  struct Point {
    double x = 0;
    double y = 0;
  };

  CharacteristicCurve();  ///< identity: x_k = y_k = k/10
  void set_point(std::size_t k, Point p) { points_[k] = p; }
  const Point& point(std::size_t k) const { return points_[k]; }
  Point& point(std::size_t k) { return points_[k]; }
  /// y for demand u (points taken in order of x).
  double map(double u) const;

 private:
  std::array<Point, kPoints> points_;
};

}  // namespace dsp408
