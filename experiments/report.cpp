#include "experiments/report.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <sstream>

#include "crosscheck/crosscheck.hpp"
#include "exact/bpt.hpp"
#include "exact/random_spline.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/algorithm2_stars.hpp"
#include "experiments/untrim_tolerance.hpp"
#include "experiments/checkerboard.hpp"
#include "experiments/curved_untrim.hpp"
#include "experiments/hybrid_experiment.hpp"
#include "experiments/teapot_stars.hpp"
#include "experiments/tolerance_study.hpp"
#include "proofs/suite.hpp"
#include "spline/compose.hpp"

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
  o << "suite,case,dim,degree,rational,inserted,operation,arith,precision_bits,structure_match,control_points,"
       "cp_abs_error,cp_rel_error,cp_bits_lost,grid_abs_error,grid_rel_error,grid_bits_lost,knot_abs_error,"
       "seconds_exact,seconds_float\n";
  o << std::setprecision(17);
  for (const auto& r : rows) {
    const auto& c = r.rep;
    o << r.suite << "," << r.case_name << "," << r.dim << "," << r.degree << "," << r.rational << "," << r.inserted << ","
      << c.operation << "," << c.arith << "," << c.precision << "," << c.structure_match << "," << c.control_point_count << ","
      << c.control_points.abs() << "," << c.control_points.rel() << "," << c.control_points.bits_lost(c.precision) << ","
      << c.grid.abs() << "," << c.grid.rel() << "," << c.grid.bits_lost(c.precision) << "," << c.knots.abs() << ","
      << c.seconds_exact << "," << c.seconds_float << "\n";
  }
  return o.str();
}

const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"};

}  // namespace

