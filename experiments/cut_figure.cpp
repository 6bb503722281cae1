#include "experiments/cut_figure.hpp"

#include <cmath>
#include <sstream>

#include "experiments/svg_plot.hpp"
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
  std::ostringstream s;
  s.precision(5);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << W + 40 << "\" viewBox=\"0 0 " << W << " "
    << W + 40 << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"" << M / 2 << "\" y=\"18\" font-family=\"sans-serif\" font-size=\"" << (title.size() > 70 ? 11 : 13) << "\">" << svg_escape(title)
    << "</text>\n";
  // boundary
  for (const auto& F : solid.facets) {
    const auto Fd = round_spline<double>(F, "facet");
    s << "<polyline fill=\"none\" stroke=\"black\" stroke-width=\"2\" points=\"";
    const double lo = Fd.domain_lo(0), hi = Fd.domain_hi(0);
    for (int k = 0; k <= 64; ++k) {
      const auto p = evaluate(Fd, std::vector<double>{lo + (hi - lo) * k / 64.0});
      s << X(p[0]) << "," << Y(p[1]) << " ";
    }
    s << "\"/>\n";
  }
  // zero level set of f by marching squares
  const auto fd = round_spline<double>(f, "guide");
  const int G = 240;
  std::vector<double> v((G + 1) * (G + 1));
  for (int j = 0; j <= G; ++j)
    for (int i = 0; i <= G; ++i) v[i + (G + 1) * j] = evaluate(fd, std::vector<double>{double(i) / G, double(j) / G})[0];
  s << "<path fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.5\" d=\"";
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
        s << "M" << X(cross[k].first) << "," << Y(cross[k].second) << "L" << X(cross[k + 1].first) << "," << Y(cross[k + 1].second);
    }
  s << "\"/>\n";
  if (curve) {
    const auto Cd = round_spline<double>(*curve, "curve");
    s << "<polyline fill=\"none\" stroke=\"#9467bd\" stroke-width=\"2.5\" stroke-dasharray=\"6,3\" points=\"";
    for (int k = 0; k <= 200; ++k) {
      const auto p = evaluate(Cd, std::vector<double>{Cd.domain_lo(0) + (Cd.domain_hi(0) - Cd.domain_lo(0)) * k / 200.0});
      s << X(p[0]) << "," << Y(p[1]) << " ";
    }
    s << "\"/>\n";
  }
  // samples
  for (std::size_t i = 0; i < samples.size(); ++i)
    s << "<circle cx=\"" << X(to_double(samples[i][0])) << "\" cy=\"" << Y(to_double(samples[i][1])) << "\" r=\"2.5\" fill=\""
      << (i < samples_positive ? "#2ca02c" : "#d62728") << "\"/>\n";
  // cut points, strips, tangents
  for (const auto& e : cut.ends) {
    const auto p = evaluate(solid.facets[e.facet], std::vector<Rational>{e.param});
    const double x = to_double(p[0]), y = to_double(p[1]), r = to_double(strip);
    s << "<rect x=\"" << X(x - r) << "\" y=\"" << Y(y + r) << "\" width=\"" << 2 * r * (W - 2 * M) << "\" height=\"" << 2 * r * (W - 2 * M)
      << "\" fill=\"#999\" fill-opacity=\"0.2\" stroke=\"none\"/>\n";
    const double tx = to_double(e.tangent[0]), ty = to_double(e.tangent[1]), tn = std::hypot(tx, ty);
    s << "<line x1=\"" << X(x) << "\" y1=\"" << Y(y) << "\" x2=\"" << X(x + 0.08 * tx / tn) << "\" y2=\"" << Y(y + 0.08 * ty / tn)
      << "\" stroke=\"#9467bd\" stroke-width=\"2\"/>\n<circle cx=\"" << X(x) << "\" cy=\"" << Y(y) << "\" r=\"4\" fill=\"#9467bd\"/>\n";
  }
  std::string verdict;
  if (sep) {
    verdict = std::string("separation: ") + certificate_word(sep->verdict);
    if (sep->witness) {
      const double x = to_double(sep->witness->point[0]), y = to_double(sep->witness->point[1]);
      s << "<circle cx=\"" << X(x) << "\" cy=\"" << Y(y) << "\" r=\"7\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2.5\"/>\n";
      verdict += " (circled: f* has the wrong sign there, exactly)";
    }
    for (const auto& u : sep->undecided) {
      const auto p = evaluate(solid.facets[u.facet], std::vector<Rational>{(u.lo + u.hi) / 2});
      s << "<circle cx=\"" << X(to_double(p[0])) << "\" cy=\"" << Y(to_double(p[1])) << "\" r=\"6\" fill=\"none\" stroke=\"orange\" stroke-width=\"2\"/>\n";
    }
  }
  s << "<text x=\"" << M << "\" y=\"" << W + 12 << "\" font-family=\"sans-serif\" font-size=\"11\">blue: f* = 0; " << (curve ? "purple dashed: cutting curve; " : "") << "green/red: samples on b/b-bar; grey: strip</text>\n";
  s << "<text x=\"" << M << "\" y=\"" << W + 30 << "\" font-family=\"sans-serif\" font-size=\"12\">" << svg_escape(verdict) << "</text>\n</svg>\n";
  return s.str();
}

}  // namespace splinex
