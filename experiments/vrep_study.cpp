// Report section `vrep` (issue 17): what a gluing tolerance does to the topology of the primitives,
// and where a float regularity test decides wrongly, both measured exactly.
//
// Gluing: the exact primitive (cylinder, cone, torus of five cells) is glued exactly; then one
// corner control point of the second half of every internal V-surface is moved by delta along z
// (exactly), the perturbed cells are glued exactly (the truth) and, rounded to double, with IRIT's
// float test at eps. A twin pair glued in double and not exactly is a false glue; one glued exactly
// and not in double a missed glue.
// Regularity: the trilinear unit cube with corner (1, 1, 1) moved to (1 - s)(1, 1, 1): det J at
// that corner is 1 - 3s, so s = 1/3 + e is singular for e >= 0 and regular for e < 0. For e = +-2^-k
// the exact verdict on the exact input, the exact verdict on the input rounded to double, and the
// double test's verdict on it.
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include "crosscheck/crosscheck.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/vrep_figures.hpp"
#include "float/rounding.hpp"
#include "io/json_io.hpp"
#include "spline/evaluate.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/primitives.hpp"

namespace splinex {

namespace {

using Pair = std::pair<std::array<int, 3>, std::array<int, 3>>;  // (cell, dir, side) of both halves, sorted

template <class T>
std::set<Pair> twin_pairs(const VModel<T>& M) {
  std::set<Pair> out;
  for (const auto& h : M.half_surfaces)
    if (h.twin) {
      const auto& t = M.half_surfaces[*h.twin];
      std::array<int, 3> a{static_cast<int>(h.cell), h.dir, h.side}, b{static_cast<int>(t.cell), t.dir, t.side};
      if (b < a) std::swap(a, b);
      out.insert({a, b});
    }
  return out;
}

/// Moves the first control point of face (dir, side) of V by delta along z.
void move_face_corner(BSpline<Rational>& V, int dir, int side, const Rational& delta) {
  std::size_t idx[3] = {0, 0, 0};
  idx[dir] = side ? V.count(dir) - 1 : 0;
  const std::size_t k = idx[0] + V.count(0) * (idx[1] + V.count(1) * idx[2]);
  V.points[k * V.q + 2] += delta;
}

/// A constructor run exactly and in double from the same (rounded) input, judged exactly.
struct Judged {
  std::string name;
  ErrorStat points, values;
};

/// Compares D (built in double) with E (built exactly): control points (Cartesian, all
/// coordinates) and the points at 5^3 parameters (i/4 of each domain, exact in double).
Judged judge(const std::string& name, const BSpline<Rational>& E, const BSpline<double>& D) {
  Judged j{name, {}, {}};
  if (D.points.size() != E.points.size()) throw std::logic_error("vrep study: " + name + ": double and exact nets differ in size");
  for (std::size_t i = 0; i < E.points.size(); ++i) j.points.add(E.points[i], exact_from_double(D.points[i]));
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; b <= 4; ++b)
      for (int c = 0; c <= 4; ++c) {
        std::vector<Rational> x;
        std::vector<double> xd;
        const int k[3] = {a, b, c};
        for (int d = 0; d < 3; ++d) {
          x.push_back(E.domain_lo(d) + Rational(k[d], 4) * (E.domain_hi(d) - E.domain_lo(d)));
          xd.push_back(to_double(x.back()));
          if (exact_from_double(xd.back()) != x.back()) throw std::logic_error("vrep study: a parameter is not a double");
        }
        const auto pe = evaluate(E, x);
        const auto pd = evaluate(D, xd);
        for (int d = 0; d < 3; ++d) j.values.add(pe[d], exact_from_double(pd[d]));
      }
  return j;
}

BSpline<Rational> doc(const char* text) { return spline_from_json(Json::parse(text)); }

/// The constructors and primitives of issue 17 in double against exact.
std::vector<Judged> judge_constructors() {
  const auto S = doc(R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, "1/3", 1, 1, 1], [0, 0, "1/2", 1, 1]],
    "points": [[0,0,0],[1,"1/5",0],[2,0,"1/3"],[3,"1/7",0], [0,1,"1/2"],[1,1,1],[2,"6/5",0],[3,1,"1/4"],
               ["1/9",2,0],[1,2,"1/3"],[2,"11/5",0],[3,2,"1/2"]]})");
  const auto S2 = doc(R"({"type": "bspline", "degrees": [1, 2], "knots": [[0, 0, "1/10", 1, 1], [0, 0, 0, 1, 1, 1]],
    "points": [[0,0,2],["1/3",0,"21/10"],[3,0,2], [0,1,"13/6"],["4/3",1,"5/2"],[3,1,"7/3"], [0,2,2],["1/3",2,"9/4"],[3,2,2]],
    "weights": [1, "3/2", 1, "5/4", 2, 1, 1, "2/3", 1]})");
  const auto P = doc(R"({"type": "bspline", "degrees": [2, 1], "knots": [[0, 0, 0, 1, 1, 1], [0, 0, 1, 1]],
    "points": [[1,0,0],[2,0,"1/2"],[1,0,1], ["3/2",0,0],["5/2",0,"1/2"],["3/2",0,1]], "weights": [1, 2, 1, 1, 3, 1]})");
  auto rd = [](const BSpline<Rational>& X) { return round_spline<double>(X); };
  std::vector<Judged> out;
  const std::vector<Rational> V{Rational(1, 3), Rational(-2), Rational(5, 7)};
  out.push_back(judge("extrude", extrude(S, V), extrude(rd(S), std::vector<double>{to_double(V[0]), to_double(V[1]), to_double(V[2])})));
  out.push_back(judge("ruled (elevation and insertion to a common space)", ruled(S, S2), ruled(rd(S), rd(S2))));
  out.push_back(judge("revolve (4 quarters)", revolve(P, 2, 4), revolve(rd(P), 2, 4)));
  // Boolean sum of the six faces of a polynomial ruled volume.
  auto S2p = S2;
  S2p.weights.clear();
  const auto T0 = ruled(S, S2p);
  std::array<std::array<BSpline<Rational>, 2>, 3> F;
  std::array<std::array<BSpline<double>, 2>, 3> Fd;
  for (int d = 0; d < 3; ++d)
    for (int side = 0; side < 2; ++side) {
      F[d][side] = face(T0, d, side);
      Fd[d][side] = rd(F[d][side]);
    }
  out.push_back(judge("Boolean sum (faces of a ruled volume)", boolean_sum(F), boolean_sum(Fd)));
  // Sweeps: four sections, well spaced and with two parameters 2^-30 apart.
  for (int close : {0, 1}) {
    std::vector<BSpline<Rational>> secs;
    std::vector<BSpline<double>> secsd;
    const std::vector<Rational> at = close ? std::vector<Rational>{0, Rational(1, 3), Rational(1, 3) + Rational(1, 1L << 30), 1}
                                           : std::vector<Rational>{0, Rational(1, 3), Rational(2, 3), 1};
    std::vector<double> atd;
    for (int k = 0; k < 4; ++k) {
      auto X = S;
      for (std::size_t i = 0; i < X.size(); ++i) X.points[i * 3 + 2] += Rational(k * k, 3) + Rational(static_cast<long>(i % 3), 7) * Rational(k);
      secs.push_back(X);
      secsd.push_back(rd(X));
      atd.push_back(to_double(at[k]));
    }
    out.push_back(judge(close ? "sweep, w = 0, 1/3, 1/3 + 2^-30, 1" : "sweep, w = 0, 1/3, 2/3, 1", sweep(secs, at, 3),
                        sweep(secsd, atd, 3)));
  }
  auto prim = [&](const std::string& name, const std::vector<BSpline<Rational>>& e, const std::vector<BSpline<double>>& d) {
    auto merge = [](ErrorStat& a, const ErrorStat& b) {
      a.max_abs = std::max(a.max_abs, b.max_abs);
      a.max_ref = std::max(a.max_ref, b.max_ref);
      a.count += b.count;
    };
    Judged all{name, {}, {}};
    for (std::size_t k = 0; k < e.size(); ++k) {
      const auto j = judge(name, e[k], d[k]);
      merge(all.points, j.points);
      merge(all.values, j.values);
    }
    return all;
  };
  out.push_back(prim("cylinder (r 2, h 3)", cylinder_cells<Rational>(2, 3), cylinder_cells<double>(2, 3)));
  out.push_back(prim("cone (r 2, 1, h 3)", cone_cells<Rational>(2, 1, 3), cone_cells<double>(2, 1, 3)));
  out.push_back(prim("torus (R 3, r 1)", torus_cells<Rational>(3, 1), torus_cells<double>(3, 1)));
  out.push_back(prim("sphere (r 2)", sphere_cells<Rational>(2), sphere_cells<double>(2)));
  return out;
}

