// The cutting package's results as documents (issue 48: no JSON in the commands): exact values
// with their doubles, the separation certificate, the cutting curve's and surface's validity, the
// guides (d = 2 and 3) and the cutting surface - written here once for `splinex cut`, the report
// and Python. It lives in cut/io/, above io/ (cut_io.hpp holds the solid and cut documents).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "cut/curve_facet.hpp"
#include "cut/guide.hpp"
#include "cut/separation.hpp"
#include "cut/surface_facet.hpp"
#include "io/json_io.hpp"

namespace splinex::cut {

/// An exact value and its double (or, beyond double's range, log2 of its magnitude).
Json q_json(const Rational& x);
/// The separation certificate of a guide (d = 2): verdict, pieces, witness, undecided pieces.
Json separation_json(const SeparationResult& s);
/// The double guide's coefficients against the exact minimizer, measured exactly.
Json judged_against_exact(const std::vector<Rational>& exact, const std::vector<Rational>& rounded);
/// A cutting curve's validity: each condition certified, violated (with a witness) or undecided.
Json validity_json(const ValidityResult& v);
/// A guide (d = 2) and, when given, its separation certificate. T: Rational or double.
template <class T>
Json guide_json(const GuideResult<T>& R, const std::optional<SeparationResult>& sep);
/// The separation certificate of a guide (d = 3).
Json separation3_json(const SeparationResult3& s);
/// A guide (d = 3) and, when given, its separation certificate. T: Rational or double.
template <class T>
Json guide3_json(const GuideResult3<T>& R, const std::optional<SeparationResult3>& sep);
/// The patch between normalized [0,1]^3 coordinates and the solid's (exact).
BSpline<Rational> patch_from_frame(BSpline<Rational> p, const Frame3& f);
BSpline<Rational> patch_to_frame(BSpline<Rational> p, const Frame3& f);
Json point3_json(const std::array<Rational, 3>& x);
/// A cutting surface's validity (Section 2's conditions), its witness in the solid's coordinates.
Json surface_validity_json(const SurfaceValidity& v, const Frame3& f);
/// A cutting surface: domain polygon, program sizes, solver, KKT check, the patch in the solid's
/// coordinates. T: Rational or double.
template <class T>
Json surface_json(const CuttingSurface<T>& R, const Frame3& f);
/// The guided patch's run (Eq. 6 added at `weight`).
Json guided_json(const GuidedResult& g, double weight, const GuideOptions3& o, const std::string& guide_status);

}  // namespace splinex::cut