int run_report(const ReportOptions& opt) {
  namespace fs = std::filesystem;
  using clock = std::chrono::steady_clock;
  const auto t_start = clock::now();
  fs::create_directories(opt.out_dir);
  // A manifest marked incomplete first: an interrupted run (Ctrl-C) leaves it so, and its files
  // cannot pass for a finished report. Writing it also probes that the folder is writable before
  // minutes of work.
  const std::string manifest = opt.out_dir + "/MANIFEST.json";
  {
    std::ofstream probe(manifest + ".tmp");
    if (!probe)
      throw UsageError("out", "cannot write into " + opt.out_dir, "give a writable folder with --out");
  }
  fs::remove(manifest + ".tmp");
  write_file_atomically(manifest, "{\"status\": \"incomplete\", \"note\": \"a run started here and has not finished; "
                                  "files in this folder may be from it or from an older run\"}\n");
  auto progress = [&](const std::string& s) {
    std::cerr << "[report " << std::fixed << std::setprecision(1)
              << std::chrono::duration<double>(clock::now() - t_start).count() << "s] " << s << std::endl;
  };
  const std::vector<std::string> ariths = opt.full ? std::vector<std::string>{"double", "mpfr:24", "mpfr:64", "mpfr:113", "mpfr:256"}
                                                   : std::vector<std::string>{"double", "mpfr:113"};
  Runner run(ariths);
  std::mt19937_64 rng(20261121);

  // 1. Random curves, surfaces and trivariates of degrees 1-7.
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

  // 2. Error against the number of inserted knots (long refinements), degree 3 and 5 curves.
  const std::size_t max_ins = opt.full ? 4096 : 512;
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

  // 3. Adversarial inputs.
  progress("adversarial cases");
  {
    // Nearly coincident knots: 1/10 and 1/10 + 2^-50 (distinct in double: 64 ulps apart).
    const Rational eps = Rational(1) / Rational(Integer(1) << 50);
    BSpline<Rational> S;
    S.degrees = {3};
    S.q = 2;
    S.knots = {{0, 0, 0, 0, Rational(1, 10), Rational(1, 10) + eps, Rational(1, 2), 1, 1, 1, 1}};
    for (int i = 0; i < 7; ++i) {
      S.points.push_back(Rational(i * i - 3 * i, 7));
      S.points.push_back(Rational(2 * i + 1, 3));
    }
    validate(S);
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
  progress("teapot surfaces");
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

  // 5. Composition orders of the paper's examples (papers/000, Section 3), from exact inputs of the
  //    stated orders: the composed orders are read off the computed compositions.
  progress("composition orders");
  struct OrdersCase {
    std::string name;
    std::vector<int> inner_orders, outer_orders;
    std::string paper, remark;
  };
  const std::vector<OrdersCase> orders_cases{
      {"teapot star pattern (Fig. 4)", {3, 3}, {4, 4}, "(13, 13)", "matches"},
      {"cross into duck trivariate (Fig. 6)", {2, 3}, {3, 3, 4}, "(8, 25)",
       "differs in the second direction: d x sum(e) = 2 x 7 = 14 gives order 15; 25 would need sum(e) = 12, "
       "which the stated (3, 3, 4) does not give, while 8 = 1 x 7 + 1 agrees with sum(e) = 7; we cannot reproduce 25 from the stated orders"},
      {"pipes into twisted torus (Fig. 7)", {4, 4}, {2, 2, 3}, "(13, 13)", "matches"},
      {"bushing (Fig. 8)", {2, 3}, {2, 3, 3}, "(11, 6)", "same orders with the two surface directions listed the other way"},
  };
  std::ostringstream orders_md;
  orders_md << "\n## Composition orders of the paper's examples\n\nInner and outer Bezier pieces with the stated orders "
               "(random exact control points, inner inside the outer box), composed exactly; the orders are those of the "
               "computed result, checked against the other method and by R(r) = T(S(r)) at a point.\n\n"
               "| example | inner orders | outer orders | computed orders | paper | remark |\n|---|---|---|---|---|---|\n";
  auto show_orders = [](const std::vector<int>& o) {
    std::string s = "(";
    for (std::size_t i = 0; i < o.size(); ++i) s += (i ? ", " : "") + std::to_string(o[i]);
    return s + ")";
  };
  bool orders_ok = true;
  for (const auto& oc : orders_cases) {
    RandomSplineSpec si, so;
    for (int o : oc.inner_orders) { si.degrees.push_back(o - 1); si.counts.push_back(o); }
    for (int o : oc.outer_orders) { so.degrees.push_back(o - 1); so.counts.push_back(o); }
    si.q = static_cast<int>(oc.outer_orders.size());
    so.q = 3;
    BSpline<Rational> S = random_spline(si, rng);
    const BSpline<Rational> T = random_spline(so, rng);
    for (auto& x : S.points) x = (x + 2) / 4;  // into the outer box [0, 1]^n
    const auto R = compose_bezier(T, S, CompositionMethod::symbolic);
    const auto R2 = compose_bezier(T, S, CompositionMethod::interpolation);
    std::vector<Rational> at;
    for (int l = 0; l < S.dim(); ++l) at.emplace_back(1, 3 + l);
    const bool ok = R.points == R2.points && evaluate(R, at) == evaluate(T, evaluate(S, at));
    orders_ok = orders_ok && ok;
    std::vector<int> ro;
    for (int d : R.degrees) ro.push_back(d + 1);
    orders_md << "| " << oc.name << " | " << show_orders(oc.inner_orders) << " | " << show_orders(oc.outer_orders) << " | "
              << show_orders(ro) << (ok ? "" : " (**check failed**)") << " | " << oc.paper << " | " << oc.remark << " |\n";
  }

  // 6. The teapot star pattern (Algorithm 1, exact and double).
  progress("teapot star pattern");
  bool stars_ok = true;
  StarPatternOptions so;
  so.out_dir = opt.out_dir;
  const std::string stars_md = run_teapot_stars(so, progress, stars_ok);

  // 7. The price of a trimming tolerance, measured exactly.
  bool tol_ok = true;
  const std::string tol_md = run_tolerance_study(opt.out_dir, progress, tol_ok);

  // 8. Algorithm 2 (untrimming) on the star pattern.
  bool a2_ok = true;
  Algorithm2StarsOptions a2o;
  a2o.out_dir = opt.out_dir;
  if (!opt.full) a2o.eps = {1e-2, 1e-3};
  const std::string a2_md = run_algorithm2_stars(a2o, progress, a2_ok);

  // 8b. The tolerance of untrimming: eps, continuity, precision.
  bool ut_ok = true;
  UntrimToleranceOptions uto;
  uto.out_dir = opt.out_dir;
  if (opt.full) uto = full_untrim_tolerance_options(opt.out_dir);
  const std::string ut_md = run_untrim_tolerance(uto, progress, ut_ok);
  progress("checkerboard texture (Definition 1)");
  const std::string cb_md = run_checkerboard(opt.out_dir, ut_ok);
  progress("untrimming with curved tile sides");
  const std::string cu_md = run_curved_untrim(opt.out_dir, ut_ok);
  progress("hybrid patch (papers/003)");
  bool hy_ok = true;
  const std::string hy_md = run_hybrid_experiment(opt.out_dir, hy_ok);

  // 9. The proofs.
  progress("exact proofs");
  const auto proofs = run_proofs({}, opt.full ? 40 : 12);

  // ---- outputs ----
  progress("writing " + opt.out_dir);
  write_file_atomically(opt.out_dir + "/crosscheck.csv", csv(run.rows));
  Json all = Json::array();
  for (const auto& r : run.rows) {
    Json j = r.rep.to_json();
    j["suite"] = r.suite;
    j["case"] = r.case_name;
    j["dim"] = r.dim;
    j["degree"] = r.degree;
    j["rational"] = r.rational;
    j["inserted"] = r.inserted;
    all.push_back(std::move(j));
  }
  write_file_atomically(opt.out_dir + "/crosscheck.json", all.dump(1) + "\n");

  // Figures 1 and 1b: worst grid error against degree, per operation and arithmetic, as a relative
  // error (log scale) and as bits lost (linear; comparable across precisions).
  auto by_degree = [&](bool bits) {
    std::vector<PlotSeries> out;
    int ci = 0;
    for (const std::string opn : {"insert-knots", "elevate"})
      for (const auto& a : ariths) {
        PlotSeries s;
        s.label = opn + ", " + a;
        s.color = kColors[ci++ % 8];
        s.dashed = opn == "elevate";
        std::map<int, double> worst;
        for (const auto& r : run.rows)
          if (r.suite == "random" && r.rep.operation == opn && r.rep.arith == a)
            worst[r.degree] = std::max(worst[r.degree], bits ? r.rep.grid.bits_lost(r.rep.precision) : r.rep.grid.rel());
        for (auto [d, e] : worst) s.points.emplace_back(d, e);
        out.push_back(std::move(s));
      }
    return out;
  };
  const std::string note = "random curves, surfaces, trivariates; worst over dimension and rationality";
  write_file_atomically(opt.out_dir + "/error_vs_degree.svg",
                        svg_line_plot({"Max relative error of evaluated points vs degree", "degree",
                                       "max relative error (exact measurement)", false, true, note},
                                      by_degree(false)));
  write_file_atomically(opt.out_dir + "/bits_lost_vs_degree.svg",
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
        s.color = kColors[ci++ % 8];
        s.dashed = suite != "refinement";
        for (const auto& r : run.rows)
          if (r.suite == suite && r.case_name == cname && r.rep.arith == a)
            s.points.emplace_back(static_cast<double>(r.inserted), r.rep.control_points.rel());
        s2.push_back(std::move(s));
      }
  write_file_atomically(opt.out_dir + "/error_vs_inserted_knots.svg",
                        svg_line_plot({"Control-point relative error vs number of inserted knots", "knots inserted",
                                       "max relative error (exact measurement)", true, true,
                                       "errors that are exactly zero are drawn on the bottom line"},
                                      s2));

  // report.md
  std::ostringstream md;
  md << "# splinex report\n\n"
     << "Every number below is measured exactly: each float result is converted to the rational it is and "
        "subtracted from the exact (GMP rational) result of the same exact input. Relative errors are normwise "
        "(max |error| / max |exact value| over the compared set); *bits lost* is precision + log2(relative error), "
        "clamped to [0, precision]. Inputs are rounded once to the float format, so a well-conditioned operation "
        "shows about 0-3 bits lost.\n\n"
     << "Arithmetics: " ;
  for (const auto& a : ariths) md << "`" << a << "` ";
  md << (opt.full ? "(full sweep)" : "(default sweep; `splinex report --full` runs the long one)") << ".\n\n";

  md << "## Proofs (exact, by identity)\n\n`proved`: an identity argument (degree bound, enough points per cell) covers "
        "the claim on every case; `checked at N points`: sampled, no identity argument; `refuted`: with the exact "
        "counterexample.\n\n| proof | verdict | cases | exact comparisons | degree bound | input structures |\n|---|---|---|---|---|---|\n";
  bool proofs_ok = true;
  for (const auto& p : proofs) {
    proofs_ok = proofs_ok && p.as_expected();
    std::string structures;
    for (const auto& t : p.structures) structures += (structures.empty() ? "" : ", ") + t;
    md << "| " << p.name << " | " << (p.refuted() ? "**" + p.verdict() + "**: " + p.counterexample : p.verdict())
       << (p.as_expected() ? "" : " **UNEXPECTED**") << " | " << p.cases << " | "
       << p.points << " | " << p.degree_bound << " | " << structures << " |\n";
  }

  auto table = [&](const std::string& suite, const std::string& title) {
    md << "\n## " << title << "\n\n| case | operation | arith | control points | cp rel error | cp bits lost | grid rel error "
          "| grid bits lost | exact s | float s |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : run.rows) {
      if (r.suite != suite) continue;
      const auto& c = r.rep;
      if (!c.structure_match) {
        md << "| " << r.case_name << " | " << c.operation << " | " << c.arith << " | " << c.control_point_count
           << " | structure differs: " << c.structure_note << " | | | | | |\n";
        continue;
      }
      md << "| " << r.case_name << " | " << c.operation << " | " << c.arith << " | " << c.control_point_count << " | "
         << fmt(c.control_points.rel()) << " | " << fmt1(c.control_points.bits_lost(c.precision)) << " | " << fmt(c.grid.rel())
         << " | " << fmt1(c.grid.bits_lost(c.precision)) << " | " << fmt(c.seconds_exact) << " | " << fmt(c.seconds_float)
         << " |\n";
    }
  };
  md << "\n## Figures\n\n![error vs degree](error_vs_degree.svg)\n\n![bits lost vs degree](bits_lost_vs_degree.svg)\n\n"
        "![error vs inserted knots](error_vs_inserted_knots.svg)\n";
  md << orders_md.str() << stars_md << tol_md << a2_md << cb_md << cu_md << ut_md << hy_md;
  table("adversarial", "Adversarial inputs");
  table("teapot", "Teapot (body, handle, spout, lid as bicubic B-spline surfaces)");
  table("refinement", "Refinement sweep (A5.4, all knots at once)");
  table("refinement-boehm", "Refinement sweep (A5.1, knot by knot)");
  table("random", "Random curves, surfaces and trivariates, degrees 1-7");
  // Time ratio summary.
  std::map<std::string, std::pair<double, double>> tsum;
  for (const auto& r : run.rows) {
    tsum[r.rep.arith].first += r.rep.seconds_exact;
    tsum[r.rep.arith].second += r.rep.seconds_float;
  }
  md << "\n## Time (whole suite, wall clock; Google Benchmark in `bench/` for real timings)\n\n| arith | exact s | float s | exact/float |\n|---|---|---|---|\n";
  for (auto [a, t] : tsum) md << "| " << a << " | " << fmt(t.first) << " | " << fmt(t.second) << " | " << fmt1(t.first / t.second) << " |\n";
  md << "\nRaw data: `crosscheck.csv`, `crosscheck.json`. Regenerate with `build/bin/splinex report --out " << opt.out_dir << "`.\n";
  write_file_atomically(opt.out_dir + "/report.md", md.str());
  {
    std::ostringstream mf;
    mf << "{\"status\": \"complete\", \"files\": [";
    bool first = true;
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(opt.out_dir))
      if (e.is_regular_file() && e.path().filename() != "MANIFEST.json") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    for (const auto& n : names) {
      mf << (first ? "" : ", ") << "\"" << n << "\"";
      first = false;
    }
    mf << "]}\n";
    write_file_atomically(manifest, mf.str());
  }
  bool all_ran = true;
  for (const auto& r : run.rows) all_ran = all_ran && r.rep.structure_match;
  progress(std::string("done: ") + std::to_string(run.rows.size()) + " crosschecks, proofs " + (proofs_ok ? "all verdicts as expected" : "UNEXPECTED VERDICT") +
           (all_ran ? "" : ", some float runs differ in structure (see report.md)"));
  return proofs_ok && orders_ok && stars_ok && tol_ok && a2_ok && ut_ok && hy_ok ? 0 : 1;
}

}  // namespace splinex
