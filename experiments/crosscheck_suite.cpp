// The crosscheck suite of `splinex report`: random curves, surfaces and trivariates of degrees
// 1-7, long refinements, adversarial inputs and the teapot, each operation run exactly and in every
// float arithmetic of the sweep, the errors measured exactly (crosscheck/).
#include <iomanip>
#include <map>
#include <random>
#include <sstream>

#include "crosscheck/crosscheck.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "fixtures/random_spline.hpp"
#include "fixtures/teapot.hpp"

namespace splinex {

namespace {

struct Row {
  std::string suite, case_name;
  int dim = 0, degree = 0;
  bool rational = false;
  std::size_t inserted = 0;  // knots inserted (refinement sweep)
  CrossReport rep;
};

std::string fmt(double v) {
  std::ostringstream o;
  if (v == 0) return "0";
  o << std::setprecision(3) << std::scientific << v;
  return o.str();
}
std::string fmt1(double v) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(1) << v;
  return o.str();
}

class Runner {
 public:
  explicit Runner(std::vector<std::string> ariths) : ariths_(std::move(ariths)) {}
  std::vector<Row> rows;

  void run(const std::string& suite, const std::string& name, const BSpline<Rational>& S, const Operation& op,
           std::size_t inserted = 0) {
    for (const auto& a : ariths_) {
      Row r;
      r.suite = suite;
      r.case_name = name;
      r.dim = S.dim();
      r.degree = *std::max_element(S.degrees.begin(), S.degrees.end());
      r.rational = S.is_rational();
      r.inserted = inserted;
      r.rep = crosscheck(op, S, ArithSpec::parse(a));
      rows.push_back(std::move(r));
    }
  }

