#include "experiments/untrim_tolerance.hpp"
#include "experiments/section.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <mutex>
#include <sstream>

#include "base/parallel.hpp"
#include "compose/trimmed_compose.hpp"
#include "exact/rational.hpp"
#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/svg_plot.hpp"
#include "float/mpfr.hpp"
#include "spline/kernel.hpp"
#include "untrim/algorithm2.hpp"
#include "untrim/polygon.hpp"

namespace splinex {

namespace {

std::string g(double v) { return fmt(v, 3); }

template <class A>
Rational ex(const A& x) {
  return ArithTraits<A>::to_rational(x);
}

// The value of the float spline R at the rational point x, exactly: R's local knots and control
// points are taken as the exact rationals they are, and evaluated in rationals. This judges the
// spline the float run produced, not a float evaluation of it.
template <class A>
std::vector<Rational> evaluate_exactly(const BSpline<A>& R, const std::vector<Rational>& x) {
  if (R.is_rational()) throw std::logic_error("evaluate_exactly: polynomial splines only");
  BSpline<Rational> L;
  L.degrees = R.degrees;
  L.q = R.q;
  std::vector<std::size_t> first(R.dim());
  for (int d = 0; d < R.dim(); ++d) {
    const int p = R.degrees[d];
    const auto& U = R.knots[d];
    std::size_t lo = p, hi = R.count(d) - 1;  // the last span s with U[s] <= x
    while (lo < hi) {
      const std::size_t mid = (lo + hi + 1) / 2;
      if (!(x[d] < ex(U[mid]))) lo = mid;
      else hi = mid - 1;
    }
    first[d] = lo - p;
    std::vector<Rational> K;
    for (std::size_t i = lo - p; i <= lo + p + 1; ++i) K.push_back(ex(U[i]));
    L.knots.push_back(std::move(K));
  }
  // Local control points, direction 0 fastest.
  std::vector<std::size_t> idx(R.dim(), 0);
  const std::size_t n = L.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t flat = 0, stride = 1, rem = k;
    for (int d = 0; d < R.dim(); ++d) {
      const std::size_t w = R.degrees[d] + 1, i = rem % w;
      rem /= w;
      flat += (first[d] + i) * stride;
      stride *= R.count(d);
    }
    for (int c = 0; c < R.q; ++c) L.points.push_back(ex(R.points[flat * R.q + c]));
  }
  return evaluate(L, x);
}

template <class A>
Tile<Rational> exact_tile(const Tile<A>& t) {
  return convert_tile<Rational>(t, [](const A& v) { return ex(v); });
}

struct Row {
  int m = 0;
  std::string arith;
  double eps = 0;
  bool skipped = false;
  std::string why;
  std::size_t tiles = 0, trapezoids = 0, max_chain = 0, control_points = 0, samples = 0;
  int deg_x = 0, deg_l = 0;
  double cpu_seconds = 0;  // the composition's CPU time on the job's thread
  Rational deviation{0}, gap{0}, overlap{0};
};

nlohmann::json row_json(const Row& r) {
  return {{"m", r.m},
          {"arith", r.arith},
          {"eps", r.eps},
          {"skipped", r.skipped},
          {"why", r.why},
          {"tiles", r.tiles},
          {"trapezoids", r.trapezoids},
          {"max_chain", r.max_chain},
          {"control_points", r.control_points},
          {"samples", r.samples},
          {"deg_x", r.deg_x},
          {"deg_l", r.deg_l},
          {"cpu_seconds", r.cpu_seconds},
          {"deviation", to_fraction_string(r.deviation)},
          {"gap", to_fraction_string(r.gap)},
          {"overlap", to_fraction_string(r.overlap)}};
}

Row row_from_json(const nlohmann::json& j) {
  Row r;
  r.m = j.at("m").get<int>();
  r.arith = j.at("arith").get<std::string>();
  r.eps = j.at("eps").get<double>();
  r.skipped = j.at("skipped").get<bool>();
  r.why = j.at("why").get<std::string>();
  r.tiles = j.at("tiles").get<std::size_t>();
  r.trapezoids = j.at("trapezoids").get<std::size_t>();
  r.max_chain = j.at("max_chain").get<std::size_t>();
  r.control_points = j.at("control_points").get<std::size_t>();
  r.samples = j.at("samples").get<std::size_t>();
  r.deg_x = j.at("deg_x").get<int>();
  r.deg_l = j.at("deg_l").get<int>();
  r.cpu_seconds = j.at("cpu_seconds").get<double>();
  r.deviation = parse_number(j.at("deviation").get<std::string>(), "deviation");
  r.gap = parse_number(j.at("gap").get<std::string>(), "gap");
  r.overlap = parse_number(j.at("overlap").get<std::string>(), "overlap");
  return r;
}

template <class A>
Row measure(const BSpline<Rational>& T, const BSpline<Rational>& S, double eps, const UntrimToleranceOptions& opt) {
  Row row;
  row.arith = ArithTraits<A>::name();
  row.eps = eps;
  const auto conv = [](const Rational& x) { return ArithTraits<A>::from_rational(x); };
  const BSpline<A> Ta = convert<A>(T, conv), Sa = convert<A>(S, conv);
  TensorOptions to;
  to.boundary = TrimBoundary::polyline;
  to.eps = eps;
  to.grid = 8;
  Limits lim;
  lim.max_control_points = opt.max_control_points;        // no tile alone above the sum's limit
  lim.max_total_control_points = opt.max_control_points;  // summed over the tiles, before composing
  const double c0 = thread_cpu_seconds();
  TensorComposition<A> C;
  try {
    C = compose_tensor(Ta, Sa, to, lim);
  } catch (const SizeLimitError& e) {
    row.skipped = true;
    row.why = e.what();
    return row;
  }
  row.cpu_seconds = thread_cpu_seconds() - c0;
  row.tiles = C.tiles.size();
  row.trapezoids = C.trapezoids;
  // Exact tiles, the union per inner piece (CGAL), gap and overlap.
  std::map<std::size_t, std::vector<Polygon>> by_piece;
  std::map<std::size_t, Rational> area_sum;
  std::vector<Tile<Rational>> et;
  for (const auto& tt : C.tiles) {
    et.push_back(exact_tile(tt.tile));
    const std::size_t piece = C.trimmed.patches[tt.patch].inner_piece;
    by_piece[piece].push_back(tile_polygon(et.back()));
    area_sum[piece] += tile_area(et.back());
    row.max_chain = std::max(row.max_chain, tt.tile.x.size());
    row.control_points += tt.R.net.size();
    row.deg_x = std::max(row.deg_x, tt.R.net.degrees[0]);
    row.deg_l = std::max(row.deg_l, tt.R.net.degrees[1]);
  }
  for (const auto& [piece, polys] : by_piece) {
    const auto& P = C.trimmed.inner_pieces[piece].spline;
    const Rational box = (ex(P.domain_hi(0)) - ex(P.domain_lo(0))) * (ex(P.domain_hi(1)) - ex(P.domain_lo(1)));
    const Rational u = polygon_union_area(polys);
    row.gap += box - u;
    row.overlap += area_sum[piece] - u;
  }
  // Deviation from T(S) at rational sample points of every tile.
  for (std::size_t k = 0; k < C.tiles.size(); ++k) {
    const auto& tt = C.tiles[k];
    const auto& te = et[k];
    const BSpline<Rational> Q = tile_spline(te);
    const bool homogeneous = tt.R.weighted;
    std::vector<std::pair<Rational, Rational>> pts;
    const std::size_t nx = te.x.size();
    const std::size_t stride = std::max<std::size_t>(1, (2 * nx) / opt.max_boundary_samples);
    for (std::size_t i = 0; i + 1 < nx; i += stride) {
      const Rational mid = (te.x[i] + te.x[i + 1]) / 2;
      for (int side = 0; side < 2; ++side) {
        pts.emplace_back(te.x[i], Rational(side));
        pts.emplace_back(mid, Rational(side));
      }
    }
    for (int a = 1; a <= 4; ++a)
      for (int b = 1; b <= 4; ++b)
        pts.emplace_back(te.x.front() + (te.x.back() - te.x.front()) * Rational(a, 5), Rational(b, 5));
    for (const auto& [x, l] : pts) {
      const auto r = evaluate(Q, {x, l});
      const auto good = evaluate(T, evaluate(S, r));
      auto bad = evaluate_exactly(tt.R.net, {x, l});
      if (homogeneous) {
        const Rational w = bad.back();
        bad.pop_back();
        for (auto& v : bad) v /= w;
      }
      for (std::size_t c = 0; c < good.size(); ++c) row.deviation = std::max(row.deviation, Rational(abs(Rational(bad[c] - good[c]))));
      ++row.samples;
    }
  }
  return row;
}


}  // namespace

