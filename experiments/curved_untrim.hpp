// Exact untrimming with curved tile sides (untrim/curved.hpp) as a report experiment: a domain of
// two cubic graph arcs with a triangular hole, split by the knot lines of a surface, tiled exactly;
// the cover certified, integrals against Green's theorem, and the same tiles in double and MPFR
// measured exactly; a knot line with irrational crossings (exact: refused; float: approximated).
#pragma once
#include <string>

namespace splinex {

/// Writes untrim_curved.svg and untrim_curved_domain.json into out_dir; returns a Markdown
/// section. ok is false if a certificate or an exact equality fails.
std::string run_curved_untrim(const std::string& out_dir, bool& ok);

}  // namespace splinex
