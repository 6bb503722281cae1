// Report section "cut3": papers/004's guiding surfaces (d = 3) on the box-built examples, exactly
// and in double, with certified separation; what coarse sampling misses; a slice figure and VTK.
#include <chrono>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "cut/examples.hpp"
#include "cut/guide.hpp"
#include "cut/separation.hpp"
#include "cut/surface_facet.hpp"
#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"
#include "experiments/svg.hpp"
#include "experiments/svg_plot.hpp"
#include "io/cut_io.hpp"
#include "io/json_io.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

struct Setting {
  std::string name;
  int inner, samples, loop_samples;
  std::array<int, 3> per_direction;
  std::string why;
};

GuideOptions3 options_of(const Setting& s) {
  GuideOptions3 o;
  o.base.inner_knots = s.inner;
  o.base.samples = s.samples;
  o.loop_samples = s.loop_samples;
  o.inner_knots = s.per_direction;
  o.base.max_inner_knots = 7;
  return o;
}

std::string bits_lost(const std::vector<Rational>& exact, const std::vector<Rational>& rounded) {
  const auto e = coefficient_error(exact, rounded);
  return e.max_abs_error == 0 ? "0" : fmt(e.bits_lost);
}

std::string witness_text(const SeparationResult3& s) {
  if (!s.witness) return certificate_word(s.verdict);
  const auto& w = *s.witness;
  return "violated at (" + to_fraction_string(w.point[0]) + ", " + to_fraction_string(w.point[1]) + ", " + to_fraction_string(w.point[2]) +
         ") on " + (w.positive_side ? "b" : "b-bar") + ", f* = " + fmt(to_double(w.value));
}

// The slice y = (y_lo + y_hi)/2 of a box-built solid (axis-parallel quads), normalized: the facets
// crossing it as segments in (x, z), and f*'s zero set by marching squares in double.
// A patch's own slice by the plane y = ym (normalized): marching squares on p_y - ym over a grid of
// its domain (cells whose centre lies in Omega), each crossing mapped by p to (x, z). In double.
struct SlicedPatch {
  const BSpline<Rational>* patch;
  const std::vector<std::array<Rational, 2>>* domain;
  std::string colour, dash;
};

template <class FX, class FY>
void patch_slice(svg::Canvas& o, const SlicedPatch& sp, double ym, FX&& X, FY&& Y) {
  const auto D = convert<double>(*sp.patch, [](const Rational& x) { return to_double(x); });
  std::vector<std::array<double, 2>> poly;
  for (const auto& w : *sp.domain) poly.push_back({to_double(w[0]), to_double(w[1])});
  auto inside = [&](double u, double v) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
      if ((poly[i][1] > v) != (poly[j][1] > v) && u < (poly[j][0] - poly[i][0]) * (v - poly[i][1]) / (poly[j][1] - poly[i][1]) + poly[i][0]) in = !in;
    return in;
  };
  const int n = 120;
  std::vector<double> g((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g[i + (n + 1) * j] = evaluate(D, std::vector<double>{double(i) / n, double(j) / n})[1] - ym;
  std::string path;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u0 = double(i) / n, u1 = double(i + 1) / n, v0 = double(j) / n, v1 = double(j + 1) / n;
      if (!inside((u0 + u1) / 2, (v0 + v1) / 2)) continue;
      const double a = g[i + (n + 1) * j], b = g[i + 1 + (n + 1) * j], c = g[i + 1 + (n + 1) * (j + 1)], d = g[i + (n + 1) * (j + 1)];
      std::vector<std::vector<double>> p;
      auto edge = [&](double fa, double fb, double ua, double va, double ub, double vb) {
        if ((fa < 0) != (fb < 0)) {
          const double t = fa / (fa - fb);
          p.push_back(evaluate(D, std::vector<double>{ua + t * (ub - ua), va + t * (vb - va)}));
        }
      };
      edge(a, b, u0, v0, u1, v0), edge(b, c, u1, v0, u1, v1), edge(c, d, u1, v1, u0, v1), edge(d, a, u0, v1, u0, v0);
      for (std::size_t k = 0; k + 1 < p.size(); k += 2) path += o.move_to(X(p[k][0]), Y(p[k][2])) + o.line_to(X(p[k + 1][0]), Y(p[k + 1][2]));
    }
  o.path(path, svg::attr("stroke", sp.colour) + svg::attr("stroke-width", 2) + (sp.dash.empty() ? "" : svg::attr("stroke-dasharray", sp.dash)));
}

