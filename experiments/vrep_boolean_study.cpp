// Report section `vrep-boolean` (issue 18, first part): Figure 3's union with the paper's counts
// from the program and CGAL's Nef polyhedra beside it, the summing colour blend of Figure 5 on four
// boxes, and the price of an IRIT-style tolerance in Booleans of nearly touching boxes, measured
// exactly (false glues, cells, the volume counted by the cells, and the misclassified volume of the
// point sets as an exact symmetric difference computed by CGAL's Nef polyhedra).
#include <array>
#include <chrono>
#include <random>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/vrep_figures.hpp"
#include "float/rounding.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/boolean/nef_check.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/blend.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_euler.hpp"
#include "vrep/topology/trimmed_glue.hpp"
#include "vrep/topology/trimmed_topology.hpp"

namespace splinex {

namespace {

VModel<Rational> exact_box(std::vector<Rational> lo, std::vector<Rational> hi) { return glue(box_cells<Rational>(lo, hi)); }

VModel<double> in_double(const VModel<Rational>& M, double eps) {
  std::vector<BSpline<double>> d;
  for (const auto& c : M.cells) d.push_back(round_spline<double>(M.trivariates[c.trivariates.front()]));
  return glue(d, eps);
}

VModel<Rational> in_exact(const VModel<double>& M) {
  std::vector<BSpline<Rational>> e;
  for (const auto& c : M.cells) e.push_back(convert<Rational>(M.trivariates[c.trivariates.front()], [](double x) { return exact_from_double(x); }));
  return glue(e);
}

Rational model_volume(const VModel<Rational>& M) {
  Rational v(0);
  for (std::size_t c = 0; c < M.cells.size(); ++c) v += cell_volume(M, c);
  return v;
}

std::string sci(double v) {
  std::ostringstream o;
  o << std::setprecision(2) << std::scientific << v;
  return o.str();
}

/// x > 0 to six significant decimal digits, rounded down (up: rounded up), exactly: an
/// enclosure's ends printed never narrower than it is.
std::string six_digits(const Rational& x, bool up) {
  if (!(Rational(0) < x)) return x == Rational(0) ? "0" : "-" + six_digits(-x, !up);
  Rational p(1);
  int k = 0;
  while (x * p < Rational(100000)) p *= 10, ++k;
  while (!(x * p < Rational(1000000))) p /= 10, --k;
  const Rational s = x * p;
  Integer m = numerator(s) / denominator(s);
  if (up && Rational(m) < s) m += 1;
  std::ostringstream o;
  o << std::setprecision(7) << to_double(Rational(m) / p);
  return o.str();
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Figures 4 and 15 and a Table 1 for trimmed cells on exact regions.
/// Per pair of leaves decided in exact arithmetic: the double run agrees (same arcs and loops),
/// is undecided, or is wrong (decided with other counts).
std::array<std::size_t, 3> compare_curves(const TrimmedCurves<Rational>& exact, const TrimmedCurves<double>& dbl) {
  std::array<std::size_t, 3> out{};
  for (const auto& p : exact.pairs) {
    if (!p.decided) continue;
    const TrimmedCurves<double>::Pair* q = nullptr;
    for (const auto& x : dbl.pairs)
      if (x.i == p.i && x.j == p.j) q = &x;
    if (q == nullptr) ++out[(p.arcs + p.loops == 0) ? 0 : 2];  // double saw no meeting at all
    else if (!q->decided) ++out[1];
    else ++out[(q->arcs == p.arcs && q->loops == p.loops) ? 0 : 2];
  }
  return out;
}

/// The V-curves of random cells (two balls and a half-space z >= h in the cube [0, 2]^3, centres,
/// radii and h in sixteenths), exact and on the region rounded to double.
void curves_sweep(std::ostringstream& md) {
  using R = Rational;
  const auto V = box_cells<R>({R(0), R(0), R(0)}, {R(2), R(2), R(2)}).front();
  const auto Vd = box_cells<double>({0, 0, 0}, {2, 2, 2}).front();
  std::mt19937 rng(20261204);
  std::uniform_int_distribution<int> pos(2, 30), rad(5, 18), height(4, 28);
  std::array<std::size_t, 3> total{};
  std::size_t undecided_exact = 0, pairs = 0, arcs = 0, loops = 0;
  std::map<std::string, std::size_t> reasons;  // of the pairs undecided in exact arithmetic
  double exact_s = 0, double_s = 0;
  // The half-V-surfaces (trimmed_topology: pieces per face and per trimming surface), the same way.
  std::array<std::size_t, 3> surf{};  // double agrees / undecided / wrong
  std::size_t surfaces = 0, surf_undecided = 0, surf_pieces = 0;
  std::map<std::string, std::size_t> surf_reasons;
  double surf_exact_s = 0, surf_double_s = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::array<R, 3> c0, c1;
    for (int e = 0; e < 3; ++e) {
      c0[e] = R(pos(rng), 16);
      c1[e] = R(pos(rng), 16);
    }
    Poly3<R> plane;
    plane.terms[{0, 0, 1}] = R(1);
    plane.terms[{0, 0, 0}] = -R(height(rng), 16);
    const R r0(rad(rng), 16), r1(rad(rng), 16);
    const auto region = region_and<R>({ball_region(c0, r0), ball_region(c1, r1), region_leaf(plane, "plane")});
    auto t0 = std::chrono::steady_clock::now();
    const auto ex = trimmed_curves(V, region);
    exact_s += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const auto db = trimmed_curves(Vd, region_to_double(region));
    double_s += seconds_since(t0);
    for (const auto& p : ex.pairs) {
      ++pairs;
      undecided_exact += !p.decided;
      if (!p.decided) ++reasons[p.undecided_reason];
      arcs += p.arcs;
      loops += p.loops;
    }
    const auto cmp = compare_curves(ex, db);
    for (int q = 0; q < 3; ++q) total[static_cast<std::size_t>(q)] += cmp[static_cast<std::size_t>(q)];
    t0 = std::chrono::steady_clock::now();
    const auto te = trimmed_topology(V, region, 1024);
    surf_exact_s += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const auto td = trimmed_topology(Vd, region_to_double(region), 1024);
    surf_double_s += seconds_since(t0);
    for (std::size_t i = 0; i < te.surfaces.size(); ++i) {
      const auto& e = te.surfaces[i];
      const auto& d = td.surfaces[i];
      if (e.collapsed) continue;
      ++surfaces;
      if (!e.decided) {
        ++surf_undecided;
        ++surf_reasons[e.undecided_reason];
        continue;
      }
      surf_pieces += e.pieces;
      ++surf[!d.decided ? 1 : d.pieces == e.pieces ? 0 : 2];
    }
  }
  auto list = [](const std::map<std::string, std::size_t>& why) {
    std::ostringstream o;
    for (auto it = why.begin(); it != why.end(); ++it) o << (it == why.begin() ? "" : "; ") << it->first << ": " << it->second;
    return o.str();
  };
  md << ReportTemplate("vrep-boolean.curves")
            .set("pairs", pairs)
            .set("pairs_undecided", undecided_exact)
            .when("pair_reasons", !reasons.empty())
            .set("pair_reasons", list(reasons))
            .set("arcs", arcs)
            .set("loops", loops)
            .set("pairs_agree", total[0])
            .set("pairs_double_undecided", total[1])
            .set("pairs_wrong", total[2])
            .when("pairs_fail_safe", total[2] == 0)
            .set("pairs_exact_s", fmt(exact_s))
            .set("pairs_double_s", fmt(double_s))
            .set("parts", surfaces)
            .set("parts_undecided", surf_undecided)
            .when("part_reasons", !surf_reasons.empty())
            .set("part_reasons", list(surf_reasons))
            .set("pieces", surf_pieces)
            .set("parts_agree", surf[0])
            .set("parts_double_undecided", surf[1])
            .set("parts_wrong", surf[2])
            .when("parts_wrong_any", surf[2] != 0)
            .set("parts_exact_s", fmt(surf_exact_s))
            .set("parts_double_s", fmt(surf_double_s))
            .render();
}

/// The gluing of trimmed cells into one V-model (trimmed_glue), exact and in double, with the time
/// it takes: Table 1's gluing column for trimmed models.
void glue_part(ReportContext& ctx, std::ostringstream& md, const TrimmedModel<Rational>& figure4, const TrimmedModel<Rational>& figure15) {
  using R = Rational;
  ctx.progress("V-rep Booleans: gluing trimmed cells");
  auto box = [](std::vector<R> lo, std::vector<R> hi) { return as_trimmed(glue(box_cells<R>(lo, hi)), box_region<R>(lo, hi)); };
  struct G {
    std::string name;
    TrimmedModel<R> model;
    std::string expected;  // counted by hand, where done
  };
  std::vector<G> models;
  models.push_back({"Figure 3 through the trimmed path (O1 u O2)",
                    trimmed_boolean(box({R(0), R(0), R(0)}, {R(2), R(1), R(1)}), box({R(1), R(0), R(0)}, {R(2), R(2), R(1)}), BooleanOp::unite),
                    "14 + 2 (the paper's counts)"});
  models.push_back({"box [0,2]x[0,1]^2 u cylinder r 1/3 along x through it",
                    trimmed_boolean(box({R(0), R(0), R(0)}, {R(2), R(1), R(1)}),
                                    placed_primitive(cylinder_cells<R>(R(1, 3), R(3)), cylinder_region<R>(R(1, 3), R(3)), 0, {R(-1, 2), R(1, 2), R(1, 2)}),
                                    BooleanOp::unite),
                    "24 + 27 (docs/vrep/topology.md)"});
  models.push_back({"Figure 4 (cone u cylinder)", figure4, ""});
  models.push_back({"Figure 15's kind", figure15, "18 + 14 (docs/vrep/topology.md)"});
  std::ostringstream rows;
  TrimmedGlueOptions go;
  go.max_boxes = 2048;
  for (const auto& m : models) {
    auto t0 = std::chrono::steady_clock::now();
    const auto e = trimmed_glue(m.model, go);
    const double es = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const auto d = trimmed_glue(trimmed_to_double(m.model), go);
    const double ds = seconds_since(t0);
    const bool same = e.decided == d.decided && e.boundary_v_surfaces == d.boundary_v_surfaces && e.internal_v_surfaces == d.internal_v_surfaces;
    std::size_t undecided_twins = 0, undecided_halves = 0;
    for (const auto& t : e.twins) undecided_twins += !t.decided;
    for (const auto& h : e.halves) undecided_halves += !h.decided;
    rows << "| " << m.name << " | " << m.model.cells.size() << " | " << e.half_v_surfaces << " | " << e.boundary_v_surfaces << " + " << e.internal_v_surfaces
       << " (" << e.internal_v_surfaces - e.contacts << " / " << e.contacts << ") | "
       << (e.decided ? "yes" : "no: " + std::to_string(undecided_halves) + " halves, " + std::to_string(undecided_twins) + " contacts undecided")
       << " | " << (m.expected.empty() ? "-" : m.expected) << " | " << std::setprecision(3) << es << " | " << d.boundary_v_surfaces << " + "
       << d.internal_v_surfaces << ", " << (d.decided ? "yes" : "no") << " | " << ds << " | "
       << (same ? "same" : e.decided && d.decided ? "**differs, both decided: wrong in double**" : "differs") << " |\n";
    if (!m.expected.empty() && e.decided) {
      const std::string got = std::to_string(e.boundary_v_surfaces) + " + " + std::to_string(e.internal_v_surfaces);
      if (m.expected.rfind(got, 0) != 0) {
        ctx.ok = false;
        rows << ReportTemplate("vrep-boolean.glue.check-failed").set("model", m.name).set("got", got).set("expected", m.expected).render();
      }
    }
  }
  md << ReportTemplate("vrep-boolean.glue").set("rows", rows.str()).render();
}

// A model of the trimmed part: its Boolean exactly and in double, with the times and chi's check.
struct TrimmedCase {
  std::string name;
  TrimmedModel<Rational> model;
  double exact_s = 0, double_s = 0;
  std::size_t double_cells = 0;
  std::string double_note;
  std::string euler;  // the model's chi and its check
};

// chi of a model's point set, exactly (model_euler), with its verdict.
long chi_of(const TrimmedModel<Rational>& M, bool& fine) {
  const auto e = model_euler(M);
  fine = fine && e.decided && e.duality;
  return e.image_chi;
}

// Figure 4: cone union a cylinder through it.
TrimmedCase figure4_case(ReportContext& ctx) {
  using R = Rational;
  const auto cone = placed_primitive(cone_cells<R>(R(1), R(1, 2), R(2)), cone_region<R>(R(1), R(1, 2), R(2)), 2, {R(0), R(0), R(0)});
  const auto cyl = placed_primitive(cylinder_cells<R>(R(1, 3), R(3)), cylinder_region<R>(R(1, 3), R(3)), 0, {R(-3, 2), R(0), R(1)});
  TrimmedCase c;
  c.name = "Figure 4: cone (r 1 to 1/2, h 2) union cylinder (r 1/3, along x at z = 1)";
  auto t0 = std::chrono::steady_clock::now();
  c.model = trimmed_boolean(cone, cyl, BooleanOp::unite);
  c.exact_s = seconds_since(t0);
  {
    bool fine = true;
    const long a = chi_of(cone, fine), b = chi_of(cyl, fine), u = chi_of(c.model, fine), i = chi_of(trimmed_boolean(cone, cyl, BooleanOp::intersect), fine);
    const bool holds = fine && u == a + b - i;
    ctx.ok = ctx.ok && holds;
    c.euler = ReportTemplate("vrep-boolean.euler.figure4")
                  .set("union", u)
                  .set("cone", a)
                  .set("cylinder", b)
                  .set("intersection", i)
                  .when("holds", holds)
                  .render();
  }
  t0 = std::chrono::steady_clock::now();
  try {
    c.double_cells = trimmed_boolean(trimmed_to_double(cone), trimmed_to_double(cyl), BooleanOp::unite, Blend::sum_clipped, {}, 1e-12).cells.size();
  } catch (const Error& e) {
    c.double_note = e.what();
  }
  c.double_s = seconds_since(t0);
  return c;
}

// Figure 15's kind of solid: a base plate and a post united, then two holes subtracted.
TrimmedCase figure15_case(ReportContext& ctx) {
  using R = Rational;
  const auto base = placed_primitive(box_cells<R>({-2, -2, 0}, {2, 2, 1}), box_region<R>({-2, -2, 0}, {2, 2, 1}), 2, {R(0), R(0), R(0)});
  const auto post = placed_primitive(cylinder_cells<R>(R(1), R(3)), cylinder_region<R>(R(1), R(3)), 2, {R(0), R(0), R(0)});
  const auto hole1 = placed_primitive(cylinder_cells<R>(R(1, 4), R(3)), cylinder_region<R>(R(1, 4), R(3)), 2, {R(3, 2), R(3, 2), R(-1)});
  const auto hole2 = placed_primitive(cylinder_cells<R>(R(1, 4), R(3)), cylinder_region<R>(R(1, 4), R(3)), 2, {R(-3, 2), R(-3, 2), R(-1)});
  TrimmedCase c;
  c.name = "Figure 15's kind: (plate union post) - hole - hole";
  auto t0 = std::chrono::steady_clock::now();
  c.model = trimmed_boolean(trimmed_boolean(trimmed_boolean(base, post, BooleanOp::unite), hole1, BooleanOp::subtract), hole2, BooleanOp::subtract);
  {
    bool fine = true;
    const auto P = trimmed_boolean(base, post, BooleanOp::unite);
    const long p = chi_of(P, fine), p1 = chi_of(trimmed_boolean(P, hole1, BooleanOp::subtract), fine), p2 = chi_of(c.model, fine);
    const bool holds = fine && p == 1 && p1 == 0 && p2 == -1;
    ctx.ok = ctx.ok && holds;
    c.euler = ReportTemplate("vrep-boolean.euler.figure15").set("plate_post", p).set("one_hole", p1).set("two_holes", p2).when("holds", holds).render();
  }
  c.exact_s = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  try {
    const auto d = trimmed_boolean(trimmed_boolean(trimmed_boolean(trimmed_to_double(base), trimmed_to_double(post), BooleanOp::unite, Blend::sum_clipped, {}, 1e-12),
                                                   trimmed_to_double(hole1), BooleanOp::subtract, Blend::sum_clipped, {}, 1e-12),
                                   trimmed_to_double(hole2), BooleanOp::subtract, Blend::sum_clipped, {}, 1e-12);
    c.double_cells = d.cells.size();
  } catch (const Error& e) {
    c.double_note = e.what();
  }
  c.double_s = seconds_since(t0);
  return c;
}

// The trimmed part's introduction and the models' table: V-cells by category and status, trivariates, the certified volume, the Booleans' times.
void models_table(std::ostringstream& md, const std::vector<TrimmedCase>& cases) {
  using R = Rational;
  std::ostringstream rows;
  for (const auto& c : cases) {
    std::map<std::string, std::size_t> cat;
    std::size_t whole = 0;
    std::map<std::string, std::size_t> sizes;
    std::vector<IntegrandCell<R>> integrands;
    for (const auto& x : c.model.cells) {
      ++cat[x.category];
      whole += x.status == Truth::in;
      const auto& V = c.model.trivariates[x.trivariate];
      // Appended to, not prepended: GCC 12 -O3 reports "(" + std::string&& here as -Wrestrict (a false positive).
      std::string key = "(";
      key += std::to_string(V.degrees[0]) + "," + std::to_string(V.degrees[1]) + "," + std::to_string(V.degrees[2]) + "), " +
             std::to_string(V.size());
      ++sizes[key];
      integrands.push_back({&V, &x.trim, nullptr});
    }
    // One adaptive run over every cell (integral_enclosures): the widest boxes refined first until
    // the model's volume is within 1% relative width or 4096 boxes per cell are spent.
    const auto E = integral_enclosures<R>(integrands, {}, R(1) / R(100), 4096);
    const R lo = E.total.lower, hi = E.total.upper;
    std::ostringstream sz;
    for (const auto& [k, n] : sizes) sz << (sz.tellp() > 0 ? "; " : "") << n << " x " << k;
    rows << "| " << c.name << " | " << c.model.cells.size() << " (" << cat["A"] << " / " << cat["both"] << " / " << cat["B"] << "; " << whole
       << " / " << c.model.cells.size() - whole << ") | " << sz.str() << " | [" << six_digits(lo, false) << ", " << six_digits(hi, true) << "] | " << std::setprecision(3) << c.exact_s << " / " << c.double_s << " | "
       << (c.double_note.empty() ? std::to_string(c.double_cells) : "refused: " + c.double_note) << " |\n";
  }
  md << ReportTemplate("vrep-boolean.trimmed").set("rows", rows.str()).render();
}

// One cell's row of the boundary-structure table: trimmed_topology, trimmed_curves (exact, and the
// double run on the model rounded to double, d), trimmed_euler, with their times.
void topology_row(std::ostringstream& md, const TrimmedCase& c, std::size_t k, const TrimmedModel<double>& d) {
  using R = Rational;
  const auto& x = c.model.cells[k];
  const auto t0 = std::chrono::steady_clock::now();
  const auto t = trimmed_topology(c.model.trivariates[x.trivariate], x.trim, 1024);
  std::size_t pieces = 0, points = 0, faces = 0, face_cover = 0, trims = 0, trim_cover = 0, odd = 0;
  for (const auto& e : t.edges) {
    pieces += e.pieces;
    points += e.points;
    odd += !e.status.is_certain() || e.status == TrimmedTopology<R>::Edge::on_trimming_surface;
  }
  std::size_t face_pieces = 0, trim_pieces = 0;
  std::string face_undecided, trim_undecided;
  for (const auto& sf : t.surfaces) {
    (sf.leaf < 0 ? faces : trims) += sf.at_least, (sf.leaf < 0 ? face_cover : trim_cover) += sf.cover;
    if (sf.collapsed) continue;
    (sf.leaf < 0 ? face_pieces : trim_pieces) += sf.pieces;
    if (!sf.decided) (sf.leaf < 0 ? face_undecided : trim_undecided) = sf.undecided_reason;
  }
  std::size_t curves = 0, curve_cover = 0, exact_curves = 0;
  bool curves_decided = true;
  for (const auto& fc : t.face_curves) {
    curves += fc.at_least, curve_cover += fc.cover;
    exact_curves += fc.arcs + fc.loops;
    curves_decided = curves_decided && fc.decided;
  }
  md << "| " << (k == 0 ? c.name.substr(0, c.name.find(':')) : "") << " | " << k << " (" << (x.category.empty() ? "input" : x.category) << ") | " << t.corners << " | " << pieces
     << (odd ? " (" + std::to_string(odd) + " edges on a trimming surface or undecided)" : "") << " | " << points << " | " << t.face_points << " / "
     << t.interior_points << (t.points_undecided ? " (" + std::to_string(t.points_undecided) + ")" : "") << " | " << faces << " ("
     << face_cover << "; exact: " << (face_undecided.empty() ? std::to_string(face_pieces) : "undecided: " + face_undecided) << ") | " << trims << " (" << trim_cover << "; exact: " << (trim_undecided.empty() ? std::to_string(trim_pieces) : "undecided: " + trim_undecided) << ") | " << curves << " (" << curve_cover << "; exact: " << (curves_decided ? std::to_string(exact_curves) : std::string("undecided")) << ") | " << std::setprecision(3)
     << seconds_since(t0) << " | ";
  const auto tc = std::chrono::steady_clock::now();
  const auto cv = trimmed_curves(c.model.trivariates[x.trivariate], x.trim);
  if (cv.decided) md << cv.arcs << " / " << cv.loops;
  else {
    std::string why;
    for (const auto& p : cv.pairs)
      if (!p.decided) why = p.undecided_reason;
    md << cv.arcs << " / " << cv.loops << " (decided pairs; undecided: " << why << ")";
  }
  md << " | " << std::setprecision(3) << seconds_since(tc) << " | ";
  {
    const auto cd = trimmed_curves(d.trivariates[x.trivariate], d.cells[k].trim);
    const auto cmp = compare_curves(cv, cd);
    md << cmp[0] << " / " << cmp[1] << " / " << cmp[2] << " | ";
  }
  const auto t1 = std::chrono::steady_clock::now();
  const auto eu = trimmed_euler(c.model.trivariates[x.trivariate], x.trim);
  if (eu.decided) md << eu.chi << " / " << eu.image_chi << (eu.duality ? ", dual" : ", not dual");
  else md << "undecided: " << eu.undecided_reason;
  md << " | " << std::setprecision(3) << seconds_since(t1) << " |\n";
}

// The boundary structure of every cell (trimmed_topology): exact on the edges, lower bounds on
// the half-V-surfaces.
void topology_table(std::ostringstream& md, const std::vector<TrimmedCase>& cases) {
  std::ostringstream rows;
  std::vector<TrimmedModel<double>> D;  // the cases rounded to double, for the curves' double run
  for (const auto& c : cases) D.push_back(trimmed_to_double(c.model));
  for (const auto& c : cases)
    for (std::size_t k = 0; k < c.model.cells.size(); ++k) topology_row(rows, c, k, D[&c - cases.data()]);
  md << ReportTemplate("vrep-boolean.topology").set("rows", rows.str()).render();
}

// The price of tolerance at a curved contact: the plane x = 1 + g against the cylinder r = 1.
void near_tangent_part(std::ostringstream& md) {
  using R = Rational;
  std::ostringstream rows;
  const auto cyl = placed_primitive(cylinder_cells<R>(R(1), R(2)), cylinder_region<R>(R(1), R(2)), 2, {R(0), R(0), R(0)});
  auto verdict = [](auto&& run) -> std::string {
    try {
      const auto M = run();
      std::size_t cut = 0;
      for (const auto& c : M.cells) cut += c.status != Truth::in;
      return std::to_string(M.cells.size()) + (M.cells.size() == 1 ? " cell (" : " cells (") + std::to_string(cut) + " cut)";
    } catch (const DomainError& e) {
      const std::string w = e.what();
      return w.find("tangential") != std::string::npos ? "refused: tangential" : w.find("empty") != std::string::npos ? "empty" : "refused";
    }
  };
  for (int sign : {-1, 0, 1})
    for (int k : {4, 10, 20, 30, 40}) {
      if (sign == 0 && k != 4) continue;
      const R g = sign == 0 ? R(0) : R(sign) / R(1LL << k);
      const auto box = placed_primitive(box_cells<R>({R(1) + g, R(-2), R(-1)}, {R(2), R(2), R(3)}),
                                       box_region<R>({R(1) + g, R(-2), R(-1)}, {R(2), R(2), R(3)}), 2, {R(0), R(0), R(0)});
      const std::string ex = verdict([&] { return trimmed_boolean(cyl, box, BooleanOp::intersect); });
      const std::string d12 = verdict([&] {
        return trimmed_boolean(trimmed_to_double(cyl), trimmed_to_double(box), BooleanOp::intersect, Blend::sum_clipped, {}, 1e-12);
      });
      const std::string d6 = verdict([&] {
        return trimmed_boolean(trimmed_to_double(cyl), trimmed_to_double(box), BooleanOp::intersect, Blend::sum_clipped, {}, 1e-6);
      });
      rows << "| " << (sign == 0 ? std::string("0") : std::string(sign < 0 ? "-" : "") + "2^-" + std::to_string(k)) << " | " << ex << " | " << d12
         << " | " << d6 << " |\n";
    }
  md << ReportTemplate("vrep-boolean.near-tangent").set("rows", rows.str()).render();
}

// Trimmed cells on exact regions: Figures 4 and 15, their cells' boundary structure, the models'
// Euler characteristics, the gluing, a near-tangent contact; the figures' files.
void trimmed_part(ReportContext& ctx, std::ostringstream& md) {
  ctx.progress("V-rep Booleans: trimmed cells (Figures 4 and 15)");
  std::vector<TrimmedCase> cases;
  cases.push_back(figure4_case(ctx));
  cases.push_back(figure15_case(ctx));
  models_table(md, cases);
  topology_table(md, cases);
  curves_sweep(md);
  std::string items;
  for (const auto& c : cases) items += ReportTemplate("vrep-boolean.euler.item").set("model", c.name.substr(0, c.name.find(':'))).set("euler", c.euler).render();
  md << ReportTemplate("vrep-boolean.euler").set("items", items).set("figure15_volume", fmt(16 + 15 * M_PI / 8, 8)).render();
  glue_part(ctx, md, cases[0].model, cases[1].model);
  near_tangent_part(md);
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_figure4.svg",
                        trimmed_svg(cases[0].model, 0.6, "Figure 4: cone union cylinder, trimmed V-cells exploded"));
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_figure4.vtu", trimmed_vtu(cases[0].model));
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_figure15.svg",
                        trimmed_svg(cases[1].model, 0.5, "Figure 15's kind: (plate union post) minus two holes, 7 V-cells exploded"));
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_figure15.vtu", trimmed_vtu(cases[1].model));
}

