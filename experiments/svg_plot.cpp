#include "experiments/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/errors.hpp"
#include "experiments/svg.hpp"

namespace splinex {

std::string svg_line_plot(const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  // The plot's drawing: axes box [L, W - R] x [T, H - B], the legend in the right column; the title
  // and the note are the canvas's bands (wrapped to its width).
  const double W = 720, H = 400, L = 80, R = 200, T = 10, B = 50;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  auto tx = [&](double x) { return spec.logx ? std::log10(x) : x; };
  for (const auto& s : series)
    for (auto [x, y] : s.points) {
      xmin = std::min(xmin, tx(x));
      xmax = std::max(xmax, tx(x));
      if (!spec.logy || y > 0) {
        const double v = spec.logy ? std::log10(y) : y;
        ymin = std::min(ymin, v);
        ymax = std::max(ymax, v);
      }
    }
  if (xmin > xmax) { xmin = 0; xmax = 1; }
  if (ymin > ymax) { ymin = -1; ymax = 0; }
  if (spec.logy) { ymin = std::floor(ymin) - 1; ymax = std::ceil(ymax); }  // one decade below for zeros
  else { const double pad = 0.05 * (ymax - ymin + 1); ymin -= pad; ymax += pad; }
  if (xmax == xmin) xmax = xmin + 1;
  const double floor_v = ymin;
  auto X = [&](double x) { return L + (tx(x) - xmin) / (xmax - xmin) * (W - L - R); };
  auto Y = [&](double y) {
    const double v = spec.logy ? (y > 0 ? std::log10(y) : floor_v) : y;
    return T + (1 - (v - ymin) / (ymax - ymin)) * (H - T - B);
  };
  svg::Canvas c(W, H);
  c.title(spec.title, 15);
  if (!spec.note.empty()) c.caption(spec.note);
  // Grid and ticks.
  const std::string grid = svg::attr("stroke", "#ddd");
  if (spec.logy) {
    // At most about 12 labelled decades; grid lines at every labelled one.
    const int step = std::max(1, static_cast<int>(std::ceil((ymax - ymin) / 12)));
    for (int e = static_cast<int>(ymin); e <= static_cast<int>(ymax); e += step) {
      const double y = T + (1 - (e - ymin) / (ymax - ymin)) * (H - T - B);
      c.line(L, y, W - R, y, grid);
      c.text(L - 6, y + 4, (e == static_cast<int>(ymin) ? "0 / " : "") + std::string("1e") + std::to_string(e), 12, svg::Anchor::end);
    }
  } else {
    // Enough decimals that neighbouring ticks read differently (at least one).
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10((ymax - ymin) / 5))), 1, 6);
    for (int i = 0; i <= 5; ++i) {
      const double v = ymin + (ymax - ymin) * i / 5, y = T + (1 - i / 5.0) * (H - T - B);
      c.line(L, y, W - R, y, grid);
      char b[32];
      std::snprintf(b, sizeof b, "%.*f", decimals, v);
      c.text(L - 6, y + 4, b, 12, svg::Anchor::end);
    }
  }
  std::vector<double> xt;
  if (spec.logx) for (int e = static_cast<int>(std::floor(xmin)); e <= static_cast<int>(std::ceil(xmax)); ++e) xt.push_back(std::pow(10.0, e));
  else for (int i = 0; i <= 6; ++i) xt.push_back(xmin + (xmax - xmin) * i / 6);
  double last_right = -1e300;  // a tick label that would touch the previous one is left out (its grid line stays)
  for (double x : xt) {
    if (tx(x) < xmin - 1e-9 || tx(x) > xmax + 1e-9) continue;
    c.line(X(x), T, X(x), H - B, svg::attr("stroke", "#eee"));
    // Decades as 1eK, as on the y axis (%g would write 1e-05 beside 0.0001).
    char b[32];
    if (spec.logx) std::snprintf(b, sizeof b, "1e%d", static_cast<int>(std::lround(std::log10(x))));
    else std::snprintf(b, sizeof b, "%.3g", x);
    const double half = svg::text_width(b, 12) / 2;
    if (X(x) - half < last_right + 4) continue;
    c.text(X(x), H - B + 16, b, 12, svg::Anchor::middle);
    last_right = X(x) + half;
  }
  c.rect(L, T, W - L - R, H - T - B, svg::attr("fill", "none") + svg::attr("stroke", "black"));
  c.text((L + W - R) / 2, H - B + 38, spec.xlabel, 12, svg::Anchor::middle);
  // The y label runs along the axis: smaller type when it is longer than the axis.
  const double ylabel_px = std::min(12.0, 12.0 * (H - T - B) / std::max(1.0, svg::text_width(spec.ylabel, 12)));
  c.text(0, 0, spec.ylabel, std::floor(ylabel_px * 10) / 10, svg::Anchor::middle,
         svg::attr("transform", "translate(18," + svg::num((T + H - B) / 2) + ") rotate(-90)"));
  double ly = T + 14;  // the legend's next baseline; a long label wraps within the legend column
  for (const auto& s : series) {
    std::vector<std::pair<double, double>> pts = s.points;
    std::sort(pts.begin(), pts.end());
    const std::string stroke = svg::attr("stroke", s.color) + svg::attr("stroke-width", 2) + (s.dashed ? svg::attr("stroke-dasharray", "6,4") : "");
    svg::Points line;
    for (auto [x, y] : pts) line.emplace_back(X(x), Y(y));
    c.polyline(line, stroke);
    for (auto [x, y] : line) c.circle(x, y, 3, svg::attr("fill", s.color));
    c.line(W - R + 12, ly - 4, W - R + 36, ly - 4, stroke);
    ly += 15.0 * static_cast<double>(c.text_block(W - R + 42, ly, s.label, R - 42 - 6)) + 3;
  }
  return c.str();
}

void write_file_atomically(const std::string& path, const std::string& text) {
  if (path.empty()) throw UsageError("output", "the file name is empty", "give a file name");
  if (std::filesystem::is_directory(path)) throw UsageError(path, "is a folder, not a file", "give a file name");
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    if (!f) throw UsageError(path, "cannot write the file", "check that the output folder is writable");
    f << text;
    if (!f) throw UsageError(path, "writing failed", "check free disk space");
  }
  std::filesystem::rename(tmp, path);
}

double loglog_slope(const std::vector<std::pair<double, double>>& pts) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (auto [x, y] : pts) {
    const double lx = std::log10(x), ly = std::log10(y);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
  }
  const double N = static_cast<double>(pts.size());
  return pts.size() >= 2 ? (N * sxy - sx * sy) / (N * sxx - sx * sx) : 0;
}

}  // namespace splinex
