// The documents of `splinex cut` (papers/004), read exactly:
//   solid: {"type": "solid2d", "facets": [<spline document>, ...]}  (curves in R^2, counter-clockwise)
//   cut:   {"type": "cut2d", "points": [{"facet": i, "parameter": s, "tangent": [tx, ty]}, {...}]}
// Numbers as in every document: integers, fractions "p/q" or decimals, exactly.
#pragma once
#include "cut/solid.hpp"
#include "io/json_io.hpp"

namespace splinex {

/// Reads and validates (validate_solid) a solid document.
Solid2<Rational> solid2_from_json(const Json& doc, const Limits& limits = {});
/// Reads a cutting-data document (validated against the solid by validate_cut).
CutData2<Rational> cut2_from_json(const Json& doc);

Json solid2_to_json(const Solid2<Rational>& S);
Json cut2_to_json(const CutData2<Rational>& C);

}  // namespace splinex
