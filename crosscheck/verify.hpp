// Judging a result computed elsewhere (issue 16): a candidate spline (or values) handed in from
// another program - a student's knot insertion in double, SciPy, the Octave NURBS toolbox,
// OpenCASCADE - compared exactly with splinex's exact reference for the same operation on the same
// input.
//
// The report has three parts:
//  - structure: degrees, knot vectors and counts "equal", "equal after rounding" (the candidate's
//    knots are the reference's rounded to the candidate's precision) or "different" (and where);
//  - coefficients (when the shapes agree): max absolute error, normwise relative error and bits
//    lost at the candidate's precision, for control points, weights and knots;
//  - the function-level error: candidate and reference compared as functions, whatever their
//    representations (other knots, another degree): for polynomial splines a certified upper bound
//    of sup_x max_c |C_c(x) - R_c(x)| over the domain - the largest coefficient of the exact
//    difference on a common refinement (B-splines are non-negative and sum to one) - refined by
//    inserting span midpoints where the bound is attained until it is within `factor` of a
//    witnessed lower bound |C(x*) - R(x*)| (evaluated exactly at the Greville point of the
//    largest coefficient), with x*. Rational splines: per Bezier piece of the common refinement,
//    C - R = (C_h R_w - R_h C_w) / (C_w R_w); the numerator's largest Bernstein coefficient over
//    the denominator's smallest (positive weights) bounds it, refined the same way.
#pragma once
#include <functional>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "crosscheck/crosscheck.hpp"