// Figure 3: the paper's counts, the program's and CGAL's Nef polyhedra's.
void figure3_part(ReportContext& ctx, std::ostringstream& md) {
  const auto O1 = exact_box({0, 0, 0}, {2, 1, 1}), O2 = exact_box({1, 0, 0}, {2, 2, 1});
  const auto U = boolean_op(O1, O2, BooleanOp::unite);
  std::size_t vc1_surfaces = 0, vc1_halves = 0, p1_curves = 0;
  for (std::size_t c = 0; c < U.curves.size(); ++c) {
    const auto& e = U.curves[c];
    const auto &a = U.points[e.ends[0]].at, &b = U.points[e.ends[1]].at;
    if (a[0] == 1 && a[1] == 1 && b[0] == 1 && b[1] == 1) {
      vc1_surfaces = e.surfaces.size();
      for (std::size_t s : e.surfaces) vc1_halves += U.surfaces[s].halves.size();
      p1_curves = U.points[e.ends[0]].curves.size();
    }
  }
  const auto nef = nef_boolean(O1, O2, BooleanOp::unite), mine = boundary_counts(U);
  md << ReportTemplate("vrep-boolean.figure3")
            .set("cells", U.cells.size())
            .set("half_surfaces", U.half_surfaces.size())
            .set("internal", U.internal_surfaces())
            .set("boundary", U.boundary_surfaces())
            .set("points", U.points.size())
            .set("curves", U.curves.size())
            .set("vc1_surfaces", vc1_surfaces)
            .set("vc1_halves", vc1_halves)
            .set("p1_curves", p1_curves)
            .set("euler", U.euler_characteristic())
            .set("vertices", mine.vertices)
            .set("edges", mine.edges)
            .set("facets", mine.facets)
            .set("volume", to_fraction_string(mine.volume))
            .set("nef_vertices", nef.vertices)
            .set("nef_edges", nef.edges)
            .set("nef_facets", nef.facets)
            .set("nef_volume", to_fraction_string(nef.volume))
            .render();
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_figure3.svg",
                        vmodel_svg(U, 0.35, "Figure 3: O1 union O2, three V-cells (the middle one holds both trivariates)", false));
}

