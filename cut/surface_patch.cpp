// The cutting surface, Step 2 (papers/004 Section 4): the initial patch, the minimizer of the
// quadratic program of Eq. 7 by a primal active set on exact (or double) KKT systems, CGAL's QP
// solver when it does not finish, and the KKT conditions of the full program checked exactly; the
// options' checks and the domain Step 2 uses (cut/surface_facet.hpp).
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "cut/guide.hpp"
#include "cut/qp.hpp"
#include "cut/surface_facet.hpp"
#include "cut/surface_facet_impl.hpp"
#include "exact/linear_solve.hpp"
#include "spline/factories.hpp"

namespace splinex {

using namespace surface_detail;

void validate_surface_options(const SurfaceFacetOptions& o) {
  if (o.inner_knots < 0 || o.inner_knots > 15)
    throw UsageError("patch-inner-knots", "must be in 0..15 (the exact KKT system is dense: 3 (k+4)^2 unknowns)", "give 0..15 (the paper: 3)");
  if (o.boundary_samples < 1 || o.boundary_samples > 1000) throw UsageError("boundary-samples", "must be in 1..1000", "give e.g. 4");
  if (!(o.weight_boundary > 0)) throw UsageError("weight-boundary", "must be > 0", "give e.g. 1");
  if (o.weight_fair < 0) throw UsageError("weight-fair", "must be >= 0", "give e.g. 1");
  if (o.lambda < 0) throw UsageError("lambda", "must be >= 0", "give e.g. 1");
  if (o.tangent_delta < 0) throw UsageError("tangent-delta", "must be >= 0", "give e.g. 1/20");
  if (!(o.strip > 0)) throw UsageError("strip", "must be > 0", "give e.g. 1/16");
  if (o.max_depth < 0 || o.max_depth > 40) throw UsageError("max-depth", "must be in 0..40", "give e.g. 14");
  if (o.domain != "auto" && o.domain != "projection" && o.domain != "qp" && o.domain != "circle")
    throw UsageError("domain", "'" + o.domain + "' is not a domain method", "give auto, projection, qp or circle");
}

namespace {

template <class T>
T from_q(const Rational& x) {
  return ArithTraits<T>::from_rational(x);
}

// x rounded to a multiple of 2^-20 (exactly, to nearest): the loop sides' unit normals carry
// 80-bit denominators from the exact inverse square root, all different; summed into the program
// they made its numbers thousands of bits long. The normal term only needs the direction.
Rational dyadic20(const Rational& x) {
  const Rational y = x * (1 << 20);
  boost::multiprecision::mpz_int q = numerator(y) / denominator(y);  // toward zero
  Rational r(q);
  if (y - r >= Rational(1, 2)) r += 1;
  else if (r - y > Rational(1, 2)) r -= 1;
  return r / (1 << 20);
}

template <class T>
void add_outer(QuadraticProgram<T>& qp, const std::vector<std::pair<std::size_t, T>>& a, const T& w) {
  for (const auto& [i, vi] : a)
    for (const auto& [j, vj] : a) qp.d(i, j) += w * vi * vj;
}

Rational sparse_dot(const std::vector<std::pair<std::size_t, Rational>>& a, const std::vector<Rational>& x) {
  Rational s(0);
  for (const auto& [i, v] : a) s += v * x[i];
  return s;
}

// Whether the vertex interpolation conditions p(W_j) = L_j are independent (exact rank).
bool vertices_independent(const DomainPolygon& D, int inner_knots) {
  const auto U = guide_knots(inner_knots);
  const std::size_t n = U.size() - 4, N = n * n, ns = D.vertices.size();
  if (ns > N) return false;
  std::vector<Rational> A(ns * N, Rational(0));
  for (std::size_t j = 0; j < ns; ++j)
    for (const auto& [i, v] : basis_row(U, n, U, n, D.vertices[j][0], D.vertices[j][1]).v) A[j * N + i] = v;
  return exact_rank(A, ns, N) == ns;
}

// The program of Step 2 as assembled: the objective (in qp), the vertex equalities and the tangent
// rows; n basis functions per direction, N = n^2 per coordinate, nv = 3 N unknowns.
template <class T>
struct PatchProgram {
  QuadraticProgram<T> qp;
  std::vector<typename QuadraticProgram<T>::Row> eq, ineq;
  std::size_t n = 0, N = 0, nv = 0;
};

// Loop side L's part of the program (edge W0 -> W1 of Omega): the equality at its start vertex, and
// at each boundary sample Eq. 7's terms (position, normal derivatives) and the tangent row.
template <class T>
void add_side_terms(PatchProgram<T>& P, const std::vector<T>& U, const P2& W0, const P2& W1, const LoopSide3& L, const SurfaceFacetOptions& o,
                    const T& omega, const T& lam) {
  using Row = typename QuadraticProgram<T>::Row;
  auto& qp = P.qp;
  const std::size_t n = P.n, N = P.N;
  const int m = o.boundary_samples;
  const P2 e{W1[0] - W0[0], W1[1] - W0[1]};
  const Rational em = std::max(rabs(e[0]), rabs(e[1]));
  const P2 inward{-e[1] / em, e[0] / em};
  // equality: the vertex
  {
    const auto row = basis_row(U, n, U, n, from_q<T>(W0[0]), from_q<T>(W0[1]));
    for (std::size_t c = 0; c < 3; ++c) {
      Row r;
      for (const auto& [i, v] : row.v) r.a.emplace_back(c * N + i, v);
      r.b = from_q<T>(L.start[c]);
      P.eq.push_back(r);
    }
  }
  for (int k = 0; k < m; ++k) {
    const Rational s(2 * k + 1, 2 * m);
    const P2 w{W0[0] + s * e[0], W0[1] + s * e[1]};
    const auto row = basis_row(U, n, U, n, from_q<T>(w[0]), from_q<T>(w[1]));
    for (std::size_t c = 0; c < 3; ++c) {
      const T Lc = from_q<T>(L.start[c] + s * (L.end[c] - L.start[c]));
      for (const auto& [i, vi] : row.v) {
        for (const auto& [i2, v2] : row.v) qp.d(c * N + i, c * N + i2) += omega * vi * v2;
        qp.c[c * N + i] += T(-2) * omega * Lc * vi;
      }
      qp.c0 += omega * Lc * Lc;
    }
    std::vector<std::pair<std::size_t, T>> au, av, at;
    for (std::size_t c = 0; c < 3; ++c) {
      const T nc = from_q<T>(dyadic20(L.normal[c])), tc = from_q<T>(L.tangent[c]);
      for (std::size_t q = 0; q < row.v.size(); ++q) {
        const std::size_t i = row.v[q].first;
        au.emplace_back(c * N + i, nc * row.dx[q].second);
        av.emplace_back(c * N + i, nc * row.dy[q].second);
        at.emplace_back(c * N + i, tc * (row.dx[q].second * from_q<T>(inward[0]) + row.dy[q].second * from_q<T>(inward[1])));
      }
    }
    add_outer(qp, au, T(omega * lam));
    add_outer(qp, av, T(omega * lam));
    Row r;
    r.a = at;
    r.b = from_q<T>(o.tangent_delta);
    P.ineq.push_back(r);
  }
}

// The objective and rows of Step 2 over Omega (vertices W) in the spline space of knots Uq: the
// thin-plate term, then each loop side's terms in cycle order (add_side_terms).
template <class T>
PatchProgram<T> assemble_patch_program(const std::vector<LoopSide3>& loop, const std::vector<P2>& W, const std::vector<Rational>& Uq,
                                       const SurfaceFacetOptions& o) {
  const std::size_t ns = loop.size();
  std::vector<T> U;
  for (const auto& k : Uq) U.push_back(from_q<T>(k));
  PatchProgram<T> P;
  const std::size_t n = Uq.size() - 4, N = n * n, nv = 3 * N;
  P.n = n, P.N = N, P.nv = nv;
  auto& qp = P.qp;
  qp.n = nv;
  qp.D.assign(nv * nv, T(0));
  qp.c.assign(nv, T(0));
  const auto M = regularization_matrix(U, U);
  const T wf = from_q<T>(o.weight_fair);
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) qp.d(c * N + i, c * N + j) += wf * M[i * N + j];
  const int m = o.boundary_samples;
  const T omega = from_q<T>(o.weight_boundary / Rational(static_cast<long>(ns) * m));
  const T lam = from_q<T>(o.lambda);
  for (std::size_t j = 0; j < ns; ++j) add_side_terms(P, U, W[j], W[(j + 1) % ns], loop[j], o, omega, lam);
  return P;
}

// The KKT system of the equalities and the working tangent rows, [2D A^T; A 0] [x; mu] = [-c; b]:
// exact (FLINT's Dixon solver) or double (Eigen's LU, the solution's doubles taken exactly); false
// when it is singular.
template <class T>
bool solve_patch_kkt(const PatchProgram<T>& P, const std::vector<std::size_t>& work, std::vector<Rational>& x, std::vector<Rational>& mu) {
  using Row = typename QuadraticProgram<T>::Row;
  const auto& qp = P.qp;
  const std::size_t nv = P.nv;
  std::vector<const Row*> rows;
  for (const auto& r : P.eq) rows.push_back(&r);
  for (auto w : work) rows.push_back(&P.ineq[w]);
  const std::size_t nr = rows.size(), nk = nv + nr;
  x.clear(), mu.clear();
  if constexpr (std::is_same_v<T, Rational>) {
    std::vector<Rational> A(nk * nk, Rational(0)), B(nk, Rational(0));
    for (std::size_t i = 0; i < nv; ++i) {
      for (std::size_t j = 0; j < nv; ++j) A[i * nk + j] = 2 * qp.d(i, j);
      B[i] = -qp.c[i];
    }
    for (std::size_t r = 0; r < nr; ++r) {
      for (const auto& [i, v] : rows[r]->a) A[(nv + r) * nk + i] = v, A[i * nk + nv + r] = v;
      B[nv + r] = rows[r]->b;
    }
    const auto X = solve_linear_exact(A, nk, B, 1);
    if (!X) return false;
    x.assign(X->begin(), X->begin() + nv);
    mu.assign(X->begin() + nv, X->end());
    return true;
  } else {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(nk, nk);
    Eigen::VectorXd B = Eigen::VectorXd::Zero(nk);
    for (std::size_t i = 0; i < nv; ++i) {
      for (std::size_t j = 0; j < nv; ++j) A(i, j) = 2 * qp.d(i, j);
      B(i) = -qp.c[i];
    }
    for (std::size_t r = 0; r < nr; ++r) {
      for (const auto& [i, v] : rows[r]->a) A(nv + r, i) = v, A(i, nv + r) = v;
      B(nv + r) = rows[r]->b;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
    if (!lu.isInvertible()) return false;
    const Eigen::VectorXd X = lu.solve(B);
    for (std::size_t i = 0; i < nk; ++i)
      if (!std::isfinite(X(i))) return false;
    for (std::size_t i = 0; i < nv; ++i) x.push_back(exact_from_double(X(i)));
    for (std::size_t r = 0; r < nr; ++r) mu.push_back(exact_from_double(X(nv + r)));
    return true;
  }
}

// Where the active set ended: the working set of tangent rows, the last KKT solution x and its
// multipliers mu (the equalities' first), whether it is optimal and after how many steps.
struct ActiveSet {
  std::vector<std::size_t> work;
  std::vector<Rational> x, mu;
  bool optimal = false;
  int steps = 0;
};

// A primal active-set method on exact (or double) KKT systems: the equalities and a working set
// of inequalities held as equalities, [2D A^T; A 0] [x; mu] = [-c; b]. A violated inequality
// joins the working set (the most violated first), a working row whose multiplier -mu is
// negative leaves it; at most `active_set_steps` steps, then CGAL's QP solver on the whole
// program. Whatever solves it, the KKT conditions of the full program are checked exactly below.
template <class T>
ActiveSet run_active_set(const PatchProgram<T>& P, const QuadraticProgram<Rational>& exact_qp, const SurfaceFacetOptions& o, std::size_t ns) {
  const auto& ineq = P.ineq;
  const std::size_t ne = P.eq.size();
  ActiveSet S;
  auto& work = S.work;
  auto& x = S.x;
  auto& mu = S.mu;
  if (!solve_patch_kkt(P, work, x, mu))
    throw DomainError("patch-inner-knots",
                      "the interpolation conditions at the loop's " + std::to_string(ns) + " vertices are singular for " +
                          std::to_string(o.inner_knots) + " inner knots (too few basis functions for the vertices)",
                      "raise --patch-inner-knots");
  bool& optimal = S.optimal;
  int& steps = S.steps;
  for (; steps <= o.active_set_steps; ++steps) {
    // a working row with a negative multiplier (y = -mu < 0) leaves
    std::size_t drop = work.size();
    for (std::size_t k = 0; k < work.size(); ++k)
      if (mu[ne + k] > 0 && (drop == work.size() || mu[ne + k] > mu[ne + drop])) drop = k;
    if (drop < work.size()) {
      work.erase(work.begin() + static_cast<long>(drop));
    } else {
      std::size_t add = ineq.size();
      Rational worst(0);
      for (std::size_t r = 0; r < ineq.size(); ++r) {
        if (std::find(work.begin(), work.end(), r) != work.end()) continue;
        const auto& row = exact_qp.rows[2 * ne + r];
        const Rational gap = row.b - sparse_dot(row.a, x);
        if (gap > worst) worst = gap, add = r;
      }
      if (add == ineq.size()) {
        optimal = true;
        break;
      }
      work.push_back(add);
    }
    if (o.progress && steps % 10 == 9)
      std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": active set step " << steps + 1 << ", " << work.size() << " tangent rows active\n";
    std::vector<Rational> x2, mu2;
    if (!solve_patch_kkt(P, work, x2, mu2)) break;  // dependent rows: leave it to CGAL
    x = std::move(x2), mu = std::move(mu2);
  }
  return S;
}

// The program's solution, its multipliers as the full program's y: the active set's when it is
// optimal, else CGAL's QP solver's on the whole program (whose x then replaces S.x); `solver` says
// which.
template <class T>
QPSolution patch_solution(const PatchProgram<T>& P, ActiveSet& S, const SurfaceFacetOptions& o, std::string& solver) {
  const std::string kind = std::is_same_v<T, Rational> ? "exact (FLINT, Dixon p-adic solves)" : "double (Eigen FullPivLU)";
  const std::size_t ne = P.eq.size();
  const auto& work = S.work;
  const auto& mu = S.mu;
  QPSolution sol;
  if (S.optimal) {
    solver = (work.empty() ? "KKT system of the equality-constrained program, " : "active set (" + std::to_string(S.steps) + " steps) on KKT systems, ") + kind;
    sol.status = QPStatus::optimal;
    sol.x = S.x;
    sol.y.assign(P.qp.rows.size(), Rational(0));
    // 2 D x + c = -A^T mu = sum_r y_r s_r a_r: an equality's >= row takes -mu, its <= row +mu;
    // a working inequality (a >= row) takes -mu
    for (std::size_t r = 0; r < ne; ++r) {
      if (mu[r] < 0) sol.y[2 * r] = -mu[r];
      else sol.y[2 * r + 1] = mu[r];
    }
    for (std::size_t k = 0; k < work.size(); ++k) sol.y[2 * ne + work[k]] = -mu[ne + k];
  } else {
    if (o.progress) std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": the active set did not finish; CGAL's QP solver on the whole program\n";
    sol = solve_qp(P.qp);
    solver = std::string("CGAL's QP solver ") + (std::is_same_v<T, Rational> ? "(exact, Gmpz)" : "on doubles (Gmpzf)") +
             " after the active set did not finish";
    if (sol.status != QPStatus::optimal)
      throw DomainError("tangent-delta", "the patch program is " + to_string(sol.status) + ": no patch with t . dp/dm >= tangent_delta at every boundary sample",
                        "lower --tangent-delta or raise --patch-inner-knots");
    S.x = sol.x;
  }
  return sol;
}

}  // namespace

DomainPolygon patch_domain(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& o) {
  auto D = domain_polygon(loop, o.domain);
  if (o.domain == "auto" && D.method == "qp" && !vertices_independent(D, o.inner_knots)) {
    auto C = domain_polygon(loop, "circle");
    C.why_not_projection = D.why_not_projection;
    C.why_not_qp = "the interpolation conditions at its " + std::to_string(D.vertices.size()) + " vertices are dependent for " +
                   std::to_string(o.inner_knots) + " inner knots (raise --patch-inner-knots to use it)";
    return C;
  }
  return D;
}

void check_patch_program(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& o) {
  validate_surface_options(o);
  const auto D = patch_domain(loop, o);
  const auto U = guide_knots(o.inner_knots);
  const std::size_t N = (U.size() - 4) * (U.size() - 4), ns = D.vertices.size();
  if (ns > N)
    throw DomainError("patch-inner-knots", "the loop has " + std::to_string(ns) + " vertices, more than the patch's " + std::to_string(N) + " control points",
                      "raise --patch-inner-knots");
  if (!vertices_independent(D, o.inner_knots))
    throw DomainError("patch-inner-knots",
                      "the interpolation conditions at the loop's " + std::to_string(ns) + " vertices (domain " + D.method + ") are dependent for " +
                          std::to_string(o.inner_knots) + " inner knots (too few basis functions around some vertices)",
                      "raise --patch-inner-knots");
}

template <class T>
CuttingSurface<T> cutting_surface(const std::vector<LoopSide3>& loop, const SurfaceFacetOptions& o) {
  validate_surface_options(o);
  const auto t0 = std::chrono::steady_clock::now();
  CuttingSurface<T> R;
  R.domain = patch_domain(loop, o);
  const std::size_t ns = loop.size();
  const auto Uq = guide_knots(o.inner_knots);
  PatchProgram<T> P = assemble_patch_program<T>(loop, R.domain.vertices, Uq, o);
  const std::size_t N = P.N, nv = P.nv;
  R.variables = nv, R.equalities = P.eq.size(), R.inequalities = P.ineq.size();
  if (o.progress)
    std::cerr << "[cut facet] " << ArithTraits<T>::name() << ": assembled " << nv << " variables, " << P.eq.size() << " equalities, " << P.ineq.size()
              << " inequalities (" << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s); solving\n";
  // the full program: each equality as a pair of rows, then the inequalities
  for (const auto& r : P.eq) {
    P.qp.rows.push_back(r);
    auto le = r;
    le.at_least = false;
    P.qp.rows.push_back(le);
  }
  for (const auto& r : P.ineq) P.qp.rows.push_back(r);
  const auto exact_qp = [&] {
    if constexpr (std::is_same_v<T, Rational>) return P.qp;
    else return exact_program(P.qp);
  }();
  ActiveSet S = run_active_set(P, exact_qp, o, ns);
  const QPSolution sol = patch_solution(P, S, o, R.solver);
  const auto& x = S.x;
  const std::size_t ne = P.eq.size();
  const auto kkt = check_kkt(exact_qp, sol);
  R.kkt_holds = kkt.holds;
  R.kkt_failed = kkt.failed;
  R.active_inequalities = 0;
  for (std::size_t r = 0; r < P.ineq.size(); ++r)
    if (sparse_dot(exact_qp.rows[2 * ne + r].a, x) == exact_qp.rows[2 * ne + r].b) ++R.active_inequalities;
  R.coefficients = x;
  R.program = exact_qp;
  std::vector<Rational> pts(3 * N);
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < N; ++i) pts[3 * i + c] = x[c * N + i];
  R.patch = make_spline<Rational>({3, 3}, {Uq, Uq}, 3, pts);
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return R;
}

template CuttingSurface<Rational> cutting_surface(const std::vector<LoopSide3>&, const SurfaceFacetOptions&);
template CuttingSurface<double> cutting_surface(const std::vector<LoopSide3>&, const SurfaceFacetOptions&);

}  // namespace splinex