std::string slice_svg(const GuideResult3<Rational>& R, const std::string& title, const std::vector<SlicedPatch>& patches = {},
                      const std::string& patches_legend = "") {
  const double W = 860, H = 360, pad = 40, padv = 20;  // wide enough for the legend; the title and legend are bands
  double ylo = 1e300, yhi = -1e300, zmax = 0;
  for (const auto& F : R.solid.facets)
    for (std::size_t i = 0; i < F.size(); ++i) {
      ylo = std::min(ylo, to_double(F.points[3 * i + 1])), yhi = std::max(yhi, to_double(F.points[3 * i + 1]));
      zmax = std::max(zmax, to_double(F.points[3 * i + 2]));
    }
  const double ym = (ylo + yhi) / 2, s = std::min((W - 2 * pad) / 1.0, (H - 2 * padv) / std::max(zmax, 1e-9));
  auto X = [&](double x) { return pad + s * x; };
  auto Y = [&](double z) { return H - padv - s * z; };
  svg::Canvas o(W, H);
  o.title(title, 13);
  for (const auto& F : R.solid.facets) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < F.size(); ++i)
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], to_double(F.points[3 * i + c])), hi[c] = std::max(hi[c], to_double(F.points[3 * i + c]));
    if (!(lo[1] < ym && ym < hi[1])) continue;
    o.line(X(lo[0]), Y(lo[2]), X(hi[0]), Y(hi[2]), svg::attr("stroke", "black") + svg::attr("stroke-width", 2));
  }
  // f* = 0 in the slice: marching squares on a 160 x 100 grid (a picture, in double).
  const auto fd = convert<double>(R.f_exact, [](const Rational& x) { return to_double(x); });
  const int nx = 160, nz = 100;
  std::vector<double> v((nx + 1) * (nz + 1));
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nx; ++i) v[i + (nx + 1) * j] = evaluate(fd, std::vector<double>{double(i) / nx, ym, zmax * j / nz})[0];
  std::string path;
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x0 = double(i) / nx, x1 = double(i + 1) / nx, z0 = zmax * j / nz, z1 = zmax * (j + 1) / nz;
      const double a = v[i + (nx + 1) * j], b = v[i + 1 + (nx + 1) * j], c = v[i + 1 + (nx + 1) * (j + 1)], d = v[i + (nx + 1) * (j + 1)];
      std::vector<std::pair<double, double>> p;
      auto edge = [&](double fa, double fb, double xa, double za, double xb, double zb) {
        if ((fa < 0) != (fb < 0)) {
          const double t = fa / (fa - fb);
          p.push_back({xa + t * (xb - xa), za + t * (zb - za)});
        }
      };
      edge(a, b, x0, z0, x1, z0), edge(b, c, x1, z0, x1, z1), edge(c, d, x1, z1, x0, z1), edge(d, a, x0, z1, x0, z0);
      for (std::size_t k = 0; k + 1 < p.size(); k += 2)
        path += o.move_to(X(p[k].first), Y(p[k].second)) + o.line_to(X(p[k + 1].first), Y(p[k + 1].second));
    }
  o.path(path, svg::attr("stroke", "#c0392b") + svg::attr("stroke-width", 1.5));
  for (const auto& sp : patches) patch_slice(o, sp, ym, X, Y);
  for (const auto& x : R.loop_points)
    if (std::abs(to_double(x[1]) - ylo) < 1e-12)
      o.circle(X(to_double(x[0])), Y(to_double(x[2])), 3, svg::attr("fill", "#2471a3"));
  if (!patches_legend.empty()) o.caption(patches_legend);
  o.caption("black: the solid's facets in the slice y = " + fmt(ym) +
            " (normalized); red: f* = 0 there (marching squares in double); blue: L* on the front face");
  return o.str();
}