// A primitive of issue 17 and its exact cells.
struct Prim {
  const char* name;
  std::vector<BSpline<Rational>> cells;
};

// The primitives glued and drawn: cylinder, cone, torus, sphere.
std::vector<Prim> primitives() {
  return {{"cylinder", cylinder_cells<Rational>(Rational(2), Rational(3))},
          {"cone", cone_cells<Rational>(Rational(2), Rational(1), Rational(3))},
          {"torus", torus_cells<Rational>(Rational(3), Rational(1))},
          {"sphere", sphere_cells<Rational>(Rational(2))}};
}

// A number for the tables: scientific, 3 digits after the point.
std::string fmt_sci(double v) {
  std::ostringstream o;
  o << std::setprecision(3) << std::scientific << v;
  return o.str();
}

// The gluing table: each primitive's internal V-surfaces moved by delta, glued exactly and in double
// at eps; vrep_gluing.csv. Returns the cylinder's false glues against eps, per delta, for the figure.
std::map<int, PlotSeries> gluing_table(ReportContext& ctx, std::ostringstream& md, const std::vector<Prim>& prims) {
  const std::vector<double> epss{1e-15, 1e-12, 1e-9, 1e-6, 1e-3};
  const std::vector<int> delta_exp{-10, -20, -30, -40, -50, 0};  // 0: delta = 0
  std::ostringstream csv;
  csv << "primitive,delta,eps,internal_exact,internal_double,false_glues,missed_glues\n";
  std::ostringstream rows;
  std::map<int, PlotSeries> series;  // cylinder: false glues vs eps per delta
  int ci = 0;
  for (const auto& p : prims) {
    const VModel<Rational> base = glue(p.cells);
    for (int e : delta_exp) {
      const Rational delta = e == 0 ? Rational(0) : Rational(1) / Rational(pow(boost::multiprecision::mpz_int(2), static_cast<unsigned>(-e)));
      std::vector<BSpline<Rational>> moved = p.cells;
      for (const auto& s : base.surfaces)
        if (s.halves.size() == 2) {
          const auto& h = base.half_surfaces[s.halves[1]];
          move_face_corner(moved[h.cell], h.dir, h.side, delta);
        }
      const auto truth = twin_pairs(glue(moved));
      std::vector<BSpline<double>> dbl;
      for (const auto& V : moved) dbl.push_back(round_spline<double>(V));
      rows << "| " << p.name << " | " << (e == 0 ? std::string("0") : "2^" + std::to_string(e)) << " | " << truth.size() << " |";
      PlotSeries& ps = series[e];
      if (ps.label.empty()) {
        ps.label = e == 0 ? "delta = 0" : "delta = 2^" + std::to_string(e);
        ps.color = svg::palette(ci++);
      }
      for (double eps : epss) {
        const auto got = twin_pairs(glue(dbl, eps));
        std::size_t false_glues = 0, missed = 0;
        for (const auto& x : got) false_glues += truth.count(x) == 0;
        for (const auto& x : truth) missed += got.count(x) == 0;
        csv << p.name << "," << (e == 0 ? 0.0 : std::ldexp(1.0, e)) << "," << eps << "," << truth.size() << "," << got.size() << ","
            << false_glues << "," << missed << "\n";
        rows << " " << got.size() << " (" << false_glues << ", " << missed << ") |";
        if (std::string(p.name) == "cylinder") ps.points.emplace_back(eps, static_cast<double>(false_glues));
      }
      rows << "\n";
    }
  }
  md << ReportTemplate("vrep.gluing").set("rows", rows.str()).render();
  write_file_atomically(ctx.options.out_dir + "/vrep_gluing.csv", csv.str());
  return series;
}

