// Certified solving: figures and the report section (experiments/solve_study.hpp).
#include "experiments/solve_study.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "float/rounding.hpp"
#include "io/json_io.hpp"
#include "solve/contact.hpp"
#include "solve/projection.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"

namespace splinex {

namespace {

std::array<double, 3> at3(const BSpline<double>& S, std::vector<double> x) {
  const auto p = evaluate(S, x);
  return {p[0], p[1], p[2]};
}

/// The surface's boundary as four polylines of points in space.
std::vector<std::vector<std::array<double, 3>>> boundary(const BSpline<double>& S, int n = 64) {
  const double u0 = S.domain_lo(0), u1 = S.domain_hi(0), v0 = S.domain_lo(1), v1 = S.domain_hi(1);
  std::vector<std::vector<std::array<double, 3>>> out(4);
  for (int i = 0; i <= n; ++i) {
    const double a = static_cast<double>(i) / n;
    out[0].push_back(at3(S, {u0 + a * (u1 - u0), v0}));
    out[1].push_back(at3(S, {u1, v0 + a * (v1 - v0)}));
    out[2].push_back(at3(S, {u1 - a * (u1 - u0), v1}));
    out[3].push_back(at3(S, {u0, v1 - a * (v1 - v0)}));
  }
  return out;
}

std::vector<std::array<double, 3>> curve_points(const BSpline<double>& C, int n = 256) {
  std::vector<std::array<double, 3>> out;
  const double t0 = C.domain_lo(0), t1 = C.domain_hi(0);
  for (int i = 0; i <= n; ++i) out.push_back(at3(C, {t0 + (t1 - t0) * i / n}));
  return out;
}

}  // namespace

std::string curve_projection_svg(const BSpline<Rational>& C0, const BSpline<Rational>& S0, const CurveProjectionResult& r,
                                 const std::string& title) {
  const auto S = round_spline<double>(S0, "surface"), C = round_spline<double>(C0, "curve");
  const int W = 360, H = 360, M = 40;
  std::ostringstream s;
  s << std::setprecision(6);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 2 * W + 3 * M << "\" height=\"" << H + 2 * M + 40
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << M
    << "\" y=\"20\" font-size=\"14\">" << title << "</text>\n";
  // Left: the parameter domain.
  const double u0 = S.domain_lo(0), u1 = S.domain_hi(0), v0 = S.domain_lo(1), v1 = S.domain_hi(1);
  const int oy = M + 10;
  const auto px = [&](double u) { return M + (u - u0) / (u1 - u0) * W; };
  const auto py = [&](double v) { return oy + H - (v - v0) / (v1 - v0) * H; };
  s << "<rect x=\"" << M << "\" y=\"" << oy << "\" width=\"" << W << "\" height=\"" << H << "\" fill=\"#f7f7f7\" stroke=\"black\"/>\n";
  for (const auto& b : r.branches) {
    s << "<polyline fill=\"none\" stroke-width=\"2.5\" stroke=\"" << kPalette[static_cast<std::size_t>(std::max(0, b.component)) % kPaletteSize] << "\" points=\"";
    for (const auto& x : b.points) s << px(x[0]) << "," << py(x[1]) << " ";
    s << "\"/>\n";
  }
  for (const auto& p : r.special) {
    const double u = to_double((p.lo[0] + p.hi[0]) / 2), v = to_double((p.lo[1] + p.hi[1]) / 2);
    const char* fill = p.kind == "turning point" ? "#ff7f0e" : p.kind == "joint" ? "white" : "black";
    s << "<circle cx=\"" << px(u) << "\" cy=\"" << py(v) << "\" r=\"3.5\" fill=\"" << fill << "\" stroke=\"black\"/>\n";
  }
  s << "<text x=\"" << M << "\" y=\"" << oy + H + 16 << "\">the surface's parameters (u, v) in [" << u0 << ", " << u1 << "] x [" << v0 << ", " << v1
    << "]</text>\n<text x=\"" << M << "\" y=\"" << oy + H + 32 << "\">dots: ends (black), joints (white), turning points (orange)</text>\n";
  // Right: the top view.
  std::vector<std::array<double, 3>> all = curve_points(C);
  for (const auto& e : boundary(S)) all.insert(all.end(), e.begin(), e.end());
  double x0 = all[0][0], x1 = x0, y0 = all[0][1], y1 = y0;
  for (const auto& p : all) {
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  }
  const double span = std::max(x1 - x0, y1 - y0) * 1.05, cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const int ox = 2 * M + W;
  const auto qx = [&](double x) { return ox + (x - cx) / span * W + W / 2.0; };
  const auto qy = [&](double y) { return oy + H / 2.0 - (y - cy) / span * H; };
  s << "<rect x=\"" << ox << "\" y=\"" << oy << "\" width=\"" << W << "\" height=\"" << H << "\" fill=\"white\" stroke=\"black\"/>\n";
  const auto line = [&](const std::vector<std::array<double, 3>>& pts, const std::string& stroke, double width, bool dashed) {
    s << "<polyline fill=\"none\" stroke-width=\"" << width << "\" stroke=\"" << stroke << "\"" << (dashed ? " stroke-dasharray=\"4,3\"" : "") << " points=\"";
    for (const auto& p : pts) s << qx(p[0]) << "," << qy(p[1]) << " ";
    s << "\"/>\n";
  };
  for (const auto& e : boundary(S)) line(e, "black", 1, false);
  line(curve_points(C), "#888888", 1.5, true);
  for (const auto& b : r.branches) {
    std::vector<std::array<double, 3>> pts;
    for (const auto& x : b.points) pts.push_back(at3(S, {x[0], x[1]}));
    line(pts, kPalette[static_cast<std::size_t>(std::max(0, b.component)) % kPaletteSize], 2.5, false);
  }
  s << "<text x=\"" << ox << "\" y=\"" << oy + H + 16 << "\">top view (x, y): C dashed, the projection coloured</text>\n";
  s << "</svg>\n";
  return s.str();
}

std::string curve_projection_obj(const BSpline<Rational>& C0, const BSpline<Rational>& S0, const CurveProjectionResult& r) {
  const auto S = round_spline<double>(S0, "surface"), C = round_spline<double>(C0, "curve");
  std::ostringstream s;
  s << "# splinex project --curve: the curve, the surface's boundary, the projected branches (polylines)\n" << std::setprecision(17);
  std::size_t base = 1;
  const auto poly = [&](const std::vector<std::array<double, 3>>& pts, const std::string& group) {
    s << "g " << group << "\n";
    for (const auto& p : pts) s << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    s << "l";
    for (std::size_t i = 0; i < pts.size(); ++i) s << " " << base + i;
    s << "\n";
    base += pts.size();
  };
  poly(curve_points(C), "curve");
  int k = 0;
  for (const auto& e : boundary(S)) poly(e, "boundary_" + std::to_string(k++));
  k = 0;
  for (const auto& b : r.branches) {
    std::vector<std::array<double, 3>> pts;
    for (const auto& x : b.points) pts.push_back(at3(S, {x[0], x[1]}));
    poly(pts, "projection_" + std::to_string(b.component) + "_" + std::to_string(k++));
  }
  return s.str();
}

}  // namespace splinex