// The guides: the examples' guiding surfaces exactly and in double, certified; the slice figures and VTK files.
void guides_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream csv;
  std::ostringstream rows;
  const std::vector<Setting> settings{
      {"cube", 0, 2, 2, {-1, -1, -1}, "no inner knots, 2 x 2 samples per facet"},
      {"slotted", 0, 1, 2, {-1, -1, -1}, "no inner knots, one sample per facet"},
      {"maiden", 3, 1, 2, {3, 0, 0}, "3 x 0 x 0 inner knots (the wave runs along x), one sample per facet"},
  };
  csv << "example,facets,loop_sides,variables,rows,exact_s,proved,exact_separation,double_s,bits_lost,double_separation\n";
  for (const auto& st : settings) {
    ctx.progress("cut3: " + st.name);
    const auto e = cut_example3(st.name);
    const auto o = options_of(st);
    const auto R = guide_surface<Rational>(e.solid, e.cut, o);
    std::string sep_e = "-", sep_d = "-", bits = "-", proved = "-";
    double t_d = 0;
    if (R.status == QPStatus::optimal) {
      proved = R.kkt.holds && R.positive_definite ? "yes (" + R.solution.method + ")" : "no: " + R.kkt.failed;
      ctx.ok = ctx.ok && R.kkt.holds && R.positive_definite;
      sep_e = witness_text(certify_separation(R.solid, R.loop, e.cut.positive, R.f_exact, o.base.strip));
      write_file_atomically(ctx.options.out_dir + "/cut3_" + st.name + "_slice.svg",
                            slice_svg(R, "papers/004 d = 3, " + st.name + ": the guiding surface f* = 0 (exact) in a slice"));
      write_file_atomically(ctx.options.out_dir + "/cut3_" + st.name + "_solid.vtk", solid3_vtk(e.solid));
      write_file_atomically(ctx.options.out_dir + "/cut3_" + st.name + "_guide.vtk", guide3_vtk(R.f_exact, R.frame.lo, R.frame.scale, 32));
    }
    ctx.progress("cut3: " + st.name + " in double");
    const auto D = guide_surface<double>(e.solid, e.cut, o);
    t_d = D.seconds;
    if (D.status == QPStatus::optimal) {
      sep_d = witness_text(certify_separation(D.solid, D.loop, e.cut.positive, D.f_exact, o.base.strip));
      if (R.status == QPStatus::optimal) bits = bits_lost(R.coefficients, D.f_exact.points);
    }
    std::ostringstream k;
    k << R.inner_knots[0] << "x" << R.inner_knots[1] << "x" << R.inner_knots[2];
    rows << "| " << st.name << " | " << e.solid.facets.size() << " | " << R.loop.size() << " | " << st.why << " (" << k.str() << " used) | "
       << R.program.n << " x " << R.program.rows.size() << " | " << fmt(R.seconds) << " | " << proved << " | " << sep_e << " | " << fmt(t_d)
       << " | " << bits << " | " << sep_d << " |\n";
    csv << st.name << "," << e.solid.facets.size() << "," << R.loop.size() << "," << R.program.n << "," << R.program.rows.size() << ","
        << R.seconds << ",\"" << proved << "\",\"" << sep_e << "\"," << t_d << "," << bits << ",\"" << sep_d << "\"\n";
  }
  write_file_atomically(ctx.options.out_dir + "/cut3_table.csv", csv.str());
  md << ReportTemplate("cut3").set("rows", rows.str()).render();
}

// What coarse sampling misses: the maiden with one sample per facet and one loop point per side.
void coarse_sampling_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream rows;
  int missed = 0, runs = 0;
  for (const std::array<int, 3> kk : {std::array<int, 3>{0, 0, 0}, std::array<int, 3>{1, 0, 1}}) {
    Setting st{"maiden", kk[0], 1, 1, kk, ""};
    const auto o = options_of(st);
    const auto e = cut_example3("maiden");
    ctx.progress("cut3: coarse maiden " + std::to_string(kk[0]) + "x" + std::to_string(kk[1]) + "x" + std::to_string(kk[2]));
    const auto R = guide_surface<Rational>(e.solid, e.cut, o);
    const auto D = guide_surface<double>(e.solid, e.cut, o);
    std::string se = to_string(R.status), sd = to_string(D.status);
    if (R.status == QPStatus::optimal) {
      const auto s = certify_separation(R.solid, R.loop, e.cut.positive, R.f_exact, o.base.strip);
      se = witness_text(s);
      ++runs, missed += s.verdict.is_refuted();
    }
    if (D.status == QPStatus::optimal) {
      const auto s = certify_separation(D.solid, D.loop, e.cut.positive, D.f_exact, o.base.strip);
      sd = witness_text(s);
      ++runs, missed += s.verdict.is_refuted();
    }
    rows << "| " << R.inner_knots[0] << "x" << R.inner_knots[1] << "x" << R.inner_knots[2] << " | " << se << " | " << sd << " |\n";
  }
  md << ReportTemplate("cut3.coarse").set("rows", rows.str()).set("missed", missed).set("guides", runs).render();
}

