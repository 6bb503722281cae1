// Certified solving: figures and the report section (experiments/solve_study.hpp).
#include "experiments/solve_study.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/vrep_ssi.hpp"
#include "float/rounding.hpp"
#include "io/json_io.hpp"
#include "solve/contact.hpp"
#include "solve/projection.hpp"
#include "fixtures/solve_examples.hpp"
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
  svg::Canvas s(2 * W + 3 * M, H + 20);
  s.title(title);
  // Left: the parameter domain.
  const double u0 = S.domain_lo(0), u1 = S.domain_hi(0), v0 = S.domain_lo(1), v1 = S.domain_hi(1);
  const int oy = 10;
  const auto px = [&](double u) { return M + (u - u0) / (u1 - u0) * W; };
  const auto py = [&](double v) { return oy + H - (v - v0) / (v1 - v0) * H; };
  s.rect(M, oy, W, H, svg::attr("fill", "#f7f7f7") + svg::attr("stroke", "black"));
  for (const auto& b : r.branches) {
    svg::Points pts;
    for (const auto& x : b.points) pts.emplace_back(px(x[0]), py(x[1]));
    s.polyline(pts, svg::attr("stroke-width", 2.5) + svg::attr("stroke", svg::palette(static_cast<std::size_t>(std::max(0, b.component)))));
  }
  for (const auto& p : r.special) {
    const double u = to_double((p.lo[0] + p.hi[0]) / 2), v = to_double((p.lo[1] + p.hi[1]) / 2);
    const char* fill = p.kind == "turning point" ? "#ff7f0e" : p.kind == "joint" ? "white" : "black";
    s.circle(px(u), py(v), 3.5, svg::attr("fill", fill) + svg::attr("stroke", "black"));
  }
  // Under each panel what it shows, wrapped to the panel's width.
  std::size_t below = s.text_block(M, oy + H + 16, "the surface's parameters (u, v) in [" + svg::num(u0) + ", " + svg::num(u1) + "] x [" +
                                                       svg::num(v0) + ", " + svg::num(v1) + "]", W);
  below += s.text_block(M, oy + H + 16 + 15.0 * static_cast<double>(below), "dots: ends (black), joints (white), turning points (orange)", W);
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
  s.rect(ox, oy, W, H, svg::attr("fill", "white") + svg::attr("stroke", "black"));
  const auto line = [&](const std::vector<std::array<double, 3>>& pts, const std::string& stroke, double width, bool dashed) {
    svg::Points q;
    for (const auto& p : pts) q.emplace_back(qx(p[0]), qy(p[1]));
    s.polyline(q, svg::attr("stroke-width", width) + svg::attr("stroke", stroke) + (dashed ? svg::attr("stroke-dasharray", "4,3") : ""));
  };
  for (const auto& e : boundary(S)) line(e, "black", 1, false);
  line(curve_points(C), "#888888", 1.5, true);
  for (const auto& b : r.branches) {
    std::vector<std::array<double, 3>> pts;
    for (const auto& x : b.points) pts.push_back(at3(S, {x[0], x[1]}));
    line(pts, svg::palette(static_cast<std::size_t>(std::max(0, b.component))), 2.5, false);
  }
  below = std::max(below, s.text_block(ox, oy + H + 16, "top view (x, y): C dashed, the projection coloured", W));
  s.set_height(oy + H + 8 + 15.0 * static_cast<double>(below));
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

