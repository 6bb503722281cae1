#include "experiments/cut_figure.hpp"

#include <cmath>
#include <sstream>

#include "experiments/svg.hpp"
#include "float/rounding.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

std::string cut_guide_svg(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const BSpline<Rational>& f,
                          const std::vector<std::array<Rational, 2>>& samples, std::size_t samples_positive,
                          const Rational& strip, const SeparationResult* sep, const std::string& title,
                          const BSpline<Rational>* curve) {
  const double W = 520, M = 30;
  auto X = [&](double x) { return M + x * (W - 2 * M); };
  auto Y = [&](double y) { return W - M - y * (W - 2 * M); };
  svg::Canvas s(W, W, 5);
  s.title(title, 13);
  // boundary
  for (const auto& F : solid.facets) {
    const auto Fd = round_spline<double>(F, "facet");
    const double lo = Fd.domain_lo(0), hi = Fd.domain_hi(0);
    svg::Points pts;
    for (int k = 0; k <= 64; ++k) {
      const auto p = evaluate(Fd, std::vector<double>{lo + (hi - lo) * k / 64.0});
      pts.emplace_back(X(p[0]), Y(p[1]));
    }
    s.polyline(pts, svg::attr("stroke", "black") + svg::attr("stroke-width", 2));
  }
  // zero level set of f by marching squares
  const auto fd = round_spline<double>(f, "guide");
  const int G = 240;
  std::vector<double> v((G + 1) * (G + 1));
  for (int j = 0; j <= G; ++j)
    for (int i = 0; i <= G; ++i) v[i + (G + 1) * j] = evaluate(fd, std::vector<double>{double(i) / G, double(j) / G})[0];
  std::string d;
  for (int j = 0; j < G; ++j)
    for (int i = 0; i < G; ++i) {
      const double c[4] = {v[i + (G + 1) * j], v[i + 1 + (G + 1) * j], v[i + 1 + (G + 1) * (j + 1)], v[i + (G + 1) * (j + 1)]};
      const double px[4] = {double(i), double(i + 1), double(i + 1), double(i)}, py[4] = {double(j), double(j), double(j + 1), double(j + 1)};
      std::vector<std::pair<double, double>> cross;
      for (int e = 0; e < 4; ++e) {
        const int a = e, b = (e + 1) % 4;
        if ((c[a] < 0) != (c[b] < 0)) {
          const double t = c[a] / (c[a] - c[b]);
          cross.push_back({(px[a] + t * (px[b] - px[a])) / G, (py[a] + t * (py[b] - py[a])) / G});
        }
      }
      for (std::size_t k = 0; k + 1 < cross.size(); k += 2)
        d += s.move_to(X(cross[k].first), Y(cross[k].second)) + s.line_to(X(cross[k + 1].first), Y(cross[k + 1].second));
    }
  s.path(d, svg::attr("stroke", "#1f77b4") + svg::attr("stroke-width", 1.5));
  if (curve) {
    const auto Cd = round_spline<double>(*curve, "curve");
    svg::Points pts;
    for (int k = 0; k <= 200; ++k) {
      const auto p = evaluate(Cd, std::vector<double>{Cd.domain_lo(0) + (Cd.domain_hi(0) - Cd.domain_lo(0)) * k / 200.0});
      pts.emplace_back(X(p[0]), Y(p[1]));
    }
    s.polyline(pts, svg::attr("stroke", "#9467bd") + svg::attr("stroke-width", 2.5) + svg::attr("stroke-dasharray", "6,3"));
  }
  // samples
  for (std::size_t i = 0; i < samples.size(); ++i)
    s.circle(X(to_double(samples[i][0])), Y(to_double(samples[i][1])), 2.5, svg::attr("fill", i < samples_positive ? "#2ca02c" : "#d62728"));
  // cut points, strips, tangents
  for (const auto& e : cut.ends) {
    const auto p = evaluate(solid.facets[e.facet], std::vector<Rational>{e.param});
    const double x = to_double(p[0]), y = to_double(p[1]), r = to_double(strip);
    s.rect(X(x - r), Y(y + r), 2 * r * (W - 2 * M), 2 * r * (W - 2 * M), svg::attr("fill", "#999") + svg::attr("fill-opacity", 0.2) + svg::attr("stroke", "none"));
    const double tx = to_double(e.tangent[0]), ty = to_double(e.tangent[1]), tn = std::hypot(tx, ty);
    s.line(X(x), Y(y), X(x + 0.08 * tx / tn), Y(y + 0.08 * ty / tn), svg::attr("stroke", "#9467bd") + svg::attr("stroke-width", 2));
    s.circle(X(x), Y(y), 4, svg::attr("fill", "#9467bd"));
  }
  std::string verdict;
  if (sep) {
    verdict = std::string("separation: ") + certificate_word(sep->verdict);
    if (sep->witness) {
      const double x = to_double(sep->witness->point[0]), y = to_double(sep->witness->point[1]);
      s.circle(X(x), Y(y), 7, svg::attr("fill", "none") + svg::attr("stroke", "#d62728") + svg::attr("stroke-width", 2.5));
      verdict += " (circled: f* has the wrong sign there, exactly)";
    }
    for (const auto& u : sep->undecided) {
      const auto p = evaluate(solid.facets[u.facet], std::vector<Rational>{(u.lo + u.hi) / 2});
      s.circle(X(to_double(p[0])), Y(to_double(p[1])), 6, svg::attr("fill", "none") + svg::attr("stroke", "orange") + svg::attr("stroke-width", 2));
    }
  }
  s.caption(std::string("blue: f* = 0; ") + (curve ? "purple dashed: cutting curve; " : "") + "green/red: samples on b/b-bar; grey: strip");
  if (!verdict.empty()) s.caption(verdict, 12);
  return s.str();
}

}  // namespace splinex
