#include "experiments/hybrid_experiment.hpp"
#include "base/point.hpp"
#include "experiments/report_template.hpp"
#include "experiments/section.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "experiments/svg.hpp"
#include "experiments/svg_plot.hpp"
#include "fixtures/hybrid_examples.hpp"
#include "float/mpfr.hpp"
#include "hybrid/form.hpp"
#include "hybrid/hybrid.hpp"
#include "io/hybrid_io.hpp"
#include "spline/kernel.hpp"

namespace splinex {

namespace {

using P2 = Point2<Rational>;

// The exact fraction when it is short, else the decimal and a pointer to the JSON.
std::string frac_or_sci(const Rational& x) {
  const auto f = to_fraction_string(x);
  std::ostringstream o;
  o << std::setprecision(3) << to_double(x);
  return f.size() <= 32 ? f + " (" + o.str() + ")" : o.str() + " (exact in hybrid_examples.json)";
}

std::string sci(double x) {
  std::ostringstream o;
  o << std::setprecision(3) << x;
  return o.str();
}

P2 centroid(const HybridPatch<Rational>& P) {
  P2 g{0, 0};
  for (const auto& v : P.vertices) {
    g[0] += v[0] / static_cast<long>(P.sides());
    g[1] += v[1] / static_cast<long>(P.sides());
  }
  return g;
}

// Fan sample: G + (a/m)(V_k - G) + (b/m)(V_{k+1} - G), a + b <= m, each point once; with the
// triangles of the fan (indices into the points) for meshes and pictures.
struct Fan {
  std::vector<P2> x;
  std::vector<std::array<std::size_t, 3>> tri;
};
Fan fan(const HybridPatch<Rational>& P, int m) {
  const P2 g = centroid(P);
  Fan F;
  const std::size_t n = P.sides();
  for (std::size_t k = 0; k < n; ++k) {
    const auto& A = P.vertices[k];
    const auto& B = P.vertices[(k + 1) % n];
    std::vector<std::vector<std::size_t>> id(m + 1);
    for (int a = 0; a <= m; ++a)
      for (int b = 0; a + b <= m; ++b) {
        F.x.push_back({g[0] + Rational(a, m) * (A[0] - g[0]) + Rational(b, m) * (B[0] - g[0]),
                       g[1] + Rational(a, m) * (A[1] - g[1]) + Rational(b, m) * (B[1] - g[1])});
        id[a].push_back(F.x.size() - 1);
      }
    for (int a = 0; a < m; ++a)
      for (int b = 0; a + b < m; ++b) {
        F.tri.push_back({id[a][b], id[a + 1][b], id[a][b + 1]});
        if (a + b + 1 < m) F.tri.push_back({id[a + 1][b], id[a + 1][b + 1], id[a][b + 1]});
      }
  }
  return F;
}

Rational max_norm_diff(const std::vector<Rational>& a, const std::vector<Rational>& b) {
  Rational m = 0;
  for (std::size_t c = 0; c < a.size(); ++c) m = std::max(m, Rational(abs(Rational(a[c] - b[c]))));
  return m;
}

std::string obj_mesh(const std::vector<std::vector<double>>& pts, const std::vector<std::array<std::size_t, 3>>& tri, const std::string& head) {
  std::ostringstream o;
  o << "# " << head << "\n" << std::setprecision(17);
  for (const auto& p : pts) o << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const auto& t : tri) o << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return o.str();
}

// The domain of P mapped to an SVG box.
struct Frame {
  double x0, y0, s;
  std::pair<double, double> operator()(double x, double y) const { return {40 + (x - x0) * s, 40 + (y0 - y) * s}; }
};
Frame frame(const HybridPatch<Rational>& P, double size) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& v : P.vertices) {
    x0 = std::min(x0, to_double(v[0]));
    x1 = std::max(x1, to_double(v[0]));
    y0 = std::min(y0, to_double(v[1]));
    y1 = std::max(y1, to_double(v[1]));
  }
  return {x0, y1, size / std::max(x1 - x0, y1 - y0)};
}

