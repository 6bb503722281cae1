// Line plots (log or linear axes) for experiment figures, drawn on svg::Canvas; no plotting dependency.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "experiments/svg.hpp"  // svg::palette for the series

namespace splinex {

struct PlotSeries {
  std::string label;
  std::vector<std::pair<double, double>> points;  // (x, y); y <= 0 on a log axis is drawn at the floor
  std::string color;  // svg::palette(k) for the k-th series
  bool dashed = false;
};

struct PlotSpec {
  std::string title, xlabel, ylabel;
  bool logx = false, logy = true;
  std::string note;  // printed under the plot (e.g. how zeros are drawn)
};

std::string svg_line_plot(const PlotSpec& spec, const std::vector<PlotSeries>& series);

/// Least-squares slope of log10(y) against log10(x) over the points (0 for fewer than two).
double loglog_slope(const std::vector<std::pair<double, double>>& pts);

/// Writes text to path through a temporary file and a rename, so readers never see half a file.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace splinex