namespace splinex {

struct VerifyOptions {
  int precision = 53;         // the candidate's significand bits, for bits lost (53: double)
  Rational factor{2};         // stop refining when upper <= factor * lower
  int max_rounds = 24;        // refinement rounds of the function-level bound
  std::size_t budget = 64;    // refinement stops before (budget x (first coefficients + 64)) coefficients
  /// Called per part of a composition ("tile 3 of 21"), for progress on stderr; may be empty.
  std::function<void(const std::string&)> progress;
};

struct FunctionError {
  bool certified = false;     // upper is a proved bound; else only `lower` was measured
  Rational upper{0}, lower{0};
  std::vector<Rational> at;   // where `lower` is attained
  int rounds = 0;             // refinement rounds used
  bool within_factor = false; // upper <= factor * lower (or both 0)
  std::string method;
  Json document() const;
};

struct VerifyReport {
  std::string operation;
  int precision = 53;
  std::string structure = "equal";  // "equal", "equal after rounding", "different"
  std::vector<std::string> structure_notes;
  std::size_t results = 0;          // splines (or points) compared
  bool coefficients_compared = false;
  ErrorStat control_points, weights, knots, values;
  FunctionError function;
  Rational reference_scale{0};  // max |reference coefficient| (or value): the function error's scale
  // Sampled checks (compositions): values of the candidate's parts at points against the exact
  // T(S(r)) - `values` holds the errors; a sampled claim, "checked at N points", not a bound.
  std::size_t points_checked = 0;
  std::size_t points_unclaimed = 0;    // no candidate part claims the point (or a tile leaves S's domain)
  std::size_t points_misassigned = 0;  // claimed by a part whose cell of T does not hold S(r) (closed box)
  std::size_t points_failed = 0;       // a homogeneous part's weight is 0 there
  bool area_compared = false;          // tiles against the exact tiling:
  Rational area_moved{0};              // sum over regions of |candidate tiles' area - exact area|
  Json parts = Json::array();          // per trimmed patch or tile: what it was paired with, its error
  bool domain_mapped = false;          // a candidate's domain ends were the reference's rounded: compared after the affine map
  /// The worst bits lost of the coefficients, the values and the function-level error.
  double worst_bits_lost() const;
  /// Which of them ("control_points", "values", "function"; "" when none lost a bit) and its bits.
  std::pair<std::string, double> worst_part() const;
  /// The top-level verdict on "the candidate is the exact result": proved (a certified bound of 0
  /// with nothing mapped, and for compositions the same structure, no area moved and every sample
  /// point claimed rightly; or every point value compared equal), refuted with a witness (a value
  /// that differs, or for kernel operations a point of the domain where the functions differ,
  /// measured exactly), otherwise undecided with the reason. {"claim", "status", "reason" | "witness"}.
  Json verdict() const;
  /// The function-level error as an error statistic against the reference's scale, where it is a
  /// certified bound (its bits lost are the function's in the JSON and in worst_part).
  std::optional<ErrorStat> function_stat() const;
  /// The whole report, ending with "worst_bits_lost", "worst_part" and "verdict".
  Json document() const;
};

/// Reference splines against candidate splines, one to one (a piece list for extraction, the two
/// halves of a split). Different counts are a structure finding, not an error; a candidate of
/// another dimension or point size is a ValidationError (it cannot be the result asked for).
VerifyReport verify_splines(const std::string& operation, const std::vector<BSpline<Rational>>& reference,
                            const std::vector<BSpline<Rational>>& candidate, const VerifyOptions& options = {},
                            const Limits& limits = {});

/// A candidate document's splines, as `splinex verify` and the Python module read it: one spline
/// document, {"splines": [...]} or {"pieces": [{"spline": ...}, ...]} (extract-bezier's output).
std::vector<BSpline<Rational>> verify_candidate_splines(const Json& doc, const Limits& limits = {});

/// A candidate document read from a file ("-": standard input); with as_doubles every decimal
/// number is read as the double nearest to it (candidate_numbers_as_doubles, `--read-as double`).
Json read_candidate(const std::string& path, bool as_doubles, const ReadLimits& read_limits);

/// A candidate's points and values: {"at": [[x0, ...], ...], "values": [[...], ...]}, numbers read
/// exactly (ValidationError naming candidate.at[i][c] otherwise).
struct CandidateValues {
  std::vector<std::vector<Rational>> at, values;
};
CandidateValues candidate_values(const Json& doc);
/// The same for a hybrid patch's values; also reads the output of `splinex hybrid eval`
/// ({"points": [{"at": [u, v], "point": [...]}, ...]}).
CandidateValues hybrid_candidate_values(const Json& doc);

/// The exact result of `op` on `input` against the candidate.
VerifyReport verify(const Operation& op, const BSpline<Rational>& input, const std::vector<BSpline<Rational>>& candidate,
                    const VerifyOptions& options = {}, const Limits& limits = {});

/// Values at points: candidate_values[i] against the exact S(at[i]).
VerifyReport verify_values(const BSpline<Rational>& S, const std::vector<std::vector<Rational>>& at,
                           const std::vector<std::vector<Rational>>& candidate_values, const VerifyOptions& options = {});

/// Values at points against any exact evaluator (the hybrid patch's, ...): candidate_values[i]
/// against exact(at[i]).
VerifyReport verify_point_values(const std::string& operation, const std::vector<std::vector<Rational>>& at,
                                 const std::vector<std::vector<Rational>>& candidate_values,
                                 const std::function<std::vector<Rational>(const std::vector<Rational>&)>& exact,
                                 const VerifyOptions& options = {});

/// Algorithm 1 (papers/000): the candidate's trimmed patches of T(S), in the JSON of `splinex
/// compose --method trimmed` ({"pieces": [{"inner_box", "outer_cell", "region", "homogeneous",
/// "patch"}]}), paired with the exact ones by inner box and outer cell: regions compared, patches
/// compared as functions on their boxes (certified; the box contains the region), and sampled: at a
/// grid of S's domain every candidate patch that claims the point against T(S(r)).
VerifyReport verify_trimmed_composition(const BSpline<Rational>& T, const BSpline<Rational>& S, const Json& candidate,
                                        const VerifyOptions& options = {}, const Limits& limits = {});

/// Algorithm 2: the candidate's tiles ({"tiles": [{"inner_box", "outer_cell", "tile",
/// "coons_patch", "homogeneous", "patch"}]}, as `splinex compose --method tensor` writes them).
/// Each tile's patch against the exact T_j^e(S_i(Q)) of its own Coons patch Q (certified); where
/// every trimming curve is straight, the tiling against the exact one (chains, area moved between
/// regions, exact); and sampled: R(x, l) against T(S(Q(x, l))) in the true region of Q(x, l).
VerifyReport verify_tensor_composition(const BSpline<Rational>& T, const BSpline<Rational>& S, const Json& candidate,
                                       const VerifyOptions& options = {}, const Limits& limits = {});

/// x rounded to nearest at `precision` significand bits (53: double), as the rational it is.
Rational rounded_to_precision(const Rational& x, int precision);

/// The function-level error of candidate C against reference R (same dimension, point size and
/// domain; DomainError otherwise).
FunctionError function_error(const BSpline<Rational>& C, const BSpline<Rational>& R, const VerifyOptions& options = {},
                             const Limits& limits = {});

/// Number text as a float program meant it: a decimal is the double nearest to it (the candidate
/// printed a double; shortest round-trip text reads back to that double), a fraction p/q stays
/// exact. Used by `splinex verify --read-as double` (the default) on every number of a candidate.
Json candidate_numbers_as_doubles(const Json& doc);

}  // namespace splinex
