#include "engine/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/raster.h"

namespace scenario {

namespace {

constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kInk{30, 30, 30};
constexpr Rgb kGrid{225, 225, 225};
constexpr Rgb kColours[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {255, 127, 14},
                            {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {23, 190, 207}};

std::string tick_label(double v, double step) {
  char buf[32];
  if (std::fabs(v) < step * 1e-6) v = 0;
  const double mag = std::max(std::fabs(v), step);
  if (mag >= 1e6 || mag < 1e-3) {
    std::snprintf(buf, sizeof buf, "%.3g", v);
  } else {
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  return buf;
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target, double& step) {
  std::vector<double> ticks;
  const double span = hi - lo;
  if (!(span > 0) || !std::isfinite(span)) {
    step = 1;
    return ticks;
  }
  const double raw = span / std::max(1, target);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / p;
  step = (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) ticks.push_back(t);
  return ticks;
}

std::string write_plot(const PlotInput& in, const std::string& path) {
  Raster r(in.width, in.height, kWhite);
  const int scale = 2;
  const int left = 110, right = in.width - 25, top = in.title.empty() ? 25 : 55, bottom = in.height - 65;
  const auto& t = *in.times;

  double x0 = t.empty() ? 0 : t.front(), x1 = t.empty() ? 1 : t.back();
  if (x1 <= x0) x1 = x0 + 1;
  double y0 = std::numeric_limits<double>::infinity(), y1 = -y0;
  for (const auto& s : in.series)
    for (double v : *s.values)
      if (std::isfinite(v)) {
        y0 = std::min(y0, v);
        y1 = std::max(y1, v);
      }
  if (!std::isfinite(y0)) {
    y0 = 0;
    y1 = 1;
  }
  if (y1 - y0 < 1e-12 * std::max(1.0, std::fabs(y0))) {
    const double pad = std::max(std::fabs(y0) * 0.1, 1e-3);
    y0 -= pad;
    y1 += pad;
  } else {
    const double pad = (y1 - y0) * 0.05;
    y0 -= pad;
    y1 += pad;
  }
  const auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (right - left); };
  const auto py = [&](double y) { return bottom - (y - y0) / (y1 - y0) * (bottom - top); };

  // Grid, ticks and their labels.
  double xs, ys;
  const auto xt = nice_ticks(x0, x1, std::max(2, (right - left) / 110), xs);
  const auto yt = nice_ticks(y0, y1, std::max(2, (bottom - top) / 60), ys);
  for (double x : xt) {
    const double X = std::round(px(x)) + 0.5;
    r.line(X, top, X, bottom, kGrid, 1);
    r.line(X, bottom, X, bottom + 6, kInk, 1);
    const auto label = tick_label(x, xs);
    r.text(static_cast<int>(X) - Raster::text_width(label, scale) / 2, bottom + 12, label, kInk, scale);
  }
  for (double y : yt) {
    const double Y = std::round(py(y)) + 0.5;
    r.line(left, Y, right, Y, kGrid, 1);
    r.line(left - 6, Y, left, Y, kInk, 1);
    const auto label = tick_label(y, ys);
    r.text(left - 10 - Raster::text_width(label, scale), static_cast<int>(Y) - Raster::text_height(scale) / 2, label, kInk, scale);
  }
  // Frame and labels.
  r.line(left + 0.5, top, left + 0.5, bottom + 0.5, kInk, 1.5);
  r.line(left, bottom + 0.5, right, bottom + 0.5, kInk, 1.5);
  if (!in.title.empty())
    r.text((in.width - Raster::text_width(in.title, 3)) / 2, 15, in.title, kInk, 3);
  r.text((left + right - Raster::text_width(in.x_label, scale)) / 2, bottom + 38, in.x_label, kInk, scale);
  if (!in.y_label.empty())
    r.text_vertical(12, (top + bottom - Raster::text_width(in.y_label, scale)) / 2, in.y_label, kInk, scale);

  // Series, clipped to the plot area; NaN breaks the line.
  r.clip(left + 1, top, right, bottom);
  for (std::size_t k = 0; k < in.series.size(); ++k) {
    const auto& v = *in.series[k].values;
    const Rgb c = kColours[k % 8];
    const std::size_t n = std::min(v.size(), t.size());
    for (std::size_t i = 1; i < n; ++i) {
      if (!std::isfinite(v[i - 1]) || !std::isfinite(v[i])) continue;
      r.line(px(t[i - 1]), py(v[i - 1]), px(t[i]), py(v[i]), c, 2.0);
    }
    if (n == 1 && std::isfinite(v[0])) r.line(px(t[0]), py(v[0]), px(t[0]), py(v[0]), c, 3.0);
  }
  r.clip_none();

  // Legend: top right inside the plot area.
  int widest = 0;
  for (const auto& s : in.series) widest = std::max(widest, Raster::text_width(s.label, scale));
  const int row = Raster::text_height(scale) + 8;
  const int lw = widest + 50, lh = static_cast<int>(in.series.size()) * row + 8;
  const int lx = right - lw - 10, ly = top + 10;
  r.fill_rect(lx, ly, lx + lw, ly + lh, kWhite);
  r.line(lx, ly + 0.5, lx + lw, ly + 0.5, kInk, 1);
  r.line(lx, ly + lh + 0.5, lx + lw, ly + lh + 0.5, kInk, 1);
  r.line(lx + 0.5, ly, lx + 0.5, ly + lh, kInk, 1);
  r.line(lx + lw + 0.5, ly, lx + lw + 0.5, ly + lh, kInk, 1);
  for (std::size_t k = 0; k < in.series.size(); ++k) {
    const int y = ly + 6 + static_cast<int>(k) * row;
    r.line(lx + 8, y + row / 2.0 - 4, lx + 36, y + row / 2.0 - 4, kColours[k % 8], 3.0);
    r.text(lx + 42, y, in.series[k].label, kInk, scale);
  }
  return r.write_png(path);
}

}  // namespace scenario