// Figure 5: four coloured models, colours summed (clipped) where they overlap.
void figure5_part(ReportContext& ctx, std::ostringstream& md) {
  std::vector<VModel<Rational>> four{exact_box({0, 0, 0}, {2, 2, 1}), exact_box({1, 1, 0}, {3, 3, 1}),
                                     exact_box({1, -1, 0}, {3, 1, 1}), exact_box({-1, 1, 0}, {1, 3, 1})};
  const std::vector<std::vector<Rational>> colours{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {Rational(1, 2), Rational(1, 2), 0}};
  for (std::size_t k = 0; k < four.size(); ++k) four[k].cells[0].attributes.constants["colour"] = colours[k];
  VModel<Rational> all = four[0];
  for (std::size_t k = 1; k < four.size(); ++k) all = boolean_op(all, four[k], BooleanOp::unite);
  std::map<std::size_t, std::size_t> by_sources;
  for (const auto& c : all.cells) ++by_sources[c.trivariates.size() - 1];
  std::string sources;
  for (const auto& [n, count] : by_sources)
    sources += ReportTemplate("vrep-boolean.figure5.sources").set("cells", count).set("sources", n).when("plural", n != 1).render() + "; ";
  md << ReportTemplate("vrep-boolean.figure5")
            .set("cells", all.cells.size())
            .set("by_sources", sources)
            .set("volume", to_fraction_string(model_volume(all)))
            .set("euler", all.euler_characteristic())
            .render();
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_colours.svg",
                        vmodel_svg(all, 0.25, "Four boxes united, colours summed where they overlap", false));
}