// Figures: the primitives exploded (Figure 9) and Figure 8's singular trivariates with det J = 0 marked.
void write_figures(ReportContext& ctx, const std::vector<Prim>& prims, const std::map<int, PlotSeries>& series) {
  for (const auto& p : prims)
    write_file_atomically(ctx.options.out_dir + "/vrep_" + p.name + ".svg",
                          vmodel_svg(glue(p.cells), 0.35,
                                     std::string("The ") + p.name + " of " + std::to_string(p.cells.size()) + " regular cells, exploded", false));
  write_file_atomically(ctx.options.out_dir + "/vrep_singular_cylinder.svg",
                        vmodel_svg(glue(std::vector<BSpline<Rational>>{singular_cylinder<Rational>(Rational(1), Rational(2))}), 0, "Figure 8 a: one trivariate, singular on its axis", true));
  write_file_atomically(ctx.options.out_dir + "/vrep_singular_sphere.svg",
                        vmodel_svg(glue(std::vector<BSpline<Rational>>{singular_sphere<Rational>(Rational(1))}), 0, "Figure 8 b: one trivariate, singular on its axis", true));
  std::vector<PlotSeries> plot;
  for (const auto& [e, s] : series) plot.push_back(s);
  write_file_atomically(ctx.options.out_dir + "/vrep_gluing.svg",
                        svg_line_plot({"Gluing the perturbed cylinder in double: false glues against eps", "eps",
                                       "false glues (of 8 internal V-surfaces)", true, false,
                                       "one corner control point of every shared face moved by delta (exactly)"},
                                      plot));
}

