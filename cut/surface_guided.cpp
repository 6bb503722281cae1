// The cutting surface's guided refinement (papers/004 Section 4, Eq. 6) in double, the exact
// projection of its result onto the vertex equalities, and the sweep over Eq. 6's weight
// (cut/surface_facet.hpp).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "cut/guide.hpp"
#include "cut/surface_facet.hpp"
#include "cut/surface_facet_impl.hpp"
#include "exact/linear_solve.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"

namespace splinex {

using namespace surface_detail;

namespace {

// The rows the refinement holds as equalities, as E x = e in double: the vertex equalities (every
// other row of the program's first 2 * equalities) and the tangent rows active at the start.
void held_rows(const CuttingSurface<Rational>& init, Eigen::MatrixXd& E, Eigen::VectorXd& e) {
  const auto& qp = init.program;
  const std::size_t nv = qp.n;
  std::vector<const QuadraticProgram<Rational>::Row*> held;
  for (std::size_t r = 0; r < init.equalities; ++r) held.push_back(&qp.rows[2 * r]);
  for (std::size_t r = 2 * init.equalities; r < qp.rows.size(); ++r) {
    Rational s(0);
    for (const auto& [i, v] : qp.rows[r].a) s += v * init.coefficients[i];
    if (s == qp.rows[r].b) held.push_back(&qp.rows[r]);
  }
  const std::size_t m = held.size();
  E = Eigen::MatrixXd::Zero(m, nv);
  e.resize(m);
  for (std::size_t r = 0; r < m; ++r) {
    for (const auto& [i, v] : held[r]->a) E(r, i) = to_double(v);
    e(r) = to_double(held[r]->b);
  }
}

// A sample of Eq. 6: the basis row of p at the point and its weight omega.
struct GuideSample {
  std::vector<std::pair<std::size_t, double>> phi;
  double omega;
};

// The samples of Eq. 6 and their weights: the grid x grid points of the bounding box of Omega that
// lie in Omega, omega their distance to Omega's boundary over the largest one.
std::vector<GuideSample> guide_samples(const DomainPolygon& domain, const std::vector<double>& Ud, std::size_t n, int grid) {
  const auto poly = cg_polygon(domain.vertices);
  std::vector<std::array<double, 2>> W;
  for (const auto& w : domain.vertices) W.push_back({to_double(w[0]), to_double(w[1])});
  double lo[2] = {W[0][0], W[0][1]}, hi[2] = {W[0][0], W[0][1]};
  for (const auto& w : W)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], w[k]), hi[k] = std::max(hi[k], w[k]);
  std::vector<GuideSample> samples;
  double dmax = 0;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const double u = lo[0] + (hi[0] - lo[0]) * (i + 0.5) / grid, v = lo[1] + (hi[1] - lo[1]) * (j + 0.5) / grid;
      if (!in_polygon({exact_from_double(u), exact_from_double(v)}, poly)) continue;
      double dist = 1e300;
      for (std::size_t k = 0; k < W.size(); ++k) {
        const auto &a = W[k], &b = W[(k + 1) % W.size()];
        const double ex = b[0] - a[0], ey = b[1] - a[1], L2 = ex * ex + ey * ey;
        const double t = std::clamp(((u - a[0]) * ex + (v - a[1]) * ey) / L2, 0.0, 1.0);
        dist = std::min(dist, std::hypot(u - a[0] - t * ex, v - a[1] - t * ey));
      }
      const auto row = basis_row(Ud, n, Ud, n, u, v);
      samples.push_back({row.v, dist});
      dmax = std::max(dmax, dist);
    }
  for (auto& s : samples) s.omega = dmax > 0 ? s.omega / dmax : 0;
  return samples;
}

// The doubles interpolate the vertices only within rounding: projected exactly onto the vertex
// equalities (the first 2 * me rows of the program, every other one), the least change in the
// Euclidean norm: x - E^T (E E^T)^-1 (E x - e), exactly.
std::vector<Rational> project_onto_vertices(const QuadraticProgram<Rational>& qp, std::size_t me, const Eigen::VectorXd& x) {
  const std::size_t nv = qp.n;
  std::vector<Rational> xq(nv);
  for (std::size_t i = 0; i < nv; ++i) xq[i] = exact_from_double(x(i));
  std::vector<Rational> G(me * me, Rational(0)), res(me, Rational(0));
  for (std::size_t r = 0; r < me; ++r) {
    const auto& a = qp.rows[2 * r].a;
    res[r] = -qp.rows[2 * r].b;
    for (const auto& [i, v] : a) res[r] += v * xq[i];
    for (std::size_t t = 0; t < me; ++t) {
      const auto& b = qp.rows[2 * t].a;
      for (const auto& [i, v] : a)
        for (const auto& [j, w] : b)
          if (i == j) G[r * me + t] += v * w;
    }
  }
  const auto lam = solve_linear_exact(G, me, res, 1);
  if (!lam) throw DomainError("patch-inner-knots", "the vertex equalities are dependent", "raise --patch-inner-knots");
  for (std::size_t r = 0; r < me; ++r)
    for (const auto& [i, v] : qp.rows[2 * r].a) xq[i] -= v * (*lam)[r];
  return xq;
}

}  // namespace

void validate_guided_options(const GuidedOptions& go) {
  if (!(go.weight_guide >= 0) || !std::isfinite(go.weight_guide)) throw UsageError("weight-guide", "must be a finite number >= 0", "give e.g. 10");
  if (go.grid < 2 || go.grid > 200) throw UsageError("guide-grid", "must be in 2..200", "give e.g. 16");
  if (go.iterations < 0 || go.iterations > 1000) throw UsageError("guide-iterations", "must be in 0..1000", "give e.g. 30");
}

