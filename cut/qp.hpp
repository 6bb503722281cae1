// Convex quadratic programs solved exactly with CGAL's QP solver (CGAL::solve_quadratic_program),
// and their KKT conditions checked exactly here, independently of the solver.
//
// The program: minimize x^T D x + c^T x + c0 over free variables x in R^n, subject to rows
// a_r . x >= b_r or a_r . x <= b_r. D is symmetric (given in full) and positive semidefinite.
// Exact data (Rational) is scaled to integers (one factor for the objective, one per row, which
// changes neither the feasible set nor the minimizer) and solved with CGAL's exact type Gmpz;
// double data is solved by the same solver on doubles with its exact type Gmpzf, as CGAL
// recommends: the exact minimizer of the rounded program. Both results are exact rationals.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "exact/rational.hpp"

namespace splinex {

template <class T>
struct QuadraticProgram {
  struct Row {
    std::vector<std::pair<std::size_t, T>> a;  // sparse: (variable, coefficient)
    T b = T(0);
    bool at_least = true;  // a . x >= b; else a . x <= b
  };
  std::size_t n = 0;
  std::vector<T> D;  // n * n, row-major, symmetric
  std::vector<T> c;  // n
  T c0 = T(0);
  std::vector<Row> rows;
  T& d(std::size_t i, std::size_t j) { return D[i * n + j]; }
  const T& d(std::size_t i, std::size_t j) const { return D[i * n + j]; }
};

enum class QPStatus { optimal, infeasible, unbounded };
std::string to_string(QPStatus s);

/// An exact answer of the solver: the minimizer and the KKT multipliers of the rows (optimal), or
/// the Farkas multipliers of an infeasibility certificate (infeasible). Multipliers y_r >= 0 are
/// stated for rows written as >= (a <= row counts as -a . x >= -b): at an optimum
/// 2 D x + c = sum_r y_r s_r a_r with s_r = +1 for >= rows, -1 for <= rows; for infeasibility
/// sum_r y_r s_r a_r = 0 and sum_r y_r s_r b_r > 0.
struct QPSolution {
  QPStatus status = QPStatus::infeasible;
  std::vector<Rational> x;
  std::vector<Rational> y;
  Rational objective;
};

QPSolution solve_qp(const QuadraticProgram<Rational>& qp);
QPSolution solve_qp(const QuadraticProgram<double>& qp);

/// The exact check of a solution against a program given exactly (for a double program: its
/// doubles' exact values). For an optimum: primal feasibility, y >= 0, complementary slackness,
/// stationarity 2 D x + c = sum y_r s_r a_r, each an exact equality or inequality; with D positive
/// semidefinite these prove x a minimizer. For infeasibility: the Farkas identity.
struct KKTCheck {
  bool holds = false;
  std::string failed;  // the first condition that does not hold, empty when all hold
  std::size_t active = 0;  // rows with a_r . x = b_r
};
KKTCheck check_kkt(const QuadraticProgram<Rational>& qp, const QPSolution& s);

/// Exact LDL^T of D without pivoting on a zero pivot: true when every pivot is positive (D positive
/// definite, so the minimizer is unique: Lemma 1 of papers/004).
bool positive_definite(const QuadraticProgram<Rational>& qp);

/// The program's data as exact rationals (every double is a dyadic rational).
QuadraticProgram<Rational> exact_program(const QuadraticProgram<double>& qp);

}  // namespace splinex
