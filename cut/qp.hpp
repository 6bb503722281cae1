// Convex quadratic programs solved exactly, and their KKT conditions checked exactly here,
// independently of the solver.
//
// The program: minimize x^T D x + c^T x + c0 over free variables x in R^n, subject to rows
// a_r . x >= b_r or a_r . x <= b_r. D is symmetric (given in full) and positive semidefinite.
// Exact data (Rational) is first solved in floating point and certified exactly, as exact LP
// solvers do (SoPlex's iterative refinement, QSopt_ex): the program rounded to double is solved by
// a dual active-set method (Goldfarb-Idnani, Eigen), its active rows are held as equalities and the
// KKT system of that set is solved exactly (FLINT, Dixon), and the exact point and multipliers must
// pass check_kkt on the original exact program (a few exact repairs: a row with a negative
// multiplier leaves, a violated row joins). An infeasible float solve gives a Farkas candidate,
// checked the same way. Only when that fails does CGAL's exact solver run
// (CGAL::solve_quadratic_program on the data scaled to integers, one factor for the objective and
// one per row, which changes neither the feasible set nor the minimizer, exact type Gmpz).
// QPSolution::method says which path gave the answer. Double data is solved by CGAL's solver on
// doubles with its exact type Gmpzf, as CGAL recommends: the exact minimizer of the rounded
// program. Every result is exact rationals.
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
  /// How the answer was found (not part of its proof: check_kkt decides that): "float active set,
  /// certified exactly" (with the exact repairs it took), "exact solver (CGAL, Gmpz)" with why the
  /// float path did not certify, or, for double programs, "exact solver on the rounded program
  /// (CGAL, Gmpzf)".
  std::string method;
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

/// True when D is proved positive definite (so the minimizer is unique: Lemma 1 of papers/004):
/// first by an exact congruence certificate (positive_definite_by_congruence), else by exact
/// elimination (positive_definite_by_elimination), which also decides the other cases.
bool positive_definite(const QuadraticProgram<Rational>& qp);
/// The fast certificate: R ~ (Cholesky factor of D)^-1 from double, rounded to integers row by row
/// (exactly nonsingular), M = R (delta D) R^T exactly (FLINT integer products), and M strictly
/// diagonally dominant with a positive diagonal after an exact power-of-two scaling. true proves D
/// positive definite; false proves nothing (ill-conditioned in double, or D not exactly symmetric).
bool positive_definite_by_congruence(const QuadraticProgram<Rational>& qp);
/// Exact LDL^T of D without pivoting: true when every pivot is positive (D positive definite); false
/// at the first pivot <= 0 (D not positive definite, when D is symmetric).
bool positive_definite_by_elimination(const QuadraticProgram<Rational>& qp);

/// The program's data as exact rationals (every double is a dyadic rational).
QuadraticProgram<Rational> exact_program(const QuadraticProgram<double>& qp);

/// The exact half of solve_qp's float path: the rows `active` held as equalities, the KKT system
/// [2D, -G^T; G, 0] [x; y] = [-c; h] (G: the active rows as >= rows) solved exactly, and the point
/// accepted only if check_kkt holds on the whole program. Up to `max_repairs` further exact solves
/// mend the set (the most negative multiplier's row leaves, else the most violated row joins). A
/// singular KKT system (dependent rows) or a failed check gives certified = false with the reason;
/// it never throws for a bad set. When a violated row that joined makes the system singular, the
/// rows are tried as a Farkas certificate: certified = true with an infeasible solution if
/// check_kkt confirms it.
struct ActiveSetCertificate {
  bool certified = false;
  QPSolution solution;           // certified: check_kkt holds (optimal: x and y exact; or infeasible)
  std::vector<std::size_t> active;  // the set that was certified (or the last one tried)
  int exact_solves = 0;
  std::string why;               // not certified: the reason
};
ActiveSetCertificate certify_active_set(const QuadraticProgram<Rational>& qp, std::vector<std::size_t> active, int max_repairs = 4);

/// The float phase alone (for tests and studies): the program rounded to double and solved by the
/// dual active-set method. optimal: `active` holds the active rows; infeasible: `active` holds the
/// rows of a Farkas candidate; `why` says why it failed otherwise (not positive definite in double,
/// a number beyond double's range, no convergence).
struct FloatActiveSet {
  QPStatus status = QPStatus::unbounded;  // unbounded here: the float phase failed
  std::vector<std::size_t> active;
  std::string why;
};
FloatActiveSet float_active_set(const QuadraticProgram<Rational>& qp);

namespace qp_testing {
/// Test seam (tests/cut/test_planted.cpp only): while alive, the float phase of solve_qp hands the
/// exact certificate `rows` as its active set (a planted wrong set) with no repairs allowed, so the
/// certificate must reject it and solve_qp must fall back to the exact solver. Off, it costs solve_qp
/// one pointer read.
class ScopedPlantedActiveSet {
 public:
  explicit ScopedPlantedActiveSet(std::vector<std::size_t> rows);
  ~ScopedPlantedActiveSet();
  ScopedPlantedActiveSet(const ScopedPlantedActiveSet&) = delete;
  ScopedPlantedActiveSet& operator=(const ScopedPlantedActiveSet&) = delete;

 private:
  std::vector<std::size_t> rows_;
  const std::vector<std::size_t>* previous_;
};
}  // namespace qp_testing

}  // namespace splinex
