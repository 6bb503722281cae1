#include "experiments/tolerance_study.hpp"
#include "experiments/section.hpp"

#include <cmath>
#include <iomanip>
#include <algorithm>
#include <map>
#include <sstream>

#include "exact/rational.hpp"
#include "exact/root_isolation.hpp"
#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/svg_plot.hpp"
#include "untrim/trimming_polyline.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"

namespace splinex {

namespace {

// The polyline as the graph r = h(t) over t in [0, 1]: a degree-1 spline with knots at the
// vertices' t (exact values of the doubles). Throws when the polyline is not such a graph.
BSpline<Rational> polyline_graph(const std::vector<Segment2<double>>& poly) {
  std::vector<std::pair<Rational, Rational>> v;  // (t, r)
  for (const auto& s : poly)
    for (const auto& p : {s.a, s.b}) v.emplace_back(exact_from_double(p[1]), exact_from_double(p[0]));
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  for (std::size_t i = 1; i < v.size(); ++i)
    if (v[i].first == v[i - 1].first) throw std::logic_error("tolerance study: the polyline is not a graph over t");
  if (v.size() != poly.size() + 1 || v.front().first != 0 || v.back().first != 1)
    throw std::logic_error("tolerance study: the polyline does not span t in [0, 1] as one graph");
  std::vector<Rational> U{v.front().first}, r;
  for (const auto& tr : v) {
    U.push_back(tr.first);
    r.push_back(tr.second);
  }
  U.push_back(v.back().first);
  return make_spline<Rational>({1}, {U}, 1, std::move(r));
}


// max_c |P(r)_c - T(S(r))_c|, exactly: what evaluating r with the patch P costs.
Rational patch_error(const TrimmedPatch<Rational>& P, const BSpline<Rational>& T, const BSpline<Rational>& S,
                     const std::vector<Rational>& r) {
  const auto bad = evaluate_patch(P, r);
  const auto good = evaluate(T, evaluate(S, r));
  Rational worst(0);
  for (std::size_t c = 0; c < good.size(); ++c) worst = std::max(worst, Rational(abs(Rational(bad[c] - good[c]))));
  return worst;
}

// The patch of the same inner piece on the other side of the (single) crossed knot.
std::size_t other_patch(const TrimmedComposition<Rational>& C, std::size_t k) {
  for (std::size_t j = 0; j < C.patches.size(); ++j)
    if (j != k && C.patches[j].inner_piece == C.patches[k].inner_piece) return j;
  throw std::logic_error("tolerance study: no patch across the knot");
}

std::string g(double v) { return fmt(v, 4); }

// A trivariate S crossing a knot plane of a trivariate T: the misassigned volume and the error.
std::string volume_case(const std::string& out_dir, const std::function<void(const std::string&)>& progress, bool& ok) {
  const int p = 3;
  const Rational u0(1, 2);
  // S: degrees (1, 2, 2) with s_u = 1/5 + 3/5 r + 1/5 t(1-t) + 1/5 w(1-w), s_v = 1/10 + 4/5 t,
  // s_w = 1/10 + 4/5 w: the trimming surface s_u = 1/2 is r*(t, w) = 1/2 - t(1-t)/3 - w(1-w)/3.
  const auto S = bezier_from<Rational>({1, 2, 2}, 3, [](const std::vector<std::size_t>& ijl) {
    const long i = static_cast<long>(ijl[0]), j = static_cast<long>(ijl[1]), l = static_cast<long>(ijl[2]);
    return std::vector<Rational>{Rational(1, 5) + Rational(3, 5) * i + (j == 1 ? Rational(1, 10) : Rational(0)) +
                                     (l == 1 ? Rational(1, 10) : Rational(0)),
                                 Rational(1, 10) + Rational(2, 5) * j, Rational(1, 10) + Rational(2, 5) * l};
  });
  auto rstar = [](const Rational& t, const Rational& w) {
    return Rational(1, 2) - t * (1 - t) / 3 - w * (1 - w) / 3;
  };
  // r* in Bernstein form on [0,1]^2
  const auto rs = bezier_from<Rational>({2, 2}, 1, [](const std::vector<std::size_t>& jl) {
    return std::vector<Rational>{Rational(1, 2) - (jl[0] == 1 ? Rational(1, 6) : Rational(0)) -
                                 (jl[1] == 1 ? Rational(1, 6) : Rational(0))};
  });
  // Float trimming surface: a height field r = h(t, w) on a G x G grid (G a power of two, so the
  // nodes are exact doubles), the crossing bisected in double at each node to eps (midpoint of the
  // last bracket), bilinear in between. G is the smallest power of two with the interpolation
  // error h^2/8 (|r*_tt| + |r*_ww|) = h^2/6 <= eps/2, so the surface stays within eps of r*.
  struct Level {
    double eps;
    int G;
    BSpline<Rational> h;
    AbsIntegral<Rational> volume;
  };
  std::vector<Level> levels;
  for (double eps : {1e-2, 1e-3, 1e-4}) {
    progress("tolerance study (volume): trimming surface for eps " + g(eps));
    int G = 1;
    while (1.0 / (static_cast<double>(G) * G) / 6 > eps / 2) G *= 2;
    std::vector<Rational> K{0};
    for (int i = 0; i <= G; ++i) K.push_back(Rational(i, G));
    K.push_back(1);
    const auto h = spline_from<Rational>({1, 1}, {K, K}, 1, [&](const std::vector<std::size_t>& jl) {
        const double t = static_cast<double>(jl[0]) / G, w = static_cast<double>(jl[1]) / G;
        auto su = [&](double r) { return 0.2 + 0.6 * r + 0.2 * t * (1 - t) + 0.2 * w * (1 - w) - 0.5; };
        double a = 0, b = 1;
        while (b - a >= eps) {
          const double mid = 0.5 * (a + b);
          (su(mid) < 0 ? a : b) = mid;
        }
        return std::vector<Rational>{exact_from_double(0.5 * (a + b))};
    });
    auto vol = integrate_abs(difference(h, rs), 8, Rational(1, 100));
    levels.push_back({eps, G, std::move(h), std::move(vol)});
  }
  auto h_at = [](const Level& L, const Rational& t, const Rational& w) { return evaluate(L.h, {t, w})[0]; };
  std::ostringstream csv, md;
  csv << "multiplicity,eps,grid,misassigned_volume_lower,misassigned_volume_upper,undecided_cells,max_abs_error\n"
      << std::setprecision(17);
  std::vector<PlotSeries> series;
  for (int m = 1; m <= p + 1; ++m) {
    progress("tolerance study (volume): knot multiplicity " + std::to_string(m));
    const auto T = spline_from<Rational>({p, 1, 1}, {knots_with(p, u0, m), {0, 0, 1, 1}, {0, 0, 1, 1}}, 2,
                                         [](const std::vector<std::size_t>& ijl) {
                                           const std::size_t i = ijl[0], j = ijl[1], l = ijl[2];
                                           return std::vector<Rational>{
                                               Rational(static_cast<long>((i * i + 3 * j + l) % 7) - 3, 4),
                                               Rational(static_cast<long>((3 * i + j + 2 * l + 1) % 5), 3)};
                                         });
    const auto C = compose_trimmed(T, S);
    PlotSeries ps;
    ps.label = "trivariate, m = " + std::to_string(m);
    ps.color = svg::palette(m - 1);
    ps.dashed = true;
    std::string vol4;
    double err4 = 0;
    std::vector<std::pair<double, double>> vol_pts;
    for (const auto& L : levels) {
      Rational worst(0);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const Rational t(2 * a + 1, 8), w(2 * b + 1, 8);
          const Rational r0 = rstar(t, w), d = h_at(L, t, w) - r0;
          if (d == 0) continue;
          const std::size_t wrong = other_patch(C, C.locate({r0 + d / 2, t, w}));
          for (int s = 1; s <= 7; ++s)
            worst = std::max(worst, patch_error(C.patches[wrong], T, S, {r0 + d * Rational(s, 8), t, w}));
        }
      csv << m << "," << L.eps << "," << L.G << "," << to_double(L.volume.lower) << "," << to_double(L.volume.upper)
          << "," << L.volume.undecided << "," << to_double(worst) << "\n";
      if (worst > 0) ps.points.emplace_back(L.eps, to_double(worst));
      vol_pts.emplace_back(L.eps, to_double(L.volume.upper));
      if (L.eps == 1e-4) {
        err4 = to_double(worst);
        vol4 = "[" + g(to_double(L.volume.lower)) + ", " + g(to_double(L.volume.upper)) + "]";
      }
    }
    const double slope = loglog_slope(ps.points);
    ok = ok && std::fabs(slope - (p - m + 1)) <= 0.25;
    md << "| " << m << " | C^" << p - m << " | " << g(slope) << " | " << p - m + 1 << " | " << vol4 << " | "
       << g(loglog_slope(vol_pts)) << " | " << g(err4) << " |\n";
    series.push_back(std::move(ps));
  }
  write_file_atomically(out_dir + "/tolerance_volume.csv", csv.str());
  write_file_atomically(out_dir + "/tolerance_volume.svg",
                        svg_line_plot({"Trivariate composition error vs trimming-surface tolerance", "tolerance eps",
                                       "max |R_eps - T(S)| (exact)", true, true,
                                       "T degrees (3,1,1), knot plane of multiplicity m; height field within eps"},
                                      series));
  return ReportTemplate("tolerance.volume").set("rows", md.str()).render();
}

// The tolerances of the curve and the surface case (the surface case from 1e-9 up).
const std::vector<double> kEpsList{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};

// The curve case: a quadratic S crossing a knot of a cubic T, the trimming point found by float
// bisection to eps.
std::string curve_case(const std::string& out_dir, const std::function<void(const std::string&)>& progress, bool& ok) {
  const int p = 3;
  const Rational u0(1, 2);
  // S: a quadratic from 1/5 to 4/5 crossing u0 transversally at an irrational parameter.
  const auto S = bezier<Rational>({2}, 1, {Rational(1, 5), Rational(3, 10), Rational(4, 5)});
  // s(r) - u0 in power form: exact root r* isolated by CGAL.
  const auto bern = std::vector<Rational>{S.points[0] - u0, S.points[1] - u0, S.points[2] - u0};
  const auto roots = isolate_real_roots(bernstein_to_power(bern), 0, 1, 200);
  if (roots.size() != 1) throw std::logic_error("tolerance study: expected one crossing");
  const IsolatedRoot rstar = roots[0];
  std::ostringstream csv, md;
  csv << "multiplicity,continuity,eps,trimming_point,misassigned_length,max_abs_error\n" << std::setprecision(17);
  std::vector<PlotSeries> series;
  for (int m = 1; m <= p + 1; ++m) {
    progress("tolerance study: knot multiplicity " + std::to_string(m));
    const auto T = spline_from<Rational>({p}, {knots_with(p, u0, m)}, 2, [](const std::vector<std::size_t>& idx) {
      const std::size_t i = idx[0];
      return std::vector<Rational>{Rational(static_cast<long>(i * i % 7) - 3, 4), Rational(static_cast<long>((3 * i + 1) % 5), 3)};
    });
    const auto C = compose_trimmed(T, S);
    // The two pieces: the one left of the crossing owns [0, r*), the other [r*, 1].
    const std::size_t left = C.locate({Rational(0)});
    PlotSeries ps;
    ps.label = "m = " + std::to_string(m) + " (C^" + std::to_string(p - m) + ")";
    ps.color = svg::palette(m - 1);
    double at6 = 0;
    for (double eps : kEpsList) {
      // Float trimming: bisection in double on s(r) - u0 until the bracket is shorter than eps.
      auto sd = [&](double r) { return 0.2 * (1 - r) * (1 - r) + 2 * 0.3 * r * (1 - r) + 0.8 * r * r - 0.5; };
      double a = 0, b = 1;
      while (b - a >= eps) {
        const double mid = 0.5 * (a + b);
        (sd(mid) < 0 ? a : b) = mid;
      }
      const Rational re = exact_from_double(b);  // the far end: the boundary moves by up to eps
      // Misassigned interval [r*, re) (re > r*): exact length bounds from the isolating interval.
      const Rational len_hi = re - rstar.lo;  // upper bound of the misassigned length
      Rational worst(0);
      for (int s = 0; s <= 16; ++s) {
        const Rational r = rstar.hi + (re - rstar.hi) * Rational(s, 16);
        if (!(r < re)) continue;
        // The float structure evaluates r < re with the left piece; the truth is T(S(r)).
        worst = std::max(worst, patch_error(C.patches[left], T, S, {r}));
      }
      csv << m << "," << p - m << "," << eps << "," << b << "," << to_double(len_hi) << "," << to_double(worst) << "\n";
      if (worst > 0) ps.points.emplace_back(eps, to_double(worst));
      if (eps == 1e-6) at6 = to_double(worst);
    }
    const double slope = loglog_slope(ps.points);
    const int predicted = p - m + 1;
    ok = ok && std::fabs(slope - predicted) <= 0.25;
    md << "| " << m << " | C^" << p - m << " | " << g(slope) << " | " << predicted << " | " << g(at6) << " |\n";
    series.push_back(std::move(ps));
  }
  write_file_atomically(out_dir + "/tolerance.csv", csv.str());
  write_file_atomically(out_dir + "/tolerance.svg",
                        svg_line_plot({"Error of the composition vs trimming tolerance", "tolerance eps",
                                       "max |R_eps - T(S)| (exact)", true, true,
                                       "cubic T, knot of multiplicity m crossed by a quadratic S; slopes p-m+1"},
                                      series));
  return ReportTemplate("tolerance.curve").set("rows", md.str()).render();
}

// The surface case's polylines within eps of s_u = 1/2 and their misassigned areas, by eps: they do
// not depend on T, so they are computed once per eps.
std::map<double, std::pair<std::vector<Segment2<double>>, AbsIntegral<Rational>>> surface_polylines(
    const BSpline<double>& S2d, const std::function<void(const std::string&)>& progress) {
  std::map<double, std::pair<std::vector<Segment2<double>>, AbsIntegral<Rational>>> polylines;
  // r*(t) = 1/2 - t(1-t)/3: Bernstein coefficients 1/2, 1/3, 1/2 on [0, 1].
  const auto rs = bezier<Rational>({2}, 1, {Rational(1, 2), Rational(1, 3), Rational(1, 2)});
  for (double eps : kEpsList) {
    if (eps < 1e-9) continue;
    progress("tolerance study (surface): polyline and misassigned area for eps " + g(eps));
    TrimmingTolerance tol;
    tol.eps = eps;
    tol.grid = 8;
    auto poly = trace_level_set(S2d, 0, 0.5, tol);
    auto area = integrate_abs(difference(polyline_graph(poly), rs), 60, Rational(1, 1000000000));
    polylines.emplace(eps, std::make_pair(std::move(poly), std::move(area)));
  }
  return polylines;
}

// ---- The surface case: trimming polylines within eps --------------------------------------
std::string surface_case(const std::string& out_dir, const std::function<void(const std::string&)>& progress, bool& ok) {
  const int p = 3;
  const Rational u0(1, 2);
  // S: the parabola case (experiments/common.hpp); r*(t) is rational at rational t, which lets the
  // misassignment along the lines t = t_i be measured exactly.
  const BSpline<Rational> S2 = parabola_trimming_inner();
  const auto S2d = convert<double>(S2, [](const Rational& x) { return to_double(x); });
  const int L = 40;
  std::ostringstream csv2;
  csv2 << "multiplicity,eps,polyline_segments,max_misassigned_length,misassigned_area_lower,misassigned_area_upper,"
          "max_abs_error\n"
       << std::setprecision(17);
  std::ostringstream md2;
  const auto polylines = surface_polylines(S2d, progress);
  std::vector<PlotSeries> series2;
  for (int m = 1; m <= p + 1; ++m) {
    progress("tolerance study (surface): knot multiplicity " + std::to_string(m));
    const auto T = spline_from<Rational>({p, p}, {knots_with(p, u0, m), clamped_knots(p, Rational(0), Rational(1))}, 2,
                                         [](const std::vector<std::size_t>& ij) {
                                           const std::size_t i = ij[0], j = ij[1];
                                           return std::vector<Rational>{
                                               Rational(static_cast<long>((i * i + 3 * j) % 7) - 3, 4),
                                               Rational(static_cast<long>((3 * i + j * j + 1) % 5), 3)};
                                         });
    const auto C = compose_trimmed(T, S2);
    PlotSeries ps;
    ps.label = "surface, m = " + std::to_string(m);
    ps.color = svg::palette(m - 1);
    ps.dashed = true;
    double len6 = 0, err6 = 0;
    std::string area6;
    std::vector<std::pair<double, double>> area_pts;
    for (double eps : kEpsList) {
      if (eps < 1e-9) continue;
      const auto& poly = polylines.at(eps).first;
      const auto& area = polylines.at(eps).second;
      Rational worst(0), max_len(0);
      for (int li = 0; li < L; ++li) {
        const Rational t(2 * li + 1, 2 * L);
        const Rational rstar2 = (Rational(3, 10) - Rational(1, 5) * t * (1 - t)) / Rational(3, 5);
        const auto xs = crossings_at(poly, to_double(t));
        if (xs.empty()) throw std::logic_error("tolerance study: the polyline misses a line");
        double best = xs[0];
        for (double x : xs)
          if (std::fabs(x - to_double(rstar2)) < std::fabs(best - to_double(rstar2))) best = x;
        const Rational rp = exact_from_double(best), d = rp - rstar2;
        if (max_len < abs(d)) max_len = abs(d);
        if (d == 0) continue;
        // Points strictly between r* and r_poly take the other side's patch.
        const std::size_t wrong = other_patch(C, C.locate({rstar2 + d / 2, t}));
        for (int s = 1; s <= 15; ++s)
          worst = std::max(worst, patch_error(C.patches[wrong], T, S2, {rstar2 + d * Rational(s, 16), t}));
      }
      csv2 << m << "," << eps << "," << poly.size() << "," << to_double(max_len) << "," << to_double(area.lower) << ","
           << to_double(area.upper) << ","
           << to_double(worst) << "\n";
      if (worst > 0) ps.points.emplace_back(eps, to_double(worst));
      if (area.upper > 0) area_pts.emplace_back(eps, to_double(area.upper));
      if (eps == 1e-6) {
        len6 = to_double(max_len);
        err6 = to_double(worst);
        area6 = area.exact() ? g(to_double(area.lower)) : "[" + g(to_double(area.lower)) + ", " + g(to_double(area.upper)) + "]";
      }
    }
    const double slope = loglog_slope(ps.points);
    ok = ok && std::fabs(slope - (p - m + 1)) <= 0.25;
    md2 << "| " << m << " | C^" << p - m << " | " << g(slope) << " | " << p - m + 1 << " | " << g(len6) << " | " << area6
        << " | " << g(loglog_slope(area_pts)) << " | " << g(err6) << " |\n";
    series2.push_back(std::move(ps));
  }
  write_file_atomically(out_dir + "/tolerance_surface.csv", csv2.str());
  write_file_atomically(out_dir + "/tolerance_surface.svg",
                        svg_line_plot({"Surface composition error vs trimming-polyline tolerance", "tolerance eps",
                                       "max |R_eps - T(S)| (exact)", true, true,
                                       "bicubic T, knot of multiplicity m; polyline within eps of s_u = 1/2"},
                                      series2));
  return ReportTemplate("tolerance.surface").set("lines", L).set("rows", md2.str()).render();
}

}  // namespace

std::string run_tolerance_study(const std::string& out_dir, const std::function<void(const std::string&)>& progress, bool& ok) {
  std::ostringstream md;
  md << curve_case(out_dir, progress, ok);
  md << surface_case(out_dir, progress, ok);
  md << volume_case(out_dir, progress, ok);
  return md.str();
}

void tolerance_section(ReportContext& ctx) {
  ctx.markdown["tolerance"] = run_tolerance_study(ctx.options.out_dir, ctx.progress, ctx.ok);
}

}  // namespace splinex
