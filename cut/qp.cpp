// cut/qp.hpp: the float active set certified exactly, CGAL's QP solver behind it (private to this
// file), and the exact KKT check.
#include "cut/qp.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <CGAL/Gmpz.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>

#include "base/errors.hpp"
#include "exact/linear_solve.hpp"

namespace splinex {

std::string to_string(QPStatus s) {
  switch (s) {
    case QPStatus::optimal: return "optimal";
    case QPStatus::infeasible: return "infeasible";
    case QPStatus::unbounded: return "unbounded";
  }
  return "?";
}

namespace {

Integer to_integer(const CGAL::Gmpz& z) {
  Integer r;
  mpz_set(r.backend().data(), z.mpz());
  return r;
}

CGAL::Gmpz to_gmpz(const Integer& z) { return CGAL::Gmpz(z.backend().data()); }

Rational to_rational(const CGAL::Gmpz& z) { return Rational(to_integer(z)); }

Rational to_rational(const CGAL::Quotient<CGAL::Gmpz>& q) {
  return Rational(to_integer(q.numerator()), to_integer(q.denominator()));
}

Rational to_rational(const CGAL::Gmpzf& f) {
  // m * 2^e
  Rational m(to_integer(f.man()));
  const long e = f.exp();
  Rational p(1);
  Integer two(2);
  if (e >= 0) return m * Rational(boost::multiprecision::pow(two, static_cast<unsigned>(e)));
  return m / Rational(boost::multiprecision::pow(two, static_cast<unsigned>(-e)));
}

Rational to_rational(const CGAL::Quotient<CGAL::Gmpzf>& q) { return to_rational(q.numerator()) / to_rational(q.denominator()); }

Integer lcm_of(const Integer& a, const Integer& b) { return boost::multiprecision::lcm(a, b); }

// x * m as an integer (m a multiple of x's denominator).
CGAL::Gmpz scaled(const Rational& x, const Integer& m) { return to_gmpz(Integer(numerator(x) * (m / denominator(x)))); }

// The certificate's multipliers in the convention of qp.hpp: y_r = sign * s_r * lambda_r * m_r / L
// (m_r: the row's scale, L: the objective's); the sign is chosen by the exact check (CGAL's
// convention: c + 2 D x + A^T lambda = 0, lambda >= 0 on <= rows).
template <class Sol, class Conv>
void read_solution(const Sol& sol, const QuadraticProgram<Rational>& exact, const std::vector<Rational>& row_scale,
                   const Rational& obj_scale, Conv conv, QPSolution& out) {
  const std::size_t m = exact.rows.size();
  if (sol.status() == CGAL::QP_OPTIMAL) {
    out.status = QPStatus::optimal;
    for (auto it = sol.variable_values_begin(); it != sol.variable_values_end(); ++it) out.x.push_back(conv(*it));
    std::vector<Rational> lam;
    for (auto it = sol.optimality_certificate_begin(); it != sol.optimality_certificate_end(); ++it) lam.push_back(conv(*it));
    out.y.assign(m, Rational(0));
    for (std::size_t r = 0; r < m && r < lam.size(); ++r)
      out.y[r] = -(exact.rows[r].at_least ? Rational(1) : Rational(-1)) * lam[r] * row_scale[r] / obj_scale;
    out.objective = exact.c0;
    for (std::size_t i = 0; i < exact.n; ++i) {
      out.objective += exact.c[i] * out.x[i];
      for (std::size_t j = 0; j < exact.n; ++j) out.objective += out.x[i] * exact.d(i, j) * out.x[j];
    }
  } else if (sol.status() == CGAL::QP_INFEASIBLE) {
    out.status = QPStatus::infeasible;
    std::vector<Rational> lam;
    for (auto it = sol.infeasibility_certificate_begin(); it != sol.infeasibility_certificate_end(); ++it)
      lam.push_back(conv(*it));
    out.y.assign(m, Rational(0));
    for (std::size_t r = 0; r < m && r < lam.size(); ++r)
      out.y[r] = (exact.rows[r].at_least ? Rational(1) : Rational(-1)) * lam[r] * row_scale[r];
    if (!check_kkt(exact, out).holds)
      for (auto& v : out.y) v = -v;
  } else {
    out.status = QPStatus::unbounded;
  }
}

}  // namespace

QuadraticProgram<Rational> exact_program(const QuadraticProgram<double>& qp) {
  QuadraticProgram<Rational> e;
  e.n = qp.n;
  for (double v : qp.D) e.D.push_back(exact_from_double(v, "D"));
  for (double v : qp.c) e.c.push_back(exact_from_double(v, "c"));
  e.c0 = exact_from_double(qp.c0, "c0");
  for (const auto& r : qp.rows) {
    QuadraticProgram<Rational>::Row x;
    for (const auto& [i, v] : r.a) x.a.emplace_back(i, exact_from_double(v, "a"));
    x.b = exact_from_double(r.b, "b");
    x.at_least = r.at_least;
    e.rows.push_back(std::move(x));
  }
  return e;
}

namespace {

QPSolution solve_qp_cgal(const QuadraticProgram<Rational>& qp) {
  // One integer factor for the objective, one per row: the same minimizer, integer data for Gmpz.
  Integer L(1);
  for (const auto& v : qp.D) L = lcm_of(L, denominator(v));
  for (const auto& v : qp.c) L = lcm_of(L, denominator(v));
  CGAL::Quadratic_program<CGAL::Gmpz> p(CGAL::LARGER, false, 0, false, 0);
  for (std::size_t i = 0; i < qp.n; ++i) {
    p.set_c(static_cast<int>(i), scaled(qp.c[i], L));
    for (std::size_t j = 0; j <= i; ++j)
      if (qp.d(i, j) != 0) p.set_d(static_cast<int>(i), static_cast<int>(j), scaled(Rational(2 * qp.d(i, j)), L));
  }
  std::vector<Rational> row_scale;
  for (std::size_t r = 0; r < qp.rows.size(); ++r) {
    const auto& row = qp.rows[r];
    Integer m = denominator(row.b);
    for (const auto& [i, v] : row.a) m = lcm_of(m, denominator(v));
    for (const auto& [i, v] : row.a)
      if (v != 0) p.set_a(static_cast<int>(i), static_cast<int>(r), scaled(v, m));
    p.set_b(static_cast<int>(r), scaled(row.b, m));
    p.set_r(static_cast<int>(r), row.at_least ? CGAL::LARGER : CGAL::SMALLER);
    row_scale.push_back(Rational(m));
  }
  const auto sol = CGAL::solve_quadratic_program(p, CGAL::Gmpz());
  QPSolution out;
  read_solution(sol, qp, row_scale, Rational(L), [](const auto& q) { return to_rational(q); }, out);
  out.method = "exact solver (CGAL, Gmpz)";
  return out;
}

// ---- The float path: a dual active-set solve in double, certified exactly ------------------------

// Test seam (qp_testing::ScopedPlantedActiveSet): a planted active set for solve_qp's float phase.
thread_local const std::vector<std::size_t>* planted_active_set = nullptr;

Rational objective_of(const QuadraticProgram<Rational>& qp, const std::vector<Rational>& x) {
  Rational f = qp.c0;
  for (std::size_t i = 0; i < qp.n; ++i) {
    if (x[i] == 0) continue;
    Rational row(0);
    for (std::size_t j = 0; j < qp.n; ++j)
      if (qp.d(i, j) != 0 && x[j] != 0) row += qp.d(i, j) * x[j];
    f += x[i] * (row + qp.c[i]);
  }
  return f;
}

// g_r . x - h_r for row r written as a >= row (g_r = s_r a_r, h_r = s_r b_r), exactly.
Rational slack_of(const QuadraticProgram<Rational>::Row& row, const std::vector<Rational>& x) {
  Rational ax(0);
  for (const auto& [i, v] : row.a) ax += v * x[i];
  return row.at_least ? Rational(ax - row.b) : Rational(row.b - ax);
}

// A Farkas candidate from the float phase: rows T = S + {p} (p last) with g_p in the cone -G_S,
// i.e. y_p = 1 and y_S from the normal equations (G_S G_S^T) y_S = -G_S g_p, solved exactly. Kept
// only if check_kkt confirms sum y_r g_r = 0, y >= 0 and sum y_r h_r > 0 exactly.
std::optional<QPSolution> certify_farkas(const QuadraticProgram<Rational>& qp, const std::vector<std::size_t>& T) {
  if (T.empty()) return std::nullopt;
  const std::size_t n = qp.n, m = qp.rows.size(), k = T.size() - 1, p = T.back();
  for (auto r : T)
    if (r >= m) return std::nullopt;
  auto dense = [&](std::size_t r) {
    std::vector<Rational> g(n, Rational(0));
    for (const auto& [i, v] : qp.rows[r].a) g[i] += qp.rows[r].at_least ? v : Rational(-v);
    return g;
  };
  std::vector<std::vector<Rational>> G;
  for (std::size_t j = 0; j < k; ++j) G.push_back(dense(T[j]));
  const auto gp = dense(p);
  QPSolution s;
  s.status = QPStatus::infeasible;
  s.y.assign(m, Rational(0));
  s.y[p] = 1;
  if (k > 0) {
    std::vector<Rational> A(k * k, Rational(0)), B(k, Rational(0));
    for (std::size_t a = 0; a < k; ++a) {
      for (std::size_t b = a; b < k; ++b) {
        Rational d(0);
        for (std::size_t i = 0; i < n; ++i)
          if (G[a][i] != 0 && G[b][i] != 0) d += G[a][i] * G[b][i];
        A[a * k + b] = d, A[b * k + a] = d;
      }
      Rational d(0);
      for (std::size_t i = 0; i < n; ++i)
        if (G[a][i] != 0 && gp[i] != 0) d += G[a][i] * gp[i];
      B[a] = -d;
    }
    const auto X = solve_linear_exact(A, k, B, 1);
    if (!X) return std::nullopt;
    for (std::size_t j = 0; j < k; ++j) s.y[T[j]] += (*X)[j];
  }
  if (!check_kkt(qp, s).holds) return std::nullopt;
  s.method = "float active set, Farkas certificate (" + std::to_string(T.size()) + " rows) checked exactly";
  return s;
}
}  // namespace

QPSolution solve_qp(const QuadraticProgram<Rational>& qp) {
  std::string why;
  if (planted_active_set) {
    // test seam: a planted active set, no repairs
    const auto cert = certify_active_set(qp, *planted_active_set, 0);
    if (cert.certified) return cert.solution;
    why = "the planted active set was not certified: " + cert.why;
  } else {
    const auto f = float_active_set(qp);
    if (f.status == QPStatus::optimal) {
      const auto cert = certify_active_set(qp, f.active);
      if (cert.certified) return cert.solution;
      why = "the float active set was not certified: " + cert.why;
    } else if (f.status == QPStatus::infeasible) {
      auto s = certify_farkas(qp, f.active);
      if (s) return *s;
      why = "the float solve found the program infeasible, but its Farkas candidate did not check exactly";
    } else {
      why = "the float solve failed: " + f.why;
    }
  }
  auto out = solve_qp_cgal(qp);
  out.method += ", after " + why;
  return out;
}

QPSolution solve_qp(const QuadraticProgram<double>& qp) {
  // CGAL reads the doubles exactly (Gmpzf): an inf or NaN stops it with a floating-point exception.
  // A program whose assembly overflowed double (weights like 1e400 round to inf) is refused here,
  // the one place every double program passes.
  auto finite = [](double v, const std::string& what) {
    if (!std::isfinite(v))
      throw DomainError("program", "has " + what + " beyond double's range (inf or NaN): the data or the weights overflow in double",
                        "give smaller weights or data, or use --arith exact");
  };
  for (double v : qp.D) finite(2 * v, "an objective entry");
  for (double v : qp.c) finite(v, "a linear term");
  finite(qp.c0, "its constant term");
  for (const auto& row : qp.rows) {
    for (const auto& [i, v] : row.a) finite(v, "a constraint coefficient");
    finite(row.b, "a constraint bound");
  }
  CGAL::Quadratic_program<double> p(CGAL::LARGER, false, 0, false, 0);
  for (std::size_t i = 0; i < qp.n; ++i) {
    p.set_c(static_cast<int>(i), qp.c[i]);
    for (std::size_t j = 0; j <= i; ++j)
      if (qp.d(i, j) != 0) p.set_d(static_cast<int>(i), static_cast<int>(j), 2 * qp.d(i, j));
  }
  for (std::size_t r = 0; r < qp.rows.size(); ++r) {
    const auto& row = qp.rows[r];
    for (const auto& [i, v] : row.a)
      if (v != 0) p.set_a(static_cast<int>(i), static_cast<int>(r), v);
    p.set_b(static_cast<int>(r), row.b);
    p.set_r(static_cast<int>(r), row.at_least ? CGAL::LARGER : CGAL::SMALLER);
  }
  const auto sol = CGAL::solve_quadratic_program(p, CGAL::Gmpzf());
  QPSolution out;
  const auto exact = exact_program(qp);
  std::vector<Rational> ones(qp.rows.size(), Rational(1));
  read_solution(sol, exact, ones, Rational(1), [](const auto& q) { return to_rational(q); }, out);
  out.method = "exact solver on the rounded program (CGAL, Gmpzf)";
  return out;
}

KKTCheck check_kkt(const QuadraticProgram<Rational>& qp, const QPSolution& s) {
  KKTCheck k;
  const std::size_t m = qp.rows.size();
  if (s.y.size() != m) {
    k.failed = "multipliers missing";
    return k;
  }
  for (std::size_t r = 0; r < m; ++r)
    if (s.y[r] < 0) {
      k.failed = "multiplier of row " + std::to_string(r) + " is negative";
      return k;
    }
  std::vector<Rational> g(qp.n, Rational(0));  // sum_r y_r s_r a_r
  for (std::size_t r = 0; r < m; ++r) {
    if (s.y[r] == 0) continue;
    const Rational ys = qp.rows[r].at_least ? s.y[r] : Rational(-s.y[r]);
    for (const auto& [i, v] : qp.rows[r].a) g[i] += ys * v;
  }
  if (s.status == QPStatus::infeasible) {
    for (std::size_t i = 0; i < qp.n; ++i)
      if (g[i] != 0) {
        k.failed = "Farkas combination of the rows is not 0 in variable " + std::to_string(i);
        return k;
      }
    Rational rhs(0);
    for (std::size_t r = 0; r < m; ++r) rhs += (qp.rows[r].at_least ? s.y[r] : Rational(-s.y[r])) * qp.rows[r].b;
    if (!(rhs > 0)) {
      k.failed = "Farkas combination of the right-hand sides is not positive";
      return k;
    }
    k.holds = true;
    return k;
  }
  if (s.status != QPStatus::optimal || s.x.size() != qp.n) {
    k.failed = "no minimizer";
    return k;
  }
  for (std::size_t r = 0; r < m; ++r) {
    Rational ax(0);
    for (const auto& [i, v] : qp.rows[r].a) ax += v * s.x[i];
    const Rational slack = qp.rows[r].at_least ? Rational(ax - qp.rows[r].b) : Rational(qp.rows[r].b - ax);
    if (slack < 0) {
      k.failed = "row " + std::to_string(r) + " is violated";
      return k;
    }
    if (slack == 0) ++k.active;
    if (slack != 0 && s.y[r] != 0) {
      k.failed = "complementary slackness fails in row " + std::to_string(r);
      return k;
    }
  }
  for (std::size_t i = 0; i < qp.n; ++i) {
    Rational grad = qp.c[i];
    for (std::size_t j = 0; j < qp.n; ++j) grad += 2 * qp.d(i, j) * s.x[j];
    if (grad != g[i]) {
      k.failed = "stationarity fails in variable " + std::to_string(i);
      return k;
    }
  }
  k.holds = true;
  return k;
}

bool positive_definite_by_congruence(const QuadraticProgram<Rational>& qp) {
  // D is congruent to M = R (delta D) R^T for any nonsingular R and delta > 0 (Sylvester's law of
  // inertia: the same signs of eigenvalues). R: the inverse of D's Cholesky factor computed in double,
  // each row rounded to integers at its own scale 2^F_i (lower triangular, non-zero diagonal: exactly
  // nonsingular), so M = S^-1 (about delta I) S^-1 with S = diag(2^-F_i). M is computed exactly in
  // integers (FLINT), and S M S strictly diagonally dominant with a positive diagonal (exact
  // integer comparisons) proves it, hence D, positive definite (Gershgorin). Only proves, never refutes.
  const std::size_t n = qp.n;
  if (n == 0 || qp.D.size() != n * n) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (qp.d(i, j) != qp.d(j, i)) return false;
  Eigen::MatrixXd Dd(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) Dd(i, j) = to_double(qp.d(i, j));
  if (!Dd.allFinite()) return false;
  const Eigen::LLT<Eigen::MatrixXd> llt(Dd);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd Rd = llt.matrixL().solve(Eigen::MatrixXd::Identity(static_cast<long>(n), static_cast<long>(n)));
  if (!Rd.allFinite()) return false;
  struct Z {
    fmpz_mat_t m;
    Z(std::size_t r, std::size_t c) { fmpz_mat_init(m, static_cast<slong>(r), static_cast<slong>(c)); }
    ~Z() { fmpz_mat_clear(m); }
    Z(const Z&) = delete;
    Z& operator=(const Z&) = delete;
  };
  Z R(n, n), Dz(n, n), T(n, n), Rt(n, n), M(n, n);
  std::vector<long> F(n);
  for (std::size_t i = 0; i < n; ++i) {
    double mx = 0;
    for (std::size_t j = 0; j <= i; ++j) mx = std::max(mx, std::abs(Rd(i, j)));
    if (!(mx > 0)) return false;
    int e = 0;
    std::frexp(mx, &e);  // mx < 2^e
    F[i] = 52 - e;
    for (std::size_t j = 0; j <= i; ++j) fmpz_set_d(fmpz_mat_entry(R.m, i, j), std::nearbyint(std::ldexp(Rd(i, j), static_cast<int>(F[i]))));
    if (fmpz_is_zero(fmpz_mat_entry(R.m, i, i))) return false;
  }
  Integer delta(1);
  for (const auto& v : qp.D) delta = boost::multiprecision::lcm(delta, denominator(v));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const Rational& v = qp.d(i, j);
      if (v == 0) continue;
      const Integer z = numerator(v) * (delta / denominator(v));
      fmpz_set_mpz(fmpz_mat_entry(Dz.m, i, j), z.backend().data());
    }
  fmpz_mat_mul(T.m, R.m, Dz.m);
  fmpz_mat_transpose(Rt.m, R.m);
  fmpz_mat_mul(M.m, T.m, Rt.m);
  // row i of S M S times 2^(K + F_i): sum_{j != i} |M_ij| 2^(K - F_j) < M_ii 2^(K - F_i)
  const long K = *std::max_element(F.begin(), F.end());
  fmpz_t off, term, diag;
  fmpz_init(off), fmpz_init(term), fmpz_init(diag);
  bool ok = true;
  for (std::size_t i = 0; i < n && ok; ++i) {
    fmpz_zero(off);
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      fmpz_abs(term, fmpz_mat_entry(M.m, i, j));
      fmpz_mul_2exp(term, term, static_cast<ulong>(K - F[j]));
      fmpz_add(off, off, term);
    }
    fmpz_mul_2exp(diag, fmpz_mat_entry(M.m, i, i), static_cast<ulong>(K - F[i]));
    ok = fmpz_sgn(diag) > 0 && fmpz_cmp(off, diag) < 0;
  }
  fmpz_clear(off), fmpz_clear(term), fmpz_clear(diag);
  return ok;
}