UntrimToleranceOptions full_untrim_tolerance_options(const std::string& out_dir) {
  UntrimToleranceOptions o;
  o.out_dir = out_dir;
  o.eps = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  // Double down to 1e-12 (130M control points, about 25 min a job); MPFR down to 1e-11 (33M, about
  // 20 min a job at 53 bits): at 1e-12 an MPFR job takes over an hour and 9 GiB or more.
  o.runs = {{0, 1e-12, 4}, {53, 1e-11, 4}, {113, 1e-11, 4}, {256, 1e-11, 4}};
  o.max_control_points = 150'000'000;
  return o;
}

std::vector<UntrimCase> untrim_tolerance_cases(const UntrimToleranceOptions& opt) {
  const int p = 3;
  std::vector<UntrimCase> cases;
  for (int m = 1; m <= p + 1; ++m)
    for (const auto& run : opt.runs)
      for (double eps : opt.eps)
        if (!(eps < run.min_eps || m > run.max_m)) cases.push_back({m, run.bits, eps});
  return cases;
}

nlohmann::json untrim_tolerance_case(const UntrimCase& c, const UntrimToleranceOptions& opt) {
  const int p = 3;
  const Rational u0(1, 2);
  // S: the parabola case of the issue-3 surface study (experiments/common.hpp).
  const BSpline<Rational> S = parabola_trimming_inner();
  const auto T = spline_from<Rational>({p, 1}, {knots_with(p, u0, c.m), {0, 0, 1, 1}}, 2, [](const std::vector<std::size_t>& ij) {
    const std::size_t i = ij[0], j = ij[1];
    return std::vector<Rational>{Rational(static_cast<long>((i * i + 3 * j) % 7) - 3, 4), Rational(static_cast<long>((3 * i + j * j + 1) % 5), 3)};
  });
  Row r;
  if (c.bits == 0) {
    r = measure<double>(T, S, c.eps, opt);
  } else {
    Mpfr::Precision prec(c.bits);
    r = measure<Mpfr>(T, S, c.eps, opt);
  }
  r.m = c.m;
  return row_json(r);
}

