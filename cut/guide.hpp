// The implicit guiding curve of papers/004 Section 3 (d = 2): f* = sum c_i phi_i, a tensor-product
// cubic spline on the unit square of the normalized solid (open knot vectors, uniform inner knots),
// found by the regularized discretized cutting problem RDCP:
//
//   minimize  lambda_int F_int + lambda_tan F_tan + lambda_reg F_reg
//   F_int = sum_{x in L*} f*(x)^2,  F_tan = sum_{x in L*} |grad f*(x) - n(x)|^2,
//   F_reg = integral over [0,1]^2 of f_xx^2 + 2 f_xy^2 + f_yy^2   (Eq. 3; c^T M c, M exact from
//           univariate integrals of products of B-spline derivatives),
//   subject to f*(x) >= delta on b*, f*(x) <= -delta on b-bar*.
//
// L* holds the two cut points; n is the tangent t turned a quarter towards b: (t_y, -t_x) at the
// first point, (-t_y, t_x) at the second, with t's length (give unit tangents such as (3/5, 4/5)
// for the paper's unit normals). b is the boundary from the first point to the second,
// counter-clockwise (f* > 0), b-bar the rest (f* < 0). b* and b-bar* are the facets' points at
// `samples` equal parameter steps, without those in the strip (max-norm distance <= strip) around
// the cut points. When RDCP is infeasible the knots are refined dyadically (k -> 2k + 1 inner knots)
// up to max_inner_knots, as in the paper.
//
// Exact: assembled in Rational, solved by solve_qp (cut/qp.hpp: a float active set certified
// exactly, CGAL's exact QP solver only when that fails; GuideResult::solution.method says which),
// the KKT conditions and the positive definiteness of the objective's matrix checked exactly
// (Lemma 1: then the minimizer is unique and this is it). Double: assembled in double, the rounded
// program solved by CGAL's solver on doubles (exactly, Gmpzf), the minimizer rounded to double.
#pragma once
#include <string>
#include <vector>

#include "cut/qp.hpp"
#include "cut/solid.hpp"
#include "cut/solid3.hpp"
#include "float/mpfr.hpp"  // ArithTraits<double>