void polygon_svg(svg::Canvas& o, const HybridPatch<Rational>& P, const Frame& f) {
  svg::Points pts;
  for (const auto& v : P.vertices) pts.push_back(f(to_double(v[0]), to_double(v[1])));
  o.polygon(pts, svg::attr("fill", "none") + svg::attr("stroke", "black") + svg::attr("stroke-width", 2));
}

// Iso-lines of s_0 (straight, through O_0) and h_0 (curves), traced in double for the picture.
std::string isolines_svg(const HybridPatch<Rational>& P) {
  const auto Pd = convert_hybrid<double>(P, [](const Rational& r) { return to_double(r); });
  const Frame f = frame(P, 520);
  svg::Canvas o(600, 600);
  const int N = 160;
  // Sample a grid of the bounding box, keep inside points, and draw short contour pieces by
  // marching squares on s_0 and h_0.
  const double xmin = f.x0, ymax = f.y0, span = 520 / f.s;
  std::vector<std::vector<double>> S(N + 1, std::vector<double>(N + 1, NAN)), H = S;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N; ++b) {
      const std::array<double, 2> x{xmin + span * a / N, ymax - span * b / N};
      try {
        const auto L = hybrid_local(Pd, x);
        S[a][b] = L.s[0];
        H[a][b] = L.h[0];
      } catch (const Error&) {
      }
    }
  auto contour = [&](const std::vector<std::vector<double>>& F, double c, const char* color) {
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < N; ++b) {
        const double v[4] = {F[a][b], F[a + 1][b], F[a + 1][b + 1], F[a][b + 1]};
        if (std::isnan(v[0]) || std::isnan(v[1]) || std::isnan(v[2]) || std::isnan(v[3])) continue;
        const double px[4] = {0, 1, 1, 0}, py[4] = {0, 0, 1, 1};
        std::vector<std::pair<double, double>> cut;
        for (int e = 0; e < 4; ++e) {
          const double p = v[e] - c, q = v[(e + 1) % 4] - c;
          if ((p < 0) != (q < 0)) {
            const double t = p / (p - q);
            cut.push_back({a + px[e] + t * (px[(e + 1) % 4] - px[e]), b + py[e] + t * (py[(e + 1) % 4] - py[e])});
          }
        }
        if (cut.size() == 2) {
          auto [x1, y1] = f(xmin + span * cut[0].first / N, ymax - span * cut[0].second / N);
          auto [x2, y2] = f(xmin + span * cut[1].first / N, ymax - span * cut[1].second / N);
          o.line(x1, y1, x2, y2, svg::attr("stroke", color));
        }
      }
  };
  for (int k = 1; k < 10; ++k) contour(S, k / 10.0, "#1f78b4");
  for (int k = 1; k < 10; ++k) contour(H, k / 10.0, "#e31a1c");
  polygon_svg(o, P, f);
  const auto [lx, ly] = f(to_double(P.vertices[0][0]), to_double(P.vertices[0][1]));
  o.text(lx, ly + 18, "V_0", 13);
  o.caption(ReportTemplate("hybrid.isolines.caption").render(), 13);
  return o.str();
}

// Height-shaded triangles of the fan mesh (z in double, colour from blue to yellow).
std::string height_svg(const HybridPatch<Rational>& P, const Fan& F, const std::vector<std::vector<double>>& pts, const std::string& title) {
  const Frame f = frame(P, 520);
  double zmin = 1e300, zmax = -1e300;
  for (const auto& p : pts) {
    zmin = std::min(zmin, p[2]);
    zmax = std::max(zmax, p[2]);
  }
  svg::Canvas o(600, 600);
  for (const auto& t : F.tri) {
    double z = 0;
    for (auto k : t) z += pts[k][2] / 3;
    const double u = zmax > zmin ? (z - zmin) / (zmax - zmin) : 0.5;
    const int r = static_cast<int>(40 + 215 * u), g = static_cast<int>(60 + 170 * u), b = static_cast<int>(200 - 160 * u);
    svg::Points tri;
    for (auto k : t) tri.push_back(f(to_double(F.x[k][0]), to_double(F.x[k][1])));
    const std::string colour = svg::rgb({r, g, b});
    o.polygon(tri, svg::attr("stroke-width", 0.6) + svg::attr("stroke", colour) + svg::attr("fill", colour));
  }
  polygon_svg(o, P, f);
  o.caption(title + " (z from " + sci(zmin) + " blue to " + sci(zmax) + " yellow)", 13);
  return o.str();
}

