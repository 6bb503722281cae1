#include "experiments/render.hpp"
#include "base/point.hpp"
#include "experiments/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "float/mpfr.hpp"
#include "spline/evaluate.hpp"
#include "vrep/model/trivariate.hpp"

namespace splinex {

std::array<int, 3> palette_rgb(std::size_t i) {
  static const std::array<int, 3> colours[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14},
                                               {140, 86, 75},  {23, 190, 207}, {188, 189, 34}, {227, 119, 194}, {127, 127, 127}};
  return colours[i % (sizeof(colours) / sizeof(colours[0]))];
}

std::string render_svg(const std::vector<Triangle3>& triangles, const std::vector<Marker3>& markers, const RenderView& view) {
  const double pi = 3.14159265358979323846, az = view.azimuth_deg * pi / 180, el = view.elevation_deg * pi / 180;
  // Camera frame: right r, up u, towards the viewer d.
  const std::array<double, 3> d{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  const std::array<double, 3> r{-std::sin(az), std::cos(az), 0};
  const std::array<double, 3> u = cross(d, r);
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  auto grow = [&](const std::array<double, 3>& p) {
    const double x = dot(p, r), y = dot(p, u);
    xmin = std::min(xmin, x);
    xmax = std::max(xmax, x);
    ymin = std::min(ymin, y);
    ymax = std::max(ymax, y);
  };
  for (const auto& t : triangles)
    for (const auto& p : t.p) grow(p);
  for (const auto& m : markers) grow(m.at);
  if (xmax < xmin) xmin = ymin = 0, xmax = ymax = 1;
  const double margin = 30, top = view.title.empty() ? 10 : 34, bottom = view.note.empty() ? 10 : 30;
  const double sx = (view.width - 2 * margin) / std::max(xmax - xmin, 1e-300), sy = (view.height - top - bottom) / std::max(ymax - ymin, 1e-300);
  const double s = std::min(sx, sy);
  const double cx = view.width / 2.0 - s * (xmin + xmax) / 2, cy = top + (view.height - top - bottom) / 2.0 + s * (ymin + ymax) / 2;
  auto screen = [&](const std::array<double, 3>& p) { return std::array<double, 2>{cx + s * dot(p, r), cy - s * dot(p, u)}; };
  // Light from the viewer's upper left.
  std::array<double, 3> light{d[0] + 0.5 * u[0] - 0.4 * r[0], d[1] + 0.5 * u[1] - 0.4 * r[1], d[2] + 0.5 * u[2] - 0.4 * r[2]};
  const double ll = std::sqrt(dot(light, light));
  for (auto& x : light) x /= ll;
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    std::array<double, 3> c{};
    for (const auto& p : t.p)
      for (int k = 0; k < 3; ++k) c[k] += p[k] / 3;
    order.emplace_back(dot(c, d), i);
  }
  std::sort(order.begin(), order.end());
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << view.width << "\" height=\"" << view.height
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!view.title.empty()) o << "<text x=\"" << view.width / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">" << svg_escape(view.title) << "</text>\n";
  char buf[256];
  for (const auto& [depth, i] : order) {
    (void)depth;
    const auto& t = triangles[i];
    std::array<double, 3> a{}, b{};
    for (int k = 0; k < 3; ++k) {
      a[k] = t.p[1][k] - t.p[0][k];
      b[k] = t.p[2][k] - t.p[0][k];
    }
    const std::array<double, 3> nrm = cross(a, b);
    const double nl = std::sqrt(dot(nrm, nrm));
    const double lambert = nl > 0 ? std::abs(dot(nrm, light)) / nl : 0;  // two-sided
    const double f = 0.35 + 0.65 * lambert;
    int c[3];
    for (int k = 0; k < 3; ++k) c[k] = std::min(255, static_cast<int>(t.rgb[k] * f));
    const auto p0 = screen(t.p[0]), p1 = screen(t.p[1]), p2 = screen(t.p[2]);
    std::snprintf(buf, sizeof buf, "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"rgb(%d,%d,%d)\" stroke=\"rgb(%d,%d,%d)\" stroke-width=\"0.3\"/>\n",
                  p0[0], p0[1], p1[0], p1[1], p2[0], p2[1], c[0], c[1], c[2], c[0], c[1], c[2]);
    o << buf;
  }
  for (const auto& m : markers) {
    const auto p = screen(m.at);
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"rgb(%d,%d,%d)\"/>\n", p[0], p[1], m.radius, m.rgb[0],
                  m.rgb[1], m.rgb[2]);
    o << buf;
  }
  if (!view.note.empty())
    o << "<text x=\"" << view.width / 2 << "\" y=\"" << view.height - 10 << "\" text-anchor=\"middle\" fill=\"#555\">" << svg_escape(view.note) << "</text>\n";
  o << "</svg>\n";
  return o.str();
}

namespace {

/// x as the double nearest to it (exact for double; through the exact rational otherwise).
template <class T>
double dbl(const T& x) {
  return to_double(ArithTraits<T>::to_rational(x));
}

}  // namespace

template <class T>
void add_surface(std::vector<Triangle3>& out, const BSpline<T>& S, const std::array<int, 3>& rgb, int n, const std::array<double, 3>& offset) {
  std::vector<std::array<double, 3>> g;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const std::vector<T> x{S.domain_lo(0) + (S.domain_hi(0) - S.domain_lo(0)) * T(i) / T(n),
                             S.domain_lo(1) + (S.domain_hi(1) - S.domain_lo(1)) * T(j) / T(n)};
      const auto v = evaluate(S, x);
      g.push_back({dbl(v[0]) + offset[0], dbl(v[1]) + offset[1], dbl(v[2]) + offset[2]});
    }
  auto at = [&](int i, int j) { return g[static_cast<std::size_t>(i + (n + 1) * j)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      out.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}, rgb});
      out.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}, rgb});
    }
}

template <class T>
void add_trivariate_boundary(std::vector<Triangle3>& out, const BSpline<T>& V, const std::array<int, 3>& rgb, int n,
                             const std::array<double, 3>& offset) {
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) add_surface(out, face(V, d, s), rgb, n, offset);
}

template void add_surface(std::vector<Triangle3>&, const BSpline<Rational>&, const std::array<int, 3>&, int, const std::array<double, 3>&);
template void add_surface(std::vector<Triangle3>&, const BSpline<double>&, const std::array<int, 3>&, int, const std::array<double, 3>&);
template void add_trivariate_boundary(std::vector<Triangle3>&, const BSpline<Rational>&, const std::array<int, 3>&, int,
                                      const std::array<double, 3>&);
template void add_trivariate_boundary(std::vector<Triangle3>&, const BSpline<double>&, const std::array<int, 3>&, int,
                                      const std::array<double, 3>&);

}  // namespace splinex
