#include "experiments/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/errors.hpp"

namespace splinex {

std::string svg_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

namespace {
std::string esc(const std::string& s) { return svg_escape(s); }
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}
}  // namespace

std::string svg_line_plot(const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  const double W = 720, H = 460, L = 80, R = 200, T = 40, B = 70;
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
  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H << "' font-family='sans-serif' font-size='12'>\n";
  o << "<rect width='100%' height='100%' fill='white'/>\n";
  o << "<text x='" << W / 2 - R / 2 << "' y='22' text-anchor='middle' font-size='15'>" << esc(spec.title) << "</text>\n";
  // Grid and ticks.
  if (spec.logy) {
    // At most about 12 labelled decades; grid lines at every labelled one.
    const int step = std::max(1, static_cast<int>(std::ceil((ymax - ymin) / 12)));
    for (int e = static_cast<int>(ymin); e <= static_cast<int>(ymax); e += step) {
      const double y = T + (1 - (e - ymin) / (ymax - ymin)) * (H - T - B);
      o << "<line x1='" << L << "' x2='" << W - R << "' y1='" << num(y) << "' y2='" << num(y) << "' stroke='#ddd'/>";
      o << "<text x='" << L - 6 << "' y='" << num(y + 4) << "' text-anchor='end'>" << (e == static_cast<int>(ymin) ? "0 / " : "")
        << "1e" << e << "</text>\n";
    }
  } else {
    for (int i = 0; i <= 5; ++i) {
      const double v = ymin + (ymax - ymin) * i / 5, y = T + (1 - i / 5.0) * (H - T - B);
      o << "<line x1='" << L << "' x2='" << W - R << "' y1='" << num(y) << "' y2='" << num(y) << "' stroke='#ddd'/>";
      o << "<text x='" << L - 6 << "' y='" << num(y + 4) << "' text-anchor='end'>" << num(v) << "</text>\n";
    }
  }
  std::vector<double> xt;
  if (spec.logx) for (int e = static_cast<int>(std::floor(xmin)); e <= static_cast<int>(std::ceil(xmax)); ++e) xt.push_back(std::pow(10.0, e));
  else for (int i = 0; i <= 6; ++i) xt.push_back(xmin + (xmax - xmin) * i / 6);
  for (double x : xt) {
    if (tx(x) < xmin - 1e-9 || tx(x) > xmax + 1e-9) continue;
    o << "<line x1='" << num(X(x)) << "' x2='" << num(X(x)) << "' y1='" << T << "' y2='" << H - B << "' stroke='#eee'/>";
    char b[32];
    std::snprintf(b, sizeof b, spec.logx ? "%g" : "%.3g", x);
    o << "<text x='" << num(X(x)) << "' y='" << H - B + 16 << "' text-anchor='middle'>" << b << "</text>\n";
  }
  o << "<rect x='" << L << "' y='" << T << "' width='" << W - L - R << "' height='" << H - T - B
    << "' fill='none' stroke='black'/>\n";
  o << "<text x='" << (L + W - R) / 2 << "' y='" << H - B + 38 << "' text-anchor='middle'>" << esc(spec.xlabel) << "</text>\n";
  o << "<text transform='translate(18," << (T + H - B) / 2 << ") rotate(-90)' text-anchor='middle'>" << esc(spec.ylabel) << "</text>\n";
  if (!spec.note.empty()) o << "<text x='" << L << "' y='" << H - 8 << "' font-size='11' fill='#555'>" << esc(spec.note) << "</text>\n";
  int li = 0;
  for (const auto& s : series) {
    std::vector<std::pair<double, double>> pts = s.points;
    std::sort(pts.begin(), pts.end());
    o << "<polyline fill='none' stroke='" << s.color << "' stroke-width='2'" << (s.dashed ? " stroke-dasharray='6,4'" : "") << " points='";
    for (auto [x, y] : pts) o << num(X(x)) << "," << num(Y(y)) << " ";
    o << "'/>\n";
    for (auto [x, y] : pts) o << "<circle cx='" << num(X(x)) << "' cy='" << num(Y(y)) << "' r='3' fill='" << s.color << "'/>";
    const double ly = T + 14 + 18 * li++;
    o << "\n<line x1='" << W - R + 12 << "' x2='" << W - R + 36 << "' y1='" << ly - 4 << "' y2='" << ly - 4 << "' stroke='" << s.color
      << "' stroke-width='2'" << (s.dashed ? " stroke-dasharray='6,4'" : "") << "/><text x='" << W - R + 42 << "' y='" << ly << "'>"
      << esc(s.label) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
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
