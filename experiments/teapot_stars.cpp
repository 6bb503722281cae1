#include "experiments/teapot_stars.hpp"
#include "experiments/section.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include "fixtures/teapot.hpp"
#include "experiments/render.hpp"
#include "experiments/report_template.hpp"
#include "experiments/svg_plot.hpp"
#include "float/mpfr.hpp"
#include "untrim/trimming_polyline.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"

namespace splinex {

BSpline<Rational> unit_star() {
  const Rational h(1, 2), q(1, 4), t(3, 4);
  return bezier<Rational>({2, 2}, 2,
                          {0, 0, h, q, 1, 0,   //
                           q, h, h, h, t, h,   //
                           0, 1, h, t, 1, 1});
}

BSpline<Rational> star_in_tile(int i, int j, int n, const Rational& w, const Rational& h) {
  BSpline<Rational> S = unit_star();
  const Rational tw = w / n, th = h / n, m(1, 20);
  for (std::size_t p = 0; p < S.size(); ++p) {
    Rational& x = S.points[2 * p];
    Rational& y = S.points[2 * p + 1];
    x = tw * (i + m + (1 - 2 * m) * x);
    y = th * (j + m + (1 - 2 * m) * y);
  }
  return S;
}

namespace {

std::string f3(double v) {
  std::ostringstream o;
  o << std::setprecision(6) << v;
  return o.str();
}

// Float trimming by polylines at one eps: the samples, the misassigned and the ambiguous ones, the
// largest error (exact).
struct PolyStat {
  std::size_t samples = 0, misassigned = 0, ambiguous = 0;
  Rational max_err{0};
};

// The tolerances of the float trimming by polylines.
const std::vector<double> kPolylineEps{1e-2, 1e-3, 1e-4};

// What the whole pattern writes as the surfaces add to it.
struct PatternRun {
  PatternRun(const StarPatternOptions& opt, const std::function<void(const std::string&)>& progress, bool& ok)
      : opt(opt), progress(progress), ok(ok) {}
  const StarPatternOptions& opt;
  const std::function<void(const std::string&)>& progress;
  bool& ok;
  std::ostringstream md, csv, poly_md;
  std::vector<Triangle3> teapot_triangles;  // every star on the 3D teapot, for stars_teapot_3d.svg
};

// One teapot surface: what its stars add up to, and the figure and the mesh they are drawn into.
struct SurfaceRun {
  SurfaceRun(const TeapotSurface& surf, const std::array<int, 3>& rgb);
  const std::string& name;
  const BSpline<Rational>& T;
  const BSpline<double> Td;
  const Rational W, H;
  const std::array<int, 3> base_rgb;
  const double sx, sy, Hpx;  // the figure's scale and height
  std::size_t n_trim = 0, n_untrim = 0, n_unproven = 0, misassigned = 0, samples = 0;
  std::set<std::pair<int, int>> orders;
  Rational max_abs{0}, max_ref{0};
  double t_exact = 0, t_double = 0;
  svg::Canvas fig;  // the parameter domain's figure
  std::ostringstream obj;
  std::size_t vbase = 1;
  std::vector<PolyStat> poly_stats = std::vector<PolyStat>(kPolylineEps.size());
};

SurfaceRun::SurfaceRun(const TeapotSurface& surf, const std::array<int, 3>& rgb)
    : name(surf.name),
      T(surf.surface),
      Td(convert<double>(T, [](const Rational& x) { return to_double(x); })),
      W(T.domain_hi(0)),
      H(T.domain_hi(1)),
      base_rgb(rgb),
      sx(720.0 / to_double(W)),
      sy(720.0 / to_double(W) * 1.0),
      Hpx(to_double(H) * sy),
      fig(760, Hpx + 20) {}

// Float trimming by polylines: the double pieces classify samples by polyline sides (no
// sign conditions); the chosen piece's exact patch is compared with T(S(r)) exactly, so
// only the tolerance of the trimming curves is measured, not rounding.
void polyline_trimming(const BSpline<Rational>& T, const BSpline<Rational>& S, const TrimmedComposition<Rational>& C,
                       const TrimmedComposition<double>& Cd, std::vector<PolyStat>& poly_stats) {
  for (std::size_t ei = 0; ei < kPolylineEps.size(); ++ei) {
    TrimmingTolerance tol;
    tol.eps = kPolylineEps[ei];
    tol.grid = 8;
    std::map<std::pair<std::size_t, std::size_t>, std::vector<Segment2<double>>> lines;  // (patch, bound) -> polyline
    for (std::size_t k = 0; k < Cd.patches.size(); ++k)
      for (std::size_t ci = 0; ci < Cd.patches[k].region.size(); ++ci)
        for (int ub = 0; ub < 2; ++ub) {
          const auto& c = Cd.patches[k].region[ci];
          if ((ub && !c.check_hi) || (!ub && !c.check_lo)) continue;
          lines[{k, 2 * ci + ub}] = trace_level_set(Cd.inner_pieces[Cd.patches[k].inner_piece].spline, c.coord,
                                                    ub ? c.hi : c.lo, tol);
        }
    const int P = 25;
    for (int b = 0; b < P; ++b)
      for (int a = 0; a < P; ++a) {
        const std::vector<Rational> r{Rational(2 * a + 1, 2 * P), Rational(2 * b + 1, 2 * P)};
        const Point2<double> rd{to_double(r[0]), to_double(r[1])};
        const std::size_t piece = Cd.locate_piece({rd[0], rd[1]});
        std::size_t chosen = Cd.patches.size(), owners = 0;
        for (std::size_t k = 0; k < Cd.patches.size(); ++k) {
          if (Cd.patches[k].inner_piece != piece) continue;
          bool in = true;
          for (std::size_t ci = 0; ci < Cd.patches[k].region.size() && in; ++ci)
            for (int ub = 0; ub < 2 && in; ++ub) {
              const auto& c = Cd.patches[k].region[ci];
              if ((ub && !c.check_hi) || (!ub && !c.check_lo)) continue;
              const bool above = polyline_side(Cd.inner_pieces[piece].spline, c.coord, ub ? c.hi : c.lo,
                                               lines[{k, 2 * ci + ub}], rd);
              in = ub ? !above : above;
            }
          if (in) { chosen = k; ++owners; }
        }
        auto& st = poly_stats[ei];
        ++st.samples;
        if (owners != 1) { ++st.ambiguous; continue; }
        const auto key = std::make_pair(static_cast<std::size_t>(Cd.patches[chosen].inner_piece), Cd.patches[chosen].outer_cell);
        const std::size_t exact_patch = C.locate(r);
        if (C.patches[exact_patch].outer_cell == key.second) continue;
        ++st.misassigned;
        const auto it = C.index.find(key);
        if (it == C.index.end()) { ++st.ambiguous; continue; }
        const auto bad = evaluate_patch(C.patches[it->second], r);
        const auto good = evaluate(T, evaluate(S, r));
        for (std::size_t c = 0; c < good.size(); ++c) {
          const Rational e = abs(Rational(bad[c] - good[c]));
          if (st.max_err < e) st.max_err = e;
        }
      }
  }
}

// Figure: 16 x 16 samples per star, coloured by the owning outer cell (exact classification).
void draw_star(SurfaceRun& s, const BSpline<Rational>& S, const TrimmedComposition<Rational>& C) {
  const int F = 16;
  for (int b = 0; b < F; ++b)
    for (int a = 0; a < F; ++a) {
      const std::vector<Rational> r{Rational(2 * a + 1, 2 * F), Rational(2 * b + 1, 2 * F)};
      const auto v = evaluate(S, r);
      const auto cell = C.patches[C.locate(r)].outer_cell;
      s.fig.circle(to_double(v[0]) * s.sx, s.Hpx - to_double(v[1]) * s.sy, 1.3, svg::attr("fill", svg::palette(cell)));
    }
}

// Mesh: a 17 x 17 grid per star through the evaluation structure (vertices are exact
// images rounded to double; the mesh is continuous across trimming curves since T is).
void mesh_star(PatternRun& run, SurfaceRun& s, const TrimmedComposition<Rational>& C, int i, int j) {
  const int M = 17;
  s.obj << "g star_" << i << "_" << j << "\n";
  std::vector<std::array<double, 3>> grid;
  for (int b = 0; b < M; ++b)
    for (int a = 0; a < M; ++a) {
      const auto v = C.evaluate({Rational(a, M - 1), Rational(b, M - 1)});
      s.obj << "v " << to_double(v[0]) << " " << to_double(v[1]) << " " << to_double(v[2]) << "\n";
      grid.push_back({to_double(v[0]), to_double(v[1]), to_double(v[2])});
    }
  // The 3D figure: every fourth grid line (4 x 4 quads per star), stars alternately lighter.
  std::array<int, 3> rgb = s.base_rgb;
  if ((i + j) % 2)
    for (auto& c : rgb) c = std::min(255, c + 60);
  for (int b = 0; b + 4 < M; b += 4)
    for (int a = 0; a + 4 < M; a += 4) {
      auto g = [&](int x, int y) { return grid[static_cast<std::size_t>(y * M + x)]; };
      run.teapot_triangles.push_back({{g(a, b), g(a + 4, b), g(a + 4, b + 4)}, rgb});
      run.teapot_triangles.push_back({{g(a, b), g(a + 4, b + 4), g(a, b + 4)}, rgb});
    }
  for (int b = 0; b + 1 < M; ++b)
    for (int a = 0; a + 1 < M; ++a) {
      const std::size_t v0 = s.vbase + b * M + a;
      s.obj << "f " << v0 << " " << v0 + 1 << " " << v0 + M + 1 << " " << v0 + M << "\n";
    }
  s.vbase += M * M;
}

// The star in tile (i, j) composed exactly and in double: its counts, its errors at samples, the
// float trimming by polylines, a row of stars.csv, its dots in the figure and its mesh.
void run_star(PatternRun& run, SurfaceRun& s, int i, int j) {
  using clock = std::chrono::steady_clock;
  const BSpline<Rational> S = star_in_tile(i, j, run.opt.tiles, s.W, s.H);
  const auto t0 = clock::now();
  const auto C = compose_trimmed(s.T, S);
  const auto t1 = clock::now();
  const auto Sd = convert<double>(S, [](const Rational& x) { return to_double(x); });
  const auto Cd = compose_trimmed(s.Td, Sd);
  const auto t2 = clock::now();
  s.t_exact += std::chrono::duration<double>(t1 - t0).count();
  s.t_double += std::chrono::duration<double>(t2 - t1).count();
  std::size_t tr = 0, un = 0, up = 0;
  for (const auto& p : C.patches) {
    (p.status == RegionStatus::untrimmed ? un : p.status == RegionStatus::trimmed ? tr : up)++;
    s.orders.insert({p.patch.net.degrees[0] + 1, p.patch.net.degrees[1] + 1});
  }
  s.n_trim += tr;
  s.n_untrim += un;
  s.n_unproven += up;
  // Samples: exact vs double, and which piece owns them.
  Rational s_abs(0), s_ref(0);
  std::size_t s_mis = 0;
  const int G = 9;
  for (int b = 0; b < G; ++b)
    for (int a = 0; a < G; ++a) {
      const std::vector<Rational> r{Rational(a, G - 1), Rational(b, G - 1)};
      const auto ve = C.evaluate(r);
      const std::vector<double> rd{to_double(r[0]), to_double(r[1])};
      const auto vd = Cd.evaluate(rd);
      for (std::size_t c = 0; c < ve.size(); ++c) {
        const Rational e = abs(Rational(exact_from_double(vd[c]) - ve[c]));
        if (s_abs < e) s_abs = e;
        if (s_ref < abs(ve[c])) s_ref = abs(ve[c]);
      }
      const auto& pe = C.patches[C.locate(r)];
      const auto& pd = Cd.patches[Cd.locate(rd)];
      if (pe.outer_cell != pd.outer_cell) ++s_mis;
      ++s.samples;
    }
  s.misassigned += s_mis;
  if (Cd.inner_pieces.size() == C.inner_pieces.size()) polyline_trimming(s.T, S, C, Cd, s.poly_stats);
  if (s.max_abs < s_abs) s.max_abs = s_abs;
  if (s.max_ref < s_ref) s.max_ref = s_ref;
  run.csv << s.name << "," << i << "," << j << "," << C.patches.size() << "," << tr << "," << un << "," << up << ","
          << C.isoparametric_splits << "," << C.patches[0].patch.net.degrees[0] + 1 << "," << C.patches[0].patch.net.degrees[1] + 1
          << "," << to_double(s_abs) << "," << (s_ref == 0 ? 0.0 : to_double(Rational(s_abs / s_ref))) << "," << s_mis << ","
          << G * G << "," << std::chrono::duration<double>(t1 - t0).count() << "," << std::chrono::duration<double>(t2 - t1).count()
          << "\n";
  draw_star(s, S, C);
  if (run.opt.write_meshes) mesh_star(run, s, C, i, j);
}

// One surface: its stars, its figure and mesh, its rows of the two tables, its progress line.
void run_surface(PatternRun& run, const TeapotSurface& surf, const std::array<int, 3>& base_rgb) {
  const StarPatternOptions& opt = run.opt;
  SurfaceRun s(surf, base_rgb);
  s.fig.title(surf.name + ": parameter domain, stars coloured by the polynomial piece of the surface (trimmed patches); grey lines: knot lines",
              12);
  s.fig.open_group(svg::attr("transform", "translate(20,10)"));
  for (int u = 0; u <= static_cast<int>(to_double(s.W)); ++u) s.fig.line(u * s.sx, 0, u * s.sx, s.Hpx, svg::attr("stroke", "#999"));
  for (int v = 0; v <= static_cast<int>(to_double(s.H)); ++v)
    s.fig.line(0, s.Hpx - v * s.sy, to_double(s.W) * s.sx, s.Hpx - v * s.sy, svg::attr("stroke", "#999"));
  for (int j = 0; j < opt.tiles; ++j)
    for (int i = 0; i < opt.tiles; ++i) run_star(run, s, i, j);
  s.fig.close_group();
  write_file_atomically(opt.out_dir + "/stars_" + surf.name + ".svg", s.fig.str());
  if (opt.write_meshes) write_file_atomically(opt.out_dir + "/stars_" + surf.name + ".obj", s.obj.str());
  std::string ord;
  for (auto [a, b] : s.orders) ord += "(" + std::to_string(a) + ", " + std::to_string(b) + ") ";
  const bool orders_ok = s.orders.size() == 1 && *s.orders.begin() == std::make_pair(13, 13);
  run.ok = run.ok && orders_ok && s.n_unproven == 0;
  run.md << "| " << surf.name << " | " << opt.tiles * opt.tiles << " | " << s.n_trim << " | " << s.n_untrim << " | " << s.n_unproven
         << " | " << ord << " | " << f3(to_double(s.max_abs)) << " | "
         << f3(s.max_ref == 0 ? 0.0 : to_double(Rational(s.max_abs / s.max_ref))) << " | " << s.misassigned << " of " << s.samples
         << " | " << f3(s.t_exact) << " | " << f3(s.t_double) << " |\n";
  for (std::size_t ei = 0; ei < kPolylineEps.size(); ++ei) {
    const auto& st = s.poly_stats[ei];
    run.poly_md << "| " << surf.name << " | " << kPolylineEps[ei] << " | " << st.samples << " | " << st.misassigned << " | "
                << st.ambiguous << " | " << f3(to_double(st.max_err)) << " |\n";
  }
  run.progress("teapot stars: " + surf.name + " done (" + f3(s.t_exact) + " s exact, " + f3(s.t_double) + " s double)");
}

}  // namespace

std::string run_teapot_stars(const StarPatternOptions& opt, const std::function<void(const std::string&)>& progress, bool& ok) {
  const auto patches = read_bpt(data_path("teapot.bpt"));
  PatternRun run(opt, progress, ok);
  std::ostringstream &md = run.md, &csv = run.csv, &poly_md = run.poly_md;
  csv << "surface,star_i,star_j,patches,trimmed,untrimmed,unproven,isoparametric_splits,orders_u,orders_v,"
         "max_abs_error,max_rel_error,misassigned_samples,samples,seconds_exact,seconds_double\n";
  std::size_t surface_index = 0;
  for (const auto& surf : teapot_surfaces(patches)) run_surface(run, surf, svg::palette_rgb(surface_index++));
  write_file_atomically(opt.out_dir + "/stars.csv", csv.str());
  if (opt.write_meshes) {
    RenderView view;
    view.azimuth_deg = -60;
    view.elevation_deg = 20;
    view.width = 760;
    view.height = 560;
    view.title = "The star pattern on the teapot (Algorithm 1, exact; body, handle, spout, lid)";
    view.note = "vertices: exact images of a 5 x 5 grid per star rounded to double; flat shading, painter's order";
    write_file_atomically(opt.out_dir + "/stars_teapot_3d.svg", render_svg(run.teapot_triangles, {}, view));
  }
  return ReportTemplate("teapot-stars").set("grid", opt.tiles).set("rows", md.str()).set("polyline_rows", poly_md.str()).render();
}

void teapot_stars_section(ReportContext& ctx) {
  ctx.progress("teapot star pattern");
  StarPatternOptions options;
  options.out_dir = ctx.options.out_dir;
  ctx.markdown["teapot-stars"] = run_teapot_stars(options, ctx.progress, ctx.ok);
}

}  // namespace splinex
