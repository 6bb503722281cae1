// The hybrid patch with B-spline boundaries (papers/003) as a report experiment: Example 3.2's
// holes (exact C1/G1 mismatch with the neighbours), Examples 4.1 and 4.2 (counts and exact
// equality), Salvi's original elevation measured exactly, double vs exact for values and
// derivatives, and the figures (iso-lines of s_i and h_i, a shaded height map, OBJ meshes).
#pragma once
#include <string>

namespace splinex {

/// Writes hybrid_isolines.svg, hybrid_height.svg, hybrid_example_2_1.obj, hybrid_hole_5.obj,
/// hybrid_hole_6.obj and hybrid_examples.json into out_dir; returns a Markdown section. ok is
/// false if an exact equality the theorems promise fails. proofs_ran: whether the report's proof
/// table is there to refer to.
std::string run_hybrid_experiment(const std::string& out_dir, bool& ok, bool proofs_ran);

}  // namespace splinex