std::vector<std::vector<double>> eval_double(const HybridPatch<Rational>& P, const std::vector<P2>& xs) {
  const auto Pd = convert_hybrid<double>(P, [](const Rational& r) { return to_double(r); });
  std::vector<std::vector<double>> out;
  const P2 g = centroid(P);
  for (const auto& x : xs) {
    // A boundary point rounded to double can land outside by an ulp (DomainError); such points
    // are moved towards the centroid by 2^-40 of the way, exactly, before rounding.
    try {
      out.push_back(hybrid_evaluate(Pd, std::array<double, 2>{to_double(x[0]), to_double(x[1])}));
    } catch (const DomainError&) {
      const Rational e(1, 1099511627776L);
      out.push_back(hybrid_evaluate(Pd, std::array<double, 2>{to_double(x[0] + e * (g[0] - x[0])), to_double(x[1] + e * (g[1] - x[1]))}));
    }
  }
  return out;
}

// Example 3.2: the mismatch along side i of a hole's patch with its neighbour A_i, exactly.
struct SideMismatch {
  Rational c1max, detmax;
  double angmax = 0;
  int zero_spans = 0;
  std::size_t spans = 0;
  Rational corner;  // the C1 mismatch at the corner V_i
};

SideMismatch side_mismatch(const HybridHole& H, std::size_t i) {
  const auto& P = H.patch;
  std::vector<Rational> cuts;
  for (const auto& u : P.knots[i])
    if (cuts.empty() || cuts.back() != u) cuts.push_back(u);
  Rational c1max = 0, detmax = 0;
  double angmax = 0;
  int zero_spans = 0;
  const auto& A = P.vertices[i];
  const auto& B = P.vertices[(i + 1) % P.sides()];
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    Rational span_max = 0;
    for (int m = 1; m <= 8; ++m) {
      const Rational t = cuts[k] + (cuts[k + 1] - cuts[k]) * Rational(m, 9);
      const auto dS = hybrid_cross_derivative(P, i, P2{A[0] + t * (B[0] - A[0]), A[1] + t * (B[1] - A[1])}).value;
      const auto At = derivative(H.neighbours[i], {t, Rational(0)}, {0, 1});
      const auto Ps = derivative(H.neighbours[i], {t, Rational(0)}, {1, 0});
      std::vector<Rational> negAt{-At[0], -At[1], -At[2]};
      const Rational c1 = max_norm_diff(dS, negAt);
      span_max = std::max(span_max, c1);
      const Rational det = triple(as_point3(Ps), as_point3(At), as_point3(dS));
      detmax = std::max(detmax, Rational(abs(det)));
      Point3<double> pd, ad, sd;
      for (int c = 0; c < 3; ++c) {
        pd[c] = to_double(Ps[c]);
        ad[c] = to_double(At[c]);
        sd[c] = -to_double(dS[c]);
      }
      const auto na = cross(pd, ad), ns = cross(pd, sd), x = cross(na, ns);
      angmax = std::max(angmax, std::atan2(std::sqrt(dot(x, x)), dot(na, ns)) * 180 / M_PI);
    }
    c1max = std::max(c1max, span_max);
    zero_spans += span_max == 0 ? 1 : 0;
  }
  // Corner V_i: the patch's derivative along s_i = 0 is -P'_{i-1}(1) (hybrid-thm-3.2-corrected).
  auto dc = derivative(hybrid_boundary_spline(P, (i + P.sides() - 1) % P.sides()), {Rational(1)}, {1});
  for (auto& c : dc) c = -c;
  const auto At0 = derivative(H.neighbours[i], {Rational(0), Rational(0)}, {0, 1});
  const Rational corner = max_norm_diff(dc, {-At0[0], -At0[1], -At0[2]});
  return {c1max, detmax, angmax, zero_spans, cuts.size() - 1, corner};
}

