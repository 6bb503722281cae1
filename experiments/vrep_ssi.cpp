#include "experiments/vrep_ssi.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "base/errors.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg_plot.hpp"
#include "fixtures/teapot.hpp"
#include "float/rounding.hpp"
#include "io/bpt.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

/// An upper bound in double of sqrt(x) for an exact x >= 0 (rounded up by a relative 2^-50).
double sqrt_up(const Rational& x) {
  if (x == 0) return 0;
  return std::sqrt(to_double(x)) * (1 + std::ldexp(1.0, -50)) + std::numeric_limits<double>::denorm_min();
}

}  // namespace

std::size_t loops_in_space(const BSpline<Rational>& S1, const SsiResult& r, double tol) {
  const auto d1 = round_spline<double>(S1, "first");
  const std::size_t n = r.branches.size();
  std::vector<std::array<double, 3>> ends;  // 2 per branch
  for (const auto& b : r.branches)
    for (const auto* x : {&b.points.front(), &b.points.back()}) {
      const auto p = evaluate(d1, {(*x)[0], (*x)[1]});
      ends.push_back({p[0], p[1], p[2]});
    }
  std::vector<std::size_t> parent(n);
  for (std::size_t i = 0; i < n; ++i) parent[i] = i;
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<int> matched(2 * n, 0);
  for (std::size_t e = 0; e < 2 * n; ++e)
    for (std::size_t f = e + 1; f < 2 * n; ++f) {
      if (r.branches[e / 2].closed || r.branches[f / 2].closed) continue;
      const double d = std::hypot(ends[e][0] - ends[f][0], ends[e][1] - ends[f][1], ends[e][2] - ends[f][2]);
      if (d > tol) continue;
      ++matched[e];
      ++matched[f];
      parent[find(e / 2)] = find(f / 2);
    }
  // A component is a loop when every end in it meets exactly one other end (closed branches alone).
  std::map<std::size_t, bool> loop;
  for (std::size_t i = 0; i < n; ++i) {
    const bool ok = r.branches[i].closed || (matched[2 * i] == 1 && matched[2 * i + 1] == 1);
    auto it = loop.emplace(find(i), true).first;
    it->second = it->second && ok;
  }
  std::size_t count = 0;
  for (const auto& [root, ok] : loop) count += ok;
  return count;
}

SsiStudy ssi_study(const BSpline<Rational>& S1, const BSpline<Rational>& S2, const SsiOptions& options, bool judge,
                   void (*progress)(const std::string&)) {
  using clock = std::chrono::steady_clock;
  SsiStudy st;
  const auto d1 = round_spline<double>(S1, "first"), d2 = round_spline<double>(S2, "second");
  auto t0 = clock::now();
  st.result = intersect_surfaces(d1, d2, options);
  st.seconds_float = std::chrono::duration<double>(clock::now() - t0).count();
  if (!judge) return st;
  // The limit before the exact work: every vertex and midpoint costs exact restrictions and
  // hodographs (about a millisecond each for bicubic patches).
  std::size_t n = 0;
  for (const auto& b : st.result.branches) n += 2 * b.points.size();
  if (n > 10000)
    throw ValidationError("judge", "would judge " + std::to_string(n) + " points exactly (at most 10000)", "give a larger --step");
  t0 = clock::now();
  std::map<std::string, std::size_t> why;
  auto take = [&](const SsiJudgement& j, bool mid) {
    std::size_t& count = mid ? st.midpoints : st.vertices;
    std::size_t& certified = mid ? st.midpoints_certified : st.vertices_certified;
    double& gap = mid ? st.max_mid_gap : st.max_vertex_gap;
    double& distance = mid ? st.max_mid_distance : st.max_vertex_distance;
    ++count;
    gap = std::max(gap, sqrt_up(j.gap2));
    if (!j.certified) {
      why[j.why_not] += 1;
      return;
    }
    ++certified;
    distance = std::max(distance, sqrt_up(j.distance2_bound));
  };
  for (std::size_t b = 0; b < st.result.branches.size(); ++b) {
    const auto& P = st.result.branches[b].points;
    for (std::size_t i = 0; i < P.size(); ++i) {
      const SsiParams& a = P[i > 0 ? i - 1 : i];
      const SsiParams& c = P[i + 1 < P.size() ? i + 1 : i];
      SsiParams dir;
      for (int k = 0; k < 4; ++k) dir[k] = c[k] - a[k];
      take(judge_point(S1, S2, P[i], dir), false);
      if (i + 1 < P.size()) {
        SsiParams m, e;
        for (int k = 0; k < 4; ++k) {
          m[k] = (P[i][k] + P[i + 1][k]) / 2;
          e[k] = P[i + 1][k] - P[i][k];
        }
        take(judge_point(S1, S2, m, e), true);
      }
    }
    if (progress) progress("branch " + std::to_string(b + 1) + "/" + std::to_string(st.result.branches.size()) + " judged");
  }
  for (const auto& [w, n] : why) st.uncertified.push_back(std::to_string(n) + " x " + w);
  st.seconds_judge = std::chrono::duration<double>(clock::now() - t0).count();
  return st;
}