// Figure 6: Eq. 2's distance blend on a slice, with the singular points r.
void figure6_part(ReportContext& ctx, std::ostringstream& md) {
  const auto W1 = exact_box({0, 0, 0}, {2, 2, 10}), W2 = exact_box({1, 1, -1}, {3, 3, 11});
  const DistanceBlend blend(W1, W2);
  const std::vector<Rational> red{1, 0, 0}, blue{0, 0, 1};
  const int n = 60;
  const double px = 6.0, margin = 30.0, top = 10.0;
  svg::Canvas fig(n * px + 2 * margin, n * px + 2 * top);
  fig.title("Eq. 2, slice z = 5: V1 red, V2 blue, r circled", 12);
  std::size_t singular = 0, points = 0;
  Rational widest(0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::vector<Rational> p{Rational(2 * i + 1, 2 * n) * 3, Rational(2 * j + 1, 2 * n) * 3, Rational(5)};
      if (!blend.in_first(p) && !blend.in_second(p)) continue;
      const auto v = blend.at(p, red, blue);
      ++points;
      std::string fill = "black";
      if (v.singular) ++singular;
      else {
        int rgb[3];
        for (int c = 0; c < 3; ++c) {
          rgb[c] = static_cast<int>(255.0 * to_double((v.value[c].lo + v.value[c].hi) / 2) + 0.5);
          if (widest < v.value[c].hi - v.value[c].lo) widest = v.value[c].hi - v.value[c].lo;
        }
        std::ostringstream f;
        f << "rgb(" << rgb[0] << "," << rgb[1] << "," << rgb[2] << ")";
        fill = f.str();
      }
      fig.rect(margin + i * px, top + (n - 1 - j) * px, px, px, svg::attr("fill", fill));
    }
  for (const auto& r : std::vector<std::array<double, 2>>{{2, 1}, {1, 2}})
    fig.circle(margin + r[0] / 3 * n * px, top + (1 - r[1] / 3) * n * px, 5, svg::attr("fill", "none") + svg::attr("stroke", "black") + svg::attr("stroke-width", 2));
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_eq2.svg", fig.str());
  const auto r1 = blend.at({2, 1, 5}, red, blue), mid = blend.at({Rational(3, 2), Rational(3, 2), 5}, red, blue),
             q = blend.at({Rational(7, 4), Rational(5, 4), 5}, red, blue), k2 = blend.at({Rational(7, 4), Rational(3, 2), 5}, red, blue, 2);
  md << ReportTemplate("vrep-boolean.figure6")
            .set("points", points)
            .set("widest", sci(to_double(widest)))
            .set("singular", singular)
            .when("r_singular", r1.singular)
            .set("mid_lo", fmt(to_double(mid.value[0].lo), 6))
            .set("mid_hi", fmt(to_double(mid.value[0].hi), 6))
            .set("mid_d1_squared", to_fraction_string(mid.d1_squared))
            .set("mid_d2_squared", to_fraction_string(mid.d2_squared))
            .set("q_lo", fmt(to_double(q.value[0].lo), 6))
            .set("q_hi", fmt(to_double(q.value[0].hi), 6))
            .set("k2_lo", fmt(to_double(k2.value[0].lo), 6))
            .set("k2_hi", fmt(to_double(k2.value[0].hi), 6))
            .render();
}