// OBJ: the hybrid patch plus its neighbours.
void write_hole_mesh(const std::string& out_dir, int n, const HybridHole& H) {
  const auto& P = H.patch;
  const auto F = fan(P, 12);
  auto pts = eval_double(P, F.x);
  auto tri = F.tri;
  for (const auto& S : H.neighbours) {
    const std::size_t base = pts.size(), m = 12;
    for (std::size_t b = 0; b <= m; ++b)
      for (std::size_t a = 0; a <= m; ++a) {
        const auto v = evaluate(S, {Rational(static_cast<long>(a), static_cast<long>(m)), Rational(static_cast<long>(b), static_cast<long>(m))});
        pts.push_back({to_double(v[0]), to_double(v[1]), to_double(v[2])});
      }
    for (std::size_t b = 0; b < m; ++b)
      for (std::size_t a = 0; a < m; ++a) {
        const std::size_t q = base + b * (m + 1) + a;
        tri.push_back({q, q + 1, q + m + 2});
        tri.push_back({q, q + m + 2, q + m + 1});
      }
  }
  write_file_atomically(out_dir + "/hybrid_hole_" + std::to_string(n) + ".obj",
                        obj_mesh(pts, tri, "splinex: Example 3.2 hole (" + std::to_string(n) + " sides): hybrid patch + neighbours"));
}

// Example 3.2: holes between tensor-product B-spline patches. Returns the holes' data for the JSON.
Json holes_part(std::ostringstream& md, const std::string& out_dir) {
  std::ostringstream rows;
  Json holes = Json::object();
  for (int n : {5, 6}) {
    const auto H = hybrid_hole_example_3_2(n);
    const auto& P = H.patch;
    for (std::size_t i = 0; i < P.sides(); ++i) {
      const auto s = side_mismatch(H, i);
      rows << ReportTemplate("hybrid.holes.side")
                  .set("n", n)
                  .set("d", P.d)
                  .set("side", i)
                  .set("c1_max", frac_or_sci(s.c1max))
                  .set("g1_det_max", sci(to_double(s.detmax)))
                  .set("angle_max", sci(s.angmax))
                  .set("zero_spans", s.zero_spans)
                  .set("spans", s.spans)
                  .set("corner_c1", to_fraction_string(s.corner))
                  .render();
      holes[std::to_string(n)]["sides"].push_back({{"side", i},
                                                   {"c1_max", to_fraction_string(s.c1max)},
                                                   {"g1_det_max", to_fraction_string(s.detmax)},
                                                   {"zero_spans", s.zero_spans},
                                                   {"corner_c1", to_fraction_string(s.corner)}});
    }
    holes[std::to_string(n)]["twist_conflicts"] = H.conflicts;
    holes[std::to_string(n)]["max_conflict"] = to_fraction_string(H.max_conflict);
    holes[std::to_string(n)]["patch"] = hybrid_to_json(P);
    rows << ReportTemplate("hybrid.holes.conflict")
                .set("n", n)
                .set("conflicts", H.conflicts)
                .set("max_conflict", to_fraction_string(H.max_conflict))
                .render();
    write_hole_mesh(out_dir, n, H);
  }
  md << ReportTemplate("hybrid.holes").set("rows", rows.str()).render();
  return holes;
}

using Shape = std::pair<std::string, HybridPatch<Rational>>;

// The domains of Examples 4.1 and 4.2 and of Salvi's elevation: the pentagon of Example 2.1, a
// hexagon S^{6,2} and the octagon.
std::vector<Shape> example_shapes(const HybridPatch<Rational>& P21) {
  const std::vector<Rational> U21{0, 0, 0, Rational(1, 5), Rational(2, 5), Rational(3, 5), Rational(4, 5), 1, 1, 1};
  const HybridPatch<Rational> hexa = hybrid_dome(hybrid_example_3_1_hexagon().vertices, 6, std::vector<int>(6, 2), std::vector<std::vector<Rational>>(6, U21));
  return {{"pentagon", P21}, {"hexagon", hexa}, {"octagon", hybrid_example_3_1_octagon()}};
}