 private:
  std::vector<std::string> ariths_;
};

Operation op_insert(int dir, std::vector<Rational> knots) {
  Operation op;
  op.kind = Operation::Kind::insert_knots;
  op.dir = dir;
  op.knots = std::move(knots);
  return op;
}
Operation op_elevate(int dir, int by) {
  Operation op;
  op.kind = Operation::Kind::elevate;
  op.dir = dir;
  op.by = by;
  return op;
}
Operation op_extract() {
  Operation op;
  op.kind = Operation::Kind::extract_bezier;
  return op;
}

// n random knots inside the domain of direction d, on a grid of 10^-6 of its width (fine enough for
// long refinements), never raising a multiplicity above the degree.
std::vector<Rational> random_knots(const BSpline<Rational>& S, int d, std::size_t n, std::mt19937_64& rng) {
  const Rational lo = S.domain_lo(d), w = S.domain_hi(d) - lo;
  std::map<long, std::size_t> used;
  std::vector<Rational> X;
  while (X.size() < n) {
    const long k = std::uniform_int_distribution<long>(1, 999999)(rng);
    const Rational x = lo + w * Rational(k, 1000000);
    if (multiplicity(S.knots[d], x) + ++used[k] > static_cast<std::size_t>(S.degrees[d])) continue;
    X.push_back(x);
  }
  return X;
}

std::string csv(const std::vector<Row>& rows) {
  std::ostringstream o;
  o << "suite,case,dim,degree,rational,inserted,operation,arith,precision,structure,control_points,"
       "cp_abs_error,cp_rel_error,cp_bits_lost,grid_abs_error,grid_rel_error,grid_bits_lost,knot_abs_error,"
       "seconds_exact,seconds_float\n";
  o << std::setprecision(17);
  for (const auto& r : rows) {
    const auto& c = r.rep;
    o << r.suite << "," << r.case_name << "," << r.dim << "," << r.degree << "," << r.rational << "," << r.inserted << ","
      << c.operation << "," << c.arith << "," << c.precision << "," << (c.structure_match ? "equal" : "different") << "," << c.control_point_count << ","
      << c.control_points.abs() << "," << c.control_points.rel() << "," << c.control_points.bits_lost(c.precision) << ","
      << c.grid.abs() << "," << c.grid.rel() << "," << c.grid.bits_lost(c.precision) << "," << c.knots.abs() << ","
      << c.seconds_exact << "," << c.seconds_float << "\n";
  }
  return o.str();
}

// 1. Random curves, surfaces and trivariates of degrees 1-7.
void run_random_suite(ReportContext& ctx, Runner& run) {
  const ReportOptions& opt = ctx.options;
  const auto& progress = ctx.progress;
  std::mt19937_64& rng = ctx.rng;
  const int max_deg = 7;
  for (int dim = 1; dim <= 3; ++dim) {
    for (int p = 1; p <= max_deg; ++p) {
      progress("random suite: dimension " + std::to_string(dim) + ", degree " + std::to_string(p));
      for (bool rational : {false, true}) {
        RandomSplineSpec spec;
        const std::size_t extra = dim == 1 ? (opt.full ? 40 : 12) : dim == 2 ? (opt.full ? 8 : 4) : (opt.full ? 3 : 1);
        spec.degrees.assign(dim, p);
        spec.counts.assign(dim, p + 1 + extra);
        spec.q = dim == 3 ? 4 : 3;  // a trivariate carries one attribute
        spec.rational = rational;
        const auto S = random_spline(spec, rng);
        const std::string name = "random-" + std::to_string(dim) + "d-p" + std::to_string(p) + (rational ? "-rational" : "");
        run.run("random", name, S, op_insert(dim - 1, random_knots(S, dim - 1, dim == 1 ? 16 : 4, rng)));
        run.run("random", name, S, op_elevate(0, 2));
        if (dim < 3 || p <= 4) run.run("random", name, S, op_extract());
      }
    }
  }
}

// 2. Error against the number of inserted knots (long refinements), degree 3 and 5 curves.
void run_refinement_sweep(ReportContext& ctx, Runner& run) {
  const auto& progress = ctx.progress;
  std::mt19937_64& rng = ctx.rng;
  const std::size_t max_ins = ctx.options.full ? 4096 : 512;
  for (int p : {3, 5}) {
    RandomSplineSpec spec;
    spec.degrees = {p};
    spec.counts = {static_cast<std::size_t>(p + 1 + 8)};
    const auto S = random_spline(spec, rng);
    for (std::size_t n = 1; n <= max_ins; n *= 4) {
      progress("refinement sweep: degree " + std::to_string(p) + ", " + std::to_string(n) + " knots");
      run.run("refinement", "curve-p" + std::to_string(p), S, op_insert(0, random_knots(S, 0, n, rng)), n);
    }
    // Knot by knot (Boehm) for the same lengths: rounding errors compound through the steps.
    for (std::size_t n = 1; n <= max_ins / 4; n *= 4) {
      Operation op = op_insert(0, random_knots(S, 0, n, rng));
      op.boehm = true;
      run.run("refinement-boehm", "curve-p" + std::to_string(p), S, op, n);
    }
  }
}

// 3. Adversarial inputs.
void run_adversarial_cases(ReportContext& ctx, Runner& run) {
  std::mt19937_64& rng = ctx.rng;
  ctx.progress("adversarial cases");
  // Nearly coincident knots: 1/10 and 1/10 + 2^-50 (distinct in double: 64 ulps apart).
  const Rational eps = Rational(1) / Rational(Integer(1) << 50);
  const auto S = spline_from<Rational>({3}, {clamped_knots(3, Rational(0), Rational(1), {Rational(1, 10), Rational(1, 10) + eps, Rational(1, 2)})},
                            2, [](const std::vector<std::size_t>& idx) {
                              const int i = static_cast<int>(idx[0]);
                              return std::vector<Rational>{Rational(i * i - 3 * i, 7), Rational(2 * i + 1, 3)};
                            });
  run.run("adversarial", "near-coincident-knots", S, op_insert(0, {Rational(1, 10) + eps / 2, Rational(1, 10) - eps}));
  run.run("adversarial", "near-coincident-knots", S, op_elevate(0, 2));
  Operation blossom = op_elevate(0, 2);
  blossom.method = ElevationMethod::blossom;  // the same map by the blossom: is the loss A5.9's?
  run.run("adversarial", "near-coincident-knots", S, blossom);
  run.run("adversarial", "near-coincident-knots", S, op_extract());
  // High degree: elevate a cubic to degree 15, and insert into a degree-15 curve.
  RandomSplineSpec spec;
  spec.degrees = {3};
  spec.counts = {10};
  const auto C = random_spline(spec, rng);
  run.run("adversarial", "elevate-3-to-15", C, op_elevate(0, 12));
  Operation blossom15 = op_elevate(0, 12);
  blossom15.method = ElevationMethod::blossom;
  run.run("adversarial", "elevate-3-to-15", C, blossom15);
  spec.degrees = {15};
  spec.counts = {24};
  const auto H = random_spline(spec, rng);
  run.run("adversarial", "degree-15", H, op_insert(0, random_knots(H, 0, 8, rng)));
  run.run("adversarial", "degree-15", H, op_extract());
  // Long refinement: 1000 knots into a cubic, all at once and near one point.
  std::vector<Rational> cluster;
  for (int i = 1; i <= 1000; ++i) cluster.push_back(Rational(1, 3) + Rational(i, 1000000000));
  run.run("adversarial", "1000-clustered-knots", C, op_insert(0, cluster));
}

// 4. The teapot: four bicubic B-spline surfaces merged exactly from data/teapot.bpt.
void run_teapot_cases(ReportContext& ctx, Runner& run) {
  ctx.progress("teapot surfaces");
  const auto patches = read_bpt(data_path("teapot.bpt"));
  for (const auto& t : teapot_surfaces(patches)) {
    const auto& S = t.surface;
    std::vector<Rational> mids;
    for (std::size_t i = 0; i + 1 < breakpoints(S.knots[0], 3, S.count(0)).size(); ++i) mids.push_back(Rational(2 * i + 1, 2));
    run.run("teapot", t.name, S, op_insert(0, mids));
    run.run("teapot", t.name, S, op_insert(1, {Rational(1, 3), Rational(1, 10)}));
    run.run("teapot", t.name, S, op_elevate(1, 1));
    run.run("teapot", t.name, S, op_extract());
  }
}

// The data: crosscheck.csv and crosscheck.json.
void write_data(const std::string& out_dir, const std::vector<Row>& rows) {
  write_file_atomically(out_dir + "/crosscheck.csv", csv(rows));
  Json all = Json::array();
  for (const auto& r : rows) {
    Json j = r.rep.document();
    j["suite"] = r.suite;
    j["case"] = r.case_name;
    j["dim"] = r.dim;
    j["degree"] = r.degree;
    j["rational"] = r.rational;
    j["inserted"] = r.inserted;
    all.push_back(std::move(j));
  }
  write_file_atomically(out_dir + "/crosscheck.json", all.dump(1) + "\n");
}

// The figures: error and bits lost against degree, error against inserted knots.
void write_figures(const std::string& out_dir, const std::vector<Row>& rows, const std::vector<std::string>& ariths) {
  // Figures 1 and 1b: worst grid error against degree, per operation and arithmetic, as a relative
  // error (log scale) and as bits lost (linear; comparable across precisions).
  auto by_degree = [&](bool bits) {
    std::vector<PlotSeries> out;
    int ci = 0;
    for (const std::string opn : {"insert-knots", "elevate"})
      for (const auto& a : ariths) {
        PlotSeries s;
        s.label = opn + ", " + a;
        s.color = svg::palette(ci++);
        s.dashed = opn == "elevate";
        std::map<int, double> worst;
        for (const auto& r : rows)
          if (r.suite == "random" && r.rep.operation == opn && r.rep.arith == a)
            worst[r.degree] = std::max(worst[r.degree], bits ? r.rep.grid.bits_lost(r.rep.precision) : r.rep.grid.rel());
        for (auto [d, e] : worst) s.points.emplace_back(d, e);
        out.push_back(std::move(s));
      }
    return out;
  };
  const std::string note = "random curves, surfaces, trivariates; worst over dimension and rationality";
  write_file_atomically(out_dir + "/error_vs_degree.svg",
                        svg_line_plot({"Max relative error of evaluated points vs degree", "degree",
                                       "max relative error (exact measurement)", false, true, note},
                                      by_degree(false)));
  write_file_atomically(out_dir + "/bits_lost_vs_degree.svg",
                        svg_line_plot({"Bits lost at evaluated points vs degree", "degree", "bits lost", false, false, note},
                                      by_degree(true)));
  // Figure 2: error against number of inserted knots.
  std::vector<PlotSeries> s2;
  int ci = 0;
  for (const std::string suite : {"refinement", "refinement-boehm"})
    for (const std::string cname : {"curve-p3", "curve-p5"})
      for (const auto& a : ariths) {
        PlotSeries s;
        s.label = (suite == "refinement" ? "A5.4 " : "A5.1 ") + cname.substr(6) + ", " + a;
        s.color = svg::palette(ci++);
        s.dashed = suite != "refinement";
        for (const auto& r : rows)
          if (r.suite == suite && r.case_name == cname && r.rep.arith == a)
            s.points.emplace_back(static_cast<double>(r.inserted), r.rep.control_points.rel());
        s2.push_back(std::move(s));
      }
  write_file_atomically(out_dir + "/error_vs_inserted_knots.svg",
                        svg_line_plot({"Control-point relative error vs number of inserted knots", "knots inserted",
                                       "max relative error (exact measurement)", true, true,
                                       "errors that are exactly zero are drawn on the bottom line"},
                                      s2));
}

// report.md's introduction: how the errors are measured, which arithmetics ran.
std::string intro_markdown(const ReportOptions& opt, const std::vector<std::string>& ariths) {
  std::string arithmetics;
  for (const auto& a : ariths) arithmetics += "`" + a + "` ";
  return ReportTemplate("crosscheck.intro").set("arithmetics", arithmetics).when("full", opt.full).render();
}

// The rows of one suite's table of report.md: every case, operation and arithmetic.
std::string suite_rows(const std::vector<Row>& rows, const std::string& suite) {
  std::ostringstream md;
  for (const auto& r : rows) {
    if (r.suite != suite) continue;
    const auto& c = r.rep;
    if (!c.structure_match) {
      md << ReportTemplate("crosscheck.tables.structure-differs")
                .set("case", r.case_name)
                .set("operation", c.operation)
                .set("arith", c.arith)
                .set("control_points", c.control_point_count)
                .set("note", c.structure_note)
                .render();
      continue;
    }
    md << "| " << r.case_name << " | " << c.operation << " | " << c.arith << " | " << c.control_point_count << " | "
       << fmt(c.control_points.rel()) << " | " << fmt1(c.control_points.bits_lost(c.precision)) << " | " << fmt(c.grid.rel())
       << " | " << fmt1(c.grid.bits_lost(c.precision)) << " | " << fmt(c.seconds_exact) << " | " << fmt(c.seconds_float)
       << " |\n";
  }
  return md.str();
}

// report.md's tables: the suites, the time summary, where the raw data is.
std::string tables_markdown(const std::vector<Row>& rows) {
  // Time ratio summary.
  std::map<std::string, std::pair<double, double>> tsum;
  for (const auto& r : rows) {
    tsum[r.rep.arith].first += r.rep.seconds_exact;
    tsum[r.rep.arith].second += r.rep.seconds_float;
  }
  std::ostringstream time_rows;
  for (auto [a, t] : tsum) time_rows << "| " << a << " | " << fmt(t.first) << " | " << fmt(t.second) << " | " << fmt1(t.first / t.second) << " |\n";
  // No folder in the text (crosscheck.tables.md): the same words wherever the report (or a sweep job of it) was written.
  return ReportTemplate("crosscheck.tables")
      .set("adversarial_rows", suite_rows(rows, "adversarial"))
      .set("teapot_rows", suite_rows(rows, "teapot"))
      .set("refinement_rows", suite_rows(rows, "refinement"))
      .set("refinement_boehm_rows", suite_rows(rows, "refinement-boehm"))
      .set("random_rows", suite_rows(rows, "random"))
      .set("time_rows", time_rows.str())
      .render();
}

}  // namespace

void crosscheck_section(ReportContext& ctx) {
  const ReportOptions& opt = ctx.options;
  const std::vector<std::string> ariths = opt.full ? std::vector<std::string>{"double", "mpfr:24", "mpfr:64", "mpfr:113", "mpfr:256"}
                                                   : std::vector<std::string>{"double", "mpfr:113"};
  Runner run(ariths);
  // The cases, in the order they draw from the seeded stream.
  run_random_suite(ctx, run);
  run_refinement_sweep(ctx, run);
  run_adversarial_cases(ctx, run);
  run_teapot_cases(ctx, run);

  ctx.crosschecks = run.rows.size();
  for (const auto& r : run.rows) ctx.float_structures_match = ctx.float_structures_match && r.rep.structure_match;

  // Files: the data and the figures.
  write_data(opt.out_dir, run.rows);
  write_figures(opt.out_dir, run.rows, ariths);

  // report.md: the introduction, the figures, the tables.
  ctx.markdown["crosscheck.intro"] = intro_markdown(opt, ariths);
  ctx.markdown["crosscheck.figures"] = ReportTemplate("crosscheck.figures").render();
  ctx.markdown["crosscheck.tables"] = tables_markdown(run.rows);
}

}  // namespace splinex