GuidedResult refine_with_guide(const CuttingSurface<Rational>& init, const BSpline<double>& f, const GuidedOptions& go) {
  validate_guided_options(go);
  const auto t0 = std::chrono::steady_clock::now();
  const auto& qp = init.program;
  const std::size_t nv = qp.n;
  const std::size_t N = nv / 3;
  const auto& U = init.patch.knots[0];
  std::vector<double> Ud;
  for (const auto& k : U) Ud.push_back(to_double(k));
  const std::size_t n = U.size() - 4;
  Eigen::MatrixXd D(nv, nv);
  Eigen::VectorXd c(nv), x(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    c(i) = to_double(qp.c[i]);
    x(i) = to_double(init.coefficients[i]);
    for (std::size_t j = 0; j < nv; ++j) D(i, j) = to_double(qp.d(i, j));
  }
  const double c0 = to_double(qp.c0);
  // the equalities (every other row of the first 2 * equalities) and the active tangent rows
  Eigen::MatrixXd E;
  Eigen::VectorXd e;
  held_rows(init, E, e);
  const std::size_t m = static_cast<std::size_t>(E.rows());
  // the samples of Eq. 6 and their weights
  const std::vector<GuideSample> samples = guide_samples(init.domain, Ud, n, go.grid);
  const double wk = samples.empty() ? 0 : go.weight_guide / samples.size();
  auto point = [&](const GuideSample& s, const Eigen::VectorXd& X) {
    std::vector<double> p(3, 0.0);
    for (const auto& [i, v] : s.phi)
      for (int k = 0; k < 3; ++k) p[k] += v * X(k * N + i);
    for (auto& t : p) t = std::clamp(t, 0.0, 1.0);
    return p;
  };
  auto objective = [&](const Eigen::VectorXd& X, double* fmax) {
    double val = X.dot(D * X) + c.dot(X) + c0;
    if (fmax) *fmax = 0;
    for (const auto& s : samples) {
      const double fv = evaluate(f, point(s, X))[0];
      val += wk * s.omega * fv * fv;
      if (fmax) *fmax = std::max(*fmax, std::abs(fv));
    }
    return val;
  };
  GuidedResult R;
  R.samples = samples.size();
  double fe = objective(x, &R.max_abs_f_before);
  R.objective_before = fe;
  for (int it = 0; it < go.iterations; ++it) {
    // Gauss-Newton: H = 2 D + 2 J^T J, g = 2 D x + c + 2 J^T r
    Eigen::MatrixXd H = 2 * D;
    Eigen::VectorXd g = 2 * D * x + c;
    for (const auto& s : samples) {
      const double w = wk * s.omega;
      if (w == 0) continue;
      const auto p = point(s, x);
      const double fv = evaluate(f, p)[0];
      double grad[3];
      for (int k = 0; k < 3; ++k) {
        std::vector<int> ord(3, 0);
        ord[k] = 1;
        grad[k] = derivative(f, p, ord)[0];
      }
      Eigen::VectorXd Jrow = Eigen::VectorXd::Zero(nv);
      for (const auto& [i, v] : s.phi)
        for (int k = 0; k < 3; ++k) Jrow(k * N + i) = grad[k] * v;
      H += 2 * w * Jrow * Jrow.transpose();
      g += 2 * w * fv * Jrow;
    }
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nv + m, nv + m);
    K.topLeftCorner(nv, nv) = H;
    K.topRightCorner(nv, m) = E.transpose();
    K.bottomLeftCorner(m, nv) = E;
    Eigen::VectorXd rhs(nv + m);
    rhs.head(nv) = -g;
    rhs.tail(m) = e - E * x;
    const Eigen::VectorXd step = Eigen::FullPivLU<Eigen::MatrixXd>(K).solve(rhs).head(nv);
    if (!step.allFinite()) break;
    double a = 1;
    bool better = false;
    for (int h = 0; h < 30; ++h, a /= 2) {
      const Eigen::VectorXd xn = x + a * step;
      const double fn = objective(xn, nullptr);
      if (fn < fe) {
        x = xn, better = fn < fe * (1 - 1e-12), fe = fn;
        break;
      }
    }
    R.iterations = it + 1;
    if (!better) break;
  }
  R.objective_after = objective(x, &R.max_abs_f_after);
  const std::vector<Rational> xq = project_onto_vertices(qp, init.equalities, x);
  std::vector<Rational> pts(3 * N);
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t i = 0; i < N; ++i) pts[3 * i + k] = xq[k * N + i];
  R.patch = make_spline<Rational>({3, 3}, {init.patch.knots[0], init.patch.knots[1]}, 3, pts);
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return R;
}

std::vector<GuidedStep> refine_with_guide_sweep(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const CuttingSurface<Rational>& initial,
                                                const BSpline<double>& f, const GuidedOptions& base, const std::vector<double>& weights,
                                                const SurfaceFacetOptions& o) {
  if (weights.empty()) throw UsageError("weight-guide", "the sweep has no weights", "give at least one weight");
  std::vector<GuidedStep> steps;
  for (const double w : weights) {
    GuidedOptions go = base;
    go.weight_guide = w;
    validate_guided_options(go);
    if (o.progress) std::cerr << "[cut facet] the guided refinement at weight " << w << "\n";
    GuidedStep st;
    st.weight = w;
    st.result = refine_with_guide(initial, f, go);
    st.validity = certify_cutting_surface(solid, loop, initial.domain, st.result.patch, o);
    const bool valid = st.validity.verdict.is_proved();
    steps.push_back(std::move(st));
    if (valid) break;
  }
  return steps;
}

}  // namespace splinex
