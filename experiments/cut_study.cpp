// The report's section on papers/004 (cutting curves, d = 2): Table 1's examples run exactly and in
// double (the guide's QP, its certified separation, the cutting curve's certified validity, times
// beside the paper's), how often a sample-feasible guide is invalid as the sampling thins out, and
// Figure 10's study of lambda_reg and delta on the L-shaped domain.
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <sstream>

#include "base/errors.hpp"
#include "cut/curve_facet.hpp"
#include "cut/examples.hpp"
#include "cut/guide.hpp"
#include "cut/separation.hpp"
#include "experiments/common.hpp"
#include "experiments/cut_figure.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "float/rounding.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

// The guide's zero set near the march: distance of a point to it and the largest curvature, in
// double at the marched points (a measurement of a picture, said so in the report).
struct CurveShape {
  double corner_distance = 0, max_curvature = 0;
};

CurveShape shape_of(const BSpline<Rational>& f, const std::vector<std::array<double, 2>>& poly, const std::array<double, 2>& corner) {
  const auto fd = round_spline<double>(f, "guide");
  CurveShape s;
  s.corner_distance = 1e300;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const double x = std::min(1.0, std::max(0.0, poly[i][0])), y = std::min(1.0, std::max(0.0, poly[i][1]));
    s.corner_distance = std::min(s.corner_distance, std::hypot(x - corner[0], y - corner[1]));
    const std::vector<double> at{x, y};
    const double fx = derivative(fd, at, {1, 0})[0], fy = derivative(fd, at, {0, 1})[0];
    const double fxx = derivative(fd, at, {2, 0})[0], fxy = derivative(fd, at, {1, 1})[0], fyy = derivative(fd, at, {0, 2})[0];
    const double g = std::hypot(fx, fy);
    if (g > 0) s.max_curvature = std::max(s.max_curvature, std::abs(fxx * fy * fy - 2 * fxy * fx * fy + fyy * fx * fx) / (g * g * g));
  }
  return s;
}

// A row of Table 1: the example's guide exactly and in double, its separation, the cutting curve
// with 8 and 16 control points, the pipeline's time beside the paper's (pap).
void table1_row(ReportContext& ctx, std::ostringstream& md, std::ostringstream& csv, const std::string& name, const std::string& pap) {
  using clock = std::chrono::steady_clock;
  ctx.progress("cut: " + name);
  const auto e = cut_example(name);
  GuideOptions o;
  const auto t0 = clock::now();
  const auto R = guide_curve<Rational>(e.solid, e.cut, o);
  std::string sep_e = "-", sep_d = "-", validity = "-", bits = "-";
  double t_pipe = 0;
  if (R.status == QPStatus::optimal) {
    sep_e = certificate_word(certify_separation(R.solid, R.cut, R.f, o.strip).verdict);
    for (int cps : {8, 16}) {
      CurveFitOptions fo;
      fo.control_points = cps;
      std::string verdict;
      try {
        const auto cc = fit_cutting_curve(R.solid, R.cut, R.f, fo);
        const auto v = certify_cutting_curve(R.solid, R.cut, cc.curve);
        verdict = validity_word(v.verdict);
        if (cps == 16 || v.verdict.is_proved())
          write_file_atomically(ctx.options.out_dir + "/cut_" + name + ".svg",
                                cut_guide_svg(R.solid, R.cut, R.f, R.sample_points, R.samples_positive, o.strip, nullptr,
                                              "papers/004 " + name + ": guide (exact), cutting curve with " + std::to_string(cps) +
                                                  " control points (" + validity_word(v.verdict) + ")",
                                              &cc.curve));
      } catch (const Error& err) {
        verdict = "no curve (the march does not reach the second point)";
        const auto sep = certify_separation(R.solid, R.cut, R.f, o.strip);
        write_file_atomically(ctx.options.out_dir + "/cut_" + name + ".svg",
                              cut_guide_svg(R.solid, R.cut, R.f, R.sample_points, R.samples_positive, o.strip, &sep,
                                            "papers/004 " + name + ": guide (exact); no cutting curve"));
      }
      validity = (validity == "-" ? "" : validity + " / ") + verdict;
      if (verdict.rfind("no curve", 0) == 0) break;
    }
    t_pipe = std::chrono::duration<double>(clock::now() - t0).count();
  }
  const auto D = guide_curve<double>(e.solid, e.cut, o);
  if (D.status == QPStatus::optimal) {
    const auto& fq = D.f_exact;
    sep_d = certificate_word(certify_separation(D.solid, D.cut, fq, o.strip).verdict);
    if (R.status == QPStatus::optimal) {
      const auto ce = coefficient_error(R.coefficients, fq.points);
      bits = ce.max_abs_error == 0 ? "0" : fmt(ce.bits_lost, 3);
    }
  }
  md << "| " << name << " | " << e.solid.facets.size() << " | " << R.program.n << " x " << R.program.rows.size() << " | " << fmt(R.seconds)
     << " | " << sep_e << " | " << fmt(D.seconds) << " | " << bits << " | " << sep_d << " | " << validity << " | " << fmt(t_pipe) << " | "
     << pap << " |\n";
  csv << name << "," << e.solid.facets.size() << "," << R.program.n << "," << R.program.rows.size() << "," << R.seconds << "," << sep_e << ","
      << D.seconds << "," << bits << "," << sep_d << ",\"" << validity << "\"," << t_pipe << "\n";
}