namespace splinex {

struct GuideOptions {
  int inner_knots = 3;
  int inner_knots_y = -1;  // inner knots in y; -1: as in x (the paper's snake needed its own knot vector)
  int max_inner_knots = 7;  // refinement doubles both counts (+1) while the x count stays within this
  Rational delta{1, 20};
  Rational lambda_int{1};
  Rational lambda_tan{1};
  Rational lambda_reg{1, 100};
  int samples = 16;  // per facet
  Rational strip{1, 16};
  /// The program's size limit (variables x (variables + rows)), checked before assembling.
  std::size_t max_size = 400000;
  /// Exact runs: the largest numerator or denominator (bits) of any input number. The exact QP's
  /// cost grows with the data's size; a tangent of 1e-100000 would take hours.
  std::size_t max_bits = 1024;
};

template <class T>
struct GuideResult {
  Frame2 frame;                 // normalized = (x - frame.lo) / frame.scale
  Solid2<Rational> solid;       // the solid in normalized coordinates
  CutData2<Rational> cut;       // validated and normalized ends
  QPStatus status = QPStatus::infeasible;
  int inner_knots = 0, inner_knots_y = 0;
  std::vector<int> tried;       // inner knot counts tried, in order
  bool refinement_stopped_by_limit = false;
  BSpline<T> f;                 // f* on [0,1]^2 (normalized coordinates); empty unless optimal
  /// f exactly: the exact run's f; the double run's f converted exactly (its knots and coefficients
  /// as the doubles hold them). Every exact check of a guide (separation, errors at L*) reads this.
  BSpline<Rational> f_exact;
  std::vector<Rational> coefficients;  // the program's exact minimizer (double: of the rounded program)
  QuadraticProgram<Rational> program;  // the last program, exactly (double: its doubles' values)
  QPSolution solution;
  KKTCheck kkt;
  bool positive_definite = false;
  std::size_t samples_positive = 0, samples_negative = 0;
  std::vector<std::array<Rational, 2>> sample_points;  // b* then b-bar* (exact, normalized)
  std::array<Rational, 2> value_at_ends{Rational(0), Rational(0)};  // f*(x), x in L*, exactly
  std::array<Rational, 2> gradient_error2{Rational(0), Rational(0)};  // |grad f*(x) - n(x)|^2 exactly
  double seconds = 0;
};

/// Checks the options (typed errors naming the option) and the size of the first program against
/// max_size, with at most samples x facets rows: before any work. Refinement stops (infeasible,
/// `refinement_stopped_by_limit`) where the next program would exceed it.
void validate_guide_options(const GuideOptions& options, std::size_t facets);

/// For exact runs: every number of the solid, the cutting data and the options within max_bits
/// (SizeLimitError naming the field otherwise, with the fix: fewer digits, or --arith double).
void check_exact_sizes(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const GuideOptions& options);

/// Validates the solid, the cutting data and the options (typed errors), then solves RDCP.
/// T = Rational or double.
template <class T>
GuideResult<T> guide_curve(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const GuideOptions& options = {});

/// A row of the bicubic basis at a point (x, y): value, d/dx and d/dy of every non-zero basis
/// function (sparse; index x fastest, n basis functions in x).
template <class T>
struct BasisRow {
  std::vector<std::pair<std::size_t, T>> v, dx, dy;
};
template <class T>
BasisRow<T> basis_row(const std::vector<T>& Ux, std::size_t n, const std::vector<T>& Uy, std::size_t ny, const T& x, const T& y);

/// A double run's coefficients against the exact run's, measured exactly: the largest absolute
/// error, the largest exact coefficient in magnitude, and the bits lost of double's 53:
/// max(0, 53 + log2(max_abs_error / max_abs)) (0 when the error is 0).
struct CoefficientError {
  Rational max_abs_error{0}, max_abs{0};
  double bits_lost = 0;
};
CoefficientError coefficient_error(const std::vector<Rational>& exact, const std::vector<Rational>& rounded);

/// The verdict on RDCP's minimizer (d = 2 and 3). Exact runs: "proved: ..." only when the program
/// has constraint rows (samples of b* or b-bar*), its KKT conditions hold exactly and its
/// objective is positive definite (Lemma 1); otherwise "undecided: <why>" (no rows: nothing keeps f*
/// off the boundary, every sample lay in the strip) or "not proved: <the failed condition>".
/// Double runs: what the double program's exact minimizer is, never "proved".
inline std::string guide_verdict(bool exact, const QuadraticProgram<Rational>& program, const KKTCheck& kkt, bool pd) {
  const std::string empty = "undecided: the program has no constraint rows (every sample of b* and b-bar* lies in the strip), so nothing keeps f* "
                            "positive on b or negative on b-bar: narrow --strip or add --samples";
  if (!exact)
    return program.rows.empty() ? empty
                                : std::string("the exact minimizer of the program assembled in double (KKT ") + (kkt.holds ? "holds" : "fails") +
                                      "), rounded to double: judge it against --arith exact";
  if (!kkt.holds) return "not proved: " + (kkt.failed.empty() ? std::string("the KKT conditions do not hold") : kkt.failed);
  if (!pd) return "not proved: the objective's matrix is not positive definite (the minimizer need not be unique)";
  if (program.rows.empty()) return empty;
  return "proved: the unique minimizer of RDCP (KKT conditions exact, objective positive definite)";
}

/// The tensor-product cubic space of the guide: clamped knots on [0, 1] with k uniform inner knots.
std::vector<Rational> guide_knots(int inner_knots);

/// The regularization matrix M of Eq. 3 (n^2 x n^2, row-major; n = k + 4 per direction), exactly,
/// from the univariate Gram matrices of the basis and its first and second derivatives.
template <class T>
std::vector<T> regularization_matrix(const std::vector<T>& knots);
/// The same for different knots in x and y ((n_x n_y)^2, x index fastest).
template <class T>
std::vector<T> regularization_matrix(const std::vector<T>& knots_x, const std::vector<T>& knots_y);


// ---- d = 3: the implicit guiding surface -----------------------------------------------------
//
// f* a trivariate tensor-product cubic on [0,1]^3 (the same k uniform inner knots in x, y and z),
// RDCP as for d = 2 with F_reg the thin-plate energy of Eq. 3 in three variables
// (f_xx^2 + f_yy^2 + f_zz^2 + 2 f_xy^2 + 2 f_xz^2 + 2 f_yz^2, exact from univariate Gram matrices).
// L*: `loop_samples` equally spaced points on every loop side (its start included, its end not),
// each with the side's target gradient n (LoopSide3::normal). b* and b-bar*: every facet's points
// at the centres of a samples x samples grid of its parameter domain, without those within
// max-norm distance `strip` of the loop. Knots are refined dyadically as for d = 2.

/// The d = 3 defaults: 1 inner knot (125 coefficients), refined up to 3 (343), and a 4 x 4 grid of
/// samples per facet; inner_knots_y is not used.
inline GuideOptions guide3_defaults() {
  GuideOptions o;
  o.inner_knots = 1;
  o.max_inner_knots = 3;
  o.samples = 4;
  // variables x (variables + rows): the cube's 125 x 445 (55625) took 2 minutes exactly on the
  // development machine; raise it deliberately (--max-size).
  o.max_size = 60000;
  return o;
}

struct GuideOptions3 {
  GuideOptions base = guide3_defaults();
  int loop_samples = 4;  // points of L* per loop side
  /// Inner knots per direction (x, y, z); -1: base.inner_knots. Refinement maps each k to 2k + 1
  /// while the largest stays within base.max_inner_knots.
  std::array<int, 3> inner_knots{-1, -1, -1};
};

template <class T>
struct GuideResult3 {
  Frame3 frame;
  Solid3<Rational> solid;           // normalized
  std::vector<LoopSide3> loop;      // validated, in cycle order (normalized coordinates)
  QPStatus status = QPStatus::infeasible;
  std::array<int, 3> inner_knots{0, 0, 0};
  std::vector<std::array<int, 3>> tried;
  bool refinement_stopped_by_limit = false;
  BSpline<T> f;                     // f* on [0,1]^3; empty unless optimal
  BSpline<Rational> f_exact;        // f exactly (double: the doubles' values)
  std::vector<Rational> coefficients;
  QuadraticProgram<Rational> program;
  QPSolution solution;
  KKTCheck kkt;
  bool positive_definite = false;
  std::size_t samples_positive = 0, samples_negative = 0;
  std::vector<std::array<Rational, 3>> sample_points;  // b* then b-bar*
  std::vector<std::array<Rational, 3>> loop_points;    // L*
  Rational max_abs_value_on_loop{0};                   // max |f*(x)|, x in L*, exactly
  Rational max_gradient_error2{0};                     // max |grad f*(x) - n(x)|^2, x in L*, exactly
  double seconds = 0;
};

/// The d = 3 options' checks and the exact size check (typed errors), before any work.
void validate_guide_options(const GuideOptions3& options, std::size_t facets);
void check_exact_sizes(const Solid3<Rational>& solid, const CutData3& cut, const GuideOptions& options);

/// Validates (typed errors), then solves RDCP for d = 3. T = Rational or double.
template <class T>
GuideResult3<T> guide_surface(const Solid3<Rational>& solid, const CutData3& cut, const GuideOptions3& options = {});

/// The thin-plate matrix in three variables ((n_x n_y n_z)^2, x index fastest), exactly.
template <class T>
std::vector<T> regularization_matrix3(const std::array<std::vector<T>, 3>& knots);

}  // namespace splinex
