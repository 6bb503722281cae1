#include "experiments/checkerboard.hpp"
#include "experiments/section.hpp"

#include <algorithm>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "exact/rational.hpp"
#include "experiments/common.hpp"
#include "experiments/report_template.hpp"
#include "experiments/svg.hpp"
#include "experiments/svg_plot.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "untrim/algorithm2.hpp"

namespace splinex {

namespace {

constexpr int kCells = 4;   // texture: kCells x kCells numbered squares
constexpr int kSub = 6;     // drawn quads per texture square and direction

std::string g(double v) { return fmt(v, 3); }

struct View {  // texture plane -> figure pixels
  double x0, y0, scale, ox, oy;
  std::pair<double, double> map(const std::vector<Rational>& p) const {
    return {ox + (to_double(p[0]) - x0) * scale, oy - (to_double(p[1]) - y0) * scale};
  }
};

// A quad of the texture cell (i, j) at texture coordinates [u0, u1] x [v0, v1], mapped by f.
template <class F>
void quad(svg::Canvas& out, const View& c, F&& f, const Rational& u0, const Rational& u1, const Rational& v0,
          const Rational& v1, bool dark) {
  svg::Points pts;
  for (const auto& [u, v] : {std::pair{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}) pts.push_back(c.map(f(u, v)));
  const char* colour = dark ? "#4a6fa5" : "#f2e6c9";
  out.polygon(pts, svg::attr("fill", colour) + svg::attr("stroke", colour) + svg::attr("stroke-width", 0.4));
}

template <class F>
void label(svg::Canvas& out, const View& c, F&& f, const Rational& u, const Rational& v, int number, bool dark) {
  const auto [X, Y] = c.map(f(u, v));
  out.text(X, Y + 4, std::to_string(number), 11, svg::Anchor::middle, svg::attr("fill", dark ? "#ffffff" : "#222222"));
}

// Draws the texture on [0,1]^2 mapped by f, clipped to the texture coordinates inside(u, v); adds 1
// to counts[k] for every number k of which it draws a part.
template <class F, class In>
void texture(svg::Canvas& out, const View& c, F&& f, In&& inside, std::map<int, int>& counts) {
  const int n = kCells * kSub;
  std::set<int> seen;  // the numbers this call draws (any part of their square)
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Rational u0(i, n), u1(i + 1, n), v0(j, n), v1(j + 1, n);
      if (!inside((u0 + u1) / 2, (v0 + v1) / 2)) continue;
      const int ci = i / kSub, cj = j / kSub;
      quad(out, c, f, u0, u1, v0, v1, (ci + cj) % 2 == 0);
      seen.insert(cj * kCells + ci + 1);
    }
  for (int cj = 0; cj < kCells; ++cj)
    for (int ci = 0; ci < kCells; ++ci) {
      const Rational u(2 * ci + 1, 2 * kCells), v(2 * cj + 1, 2 * kCells);
      if (!inside(u, v)) continue;
      label(out, c, f, u, v, cj * kCells + ci + 1, (ci + cj) % 2 == 0);
    }
  for (int k : seen) ++counts[k];
}

}  // namespace

std::string run_checkerboard(const std::string& out_dir, bool& ok) {
  // T: a biquadratic map of [0, 1]^2 into the plane with knot lines u = 1/2, v = 1/2 (C^1 there).
  const auto U = clamped_knots(2, Rational(0), Rational(1), {Rational(1, 2)});
  const auto T = spline_from<Rational>({2, 2}, {U, U}, 2, [](const std::vector<std::size_t>& ij) {
    const int i = static_cast<int>(ij[0]), j = static_cast<int>(ij[1]);
    const Rational x(i, 3), y(j, 3);
    return std::vector<Rational>{x + (j == 1 || j == 2 ? Rational(1, 6) : Rational(0)) * (i == 1 ? 1 : 0),
                                 y + Rational((i * j) % 3, 12) - (i == 2 ? Rational(1, 10) : Rational(0))};
  });
  // S: affine, a rotated square inside T's domain crossing both knot lines obliquely.
  const Rational c0(1, 2), c1(1, 2), a(7, 20), b(3, 20);  // centre, half-axes of the rotated square
  // Corners c + (a r - b t, b r + a t) for r, t = -1, 1: the affine map from the corner (-1, -1).
  const auto S = affine_map<Rational>({c0 - a + b, c1 - b - a}, {{2 * a, 2 * b}, {-2 * b, 2 * a}});
  const auto A = compose_tensor(T, S);  // exact: S is affine, the trimming lines are straight
  const auto& C = A.trimmed;
  // Canvas from T(S) at the texture corners and edges.
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i <= 16; ++i) {
      const auto p = evaluate(T, evaluate(S, {Rational(i, 16), Rational(j, 16)}));
      xmin = std::min(xmin, to_double(p[0]));
      xmax = std::max(xmax, to_double(p[0]));
      ymin = std::min(ymin, to_double(p[1]));
      ymax = std::max(ymax, to_double(p[1]));
    }
  const double W = 360, margin = 30, scale = W / std::max(xmax - xmin, ymax - ymin);
  // Two panels side by side, each titled within its own width (wrapped by the canvas).
  svg::Canvas fig(2 * W + 4 * margin, W + 2 * margin);
  fig.panel_title(margin, W + margin - 10, "(a) Algorithm 1: trimmed patches, texture by S's parameters (Definition 1 holds)");
  fig.panel_title(W + 3 * margin, W + margin - 10,
                  "(b) Algorithm 2: " + std::to_string(A.tiles.size()) + " tensor-product tiles, texture by each tile's parameters");
  // (a) Algorithm 1: each patch draws the part of the texture its region owns.
  std::map<int, int> counts1, counts2;
  const View ca{xmin, ymin, scale, margin, W + margin};
  Rational loss1(0);
  for (std::size_t k = 0; k < C.patches.size(); ++k) {
    auto f = [&](const Rational& u, const Rational& v) { return evaluate_patch(C.patches[k], {u, v}); };
    auto in = [&](const Rational& u, const Rational& v) { return C.locate({u, v}) == k; };
    texture(fig, ca, f, in, counts1);
  }
  // Algorithm 1 at the texture points: the owning patch equals T(S) exactly (Definition 1).
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      const std::vector<Rational> r{Rational(i, 8), Rational(j, 8)};
      const auto p = evaluate_patch(C.patches[C.locate(r)], r), q = evaluate(T, evaluate(S, r));
      for (int d = 0; d < 2; ++d) loss1 = std::max(loss1, Rational(abs(Rational(p[d] - q[d]))));
    }
  // (b) Algorithm 2: each tile draws the whole texture in its own parameters.
  const View cb{xmin, ymin, scale, W + 3 * margin, W + margin};
  Rational loss2(0), sum2(0);
  std::size_t n2 = 0;
  for (std::size_t k = 0; k < A.tiles.size(); ++k) {
    const auto& t = A.tiles[k].tile;
    auto f = [&](const Rational& u, const Rational& v) {
      return A.evaluate_tile(k, {t.x.front() + (t.x.back() - t.x.front()) * u, v});
    };
    texture(fig, cb, f, [](const Rational&, const Rational&) { return true; }, counts2);
    // The loss: the tile's point at texture coordinate (u, v) against T(S(u, v)), exactly.
    for (int j = 0; j <= 8; ++j)
      for (int i = 0; i <= 8; ++i) {
        const Rational u(i, 8), v(j, 8);
        const auto p = f(u, v), q = evaluate(T, evaluate(S, {u, v}));
        Rational d(0);
        for (int e = 0; e < 2; ++e) d = std::max(d, Rational(abs(Rational(p[e] - q[e]))));
        loss2 = std::max(loss2, d);
        sum2 += d;
        ++n2;
      }
  }
  write_file_atomically(out_dir + "/checkerboard.svg", fig.str());
  ok = ok && loss1 == 0;
  int min1 = 1 << 30, max1 = 0, min2 = 1 << 30, max2 = 0;
  for (int num = 1; num <= kCells * kCells; ++num) {
    min1 = std::min(min1, counts1[num]);
    max1 = std::max(max1, counts1[num]);
    min2 = std::min(min2, counts2[num]);
    max2 = std::max(max2, counts2[num]);
  }
  return ReportTemplate("checkerboard")
      .set("cells", kCells)
      .set("alg1_min", min1)
      .set("alg1_max", max1)
      .set("alg1_loss", g(to_double(loss1)))
      .set("tiles", A.tiles.size())
      .set("alg2_min", min2)
      .set("alg2_max", max2)
      .set("alg2_loss_max", g(to_double(loss2)))
      .set("alg2_loss_mean", g(to_double(sum2 / Rational(static_cast<long>(n2)))))
      .set("span", g(std::max(xmax - xmin, ymax - ymin)))
      .render();
}

void checkerboard_section(ReportContext& ctx) {
  ctx.progress("checkerboard texture (Definition 1)");
  ctx.markdown["checkerboard"] = run_checkerboard(ctx.options.out_dir, ctx.ok);
}

}  // namespace splinex