// One example of the cutting-surface table: the solid normalized, its loop, the row's options.
struct SurfaceCase {
  std::string name, base;
  bool guided = false;
  CutExample3 e;
  Solid3<Rational> Sn;
  std::vector<LoopSide3> loop;
  SurfaceFacetOptions so;
};

SurfaceCase surface_case(const std::string& name) {
  SurfaceCase c;
  c.name = name;
  c.base = name.substr(0, name.find(','));
  c.guided = name.find(", guided") != std::string::npos;
  c.e = cut_example3(c.base);
  c.Sn = to_frame(c.e.solid, unit_frame(c.e.solid));
  c.loop = validate_cut(c.Sn, c.e.cut);
  if (c.base == "vase" && name != "vase, guided, auto weight") c.so.weight_fair = Rational(1, 100);
  if (name == "maiden, Eq. 5") c.so.domain = "qp", c.so.inner_knots = 15;
  return c;
}

// What the rows of the cutting-surface table share: its CSV, the exact guide of the vase and the
// text of the weight sweeps.
struct SurfaceRows {
  std::ostringstream csv;
  std::optional<GuideResult3<Rational>> vase_guide;  // computed once, for both guided rows
  std::string sweep_text;
};

// The exact patch of a row: Step 2's, bulged by hand, or refined by the exact guide (Eq. 6).
CuttingSurface<Rational> exact_patch(ReportContext& ctx, const SurfaceCase& c, SurfaceRows& rows) {
  auto R = cutting_surface<Rational>(c.loop, c.so);
  ctx.ok = ctx.ok && R.kkt_holds;
  if (c.name == "slotted, bulged") {
    const std::size_t n = R.patch.count(0);
    for (std::size_t j = 1; j + 1 < n; ++j)
      for (std::size_t i = 1; i + 1 < n; ++i) R.patch.points[3 * (i + n * j) + 2] += Rational(3, 10);
  }
  if (c.guided && (!rows.vase_guide || c.name.rfind("twisted", 0) == 0)) {
    // the guide (1 inner knot, one sample per facet, 2 points per loop side)
    Setting st{c.base, 1, 1, 2, {-1, -1, -1}, ""};
    rows.vase_guide = guide_surface<Rational>(c.e.solid, c.e.cut, options_of(st));
    R.seconds += rows.vase_guide->seconds;
  }
  if (c.name.find("auto weight") != std::string::npos && rows.vase_guide->status == QPStatus::optimal) {
    // the paper's thin-plate weight 1 and Eq. 6's weight swept (cut facet --weight-guide auto)
    const auto steps = refine_with_guide_sweep(c.Sn, c.loop, R,
                                               convert<double>(rows.vase_guide->f_exact, [](const Rational& x) { return to_double(x); }),
                                               {}, {10, 1e2, 1e3, 1e4, 1e5, 1e6}, c.so);
    const auto initial = R.patch;
    R.patch = steps.back().result.patch;
    if (c.base == "twisted-vase")
      write_file_atomically(ctx.options.out_dir + "/cut3_twisted-vase_surfaces_slice.svg",
                            slice_svg(*rows.vase_guide,
                                      "papers/004, Figure 1's kind of vase (non-planar faces and loop), slice through the middle",
                                      {{&initial, &R.domain.vertices, "#7f8c8d", "6 4"}, {&R.patch, &R.domain.vertices, "#1e8449", ""}},
                                      "grey dashed: the initial patch (invalid); green: the guided patch, weight by the sweep (" +
                                          std::string(validity_word(steps.back().validity.verdict)) + ")"));
    std::string sweep;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const auto& st = steps[k];
      sweep += (k ? ", " : "") + ReportTemplate("cut3.surfaces.sweep-step")
                                     .set("weight", fmt(st.weight))
                                     .set("verdict", validity_word(st.validity.verdict))
                                     .set("max_f", fmt(st.result.max_abs_f_after))
                                     .render();
      R.seconds += st.result.seconds + st.validity.seconds;
    }
    rows.sweep_text += ReportTemplate("cut3.surfaces.sweep").set("example", c.base).set("steps", sweep).render();
  }
  if (c.name == "vase, guided") {
    const auto& G = *rows.vase_guide;
    if (G.status == QPStatus::optimal) {
      GuidedOptions go;
      go.weight_guide = 1000;
      const auto initial = R.patch;
      R.patch = refine_with_guide(R, convert<double>(G.f_exact, [](const Rational& x) { return to_double(x); }), go).patch;
      write_file_atomically(ctx.options.out_dir + "/cut3_vase_surfaces_slice.svg",
                            slice_svg(G, "papers/004, Figure 12's story on the vase (slice through the middle)",
                                      {{&initial, &R.domain.vertices, "#7f8c8d", "6 4"}, {&R.patch, &R.domain.vertices, "#1e8449", ""}},
                                      "grey dashed: the initial patch (through the cavity: invalid); green: the guided patch (valid)"));
    }
  }
  return R;
}

