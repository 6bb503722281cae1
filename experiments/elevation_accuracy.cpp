// What each degree-elevation method loses in double, measured exactly, against the degree and the
// number of control points (issue 15, target 4): A5.9 (Bezier pieces, then knot removal) and the
// blossom, on random clamped curves with dyadic data (k/1024: the input is exact in double, so
// every bit lost is the method's). The exact reference is A5.9 in GMP rationals; the blossom's
// exact result equals it (the kernel proof `elevation methods agree`).
#include <iomanip>
#include <map>
#include <sstream>

#include "crosscheck/crosscheck.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "fixtures/random_spline.hpp"
#include "float/rounding.hpp"
#include "spline/elevate.hpp"

namespace splinex {

namespace {

struct Method {
  const char* name;
  ElevationMethod method;
};
constexpr Method kMethods[] = {{"A5.9", ElevationMethod::bezier_pieces}, {"blossom", ElevationMethod::blossom}};

std::string sci(double v) {
  if (v == 0) return "0";
  std::ostringstream o;
  o << std::setprecision(2) << std::scientific << v;
  return o.str();
}

std::string fixed1(double v) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(1) << v;
  return o.str();
}

}  // namespace

void elevation_accuracy_section(ReportContext& ctx) {
  ctx.progress("elevation accuracy (A5.9 and blossom in double)");
  const std::vector<int> degrees{1, 2, 3, 4, 5, 6, 7, 8, 9};
  const std::vector<std::size_t> counts{16, 64, 256, 1024};
  const int seeds = 3;
  std::mt19937_64 rng(20261202);  // its own stream: the sections before it draw the same numbers as before
  std::map<std::tuple<std::string, int, std::size_t>, ErrorStat> cells;  // worst over the seeds
  std::ostringstream csv;
  csv << "method,degree,count,seed,abs_error,rel_error,bits_lost\n";
  for (int p : degrees)
    for (std::size_t n : counts)
      for (int seed = 0; seed < seeds; ++seed) {
        RandomSplineSpec spec;
        spec.degrees = {p};
        spec.counts = {n};
        spec.q = 3;
        spec.dyadic = true;
        spec.max_interior_multiplicity = 1;
        const BSpline<Rational> S = random_spline(spec, rng);
        const BSpline<Rational> E = elevate_degree(S, 0, 1, ElevationMethod::bezier_pieces);
        const BSpline<double> F = round_spline<double>(S);
        for (const Method& m : kMethods) {
          const BSpline<double> R = elevate_degree(F, 0, 1, m.method);
          ErrorStat one;
          if (R.points.size() != E.points.size()) {
            ctx.ok = false;
            ctx.progress(std::string("elevation accuracy: ") + m.name + " changed the structure at p = " + std::to_string(p));
            continue;
          }
          ErrorStat& cell = cells[{m.name, p, n}];
          for (std::size_t i = 0; i < E.points.size(); ++i) {
            const Rational r = exact_from_double(R.points[i], "elevated control point");
            one.add(E.points[i], r);
            cell.add(E.points[i], r);
          }
          csv << m.name << "," << p << "," << n << "," << seed << "," << sci(one.abs()) << "," << sci(one.rel()) << ","
              << fixed1(one.bits_lost(53)) << "\n";
        }
      }
  write_file_atomically(ctx.options.out_dir + "/elevation_accuracy.csv", csv.str());

  auto bits = [&](const std::string& m, int p, std::size_t n) { return cells.at({m, p, n}).bits_lost(53); };
  std::vector<PlotSeries> by_degree, by_count;
  int ci = 0;
  for (const Method& m : kMethods)
    for (std::size_t n : counts) {
      PlotSeries s;
      s.label = std::string(m.name) + ", n = " + std::to_string(n);
      s.color = svg::palette(ci++);
      s.dashed = std::string(m.name) == "blossom";
      for (int p : degrees) s.points.emplace_back(p, bits(m.name, p, n));
      by_degree.push_back(std::move(s));
    }
  ci = 0;
  for (const Method& m : kMethods)
    for (int p : {3, 5, 7, 9}) {
      PlotSeries s;
      s.label = std::string(m.name) + ", p = " + std::to_string(p);
      s.color = svg::palette(ci++);
      s.dashed = std::string(m.name) == "blossom";
      for (std::size_t n : counts) s.points.emplace_back(static_cast<double>(n), bits(m.name, p, n));
      by_count.push_back(std::move(s));
    }
  const std::string note = "random clamped curves in R^3, simple dyadic knots and coordinates; worst of " +
                           std::to_string(seeds) + " curves per point; control points measured exactly";
  write_file_atomically(ctx.options.out_dir + "/elevation_bits_vs_degree.svg",
                        svg_line_plot({"Degree elevation by one in double: bits lost vs degree", "degree p", "bits lost",
                                       false, false, note},
                                      by_degree));
  write_file_atomically(ctx.options.out_dir + "/elevation_bits_vs_count.svg",
                        svg_line_plot({"Degree elevation by one in double: bits lost vs control points", "control points n",
                                       "bits lost", true, false, note},
                                      by_count));

  std::string count_columns, count_rules;
  for (std::size_t n : counts) {
    count_columns += ReportTemplate("elevation-accuracy.column").set("n", n).render();
    count_rules += "---|";
  }
  std::ostringstream rows;
  for (int p : degrees) {
    rows << "| " << p << " |";
    for (std::size_t n : counts) rows << " " << fixed1(bits("A5.9", p, n)) << " / " << fixed1(bits("blossom", p, n)) << " |";
    rows << "\n";
  }
  ctx.markdown["elevation-accuracy"] = ReportTemplate("elevation-accuracy")
                                           .set("curves", seeds)
                                           .set("count_columns", count_columns)
                                           .set("count_rules", count_rules)
                                           .set("rows", rows.str())
                                           .render();
}

}  // namespace splinex