// The price of tolerance: A = [0,1]^3 and B = [1 + g, 2] x [0,1] x [0,1] (a gap, g > 0) or
// overlapping by |g| (g < 0), united exactly and in double at eps.
void tolerance_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream rows;
  std::ostringstream csv;
  csv << "g,eps,cells_exact,cells_double,internal_exact,internal_double,volume_error,misclassified\n";
  std::map<int, PlotSeries> series;
  int ci = 0;
  for (int sign : {1, -1})
    for (int k : {10, 20, 30, 40, 50}) {
      const Rational g = Rational(sign) / Rational(boost::multiprecision::pow(Integer(2), static_cast<unsigned>(k)));
      const auto A = exact_box({0, 0, 0}, {1, 1, 1}), B = exact_box({1 + g, 0, 0}, {2, 1, 1});
      const auto E = boolean_op(A, B, BooleanOp::unite);
      const Rational truth = model_volume(E);
      PlotSeries& ps = series[sign * k];
      ps.label = std::string(sign > 0 ? "gap" : "overlap") + " 2^-" + std::to_string(k);
      ps.color = svg::palette(ci++);
      for (double eps : {1e-15, 1e-12, 1e-9, 1e-6, 1e-3}) {
        std::string cells_d = "error", internal_d = "error", verr = "-", mis = "-", chi_d = "-";
        double verr_value = 0;
        try {
          const auto D = boolean_op(in_double(A, eps), in_double(B, eps), BooleanOp::unite, eps);
          const auto DE = in_exact(D);
          const Rational ve = model_volume(DE) - truth;
          const Rational m = nef_boolean(E, DE, BooleanOp::subtract).volume + nef_boolean(DE, E, BooleanOp::subtract).volume;
          cells_d = std::to_string(D.cells.size());
          internal_d = std::to_string(D.internal_surfaces());
          chi_d = std::to_string(check_invariants(D).euler);
          verr = ve == 0 ? "0" : sci(to_double(ve));
          mis = m == 0 ? "0" : sci(to_double(m));
          verr_value = to_double(ve);
        } catch (const Error& e) {
          cells_d = "refused";
        }
        rows << "| " << (sign > 0 ? "" : "-") << "2^-" << k << " | " << fmt(eps, 6) << " | " << E.cells.size() << " / " << cells_d << " | "
           << E.internal_surfaces() << " / " << internal_d << " | " << check_invariants(E).euler << " / " << chi_d << " | " << verr << " | " << mis << " |\n";
        csv << (sign > 0 ? "" : "-") << std::ldexp(1.0, -k) << "," << eps << "," << E.cells.size() << "," << cells_d << ","
            << E.internal_surfaces() << "," << internal_d << "," << verr << "," << mis << "\n";
        if (sign < 0) ps.points.emplace_back(eps, verr_value != 0 ? std::abs(verr_value) : 1e-20);
      }
    }
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_tolerance.csv", csv.str());
  std::vector<PlotSeries> plot;
  for (auto& [k, s] : series)
    if (k < 0) plot.push_back(s);
  write_file_atomically(ctx.options.out_dir + "/vrep_boolean_tolerance.svg",
                        svg_line_plot({"Union of two overlapping boxes in double: volume counted twice against eps", "eps",
                                       "sum of cell volumes - true volume (exact; 1e-20 drawn for 0)", true, true,
                                       "A = [0,1]^3, B = [1-2^-k,2]x[0,1]^2"},
                                      plot));
  md << ReportTemplate("vrep-boolean.tolerance").set("rows", rows.str()).render();
}

}  // namespace

void vrep_boolean_section(ReportContext& ctx) {
  ctx.progress("V-rep Booleans: Figure 3, colour blending, the price of tolerance");
  std::ostringstream md;
  md << ReportTemplate("vrep-boolean").render();
  figure3_part(ctx, md);
  figure5_part(ctx, md);
  figure6_part(ctx, md);
  tolerance_part(ctx, md);
  trimmed_part(ctx, md);
  md << ReportTemplate("vrep-boolean.not-built").when("ran:vrep-teapot", ctx.ran("vrep-teapot")).render();
  ctx.markdown["vrep-boolean"] = md.str();
}

}  // namespace splinex