nlohmann::json untrim_tolerance_options_json(const UntrimToleranceOptions& o) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& r : o.runs) runs.push_back({{"bits", r.bits}, {"min_eps", r.min_eps}, {"max_m", r.max_m}});
  return {{"eps", o.eps}, {"runs", runs}, {"max_boundary_samples", o.max_boundary_samples}, {"max_control_points", o.max_control_points}};
}

UntrimToleranceOptions untrim_tolerance_options_from_json(const nlohmann::json& j) {
  UntrimToleranceOptions o;
  o.eps = j.at("eps").get<std::vector<double>>();
  o.runs.clear();
  for (const auto& r : j.at("runs")) o.runs.push_back({r.at("bits").get<int>(), r.at("min_eps").get<double>(), r.at("max_m").get<int>()});
  o.max_boundary_samples = j.at("max_boundary_samples").get<std::size_t>();
  o.max_control_points = j.at("max_control_points").get<std::size_t>();
  return o;
}

std::string run_untrim_tolerance(const UntrimToleranceOptions& opt, const std::function<void(const std::string&)>& progress,
                                 bool& ok, std::size_t threads) {
  const auto cases = untrim_tolerance_cases(opt);
  std::vector<nlohmann::json> rows(cases.size());
  std::mutex lock;  // the progress callback and the partial file
  // Each case is deterministic and MPFR's precision is per thread: the rows do not depend on the
  // threads; they are merged in the cases' order.
  parallel_for(cases.size(), threads == 0 ? hardware_threads() : threads, [&](std::size_t k) {
    const auto& c = cases[k];
    {
      std::lock_guard<std::mutex> hold(lock);
      progress("untrimming tolerance: m = " + std::to_string(c.m) + ", " +
               (c.bits == 0 ? std::string("double") : "mpfr:" + std::to_string(c.bits)) + ", eps " + g(c.eps));
    }
    rows[k] = untrim_tolerance_case(c, opt);
    const Row r = row_from_json(rows[k]);
    // Long sweeps: every finished row is on disk at once, in the order rows finish (the final CSV
    // replaces this file).
    std::lock_guard<std::mutex> hold(lock);
    std::ofstream partial(opt.out_dir + "/untrim_tolerance.partial.csv", std::ios::app);
    partial << std::setprecision(17) << r.m << "," << r.arith << "," << r.eps << "," << r.control_points << "," << r.cpu_seconds << ","
            << to_double(r.deviation) << "," << to_double(r.gap) << "," << to_double(r.overlap) << "," << r.skipped << "\n";
  });
  return untrim_tolerance_merge(rows, opt, ok);
}

