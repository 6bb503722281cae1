// The V-rep package's results as documents (issue 48: no JSON in the commands): the Euler
// characteristic, the V-curves between trimming surfaces, regularity reports, the gluing of trimmed
// cells, a V-model's summary, the topology of trimmed cells and the volume (with centroid and field
// integrals) - written here once, for the command line, the report and Python.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "io/json_io.hpp"
#include "vrep/io/api.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_euler.hpp"
#include "vrep/topology/trimmed_glue.hpp"

namespace splinex::vrep {

/// A certified enclosure lo <= x <= hi into j: `exact_key` when lo == hi, else "lower" and "upper"
/// (and, with `approx`, their doubles as "approximately").
void put_enclosure(Json& j, const char* exact_key, const Rational& lo, const Rational& hi, bool approx);

/// (hi - lo) / lo as a decimal rounded up to two significant digits ("0" when exact, "unbounded"
/// when lo <= 0 < hi), exactly: never narrower than the enclosure.
std::string relative_width_text(const Rational& lo, const Rational& hi);

/// An Euler characteristic: decided or the reason, chi in the parameters and in space, the
/// interior's chi_c and whether duality holds (the only case in which chi is the regularized
/// cell's for sure).
Json euler_json(const TrimmedEuler<Rational>& e);

/// The V-curves between two trimming surfaces: per pair of leaves, arcs and loops or the reason it
/// is undecided.
Json curves_json(const TrimmedCurves<Rational>& c);

/// A regularity report (verdict, reason, sign, the points and det J's numerator there).
template <class F>
Json report_to_json(const RegularityReport<F>& r);
/// `vrep certify`'s result: the regularity report.
template <class F>
Json document(const RegularityReport<F>& r) {
  return report_to_json(r);
}

/// A V-model (`vrep glue --eps`, a constructed primitive) and, when given, the exact region it
/// fills ("implicit"). F: Rational, double or Mpfr.
template <class F>
Json vmodel_document(const VModel<F>& M, const std::optional<Region<F>>& implicit = std::nullopt);
/// A model read and glued exactly, with its validity verdict for the reader (ignored on input).
Json glued_document(const LoadedModel& r);
/// `vrep eval`: a cell's point, coordinates, fields and constants at a parameter, as fractions.
Json cell_value_document(std::size_t cell, const CellValue<Rational>& r);
/// `vrep classify`: which cells contain the point x (cells with planar faces) or, otherwise, where
/// x lies against the model's exact region (DomainError when the operand has neither).
Json classify_document(const Operand& O, const std::vector<Rational>& x);
/// `vrep blend`: Eq. 2's distance blend of `attribute` of V1 and V2 at x (order k, MPFI enclosure
/// at `bits`), with each model's value where x is in it.
Json blend_document(const VModel<Rational>& V1, const VModel<Rational>& V2, const std::vector<Rational>& x, const std::string& attribute,
                    int k, int bits);

/// trimmed_glue's result (halves, twins, the V-surface counts, the time taken).
Json gluing_json(const TrimmedGluing<Rational>& G, const TrimmedModel<Rational>& M, double seconds);

/// The V-model's summary: counts, Euler characteristic, invariants, per cell its neighbours and
/// regularity verdict (computed by the validation, vrep/model/validate.hpp), and the model's validity.
Json info_document(const VModel<Rational>& M, const ValidityReport& v);

/// The boundary structure of a trimmed V-model's cells (vrep topology): per cell the exact edge
/// V-curves and V-points, the half-V-surfaces and face curves (exact where decided), the V-curves
/// between trimming surfaces and the Euler characteristic; the model's; with `glue` the gluing.
/// `boxes`: the subdivision budget per cell.
Json topology_document(const TrimmedModel<Rational>& M, const ValidityReport& validity, std::size_t boxes, bool glue,
                       const Limits& limits);

/// What vrep volume computes: every cell's volume and the model's, exact (polynomial cells) or a
/// certified enclosure refined until its relative width is at most `rel_width` or the budget of
/// `boxes` per cell is spent; with `centroid` the centroid; with a `field` name its integral.
struct VolumeRequest {
  Rational rel_width{1, 100};
  std::size_t boxes = 500;
  bool centroid = false;
  std::string field;
  int component = 0;
};
Json volume_document(const Operand& O, const VolumeRequest& rq, const Limits& limits);

}  // namespace splinex::vrep