// The snake with settings chosen by hand, as the paper did for it ("a different knot vector"):
// 15 x 3 inner knots, delta 1/100, strip 1/32, 32 samples per facet, 48 control points.
void snake_by_hand_row(ReportContext& ctx, std::ostringstream& md, std::ostringstream& csv) {
  using clock = std::chrono::steady_clock;
  ctx.progress("cut: snake, manual settings (about 75 s exact)");
  const auto e = cut_example("snake");
  GuideOptions o;
  o.inner_knots = 15;
  o.inner_knots_y = 3;
  o.max_inner_knots = 15;
  o.delta = Rational(1, 100);
  o.strip = Rational(1, 32);
  o.samples = 32;
  const auto t0 = clock::now();
  const auto R = guide_curve<Rational>(e.solid, e.cut, o);
  std::string sep = "-", validity = "-";
  if (R.status == QPStatus::optimal) {
    sep = certificate_word(certify_separation(R.solid, R.cut, R.f, o.strip).verdict);
    CurveFitOptions fo;
    fo.control_points = 48;
    try {
      const auto cc = fit_cutting_curve(R.solid, R.cut, R.f, fo);
      const auto v = certify_cutting_curve(R.solid, R.cut, cc.curve);
      validity = validity_word(v.verdict) + std::string(" (48 control points)");
      write_file_atomically(ctx.options.out_dir + "/cut_snake_manual.svg",
                            cut_guide_svg(R.solid, R.cut, R.f, R.sample_points, R.samples_positive, o.strip, nullptr,
                                          std::string("papers/004 snake, 15 x 3 inner knots, delta 1/100: cutting curve (") + validity_word(v.verdict) + ")", &cc.curve));
    } catch (const Error&) {
      validity = "no curve (the march does not reach the second point)";
    }
  }
  const double t_pipe = std::chrono::duration<double>(clock::now() - t0).count();
  md << "| snake, by hand: 15 x 3 knots, delta 1/100, strip 1/32, 32 samples | 4 | " << R.program.n << " x " << R.program.rows.size() << " | "
     << fmt(R.seconds) << " | " << sep << " | - | - | - | " << validity << " | " << fmt(t_pipe) << " | 27 |\n";
  csv << "snake_manual,4," << R.program.n << "," << R.program.rows.size() << "," << R.seconds << "," << sep << ",,,,\"" << validity << "\","
      << t_pipe << "\n";
}

// The section's introduction and Table 1: every example, then the snake by hand; cut_examples.csv.
void table1_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream csv;
  const std::map<std::string, std::string> paper{{"U", "9"}, {"J", "10"}, {"K", "11"}, {"maze", "15"}, {"snake", "27"}};
  std::ostringstream rows;
  csv << "example,facets,variables,rows,exact_s,exact_separation,double_s,bits_lost,double_separation,curve_validity,pipeline_s\n";
  for (const auto& name : cut_example_names()) table1_row(ctx, rows, csv, name, paper.count(name) ? paper.at(name) : "-");
  snake_by_hand_row(ctx, rows, csv);
  md << ReportTemplate("cut").set("rows", rows.str()).render();
  write_file_atomically(ctx.options.out_dir + "/cut_examples.csv", csv.str());
}

// Sampling density: is a sample-feasible guide valid on the whole boundary?
void sampling_part(ReportContext& ctx, std::ostringstream& md) {
  ctx.progress("cut: sampling density");
  std::ostringstream dcsv;
  dcsv << "example,samples_per_facet,arithmetic,status,separation\n";
  std::ostringstream rows;
  int invalid = 0, runs = 0;
  for (const std::string name : {"L", "U", "J", "K"}) {
    const auto e = cut_example(name);
    for (int samples : {1, 2, 4, 8}) {
      GuideOptions o;
      o.samples = samples;
      std::string ve = "infeasible", vd = "infeasible";
      const auto R = guide_curve<Rational>(e.solid, e.cut, o);
      if (R.status == QPStatus::optimal) ve = certificate_word(certify_separation(R.solid, R.cut, R.f, o.strip).verdict);
      const auto D = guide_curve<double>(e.solid, e.cut, o);
      if (D.status == QPStatus::optimal) vd = certificate_word(certify_separation(D.solid, D.cut, D.f_exact, o.strip).verdict);
      for (const auto* v : {&ve, &vd})
        if (*v != "infeasible") ++runs, invalid += *v == "violated";
      rows << "| " << name << " | " << samples << " | " << ve << " | " << vd << " |\n";
      dcsv << name << "," << samples << ",exact," << to_string(R.status) << "," << ve << "\n";
      dcsv << name << "," << samples << ",double," << to_string(D.status) << "," << vd << "\n";
    }
  }
  md << ReportTemplate("cut.sampling").set("rows", rows.str()).set("violated", invalid).set("guides", runs).render();
  write_file_atomically(ctx.options.out_dir + "/cut_sampling.csv", dcsv.str());
}

