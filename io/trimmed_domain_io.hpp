// The trimmed-domain document of `splinex untrim`, read exactly.
#pragma once
#include "io/json_io.hpp"
#include "untrim/loops.hpp"
#include "untrim/run.hpp"

namespace splinex {

/// Reads {"type": "trimmed_domain", "domain": [[x0, x1], [y0, y1]], "loops": [[[x, y], ...], ...]}
/// exactly and validates it (validate_domain). A loop item {"controls": [[x, y], ...]} after vertex
/// i makes edge i a Bezier curve with these inner control points (untrim/curved.hpp: a polynomial
/// graph y = f(x), control x evenly spaced between the end points).
TrimmedDomain trimmed_domain_from_json(const Json& doc);

/// `splinex untrim`'s result: the tiles (each with its area, Coons patch and, when computed, its
/// patch in the surface and its integral), the area and integral against the exact references
/// (absolute errors) and, in exact runs, the cover certificate. F: Rational, double or Mpfr.
template <class F>
Json untrim_document(const UntrimRun<F>& run);

}  // namespace splinex