std::string ssi_svg(const BSpline<Rational>& S1, const BSpline<Rational>& S2, const SsiResult& r, const std::string& name1,
                    const std::string& name2, const std::string& title) {
  const int W = 360, H = 360, M = 40;
  svg::Canvas s(2 * W + 3 * M, H + 20);
  s.title(title);
  std::size_t below = 0;  // lines of text under the panels
  for (int side = 0; side < 2; ++side) {
    const auto& S = side == 0 ? S1 : S2;
    const double u0 = to_double(S.domain_lo(0)), u1 = to_double(S.domain_hi(0)), v0 = to_double(S.domain_lo(1)), v1 = to_double(S.domain_hi(1));
    const int ox = M + side * (W + M), oy = 10;
    s.rect(ox, oy, W, H, svg::attr("fill", "#f7f7f7") + svg::attr("stroke", "black"));
    below = std::max(below, s.text_block(ox, oy + H + 16, (side == 0 ? name1 : name2) + ": (" + (side == 0 ? "u, v" : "s, t") + ") in [" + svg::num(u0) +
                                                              ", " + svg::num(u1) + "] x [" + svg::num(v0) + ", " + svg::num(v1) + "]", W));
    for (std::size_t b = 0; b < r.branches.size(); ++b) {
      svg::Points pts;
      for (const auto& x : r.branches[b].points)
        pts.emplace_back(ox + (x[2 * side] - u0) / (u1 - u0) * W, oy + H - (x[2 * side + 1] - v0) / (v1 - v0) * H);
      s.polyline(pts, svg::attr("stroke-width", 2) + svg::attr("stroke", svg::palette(b)));
    }
  }
  s.set_height(10 + H + 8 + 15.0 * static_cast<double>(below));
  return s.str();
}

std::string ssi_obj(const BSpline<Rational>& S1, const SsiResult& r) {
  const auto d1 = round_spline<double>(S1, "first");
  std::ostringstream s;
  s << "# splinex vrep ssi: the intersection branches as polylines\n" << std::setprecision(17);
  std::size_t base = 1;
  for (const auto& br : r.branches) {
    for (const auto& x : br.points) {
      const auto p = evaluate(d1, {x[0], x[1]});
      s << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    s << "l";
    for (std::size_t i = 0; i < br.points.size(); ++i) s << " " << base + i;
    if (br.closed) s << " " << base;
    s << "\n";
    base += br.points.size();
  }
  return s.str();
}

BSpline<Rational> teapot_surface(const std::string& name) {
  for (const auto& t : teapot_surfaces(read_bpt(data_path("teapot.bpt"))))
    if (t.name == name) return t.surface;
  throw ValidationError("teapot", "has no surface \"" + name + "\"", "give body, handle, spout or lid");
}

}  // namespace splinex