// Examples 4.1 and 4.2 on each domain: the counts, exact equality at sample points, the times.
Json examples_4_part(std::ostringstream& md, const std::vector<Shape>& shapes, bool& ok) {
  std::ostringstream rows;
  Json ex4 = Json::array();
  for (const auto& [name, P] : shapes) {
    const auto F = hybrid_form(P);
    const auto xs = fan(P, 6).x;
    auto t0 = std::chrono::steady_clock::now();
    auto G = F;
    for (int r = 0; r < 3; ++r) G = hybrid_elevate(G);
    const double te = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::size_t same = 0;
    for (const auto& x : xs) same += hybrid_form_evaluate(G, x) == hybrid_evaluate(P, x) ? 1 : 0;
    ok = ok && same == xs.size();
    rows << ReportTemplate("hybrid.examples-4.elevate")
                .set("patch", name)
                .set("interior_degree", G.sides[0].du)
                .set("ribbon_p", G.sides[0].p)
                .set("ribbon_coefficients", G.sides[0].count_b())
                .set("equal", same)
                .set("samples", xs.size())
                .set("seconds", sci(te))
                .render();
    t0 = std::chrono::steady_clock::now();
    auto R = F;
    for (int k = 0; k < 5; ++k) R = hybrid_insert(R, Rational(k + 1, 6), Rational(k + 1, 6), Rational(2 * k + 1, 10));
    const double ti = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    same = 0;
    for (const auto& x : xs) same += hybrid_form_evaluate(R, x) == hybrid_evaluate(P, x) ? 1 : 0;
    ok = ok && same == xs.size();
    rows << ReportTemplate("hybrid.examples-4.insert")
                .set("patch", name)
                .set("interior_degree", R.sides[0].du)
                .set("count_u", R.sides[0].count_u())
                .set("count_h", R.sides[0].count_h())
                .set("ribbon_p", R.sides[0].p)
                .set("ribbon_coefficients", R.sides[0].count_b())
                .set("equal", same)
                .set("samples", xs.size())
                .set("seconds", sci(ti))
                .render();
    ex4.push_back({{"patch", name}, {"elevated_interior_degree", G.sides[0].du}, {"elevated_p", G.sides[0].p}, {"refined_ribbon_count", R.sides[0].count_b()}});
  }
  md << ReportTemplate("hybrid.examples-4").set("rows", rows.str()).render();
  return ex4;
}

// Salvi's original elevation (Bezier sides, d = 5 -> 6) against the improved one, measured exactly.
Json salvi_part(std::ostringstream& md, const std::vector<Shape>& shapes, bool& ok) {
  std::ostringstream rows;
  Json salvi = Json::array();
  for (const auto& [name, Pshape] : shapes) {
    const auto B = hybrid_dome(Pshape.vertices, 5, std::vector<int>(Pshape.sides(), 5),
                               std::vector<std::vector<Rational>>(Pshape.sides(), uniform_clamped_knots(5, 5)));
    const auto Q = hybrid_elevate_salvi(B);
    const auto Fi = hybrid_elevate(hybrid_form(B));
    const auto xs = fan(B, 12).x;
    Rational worst = 0, improved = 0;
    for (const auto& x : xs) {
      const auto a = hybrid_evaluate(B, x);
      worst = std::max(worst, max_norm_diff(a, hybrid_evaluate(Q, x)));
      improved = std::max(improved, max_norm_diff(a, hybrid_form_evaluate(Fi, x)));
    }
    const P2 g = centroid(B);
    const Rational at_g = max_norm_diff(hybrid_evaluate(B, g), hybrid_evaluate(Q, g));
    ok = ok && improved == 0 && worst > 0;
    rows << "| " << name << " | " << frac_or_sci(worst) << " | " << frac_or_sci(at_g) << " | " << to_fraction_string(improved) << " |\n";
    salvi.push_back({{"domain", name}, {"max_displacement", to_fraction_string(worst)}, {"centroid_displacement", to_fraction_string(at_g)},
                     {"improved_displacement", to_fraction_string(improved)}});
  }
  md << ReportTemplate("hybrid.salvi").set("rows", rows.str()).render();
  return salvi;
}

