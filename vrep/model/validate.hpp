// Validation of V-models before use (issue 47, reproducers vrep 2-4): the one function every reader
// of a V-model calls (the CLI's vrep commands, Python, the report), so that a model that is proved
// invalid is a typed error naming its cells and one that cannot be decided says so.
//
// A V-model (vrep/model/vmodel.hpp) is valid when
//  - every cell is a trivariate whose det J does not change sign and is not identically 0 on any
//    part (certified: the Bernstein coefficients of det J, vrep/model/regularity.hpp; det J may vanish
//    on a set of measure zero, as on a collapsed edge, when it keeps one sign: `degenerate`).
//    A fold (both strict signs) or a flat part (det J = 0 on a box) is a ValidationError;
//  - the interiors of no two cells overlap. Decided exactly for convex cells with planar faces
//    (vrep/boolean/boolean.hpp: convex_planes; separating-axis test on the exact corners with the face
//    normals and the edges' cross products as axes) and, for any cells, when their control-point
//    boxes' interiors are disjoint or a planar face separates their control points (convex hull
//    property). Identical trivariates are always refused. Otherwise the pair is `undecided`
//    (listed with the reason), never claimed disjoint;
//  - cells meet conformingly: no corner of one convex planar cell lies inside an edge or a face of
//    another, and no two unglued boundary faces overlap in a plane (a T-junction or a partial edge
//    or vertex contact: the glued topology and its Euler characteristic would be wrong). Not
//    checked between curved cells (said in `not_checked`);
//  - the glued topology passes check_invariants (vrep/model/vmodel.hpp).
// A trimmed V-model (vrep/trimmed/trimmed.hpp) is valid when its cells' categories are "A", "both", "B" or
// "", their trivariates satisfy the first rule, and no two cells are the same (trivariate and trim);
// the overlap of trimmed cells is decided only by disjoint control-point boxes (else listed in
// `not_checked`, and every command then prints the verdict).
// Exact throughout (Rational); nothing passes through double.
#pragma once
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "exact/rational.hpp"
#include "spline/bspline.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

struct ValidityOptions {
  int levels = 6;            // subdivision levels of the det J test (vrep certify's --levels)
  bool topology = true;      // check the glued model's invariants and conformity (false: cells only)
};

/// What a validation proved and what it left open (a proved defect is a ValidationError instead).
struct ValidityReport {
  std::size_t cells = 0;
  std::size_t pairs_tested = 0;       // pairs whose control-point boxes meet (the others are disjoint)
  std::vector<RegularityReport<Rational>> regularity;  // per cell (VModel) or per trivariate (trimmed)
  std::vector<std::string> degenerate;  // cells with det J = 0 somewhere but one sign (valid)
  std::vector<std::string> undecided;   // what could not be decided, with the reason
  std::vector<std::string> not_checked; // checks the method does not cover for this model
  bool decided() const { return undecided.empty(); }
  /// Decided and nothing left unchecked: only then may a command leave the verdict out.
  bool complete() const { return undecided.empty() && not_checked.empty(); }
  /// "valid" or "undecided: <first reason> (and N more)".
  std::string verdict() const;
};

/// Validates the cells of a V-model given as trivariates (names for messages; `where` prefixes the
/// field, e.g. "vmodel"): ValidationError naming the cells for a fold, a flat cell, two cells whose
/// interiors overlap (duplicated, contained, overlapping) or a non-conforming contact between
/// convex planar cells.
ValidityReport validate_cells(const std::vector<BSpline<Rational>>& cells, const std::vector<std::string>& names,
                              const std::string& where, const ValidityOptions& options = {}, const Limits& limits = {});

/// validate_cells on the model's cells, then (options.topology) its invariants and unglued
/// boundary faces overlapping in a plane (T-junctions).
ValidityReport validate_vmodel(const VModel<Rational>& M, const std::string& where, const ValidityOptions& options = {},
                               const Limits& limits = {});

/// The trimmed model's rules above: ValidationError naming the cell and field.
ValidityReport validate_trimmed(const TrimmedModel<Rational>& M, const std::string& where, const ValidityOptions& options = {},
                                const Limits& limits = {});

/// det J's sign on one trivariate, certified. The claim "the cell is valid" (det J >= 0 or <= 0
/// everywhere and not 0 on any open set) is proved - regular (det J > 0 or < 0 everywhere) or
/// degenerate (0 somewhere, e.g. on a collapsed edge) - or undecided; a fold or a flat part is
/// refuted by a ValidationError naming `field`. `regularity` is certify_regularity's report
/// (vrep/model/regularity.hpp) with its reason extended.
struct CellShape {
  RegularityReport<Rational> regularity;
  Verdict valid;
  bool degenerate = false;
};
CellShape certify_cell_shape(const BSpline<Rational>& V, const std::string& field, int levels, const Limits& limits);

}  // namespace splinex