namespace splinex {

void vrep_ssi_section(ReportContext& ctx) {
  std::ostringstream step_rows, csv;
  csv << "surfaces,step,tolerance,branches,closed,vertices,vertices_certified,max_vertex_gap,max_vertex_distance,midpoints,midpoints_certified,"
         "max_midpoint_gap,max_midpoint_distance,seconds_double,seconds_judge\n";
  const auto body = teapot_surface("body");
  std::vector<PlotSeries> series;
  bool ok = true;
  auto row = [&](const std::string& name, const BSpline<Rational>& S1, double step, double tol, bool table) {
    SsiOptions o;
    o.step = step;
    o.tolerance = tol;
    const auto st = ssi_study(S1, body, o, true);
    const std::size_t closed = loops_in_space(S1, st.result, step / 4);
    std::ostringstream r;
    r << std::setprecision(3);
    if (table)
      step_rows << "| " << name << " | 1/" << std::lround(1 / step) << " | " << st.result.branches.size() << " (" << closed << ") | "
         << st.vertices_certified << "/" << st.vertices << " | " << st.max_vertex_gap << " | " << st.max_vertex_distance << " | "
         << st.midpoints_certified << "/" << st.midpoints << " | " << st.max_mid_gap << " | " << st.max_mid_distance << " | "
         << std::setprecision(3) << st.seconds_float << " | " << st.seconds_judge << " |\n";
    csv << name << "," << step << "," << tol << "," << st.result.branches.size() << "," << closed << "," << st.vertices << "," << st.vertices_certified << ","
        << st.max_vertex_gap << "," << st.max_vertex_distance << "," << st.midpoints << "," << st.midpoints_certified << "," << st.max_mid_gap << ","
        << st.max_mid_distance << "," << st.seconds_float << "," << st.seconds_judge << "\n";
    // Every inner point certified is what this section claims for the finer steps.
    ok = ok && st.vertices_certified + 2 * st.result.branches.size() >= st.vertices;
    return st;
  };
  const double steps[] = {1.0 / 4, 1.0 / 8, 1.0 / 16, 1.0 / 32, 1.0 / 64, 1.0 / 128};
  for (const std::string name : {"handle", "spout"}) {
    const auto S = teapot_surface(name);
    PlotSeries mid{name + ": certified midpoint distance", {}, svg::palette(name == "handle" ? 0 : 1)};
    PlotSeries gap{name + ": midpoint gap", {}, svg::palette(name == "handle" ? 0 : 1), true};
    for (double h : steps) {
      ctx.progress("vrep ssi: " + name + " and body, step 1/" + std::to_string(std::lround(1 / h)));
      const auto st = row(name, S, h, 1e-12, true);
      // The slope over the steps that trace whole loops (1/16 and finer).
      if (st.max_mid_distance > 0 && h <= 1.0 / 16) mid.points.push_back({h, st.max_mid_distance});
      gap.points.push_back({h, st.max_mid_gap});
      if (name == "handle" && h == 1.0 / 16) {
        write_file_atomically(ctx.options.out_dir + "/vrep_ssi_handle_body.svg",
                              ssi_svg(S, body, st.result, "handle", "body", "Teapot handle and body: the intersection branches in both parameter planes (step 1/16)"));
        write_file_atomically(ctx.options.out_dir + "/vrep_ssi_handle_body.obj", ssi_obj(S, st.result));
      }
    }
    series.push_back(mid);
    series.push_back(gap);
  }
  std::ostringstream slopes;
  for (std::size_t k = 0; k < series.size(); k += 2) slopes << (k ? ", " : "") << series[k].label << " " << std::setprecision(3) << loglog_slope(series[k].points);
  std::ostringstream tolerance_rows;
  tolerance_rows << std::setprecision(3);  // as the step table's last column leaves its stream
  const auto handle = teapot_surface("handle");
  for (double tol : {1e-2, 1e-4, 1e-8, 1e-12}) {
    std::ostringstream t;
    t << tol;
    ctx.progress("vrep ssi: tolerance " + t.str());
    const auto st = row("handle", handle, 1.0 / 16, tol, false);
    tolerance_rows << "| " << tol << " | " << st.max_vertex_gap << " | " << st.max_vertex_distance << " | " << st.max_mid_distance << " |\n";
  }
  write_file_atomically(ctx.options.out_dir + "/vrep_ssi.csv", csv.str());
  write_file_atomically(ctx.options.out_dir + "/vrep_ssi_steps.svg",
                        svg_line_plot({"Trimming curves of the teapot from a float SSI: exact distance from the true intersection", "marching step",
                                       "largest bound / gap at segment midpoints", true, true, "dashed: the exact gap |S1 - S2|; solid: the certified distance bound"},
                                      series));
  ctx.markdown["vrep-ssi"] = ReportTemplate("vrep-ssi")
                                 .set("step_rows", step_rows.str())
                                 .set("slopes", slopes.str())
                                 .set("tolerance_rows", tolerance_rows.str())
                                 .when("ran:vrep-teapot", ctx.ran("vrep-teapot"))
                                 .render();
  ctx.ok = ctx.ok && ok;
}

Json ssi_document(const BSpline<Rational>& S1, const SsiStudy& st, const SsiOptions& options, bool judge) {
  Json branches = Json::array();
  for (const auto& b : st.result.branches) {
    Json pts = Json::array();
    for (const auto& x : b.points) pts.push_back({x[0], x[1], x[2], x[3]});
    branches.push_back({{"closed", b.closed}, {"ends_meet", b.ends_meet}, {"tangential_stop", b.tangential_stop}, {"points", pts}});
  }
  Json out{{"branches", branches},
           {"candidates", st.result.candidates},
           {"seeds", st.result.seeds},
           {"newton_failures", st.result.newton_failures},
           {"starts_skipped", st.result.skipped},
           {"loops_in_space", loops_in_space(S1, st.result, options.step / 4)},
           {"seconds", st.seconds_float},
           {"note", "computed in double on the surfaces rounded to double; points are (u, v, s, t)"}};
  std::size_t tangential = 0;
  for (const auto& b : st.result.branches) tangential += b.tangential_stop;
  if (tangential > 0)
    out["warning"] = std::to_string(tangential) + " branches stopped where the normals are parallel: tangential contact or surfaces "
                     "that coincide over a region, where the intersection is not a curve and this method does not apply";
  if (judge)
    out["judged"] = {{"vertices", st.vertices},
                     {"vertices_certified", st.vertices_certified},
                     {"midpoints", st.midpoints},
                     {"midpoints_certified", st.midpoints_certified},
                     {"max_vertex_gap_at_most", st.max_vertex_gap},
                     {"max_vertex_distance_at_most", st.max_vertex_distance},
                     {"max_midpoint_gap_at_most", st.max_mid_gap},
                     {"max_midpoint_distance_at_most", st.max_mid_distance},
                     {"uncertified", st.uncertified},
                     {"seconds", st.seconds_judge},
                     {"meaning", "gap: |S1(u,v) - S2(s,t)| exactly (rounded up); distance: certified bound of |S1(u,v) - q| for the "
                                 "unique true intersection point q Krawczyk proves in a box about the point (certified points only)"}};
  return out;
}

}  // namespace splinex
