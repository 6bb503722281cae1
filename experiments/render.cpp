#include "experiments/render.hpp"
#include "base/point.hpp"
#include "experiments/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "float/mpfr.hpp"
#include "spline/evaluate.hpp"
#include "vrep/model/trivariate.hpp"

namespace splinex {

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
  // The drawing area (the title and the note are the canvas's bands around it).
  const double margin = 30, pad = 10, Wd = view.width, Hd = std::max(100.0, view.height - (view.title.empty() ? 0.0 : 30.0) - (view.note.empty() ? 0.0 : 20.0));
  const double sx = (Wd - 2 * margin) / std::max(xmax - xmin, 1e-300), sy = (Hd - 2 * pad) / std::max(ymax - ymin, 1e-300);
  const double s = std::min(sx, sy);
  const double cx = Wd / 2.0 - s * (xmin + xmax) / 2, cy = Hd / 2.0 + s * (ymin + ymax) / 2;
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
  svg::Canvas canvas(Wd, Hd, 4);  // 4 digits: a tenth of a pixel
  if (!view.title.empty()) canvas.title(view.title);
  if (!view.note.empty()) canvas.caption(view.note, 12);
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
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k) c[k] = std::min(255, static_cast<int>(t.rgb[k] * f));
    const auto p0 = screen(t.p[0]), p1 = screen(t.p[1]), p2 = screen(t.p[2]);
    const std::string colour = svg::rgb(c);
    canvas.polygon({{p0[0], p0[1]}, {p1[0], p1[1]}, {p2[0], p2[1]}}, svg::attr("fill", colour) + svg::attr("stroke", colour) + svg::attr("stroke-width", 0.3));
  }
  for (const auto& m : markers) {
    const auto p = screen(m.at);
    canvas.circle(p[0], p[1], m.radius, svg::attr("fill", svg::rgb(m.rgb)));
  }
  return canvas.str();
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