bool positive_definite_by_elimination(const QuadraticProgram<Rational>& qp) {
  const std::size_t n = qp.n;
  std::vector<Rational> A = qp.D;
  for (std::size_t k = 0; k < n; ++k) {
    const Rational piv = A[k * n + k];
    if (!(piv > 0)) return false;
    for (std::size_t i = k + 1; i < n; ++i) {
      if (A[i * n + k] == 0) continue;
      const Rational f = A[i * n + k] / piv;
      for (std::size_t j = k + 1; j < n; ++j)
        if (A[k * n + j] != 0) A[i * n + j] -= f * A[k * n + j];
    }
  }
  return true;
}

bool positive_definite(const QuadraticProgram<Rational>& qp) { return positive_definite_by_congruence(qp) || positive_definite_by_elimination(qp); }

FloatActiveSet float_active_set(const QuadraticProgram<Rational>& qp) {
  // Goldfarb and Idnani's dual method (Math. Programming 27, 1983) on the program rounded to double,
  // in the whitened variables v = L^T x (2D = L L^T): minimize |v - v0|^2 / 2 subject to
  // w_r . v >= h_r, w_r = L^-1 g_r. It starts from the unconstrained minimizer and adds the most
  // violated row, dropping rows whose multiplier would turn negative; every iterate is dual feasible.
  FloatActiveSet out;
  const std::size_t n = qp.n, m = qp.rows.size();
  if (n == 0) {
    out.why = "the program has no variables";
    return out;
  }
  auto fd = [](const Rational& v) { return to_double(v); };
  Eigen::MatrixXd H(n, n);
  Eigen::VectorXd c(n);
  for (std::size_t i = 0; i < n; ++i) {
    c(i) = fd(qp.c[i]);
    for (std::size_t j = 0; j < n; ++j) H(i, j) = 2 * fd(qp.d(i, j));
  }
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, m);
  Eigen::VectorXd h(m);
  std::vector<char> zero_row(m, 0);
  for (std::size_t r = 0; r < m; ++r) {
    const double s = qp.rows[r].at_least ? 1 : -1;
    for (const auto& [i, v] : qp.rows[r].a) G(i, r) += s * fd(v);
    h(r) = s * fd(qp.rows[r].b);
    const double mx = G.col(r).cwiseAbs().maxCoeff();
    if (!std::isfinite(mx) || !std::isfinite(h(r))) {
      out.why = "a constraint row is beyond double's range";
      return out;
    }
    if (mx == 0) {
      zero_row[r] = 1;
      if (h(r) > 0) {  // 0 >= h > 0: a Farkas certificate by itself
        out.status = QPStatus::infeasible;
        out.active = {r};
        return out;
      }
      continue;
    }
    G.col(r) /= mx, h(r) /= mx;
  }
  if (!H.allFinite() || !c.allFinite()) {
    out.why = "the objective is beyond double's range";
    return out;
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(H);
  if (llt.info() != Eigen::Success) {
    out.why = "the objective's matrix is not positive definite in double";
    return out;
  }
  const auto L = llt.matrixL();
  // No inequality rows: an empty W (Eigen's triangular solve binds a reference to an empty
  // right-hand side's first entry, which UBSan reports).
  const Eigen::MatrixXd W = G.cols() == 0 ? Eigen::MatrixXd(H.rows(), 0) : Eigen::MatrixXd(L.solve(G));
  Eigen::VectorXd v = -L.solve(c);
  if (!W.allFinite() || !v.allFinite()) {
    out.why = "the whitened program is beyond double's range";
    return out;
  }
  Eigen::VectorXd wnorm(m);
  for (std::size_t r = 0; r < m; ++r) wnorm(r) = W.col(r).norm();
  std::vector<std::size_t> S;  // the active rows
  std::vector<double> u;       // their multipliers (>= 0)
  std::vector<char> in_S(m, 0);
  const double eps = std::numeric_limits<double>::epsilon();
  const std::size_t max_steps = 4 * (m + n) + 100;
  for (std::size_t step = 0; step < max_steps; ++step) {
    // the most violated row, by its distance in v
    std::size_t p = m;
    double worst = 0;
    for (std::size_t r = 0; r < m; ++r) {
      if (in_S[r] || zero_row[r]) continue;
      const double wv = W.col(r).dot(v), sl = wv - h(r);
      if (sl >= -1e-11 * (1 + std::abs(h(r)) + std::abs(wv))) continue;
      const double dist = -sl / wnorm(r);
      if (dist > worst) worst = dist, p = r;
    }
    if (p == m) {
      out.status = QPStatus::optimal;
      out.active = S;
      return out;
    }
    const Eigen::VectorXd wp = W.col(p);
    double up = 0;
    bool added = false;
    for (std::size_t inner = 0; inner <= S.size() + 1 && !added; ++inner) {
      const std::size_t k = S.size();
      Eigen::VectorXd z = wp, rr(k);
      if (k > 0) {
        Eigen::MatrixXd N(n, k);
        for (std::size_t j = 0; j < k; ++j) N.col(j) = W.col(S[j]);
        const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(N);
        rr = qr.solve(wp);
        z = wp - N * rr;
      }
      double t1 = std::numeric_limits<double>::infinity();
      std::size_t l = k;
      for (std::size_t j = 0; j < k; ++j)
        if (rr(j) > 0 && u[j] / rr(j) < t1) t1 = u[j] / rr(j), l = j;
      const double zz = z.dot(wp);
      auto drop = [&](std::size_t j) {
        in_S[S[j]] = 0;
        S.erase(S.begin() + static_cast<long>(j));
        u.erase(u.begin() + static_cast<long>(j));
      };
      if (!(zz > 64 * eps * wp.squaredNorm())) {  // w_p lies in the span of the active rows
        if (l == k) {  // and in the cone of their negatives: infeasible (a Farkas candidate)
          out.status = QPStatus::infeasible;
          out.active = S;
          out.active.push_back(p);
          return out;
        }
        for (std::size_t j = 0; j < k; ++j) u[j] = std::max(0.0, u[j] - t1 * rr(j));
        up += t1;
        drop(l);
        continue;
      }
      const double t2 = -(wp.dot(v) - h(p)) / zz;
      const double t = std::min(t1, t2);
      v += t * z;
      for (std::size_t j = 0; j < k; ++j) u[j] = std::max(0.0, u[j] - t * rr(j));
      up += t;
      if (t2 <= t1) {
        S.push_back(p), u.push_back(up), in_S[p] = 1;
        added = true;
      } else {
        drop(l);
      }
    }
    if (!v.allFinite()) break;
  }
  out.why = "the dual active-set method did not finish";
  return out;
}

