// The cutting curve (papers/004 Section 4, d = 2) and its certified validity (Section 2's four
// conditions), and the split of the solid into two.
//
// Parameterization: f* = 0 is traced in double by a predictor-corrector march from the first cut
// point to the second (a polygon; approximate by nature), then a cubic B-spline with uniform knots
// is fitted by least squares with the end points and the end tangent directions imposed:
// C(0) = p, C(1) = q, C'(0) = a t_p, C'(1) = -b t_q (a, b > 0 fixed from the polygon's length).
// The fit is solved exactly (normal equations in Rational on the polygon's dyadic points) and its
// free control points rounded to doubles (their exact denominators grow with the data); the ends
// and end tangents stay exact. The curve is thus exactly represented, and its validity decided
// exactly for it.
//
// Validity, each condition decided exactly or left undecided with the reason:
//  - boundary interpolation and tangent conditions: exact equalities and signs;
//  - regularity: C' != 0, by Bernstein signs of the hodograph with subdivision;
//  - injectivity: subdivision of pairs of parameter intervals: disjoint control boxes, or for
//    neighbouring intervals a direction d with d . C' > 0 on both (C monotone along d);
//  - no collision with the boundary (C(0,1) inside the solid): pairs of curve intervals and facet
//    pieces separated by disjoint boxes, or at a cut point by a line through it (n . C' of one sign,
//    n . (F - p) <= 0). A violation is shown by an exact point C(s) outside the solid or on its
//    boundary (exact ray casting: real roots of the facets' polynomials isolated by CGAL).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "cut/solid.hpp"

namespace splinex {

struct CurveFitOptions {
  int control_points = 8;   // of the fitted cubic (>= 4)
  double step = 1.0 / 256;  // marching step in normalized units
  int max_steps = 20000;  // 78 unit lengths at the default step
};

struct CuttingCurve {
  BSpline<Rational> curve;                        // normalized coordinates, parameter [0, 1]
  std::vector<std::array<double, 2>> polygon;     // the marched points (normalized)
  double fit_max_deviation = 0;                   // max distance of polygon points to the curve at their parameters (double)
};

/// f: the guide (normalized coordinates), in double for the march. DomainError when the zero set
/// traced from the first cut point does not reach the second.
CuttingCurve fit_cutting_curve(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const BSpline<Rational>& f,
                               const CurveFitOptions& options = {});

struct ValidityOptions {
  int max_depth = 24;
  std::size_t max_pairs = 40000;  // interval pairs examined in all (a few hundred for the examples)
};

struct ValidityResult {
  bool interpolates = false;  // C(0) = p, C(1) = q exactly
  bool tangents = false;      // C'(0) = a t_p, C'(1) = -b t_q with a, b > 0, exactly
  Verdict regular;            // C' != 0 (refuted: singular_s)
  Verdict injective;          // no self-intersection (proved or undecided)
  Verdict inside;             // no collision with the boundary (refuted: the witness)
  std::optional<Rational> singular_s;              // a parameter where C' = 0, exactly (regular: violated)
  std::optional<Rational> witness_s;               // a parameter where C is outside the solid or on its boundary
  std::optional<std::array<Rational, 2>> witness;  // C(witness_s), exactly
  std::string witness_meaning;
  std::size_t pairs = 0;
  Verdict verdict;  // all of Section 2's conditions (certificate_word / validity_word: cut/solid.hpp)
};

ValidityResult certify_cutting_curve(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const BSpline<Rational>& C,
                                     const ValidityOptions& options = {});

/// Exact point classification by ray casting: -1 outside, 0 on the boundary, +1 inside; nullopt
/// when the ray meets a vertex or touches a facet (try another point).
std::optional<int> classify_point(const Solid2<Rational>& solid, const std::array<Rational, 2>& x);

/// The two sub-solids: S1 = b (first cut point to second, counter-clockwise) closed by C reversed,
/// S2 = b-bar closed by C; both validated (closed, counter-clockwise), and area(S1) + area(S2) =
/// area(S) checked exactly (DomainError otherwise).
std::pair<Solid2<Rational>, Solid2<Rational>> split_solid(const Solid2<Rational>& solid, const CutData2<Rational>& cut,
                                                          const BSpline<Rational>& C);

/// The affine map back from normalized coordinates: x = lo + scale * x_hat, applied to control points.
BSpline<Rational> from_frame(const BSpline<Rational>& C, const Frame2& f);

}  // namespace splinex
