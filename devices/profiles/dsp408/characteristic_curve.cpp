#include "devices/profiles/dsp408/characteristic_curve.h"

#include <algorithm>

namespace dsp408 {

CharacteristicCurve::CharacteristicCurve() {
  for (std::size_t k = 0; k < kPoints; ++k) {
    const double v = static_cast<double>(k) / static_cast<double>(kPoints - 1);
    points_[k] = Point{v, v};
  }
}

double CharacteristicCurve::map(double u) const {
  std::array<Point, kPoints> p = points_;  // small, on the stack: sorting keeps input order free
  std::stable_sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
  if (u <= p.front().x) return p.front().y;
  for (std::size_t k = 1; k < kPoints; ++k) {
    if (u <= p[k].x) {
      const double dx = p[k].x - p[k - 1].x;
      if (dx <= 0) return p[k].y;
      return p[k - 1].y + (p[k].y - p[k - 1].y) * (u - p[k - 1].x) / dx;
    }
  }
  return p.back().y;
}

}  // namespace dsp408
