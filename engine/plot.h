// Line plots of recorded signals as PNG: title, axes with "nice" ticks and tick labels, axis
// labels, grid, and a legend; one colour per series. NaN samples break the line.
#pragma once

#include <string>
#include <vector>

namespace scenario {

struct PlotSeries {
  std::string label;
  const std::vector<double>* values;
};

struct PlotInput {
  std::string title;
  std::string x_label = "time [s]";
  std::string y_label;
  int width = 1000;
  int height = 600;
  const std::vector<double>* times = nullptr;
  std::vector<PlotSeries> series;
};

/// Renders and writes the plot; returns an error message, empty on success.
std::string write_plot(const PlotInput& in, const std::string& path);

/// Tick positions covering [lo, hi] at a 1-2-5 step (about `target` ticks).
std::vector<double> nice_ticks(double lo, double hi, int target, double& step);

}  // namespace scenario