// Figure 10's trends, read from the data (not asserted): distance against delta per lambda_reg,
// curvature against lambda_reg per delta.
void figure10_trends(std::ostringstream& md, const std::vector<PlotSeries>& dist_series, const std::vector<PlotSeries>& curv_series,
                     std::size_t lambdas) {
  int dist_up = 0, dist_pairs = 0, curv_down = 0, curv_pairs = 0;
  for (std::size_t li = 0; li < lambdas; ++li)
    for (std::size_t di = 0; di + 1 < dist_series.size(); ++di)
      if (li < dist_series[di].points.size() && li < dist_series[di + 1].points.size() &&
          dist_series[di].points[li].first == dist_series[di + 1].points[li].first) {
        ++dist_pairs;
        dist_up += dist_series[di + 1].points[li].second > dist_series[di].points[li].second;
      }
  for (const auto& cs : curv_series)
    for (std::size_t k = 0; k + 1 < cs.points.size(); ++k) {
      ++curv_pairs;
      curv_down += cs.points[k + 1].second < cs.points[k].second;
    }
  md << ReportTemplate("cut.figure10-trends")
            .set("distance_up", dist_up)
            .set("distance_steps", dist_pairs)
            .set("curvature_down", curv_down)
            .set("curvature_steps", curv_pairs)
            .render();
}

// Figure 10: lambda_reg and delta on the L.
void figure10_part(ReportContext& ctx, std::ostringstream& md) {
  ctx.progress("cut: Figure 10 (lambda_reg, delta)");
  const auto L = cut_example("L");
  std::ostringstream fcsv;
  fcsv << "lambda_reg,delta,corner_distance,max_curvature,separation\n";
  std::vector<PlotSeries> dist_series, curv_series;
  std::ostringstream rows;
  const Rational deltas[] = {Rational(1, 40), Rational(1, 20), Rational(1, 10)};
  const Rational lambdas[] = {Rational(1, 1000), Rational(1, 100), Rational(1, 10), Rational(1), Rational(10)};
  for (std::size_t di = 0; di < 3; ++di) {
    PlotSeries ds, cs;
    ds.label = cs.label = "delta = " + to_fraction_string(deltas[di]);
    ds.color = cs.color = svg::palette(di);
    for (const auto& lr : lambdas) {
      GuideOptions o;
      o.delta = deltas[di];
      o.lambda_reg = lr;
      const auto R = guide_curve<Rational>(L.solid, L.cut, o);
      if (R.status != QPStatus::optimal) continue;
      const std::string sep = certificate_word(certify_separation(R.solid, R.cut, R.f, o.strip).verdict);
      try {
        const auto cc = fit_cutting_curve(R.solid, R.cut, R.f);
        const double sc = to_double(R.frame.scale);
        const std::array<double, 2> corner{(1 - to_double(R.frame.lo[0])) / sc, (1 - to_double(R.frame.lo[1])) / sc};
        auto s = shape_of(R.f, cc.polygon, corner);
        s.corner_distance *= sc;
        s.max_curvature /= sc;
        ds.points.push_back({to_double(lr), s.corner_distance});
        cs.points.push_back({to_double(lr), s.max_curvature});
        rows << "| " << to_fraction_string(lr) << " | " << to_fraction_string(deltas[di]) << " | " << fmt(s.corner_distance, 4) << " | "
           << fmt(s.max_curvature, 4) << " | " << sep << " |\n";
        fcsv << to_double(lr) << "," << to_double(deltas[di]) << "," << s.corner_distance << "," << s.max_curvature << "," << sep << "\n";
      } catch (const Error&) {
        rows << "| " << to_fraction_string(lr) << " | " << to_fraction_string(deltas[di]) << " | no curve | - | " << sep << " |\n";
      }
    }
    dist_series.push_back(ds);
    curv_series.push_back(cs);
  }
  md << ReportTemplate("cut.figure10").set("rows", rows.str()).render();
  write_file_atomically(ctx.options.out_dir + "/cut_figure10.csv", fcsv.str());
  write_file_atomically(ctx.options.out_dir + "/cut_figure10_distance.svg",
                        svg_line_plot({"Figure 10: distance from the reflex corner to f* = 0", "lambda_reg", "distance", true, false, ""}, dist_series));
  write_file_atomically(ctx.options.out_dir + "/cut_figure10_curvature.svg",
                        svg_line_plot({"Figure 10: largest curvature of f* = 0", "lambda_reg", "max curvature", true, true, ""}, curv_series));
  figure10_trends(md, dist_series, curv_series, std::size(lambdas));
}

}  // namespace

void cut_section(ReportContext& ctx) {
  std::ostringstream md;
  table1_part(ctx, md);
  sampling_part(ctx, md);
  figure10_part(ctx, md);
  ctx.markdown["cut"] = md.str();
}

}  // namespace splinex