std::string untrim_tolerance_merge(const std::vector<nlohmann::json>& row_docs, const UntrimToleranceOptions& opt, bool& ok) {
  const int p = 3;
  std::vector<Row> rows;
  for (const auto& j : row_docs) rows.push_back(row_from_json(j));
  // CSV.
  std::ostringstream csv;
  csv << "multiplicity,arith,eps,tiles,trapezoids,max_chain_vertices,degree_x,degree_l,control_points,cpu_seconds,samples,"
         "max_abs_deviation,gap_area,overlap_area,skipped\n"
      << std::setprecision(17);
  for (const auto& r : rows)
    csv << r.m << "," << r.arith << "," << r.eps << "," << r.tiles << "," << r.trapezoids << "," << r.max_chain << ","
        << r.deg_x << "," << r.deg_l << "," << r.control_points << "," << r.cpu_seconds << "," << r.samples << ","
        << to_double(r.deviation) << "," << to_double(r.gap) << "," << to_double(r.overlap) << ","
        << (r.skipped ? "\"" + r.why + "\"" : std::string()) << "\n";
  // Slopes, plot series.
  std::vector<std::string> ariths;
  for (const auto& r : rows)
    if (std::find(ariths.begin(), ariths.end(), r.arith) == ariths.end()) ariths.push_back(r.arith);
  std::vector<PlotSeries> series, cost;
  std::ostringstream table;
  std::string arith_columns, arith_rules;
  for (const auto& a : ariths) {
    arith_columns += ReportTemplate("untrim-tolerance.column").set("arith", a).render();
    for (int k = 0; k < 2; ++k) arith_rules += "---|";
  }
  Rational worst_gap(0), worst_overlap(0);
  for (const auto& r : rows) {
    worst_gap = std::max(worst_gap, Rational(abs(r.gap)));
    worst_overlap = std::max(worst_overlap, Rational(abs(r.overlap)));
  }
  for (int m = 1; m <= p + 1; ++m) {
    const int predicted = m <= p ? p - m + 1 : 0;
    double judged = 0;
    table << "| " << m << " | " << (m <= p ? "C^" + std::to_string(p - m) : std::string("discontinuous")) << " | " << predicted
          << " |";
    for (std::size_t ai = 0; ai < ariths.size(); ++ai) {
      PlotSeries s;
      s.label = "m = " + std::to_string(m) + ", " + ariths[ai];
      s.color = svg::palette(m - 1);
      s.dashed = ai == 0;
      std::string last = "-";
      double last_eps = 1;
      bool any = false;
      for (const auto& r : rows)
        if (r.m == m && r.arith == ariths[ai] && !r.skipped) {
          any = true;
          if (r.deviation > 0) s.points.emplace_back(r.eps, to_double(r.deviation));
          if (r.eps <= last_eps) {
            last_eps = r.eps;
            last = g(to_double(r.deviation)) + " (eps " + g(r.eps) + ")";
          }
        }
      if (!any) {
        table << " - | - |";
        continue;
      }
      const double slope = loglog_slope(s.points);
      table << " " << g(slope) << " | " << last << " |";
      // The highest precision run for this m judges the slope; double may sit on its rounding floor.
      judged = slope;
      series.push_back(std::move(s));
    }
    if (std::fabs(judged - predicted) > 0.3) ok = false;
    table << " " << g(judged) << " |\n";
  }
  for (std::size_t ai = 0; ai < ariths.size(); ++ai) {
    PlotSeries s;
    s.label = "control points, " + ariths[ai] + " (m = 1)";
    s.color = ai == 0 ? "#444444" : "#ff7f0e";
    s.dashed = ai == 0;
    for (const auto& r : rows)
      if (r.m == 1 && r.arith == ariths[ai] && !r.skipped) s.points.emplace_back(r.eps, static_cast<double>(r.control_points));
    cost.push_back(std::move(s));
  }
  if (worst_gap != 0 || worst_overlap != 0) ok = false;
  std::vector<std::pair<double, double>> cp_pts;
  for (const auto& s : cost)
    for (const auto& pt : s.points) cp_pts.push_back(pt);
  write_file_atomically(opt.out_dir + "/untrim_tolerance.csv", csv.str());
  std::remove((opt.out_dir + "/untrim_tolerance.partial.csv").c_str());
  write_file_atomically(opt.out_dir + "/untrim_tolerance.svg",
                        svg_line_plot({"Algorithm 2 tiles: deviation from T(S) vs tolerance",
                                       "tolerance eps", "max |R(x,l) - T(S(Q(x,l)))| (exact)", true, true,
                                       "T degrees (3,1), knot of multiplicity m; dashed: double, solid: MPFR"},
                                      series));
  write_file_atomically(opt.out_dir + "/untrim_tolerance_cost.svg",
                        svg_line_plot({"Algorithm 2 tiles: control points vs tolerance",
                                       "tolerance eps", "control points", true, true,
                                       "polyline tiles: one Bezier piece per chain vertex"},
                                      cost));
  std::ostringstream md;
  const Row* first = nullptr;
  const Row* lastrow = nullptr;
  for (const auto& r : rows)
    if (r.m == 1 && r.arith == ariths.front() && !r.skipped) {
      if (!first) first = &r;
      lastrow = &r;
    }
  std::string cost_md;
  if (first && lastrow)
    cost_md = ReportTemplate("untrim-tolerance.cost")
                  .set("arith", ariths.front())
                  .set("eps_first", g(first->eps))
                  .set("tiles_first", first->tiles)
                  .set("degree_x", first->deg_x)
                  .set("degree_l", first->deg_l)
                  .set("chain_first", first->max_chain)
                  .set("control_points_first", first->control_points)
                  .set("seconds_first", g(first->cpu_seconds))
                  .set("eps_last", g(lastrow->eps))
                  .set("tiles_last", lastrow->tiles)
                  .set("chain_last", lastrow->max_chain)
                  .set("control_points_last", lastrow->control_points)
                  .set("seconds_last", g(lastrow->cpu_seconds))
                  .set("control_points_slope", g(loglog_slope(cp_pts)))
                  .render();
  md << ReportTemplate("untrim-tolerance")
            .set("boundary_samples", opt.max_boundary_samples / 2)
            .set("arith_columns", arith_columns)
            .set("arith_rules", arith_rules)
            .set("rows", table.str())
            .set("gap", g(to_double(worst_gap)))
            .set("overlap", g(to_double(worst_overlap)))
            .when("partition", worst_gap == 0 && worst_overlap == 0)
            .set("cost", cost_md)
            .render();
  write_file_atomically(opt.out_dir + "/untrim_tolerance.md", "# Untrimming tolerance study\n" + md.str());
  return md.str();
}

void untrim_tolerance_section(ReportContext& ctx) {
  UntrimToleranceOptions options;
  options.out_dir = ctx.options.out_dir;
  if (ctx.options.full) options = full_untrim_tolerance_options(ctx.options.out_dir);
  // The section's cases on the report's threads (the full sweep is hours of independent cases).
  ctx.markdown["untrim-tolerance"] = run_untrim_tolerance(options, ctx.progress, ctx.ok, ctx.options.jobs);
}

}  // namespace splinex