// A row of the cutting-surface table: the exact patch certified, the double patch beside it, the VTK files.
void surface_row(ReportContext& ctx, std::ostringstream& table, SurfaceRows& rows, const SurfaceCase& c) {
  const auto R = exact_patch(ctx, c, rows);
  const auto V = certify_cutting_surface(c.Sn, c.loop, R.domain, R.patch, c.so);
  const auto D = cutting_surface<double>(c.loop, c.so);
  const auto DV = certify_cutting_surface(c.Sn, c.loop, D.domain, D.patch, c.so);
  std::string witness = "-";
  if (V.witness)
    witness = V.witness->condition + " at p(" + to_fraction_string(V.witness->param[0]) + ", " + to_fraction_string(V.witness->param[1]) + ")";
  std::string bits = "-";
  if (c.name != "slotted, bulged" && !c.guided) bits = bits_lost(R.coefficients, D.coefficients);
  const std::string file = "cut3_" + c.base +
                           (c.name == c.base                          ? ""
                            : c.name == "vase, guided"                ? "_guided"
                            : c.name.find("auto weight") != std::string::npos ? "_guided_auto"
                            : c.name == "maiden, Eq. 5"               ? "_qp"
                                                                      : "_bulged") +
                           "_surface.vtk";
  const auto frame = unit_frame(c.e.solid);
  auto P = R.patch;
  for (std::size_t i = 0; i < P.points.size(); ++i) P.points[i] = frame.lo[i % 3] + frame.scale * P.points[i];
  write_file_atomically(ctx.options.out_dir + "/" + file, surface3_vtk(P, R.domain.vertices, 40));
  if (c.name == "twisted-vase") write_file_atomically(ctx.options.out_dir + "/cut3_twisted-vase_solid.vtk", solid3_vtk(c.e.solid));
  table << "| " << c.name << " | " << R.domain.method << " | " << fmt(R.seconds + V.seconds) << " | **" << validity_word(V.verdict) << "** | "
     << fmt(to_double(V.boundary_deviation)) << " | " << certificate_word(V.tangents) << " | " << status_name(V.regular.status()) << ", "
     << status_name(V.injective.status()) << " | " << collision_word(V.collision) << " | " << witness << " | " << fmt(D.seconds + DV.seconds) << " | " << bits << " | " << validity_word(DV.verdict) << " |\n";
  rows.csv << "\"" << c.name << "\"," << R.domain.method << "," << R.seconds + V.seconds << "," << validity_word(V.verdict) << ","
           << to_double(V.boundary_deviation) << "," << certificate_word(V.tangents) << "," << status_name(V.regular.status()) << ","
           << status_name(V.injective.status()) << ",\"" << collision_word(V.collision) << "\"," << D.seconds + DV.seconds << "," << bits
           << "," << validity_word(DV.verdict) << "\n";
}

// The cutting surfaces: the paper's quadratic initial patch, exactly and in double, certified.
void surfaces_part(ReportContext& ctx, std::ostringstream& md) {
  std::ostringstream table;
  SurfaceRows rows;
  rows.csv << "example,domain,exact_s,verdict,boundary_deviation,tangents,regular,injective,collision,double_s,bits_lost,double_verdict\n";
  for (const std::string name : {"cube", "slotted", "slotted, bulged", "maiden", "maiden, Eq. 5", "vase", "vase, guided", "vase, guided, auto weight",
                                 "twisted-vase", "twisted-vase, guided, auto weight"}) {
    ctx.progress("cut3: cutting surface of " + name);
    surface_row(ctx, table, rows, surface_case(name));
  }
  write_file_atomically(ctx.options.out_dir + "/cut3_surfaces.csv", rows.csv.str());
  md << ReportTemplate("cut3.surfaces")
            .set("rows", table.str())
            .when("swept", !rows.sweep_text.empty())
            .set("sweeps", rows.sweep_text)
            .render();
}

}  // namespace

void cut3_section(ReportContext& ctx) {
  std::ostringstream md;
  guides_part(ctx, md);
  coarse_sampling_part(ctx, md);
  surfaces_part(ctx, md);
  ctx.markdown["cut3"] = md.str();
}

}  // namespace splinex
