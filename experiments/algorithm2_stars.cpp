#include "experiments/algorithm2_stars.hpp"
#include "experiments/section.hpp"

#include <gmp.h>

#include <chrono>
#include <iomanip>
#include <set>
#include <sstream>

#include "fixtures/teapot.hpp"
#include "exact/rational.hpp"
#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/teapot_stars.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "untrim/algorithm2.hpp"

namespace splinex {

namespace {
std::string g(double v) { return fmt(v, 3); }
BSpline<double> to_dbl(const BSpline<Rational>& S) {
  return convert<double>(S, [](const Rational& x) { return to_double(x); });
}
BSpline<Rational> to_exact(const BSpline<double>& S) {
  return convert<Rational>(S, [](double x) { return exact_from_double(x); });
}
}  // namespace

std::string run_algorithm2_stars(const Algorithm2StarsOptions& opt, const std::function<void(const std::string&)>& progress,
                                 bool& ok) {
  using clock = std::chrono::steady_clock;
  const auto patches = read_bpt(data_path("teapot.bpt"));
  std::ostringstream md, csv;
  csv << "surface,eps,stars,alg1_patches,alg1_control_points,alg1_seconds,alg2_tiles,alg2_control_points,alg2_seconds,"
         "orders,max_abs_deviation,gap_area,overlap_area,cover_defect\n"
      << std::setprecision(17);
  std::set<std::pair<int, int>> all_orders;
  const auto surfaces = teapot_surfaces(patches);
  for (const auto& surf : surfaces) {
    const BSpline<Rational>& T = surf.surface;
    const BSpline<double> Td = to_dbl(T);
    const Rational W = T.domain_hi(0), H = T.domain_hi(1);
    for (double eps : opt.eps) {
      progress("algorithm 2: " + surf.name + ", eps " + g(eps));
      std::size_t a1_patches = 0, a1_cp = 0, a2_tiles = 0, a2_cp = 0;
      double t1 = 0, t2 = 0;
      Rational dev(0), gap(0), overlap(0), defect(0);
      std::set<std::pair<int, int>> orders;
      for (int j = 0; j < opt.tiles; ++j)
        for (int i = 0; i < opt.tiles; ++i) {
          const BSpline<Rational> S = star_in_tile(i, j, opt.tiles, W, H);
          const BSpline<double> Sd = to_dbl(S);
          const auto c0 = clock::now();
          const auto C1 = compose_trimmed(Td, Sd);
          const auto c1 = clock::now();
          TensorOptions to;
          to.boundary = TrimBoundary::polyline;
          to.eps = eps;
          to.grid = 8;
          const auto A = compose_tensor(Td, Sd, to);
          const auto c2 = clock::now();
          t1 += std::chrono::duration<double>(c1 - c0).count();
          t2 += std::chrono::duration<double>(c2 - c1).count();
          a1_patches += C1.patches.size();
          for (const auto& p : C1.patches) a1_cp += p.patch.net.size();
          a2_tiles += A.tiles.size();
          Rational area(0);
          for (std::size_t k = 0; k < A.tiles.size(); ++k) {
            const auto& t = A.tiles[k];
            a2_cp += t.R.net.size();
            orders.insert({t.R.net.degrees[0] + 1, t.R.net.degrees[1] + 1});
            area += exact_from_double(t.area);
            const BSpline<Rational> Qx = to_exact(t.Q);
            for (int a = 1; a <= 2; ++a)
              for (int b = 1; b <= 2; ++b) {
                const double x = t.tile.x.front() + (t.tile.x.back() - t.tile.x.front()) * a / 3.0, l = b / 3.0;
                const auto vd = A.evaluate_tile(k, {x, l});
                const auto rt = evaluate(Qx, {exact_from_double(x), exact_from_double(l)});
                const auto truth = evaluate(T, evaluate(S, rt));
                for (std::size_t c = 0; c < truth.size(); ++c) {
                  const Rational e = abs(Rational(exact_from_double(vd[c]) - truth[c]));
                  if (dev < e) dev = e;
                }
              }
          }
          gap += exact_from_double(A.gap_area);
          overlap += exact_from_double(A.overlap_area);
          const Rational d = abs(Rational(area + exact_from_double(A.gap_area) - exact_from_double(A.overlap_area) - 1));
          if (defect < d) defect = d;
        }
      std::string ord;
      for (const auto& o : orders) {
        ord += (ord.empty() ? "(" : ", (") + std::to_string(o.first) + ", " + std::to_string(o.second) + ")";
        all_orders.insert(o);
      }
      md << "| " << surf.name << " | " << g(eps) << " | " << a1_patches << " | " << a1_cp << " | " << g(t1) << " | "
         << a2_tiles << " | " << a2_cp << " | " << g(t2) << " | " << ord << " | " << g(to_double(dev)) << " | "
         << g(to_double(gap)) << " | " << g(to_double(overlap)) << " |\n";
      csv << surf.name << "," << eps << "," << opt.tiles * opt.tiles << "," << a1_patches << "," << a1_cp << "," << t1
          << "," << a2_tiles << "," << a2_cp << "," << t2 << ",\"" << ord << "\"," << to_double(dev) << ","
          << to_double(gap) << "," << to_double(overlap) << "," << to_double(defect) << "\n";
      ok = ok && defect < Rational(1, 1000000000);
    }
  }
  ok = ok && all_orders == std::set<std::pair<int, int>>{{25, 25}};
  std::string exact_star;
  if (opt.exact_star) {
    // One star exactly: the cost ratio of Algorithm 2 in rationals (same double polylines).
    progress("algorithm 2: one star on the body, exact");
    const auto& body = surfaces.front().surface;
    const BSpline<Rational> S = star_in_tile(0, 2, opt.tiles, body.domain_hi(0), body.domain_hi(1));
    TensorOptions to;
    to.boundary = TrimBoundary::polyline;
    to.eps = 1e-2;
    to.grid = 8;
    const auto c0 = clock::now();
    const auto A = compose_tensor(body, S, to);
    const auto c1 = clock::now();
    const auto Ad = compose_tensor(to_dbl(body), to_dbl(S), to);
    const auto c2 = clock::now();
    std::size_t bits = 0, coefs = 0;
    for (const auto& t : A.tiles)
      for (const auto& v : t.R.net.points) {
        bits += mpz_sizeinbase(mpq_numref(v.backend().data()), 2) + mpz_sizeinbase(mpq_denref(v.backend().data()), 2);
        ++coefs;
      }
    const double te = std::chrono::duration<double>(c1 - c0).count(), td = std::chrono::duration<double>(c2 - c1).count();
    exact_star = ReportTemplate("algorithm2-stars.exact-star")
                     .set("tiles", A.tiles.size())
                     .set("t_exact", g(te))
                     .set("t_double", g(td))
                     .set("ratio", g(te / td))
                     .set("bits", g(static_cast<double>(bits) / static_cast<double>(coefs)))
                     .render();
  }
  write_file_atomically(opt.out_dir + "/algorithm2_stars.csv", csv.str());
  return ReportTemplate("algorithm2-stars").set("grid", opt.tiles).set("rows", md.str()).set("exact_star", exact_star).render();
}

void algorithm2_stars_section(ReportContext& ctx) {
  Algorithm2StarsOptions options;
  options.out_dir = ctx.options.out_dir;
  if (!ctx.options.full) options.eps = {1e-2, 1e-3};
  ctx.markdown["algorithm2-stars"] = run_algorithm2_stars(options, ctx.progress, ctx.ok);
}

}  // namespace splinex