// The sphere's radius: certified deviation against degree and pieces.
void sphere_radius_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream rows;
  std::ostringstream scsv;
  scsv << "degree,pieces,bound,witness\n";
  for (int p : {2, 3, 4, 5})
    for (int n : {1, 2, 4, 8}) {
      const auto cells = sphere_cells<Rational>(Rational(1), p, n);
      const auto d = sphere_deviation(face(cells[1], 2, 1), {Rational(0), Rational(0), Rational(0)}, Rational(1));
      rows << "| " << p << " | " << n << " | " << fmt_sci(to_double(d.bound)) << " | " << fmt_sci(to_double(d.witness)) << " |\n";
      scsv << p << "," << n << "," << to_double(d.bound) << "," << to_double(d.witness) << "\n";
    }
  write_file_atomically(ctx.options.out_dir + "/vrep_sphere_radius.csv", scsv.str());
  md << ReportTemplate("vrep.sphere").set("rows", rows.str()).render();
}

// The constructors in double, judged exactly.
void constructors_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream rows;
  std::ostringstream kcsv;
  kcsv << "constructor,points_abs,points_rel,points_bits_lost,values_abs,values_rel,values_bits_lost\n";
  for (const auto& j : judge_constructors()) {
    rows << "| " << j.name << " | " << fmt_sci(j.points.abs()) << " | " << fmt_sci(j.points.rel()) << " | " << std::fixed
       << std::setprecision(1) << j.points.bits_lost(53) << " | " << fmt_sci(j.values.abs()) << " | " << fmt_sci(j.values.rel())
       << " | " << std::fixed << std::setprecision(1) << j.values.bits_lost(53) << " |\n";
    kcsv << "\"" << j.name << "\"," << j.points.abs() << "," << j.points.rel() << "," << j.points.bits_lost(53) << "," << j.values.abs()
         << "," << j.values.rel() << "," << j.values.bits_lost(53) << "\n";
  }
  write_file_atomically(ctx.options.out_dir + "/vrep_constructors.csv", kcsv.str());
  md << ReportTemplate("vrep.constructors").set("rows", rows.str()).render();
}

// Regularity in double near the singular threshold s = 1/3.
void regularity_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream table;
  std::ostringstream rcsv;
  rcsv << "e,exact,rounded_exact,double\n";
  int wrong = 0, rows = 0, arithmetic = 0;
  for (int k = 10; k <= 70; k += 5)
    for (int sign : {-1, 1}) {
      const Rational e = Rational(sign) / Rational(pow(boost::multiprecision::mpz_int(2), static_cast<unsigned>(k)));
      const Rational s = Rational(1, 3) + e;
      auto cube = box_cells<Rational>({0, 0, 0}, {1, 1, 1})[0];
      for (int c = 0; c < 3; ++c) cube.points[7 * 3 + c] = 1 - s;
      const auto ex = certify_regularity(cube).verdict;
      const auto rd = round_spline<double>(cube);
      const auto re = certify_regularity(convert<Rational>(rd, [](double x) { return exact_from_double(x); })).verdict;
      const auto db = certify_regularity(rd).verdict;
      ++rows;
      wrong += db.status() != ex.status();
      arithmetic += db.status() != re.status();
      table << "| " << (sign < 0 ? "-" : "+") << "2^-" << k << " | " << regularity_name(ex) << " | " << regularity_name(re) << " | "
         << regularity_name(db) << " | " << (db.status() != ex.status() ? "**yes**" : "no") << " |\n";
      rcsv << (sign < 0 ? "-" : "") << "2^-" << k << "," << regularity_name(ex) << "," << regularity_name(re) << "," << regularity_name(db) << "\n";
    }
  write_file_atomically(ctx.options.out_dir + "/vrep_regularity.csv", rcsv.str());
  md << ReportTemplate("vrep.regularity")
            .set("rows", table.str())
            .set("wrong", wrong)
            .set("cases", rows)
            .set("arithmetic", arithmetic)
            .when("double_never_erred", arithmetic == 0)
            .render();
}

}  // namespace

void vrep_section(ReportContext& ctx) {
  ctx.progress("V-rep: figures, gluing tolerance and float regularity");
  const std::vector<Prim> prims = primitives();
  std::ostringstream md;
  const auto series = gluing_table(ctx, md, prims);
  write_figures(ctx, prims, series);
  sphere_radius_part(ctx, md);
  constructors_part(ctx, md);
  regularity_part(ctx, md);
  ctx.markdown["vrep"] = md.str();
}

}  // namespace splinex