ActiveSetCertificate certify_active_set(const QuadraticProgram<Rational>& qp, std::vector<std::size_t> active, int max_repairs) {
  ActiveSetCertificate out;
  const std::size_t n = qp.n, m = qp.rows.size();
  std::sort(active.begin(), active.end());
  active.erase(std::unique(active.begin(), active.end()), active.end());
  for (auto r : active)
    if (r >= m) {
      out.active = active;
      out.why = "row " + std::to_string(r) + " of the active set does not exist";
      return out;
    }
  std::size_t joined = m;  // the row the last repair added
  for (int step = 0;; ++step) {
    out.active = active;
    const std::size_t k = active.size(), N = n + k;
    // [2D, -G^T; G, 0] [x; y] = [-c; h]: stationarity 2Dx + c = G^T y and the active rows tight
    std::vector<Rational> A(N * N, Rational(0)), B(N, Rational(0));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j)
        if (qp.d(i, j) != 0) A[i * N + j] = 2 * qp.d(i, j);
      B[i] = -qp.c[i];
    }
    for (std::size_t t = 0; t < k; ++t) {
      const auto& row = qp.rows[active[t]];
      for (const auto& [i, v] : row.a) {
        const Rational g = row.at_least ? v : Rational(-v);
        A[(n + t) * N + i] += g;
        A[i * N + n + t] -= g;
      }
      B[n + t] = row.at_least ? row.b : Rational(-row.b);
    }
    ++out.exact_solves;
    const auto X = solve_linear_exact(A, N, B, 1);
    if (!X) {
      out.why = "the KKT system of the " + std::to_string(k) + " active rows is singular (dependent rows)";
      // A violated row that joined dependent on the others may prove infeasibility: try the rows as
      // a Farkas certificate, the joined row last.
      if (joined < m) {
        std::vector<std::size_t> T;
        for (auto r : active)
          if (r != joined) T.push_back(r);
        T.push_back(joined);
        if (auto f = certify_farkas(qp, T)) {
          f->method += " after " + std::to_string(step) + " exact repair" + (step == 1 ? "" : "s");
          out.certified = true;
          out.solution = std::move(*f);
          out.why.clear();
        }
      }
      return out;
    }
    QPSolution s;
    s.status = QPStatus::optimal;
    s.x.assign(X->begin(), X->begin() + static_cast<long>(n));
    s.y.assign(m, Rational(0));
    for (std::size_t t = 0; t < k; ++t) s.y[active[t]] = (*X)[n + t];
    // a negative multiplier: its row leaves (the most negative); else the most violated row joins
    std::size_t leave = k;
    for (std::size_t t = 0; t < k; ++t)
      if (s.y[active[t]] < 0 && (leave == k || s.y[active[t]] < s.y[active[leave]])) leave = t;
    std::size_t join = m;
    double worst = 0;
    if (leave == k)
      for (std::size_t r = 0; r < m; ++r) {
        if (std::binary_search(active.begin(), active.end(), r)) continue;
        const Rational sl = slack_of(qp.rows[r], s.x);
        if (!(sl < 0)) continue;
        double norm = 0;
        for (const auto& [i, v] : qp.rows[r].a) norm = std::max(norm, std::abs(to_double(v)));
        const double dist = -to_double(sl) / (norm > 0 ? norm : 1);
        if (join == m || dist > worst) worst = dist, join = r;
      }
    if (leave == k && join == m) {
      s.objective = objective_of(qp, s.x);
      const auto kkt = check_kkt(qp, s);
      if (!kkt.holds) {
        out.why = "the exact KKT check fails: " + kkt.failed;
        return out;
      }
      s.method = "float active set (" + std::to_string(k) + " active rows), certified exactly" +
                 (step == 0 ? std::string() : " after " + std::to_string(step) + " exact repair" + (step == 1 ? "" : "s"));
      out.certified = true;
      out.solution = std::move(s);
      return out;
    }
    if (step >= max_repairs) {
      out.why = leave < k ? "the multiplier of active row " + std::to_string(active[leave]) + " is negative"
                          : "row " + std::to_string(join) + " is violated by the active set's point";
      if (max_repairs > 0) out.why += " after " + std::to_string(max_repairs) + " exact repairs";
      return out;
    }
    joined = leave < k ? m : join;
    if (leave < k) active.erase(active.begin() + static_cast<long>(leave));
    else active.insert(std::upper_bound(active.begin(), active.end(), join), join);
  }
}

namespace qp_testing {
ScopedPlantedActiveSet::ScopedPlantedActiveSet(std::vector<std::size_t> rows) : rows_(std::move(rows)), previous_(planted_active_set) {
  planted_active_set = &rows_;
}
ScopedPlantedActiveSet::~ScopedPlantedActiveSet() { planted_active_set = previous_; }
}  // namespace qp_testing

}  // namespace splinex