namespace splinex {

namespace {

using R = Rational;

struct ProjectionCase {
  std::string name;
  BSpline<R> S;
  std::vector<R> P;
};

R pow2(int k) { return R(boost::multiprecision::mpz_int(1) << k); }

/// The parabolic cylinder z = x^2 and a point whose feet are x = 1/4, 1/4 + 2^-k and -(1/2 + 2^-k):
/// (x - p_x) + 2x(x^2 - p_z) = 0 is 2 (x - x1)(x - x2)(x - x3) for p_x = 2 x1 x2 x3,
/// p_z = (1 - 2 e2) / 2, e2 = x1 x2 + x1 x3 + x2 x3 (the roots sum to 0).
ProjectionCase separated(int k) {
  const R x1(1, 4), x2 = x1 + R(1) / pow2(k), x3 = -(x1 + x2);
  const R e2 = x1 * x2 + x1 * x3 + x2 * x3;
  return {"feet 2^-" + std::to_string(k) + " apart", quadric_patch(R(1), R(0), R(1)), {2 * x1 * x2 * x3, R(0), (1 - 2 * e2) / 2}};
}

std::vector<ProjectionCase> projection_suite() {
  const R e = R(1) / pow2(20);
  return {{"generic: bicubic bumps", cubic_bumps(), {R(7, 5), R(8, 5), R(3)}},
          {"rational: sphere, irrational foot", stereographic_sphere(), {R(1), R(1), R(0)}},
          {"near-degenerate: 2^-20 from the sphere's centre", stereographic_sphere(), {e, e, -e}},
          {"multiple root: paraboloid's focal point", quadric_patch(R(1), R(1), R(1)), {R(0), R(0), R(1, 2)}},
          {"root on a knot line (C^2)", symmetric_knotted(), {R(0), R(1, 2), R(3)}},
          separated(10),
          separated(30)};
}

/// Max-norm distance of x from the box [lo, hi], exactly.
R box_distance(const std::vector<R>& lo, const std::vector<R>& hi, const std::vector<R>& x) {
  R d(0);
  for (std::size_t l = 0; l < x.size(); ++l) {
    const R g = x[l] < lo[l] ? R(lo[l] - x[l]) : hi[l] < x[l] ? R(x[l] - hi[l]) : R(0);
    if (d < g) d = g;
  }
  return d;
}

struct FloatJudgement {
  std::size_t found = 0, matched = 0, missed = 0, spurious = 0, in_undecided = 0;
  double max_error = 0, max_residual = 0, ms = 0;
};

/// Float stationary points (u, v) judged against the certified interior critical points.
FloatJudgement judge(const ProjectionCase& c, const ProjectionResult<R>& cert, const std::vector<std::array<double, 2>>& pts, double ms) {
  FloatJudgement j;
  j.found = pts.size();
  j.ms = ms;
  const R size = std::max(R(c.S.domain_hi(0) - c.S.domain_lo(0)), R(c.S.domain_hi(1) - c.S.domain_lo(1)));
  const R tol = size / R(1000000);
  std::vector<const CriticalPoint<R>*> roots;
  for (const auto& p : cert.critical)
    if (p.where == "interior") roots.push_back(&p);
  // A root's own tolerance: tol, and at most half its distance to the nearest other root (a float
  // point between two close roots approximates neither).
  std::vector<R> own(roots.size(), tol);
  for (std::size_t i = 0; i < roots.size(); ++i)
    for (std::size_t k = 0; k < roots.size(); ++k)
      if (k != i) {
        const R d = std::max(box_distance(roots[k]->lo, roots[k]->hi, roots[i]->lo), box_distance(roots[k]->lo, roots[k]->hi, roots[i]->hi)) / 2;
        if (d < own[i]) own[i] = d;
      }
  std::vector<bool> used(roots.size(), false);
  for (const auto& x : pts) {
    const std::vector<R> xr{exact_from_double(x[0], "u"), exact_from_double(x[1], "v")};
    std::size_t best = roots.size();
    R bd(-1);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      const R d = box_distance(roots[i]->lo, roots[i]->hi, xr);
      if (bd < 0 || d < bd) bd = d, best = i;
    }
    if (best < roots.size() && !(own[best] < bd) && !used[best]) {
      used[best] = true;
      ++j.matched;
      j.max_error = std::max(j.max_error, to_double(bd));
      // The exact residual of Eq. 3 at the float point: (S - P).S_u and (S - P).S_v.
      const auto s = evaluate(c.S, xr), su = derivative(c.S, xr, {1, 0}), sv = derivative(c.S, xr, {0, 1});
      R fu(0), fv(0);
      for (int k = 0; k < 3; ++k) {
        fu += (s[k] - c.P[k]) * su[k];
        fv += (s[k] - c.P[k]) * sv[k];
      }
      j.max_residual = std::max({j.max_residual, std::abs(to_double(fu)), std::abs(to_double(fv))});
      continue;
    }
    bool undecided = false;
    for (const auto& u : cert.undecided) undecided = undecided || box_distance(u.lo, u.hi, xr) <= tol;
    (undecided ? j.in_undecided : j.spurious) += 1;
  }
  for (bool u : used) j.missed += u ? 0 : 1;
  return j;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// What the parts of the section share: report.md's part, solve.csv, the section's own checks and
// the certified solver's options.
struct SolveReport {
  explicit SolveReport(ReportContext& c) : ctx(c) { deep.max_depth = 64; }
  ReportContext& ctx;
  std::ostringstream md, csv;
  std::ostringstream rows;  // the projection table's
  bool ok = true;
  SolveOptions deep;  // boxes down to 2^-64 of the domain: roots 2^-40 apart are separated
};

// A projection case certified, then by the double subdivision and by Newton from 16 x 16 and
// 64 x 64 grids, each judged against the certified roots: a row of solve.csv (and of the table).
std::array<FloatJudgement, 3> projection_row(SolveReport& rep, const ProjectionCase& c, bool table) {
  rep.ctx.progress("solve: projection, " + c.name);
  auto t0 = std::chrono::steady_clock::now();
  const auto cert = project_point(c.S, c.P, rep.deep);
  const double ms_exact = ms_since(t0);
  const auto Sd = round_spline<double>(c.S, "surface");
  const std::vector<double> Pd{to_double(c.P[0]), to_double(c.P[1]), to_double(c.P[2])};
  t0 = std::chrono::steady_clock::now();
  const auto sub = project_point(Sd, Pd);
  const double ms_sub = ms_since(t0);
  std::vector<std::array<double, 2>> sub_pts;
  for (const auto& p : sub.critical)
    if (p.where == "interior") sub_pts.push_back({(p.lo[0] + p.hi[0]) / 2, (p.lo[1] + p.hi[1]) / 2});
  const auto js = judge(c, cert, sub_pts, ms_sub);
  t0 = std::chrono::steady_clock::now();
  const auto g16 = project_point_sampled(Sd, {Pd[0], Pd[1], Pd[2]}, 16);
  const auto j16 = judge(c, cert, g16, ms_since(t0));
  t0 = std::chrono::steady_clock::now();
  const auto g64 = project_point_sampled(Sd, {Pd[0], Pd[1], Pd[2]}, 64);
  const auto j64 = judge(c, cert, g64, ms_since(t0));
  std::size_t interior = 0, exact = 0;
  for (const auto& p : cert.critical)
    if (p.where == "interior") {
      ++interior;
      exact += p.exact;
    }
  std::ostringstream row;
  row << std::setprecision(3);
  row << "| " << c.name << " | " << interior << " (" << exact << ") / " << cert.undecided.size() << " | " << ms_exact << " | " << js.found << " / "
      << js.missed << " / " << js.spurious << ", " << js.max_error << " | " << js.ms << " | " << j16.found << " / " << j16.missed << " / " << j16.spurious
      << ", " << j16.max_error << ", " << j16.max_residual << " | " << j16.ms << " | " << j64.missed << " / " << j64.spurious << " | " << j64.ms << " |\n";
  if (table) rep.rows << row.str();
  rep.csv << "\"" << c.name << "\"," << interior << "," << exact << "," << cert.undecided.size() << "," << ms_exact << "," << js.found
          << "," << js.missed << "," << js.spurious << "," << js.max_error << "," << js.ms << "," << j16.found << "," << j16.missed << ","
          << j16.spurious << "," << j16.max_error << "," << j16.max_residual << "," << j16.ms << "," << j64.missed << "," << j64.spurious
          << "," << j64.ms << "\n";
  return std::array<FloatJudgement, 3>{js, j16, j64};
}

// The separation family: the feet 2^-k apart, k = 2 .. 40.
void separation_part(SolveReport& rep) {
  PlotSeries sm{"double subdivision", {}, svg::palette(0)}, s16{"Newton 16 x 16", {}, svg::palette(1)}, s64{"Newton 64 x 64", {}, svg::palette(2)};
  std::size_t certified_all = 0, family = 0;
  for (int k = 2; k <= 40; k += 2) {
    const auto c = separated(k);
    const auto cert = project_point(c.S, c.P, rep.deep);
    std::size_t exact = 0;
    for (const auto& p : cert.critical) exact += p.where == "interior" && p.exact && p.unique;
    certified_all += exact == 3 ? 1 : 0;
    ++family;
    const auto j = projection_row(rep, c, false);
    sm.points.push_back({double(k), double(j[0].missed)});
    s16.points.push_back({double(k), double(j[1].missed)});
    s64.points.push_back({double(k), double(j[2].missed)});
  }
  rep.ok = rep.ok && certified_all == family;
  rep.md << ReportTemplate("solve.separation").set("certified", certified_all).set("cases", family).render();
  write_file_atomically(rep.ctx.options.out_dir + "/solve_separation.svg",
                        svg_line_plot({"Stationary points 2^-k apart: missed by the float solvers", "k (the feet are 2^-k apart)", "missed (of 3)", false, false,
                                       "the certified solver finds all three exactly for every k"},
                                      {sm, s16, s64}));
}

// Contact: the exact sphere and its reflected copy.
void contact_part(SolveReport& rep) {
  auto& md = rep.md;
  rep.ctx.progress("solve: contact, two spheres");
  const auto S1 = stereographic_sphere();
  auto S2 = S1;
  for (std::size_t i = 0; i < S2.size(); ++i) {
    S2.points[3 * i] = R(3, 2) - S2.points[3 * i];
    S2.points[3 * i + 1] = R(3, 2) - S2.points[3 * i + 1];
  }
  auto t0 = std::chrono::steady_clock::now();
  const auto cert = surface_distance(S1, S2);
  const double ms_exact = ms_since(t0);
  t0 = std::chrono::steady_clock::now();
  const auto dbl = surface_distance(round_spline<double>(S1, "first"), round_spline<double>(S2, "second"));
  const double ms_double = ms_since(t0);
  const R d = exact_from_double(dbl.distance2_hi, "d2");
  const R err = d < cert.distance2_lo ? R(cert.distance2_lo - d) : cert.distance2_hi < d ? R(d - cert.distance2_hi) : R(0);
  md << ReportTemplate("solve.contact")
            .set("d2_lo", fmt(to_double(cert.distance2_lo), 17))
            .set("d2_hi", fmt(to_double(cert.distance2_hi), 17))
            .set("width", fmt(to_double(R(cert.distance2_hi - cert.distance2_lo))))
            .when("closest_certified", cert.closest_certified)
            .set("pairs_solved", cert.pairs_solved)
            .set("strata_pairs", cert.strata_pairs)
            .set("ms_exact", fmt(ms_exact))
            .set("ms_double", fmt(ms_double))
            .set("d2_error", fmt(to_double(err)))
            .render();
  rep.ok = rep.ok && cert.closest_certified;
  rep.csv << "\"contact: spheres\",,,," << ms_exact << ",,,," << to_double(err) << "," << ms_double << ",,,,,,,,,\n";
}

// Figure 12: a circle projected onto a saddle, then around the teapot's body.
void curve_projection_part(SolveReport& rep) {
  auto& md = rep.md;
  auto& ok = rep.ok;
  rep.ctx.progress("solve: Figure 12, a circle projected onto a saddle");
  const auto S = quadric_patch(R(1, 8), R(-1), R(2)), C = rational_circle(R(13, 5), R(1, 2));
  auto t0 = std::chrono::steady_clock::now();
  const auto r = project_curve(C, S);
  const double ms = ms_since(t0);
  write_file_atomically(rep.ctx.options.out_dir + "/solve_figure12.svg",
                        curve_projection_svg(C, S, r, "Figure 12's situation: a circle (radius 13/5, z = 1/2) projected onto z = (x^2 - y^2)/8"));
  write_file_atomically(rep.ctx.options.out_dir + "/solve_figure12.obj", curve_projection_obj(C, S, r));
  ok = ok && r.segments == 4 && r.certified_counts && r.consistent;
  // The same circle around the teapot's body (real data: 48 pairs of pieces, seams, knot lines),
  // once turned by the rational angle (3/5, 4/5), once starting on the body's seam (angle 0).
  rep.ctx.progress("solve: a circle projected onto the teapot's body");
  const auto body = teapot_surface("body");
  auto turned = C;
  for (std::size_t i = 0; i < turned.size(); ++i) {
    const R x = turned.points[3 * i], y = turned.points[3 * i + 1];
    turned.points[3 * i] = R(3, 5) * x - R(4, 5) * y;
    turned.points[3 * i + 1] = R(4, 5) * x + R(3, 5) * y;
  }
  std::string circles;
  for (const BSpline<R>* c : {static_cast<const BSpline<R>*>(&turned), &C}) {
    t0 = std::chrono::steady_clock::now();
    const auto rb = project_curve(*c, body);
    circles += ReportTemplate("solve.teapot-circle")
                   .when("on_seam", c == &C)
                   .set("segments", rb.segments)
                   .set("loops", rb.loops)
                   .set("special_points", rb.special.size())
                   .set("undecided", rb.undecided.size())
                   .when("counts_certified", rb.certified_counts)
                   .when("consistent", rb.consistent)
                   .set("ms", fmt(ms_since(t0)))
                   .render();
    if (c == &turned) ok = ok && rb.certified_counts && rb.consistent;
  }
  md << ReportTemplate("solve.figure12")
            .set("segments", r.segments)
            .set("loops", r.loops)
            .set("end_points", r.special.size())
            .when("counts_certified", r.certified_counts)
            .when("consistent", r.consistent)
            .set("traced_points", r.traced_points)
            .set("max_cosine", fmt(r.max_cosine, 2))
            .set("ms", fmt(ms))
            .set("teapot_circles", circles)
            .render();
}

}  // namespace

void solve_section(ReportContext& ctx) {
  SolveReport rep(ctx);
  rep.csv << "case,certified_interior,certified_exact,undecided,ms_exact,sub_found,sub_missed,sub_spurious,sub_max_error,ms_sub,"
           "grid16_found,grid16_missed,grid16_spurious,grid16_max_error,grid16_max_residual,ms_grid16,grid64_missed,grid64_spurious,ms_grid64\n";
  for (const auto& c : projection_suite()) projection_row(rep, c, true);
  rep.md << ReportTemplate("solve").set("rows", rep.rows.str()).render();
  separation_part(rep);
  contact_part(rep);
  curve_projection_part(rep);
  rep.md << ReportTemplate("solve.data").render();
  write_file_atomically(ctx.options.out_dir + "/solve.csv", rep.csv.str());
  ctx.markdown["solve"] = rep.md.str();
  ctx.ok = ctx.ok && rep.ok;
}

}  // namespace splinex