// Double and MPFR against exact: values and derivatives.
void rounding_part(std::ostringstream& md, const HybridPatch<Rational>& P21) {
  const auto F = fan(P21, 6);
  std::vector<P2> xs;
  for (const auto& x : F.x) {
    bool corner = false;
    for (const auto& v : P21.vertices) corner = corner || (v[0] == x[0] && v[1] == x[1]);
    if (!corner) xs.push_back(x);
  }
  std::ostringstream rows;
  auto measure = [&](auto tag, const std::string& name) {
    using T = decltype(tag);
    const auto Q = convert_hybrid<T>(P21, [](const Rational& r) { return ArithTraits<T>::from_rational(r); });
    Rational ev = 0, ed = 0, scale = 0;
    for (const auto& x : xs) {
      const auto De = hybrid_derivatives(P21, x);
      const auto Df = hybrid_derivatives(Q, std::array<T, 2>{ArithTraits<T>::from_rational(x[0]), ArithTraits<T>::from_rational(x[1])});
      for (std::size_t c = 0; c < De.point.size(); ++c) {
        ev = std::max(ev, Rational(abs(Rational(ArithTraits<T>::to_rational(Df.point[c]) - De.point[c]))));
        ed = std::max(ed, Rational(abs(Rational(ArithTraits<T>::to_rational(Df.du[c]) - De.du[c]))));
        ed = std::max(ed, Rational(abs(Rational(ArithTraits<T>::to_rational(Df.dv[c]) - De.dv[c]))));
        scale = std::max(scale, Rational(abs(De.point[c])));
      }
    }
    const double bits = ev == 0 ? 0 : ArithTraits<T>::precision_bits() + std::log2(to_double(ev / scale));
    rows << "| " << name << " | " << sci(to_double(ev)) << " | " << sci(to_double(ed)) << " | " << sci(std::max(0.0, bits)) << " |\n";
  };
  measure(double{}, "double");
  {
    Mpfr::Precision guard(113);
    measure(Mpfr{}, "mpfr:113");
  }
  md << ReportTemplate("hybrid.rounding").set("rows", rows.str()).set("points", xs.size()).render();
}

}  // namespace

std::string run_hybrid_experiment(const std::string& out_dir, bool& ok, bool proofs_ran) {
  std::ostringstream md;
  md << ReportTemplate("hybrid.intro").when("ran:proofs", proofs_ran).render();
  const auto P21 = hybrid_example_2_1();

  const Json holes = holes_part(md, out_dir);

  // Examples 4.1 and 4.2, and Salvi's elevation.
  const auto shapes = example_shapes(P21);
  const Json ex4 = examples_4_part(md, shapes, ok);
  const Json salvi = salvi_part(md, shapes, ok);

  rounding_part(md, P21);

  // Figures.
  write_file_atomically(out_dir + "/hybrid_isolines.svg", isolines_svg(P21));
  {
    const auto F = fan(P21, 16);
    const auto pts = eval_double(P21, F.x);
    write_file_atomically(out_dir + "/hybrid_example_2_1.obj", obj_mesh(pts, F.tri, "splinex: Example 2.1 hybrid patch (constructed control points), double"));
    write_file_atomically(out_dir + "/hybrid_height.svg", height_svg(P21, F, pts, "Example 2.1 hybrid patch, height"));
  }
  Json all{{"example_3_2", holes}, {"examples_4", ex4}, {"salvi_elevation", salvi}};
  write_file_atomically(out_dir + "/hybrid_examples.json", all.dump(1) + "\n");
  md << ReportTemplate("hybrid.figures").render();
  return md.str();
}

void hybrid_section(ReportContext& ctx) {
  ctx.progress("hybrid patch (papers/003)");
  ctx.markdown["hybrid"] = run_hybrid_experiment(ctx.options.out_dir, ctx.ok, ctx.ran("proofs"));
}

}  // namespace splinex
