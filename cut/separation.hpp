// Certified separation (issue 20, item 3): the samples b* only approximate "f* > 0 on all of b".
// f* composed with every boundary facet (papers/000's composition: each Bezier piece of a facet
// with each polynomial piece of f* whose cell its control polygon's box meets, extended beyond
// the cell by Observation 1) is a univariate Bernstein polynomial; if every such polynomial has
// coefficients of the required strict sign, the sign holds on the whole piece. Otherwise the piece
// is halved, and exact values of f* at exact boundary points serve as witnesses of a violation.
// Points within the strip around the cut points (max-norm distance <= strip) are excluded, as the
// samples exclude them.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "cut/solid.hpp"
#include "cut/solid3.hpp"

namespace splinex {

struct SeparationOptions {
  int max_depth = 30;               // halvings of one Bezier piece
  std::size_t max_pieces = 200000;  // pieces examined in total
};

struct SeparationWitness {
  std::size_t facet = 0;
  Rational param;
  std::array<Rational, 2> point;  // normalized coordinates
  Rational value;                 // f* there, exactly
  bool positive_side = true;      // b (f* must be > 0) or b-bar (< 0)
};

struct SeparationResult {
  Verdict verdict;  // proved only when some piece was certified; refuted: the witness
  std::optional<SeparationWitness> witness;
  std::size_t pieces = 0;         // pieces certified (after subdivision)
  std::size_t excluded = 0;       // pieces inside the strip
  struct Open { std::size_t facet; Rational lo, hi; };
  std::vector<Open> undecided;    // parameter intervals left undecided
};

/// f: the guide on [0,1]^2 (normalized coordinates); solid and cut: normalized (GuideResult).
SeparationResult certify_separation(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const BSpline<Rational>& f,
                                    const Rational& strip, const SeparationOptions& options = {});


// ---- d = 3 ---------------------------------------------------------------------------------------
// The same for surface facets: f* composed with each Bezier piece of a facet is a bivariate
// Bernstein polynomial; pieces are halved alternately in u and v. The strip is the set of points
// within max-norm distance `strip` of a loop side; a piece is excluded when its control net's box
// lies in the strip of one side (the distance to a segment is convex, so the box's corners decide).

struct SeparationWitness3 {
  std::size_t facet = 0;
  std::array<Rational, 2> param;
  std::array<Rational, 3> point;  // normalized coordinates
  Rational value;
  bool positive_side = true;
};

struct SeparationResult3 {
  Verdict verdict;  // proved only when some piece was certified; refuted: the witness
  std::optional<SeparationWitness3> witness;
  std::size_t pieces = 0, excluded = 0;
  struct Open { std::size_t facet; std::array<Rational, 2> lo, hi; };
  std::vector<Open> undecided;
};

/// f: the guide on [0,1]^3; solid, loop: normalized (GuideResult3); positive: the facets of b.
SeparationResult3 certify_separation(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const std::vector<std::size_t>& positive,
                                     const BSpline<Rational>& f, const Rational& strip, const SeparationOptions& options = {});

}  // namespace splinex
