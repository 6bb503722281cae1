// CGAL's QP solver behind cut/qp.hpp (private to this file), and the exact KKT check.
#include "cut/qp.hpp"

#include <CGAL/Gmpz.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include "spline/errors.hpp"

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

QPSolution solve_qp(const QuadraticProgram<Rational>& qp) {
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

bool positive_definite(const QuadraticProgram<Rational>& qp) {
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

}  // namespace splinex
