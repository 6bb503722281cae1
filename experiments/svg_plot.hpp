// Minimal SVG line plots (log or linear axes) for experiment figures; no plotting dependency.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace splinex {

/// The colours of every figure's series, in order.
inline const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"};
inline constexpr std::size_t kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);

struct PlotSeries {
  std::string label;
  std::vector<std::pair<double, double>> points;  // (x, y); y <= 0 on a log axis is drawn at the floor
  std::string color;
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

/// Text for SVG/XML: <, > and & as entities.
std::string svg_escape(const std::string& s);

/// Writes text to path through a temporary file and a rename, so readers never see half a file.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace splinex
