// Planted bugs for V-rep's certificates (issue 47, "Prove it"): TEST-ONLY.
//
// A test seam in the manner of proofs/suite.hpp's ScopedPlantedBug: while a ScopedPlant is alive,
// one certificate of vrep/ runs an unsound variant (a skipped check, a dropped subdivision box, a
// wrong sign, a piece count ignored), so that tests/vrep/test_planted.cpp can show that the
// certificate's own checks, and the ordinary tests, refute it: with the plant on, the certified
// answer is wrong in a way the test detects independently (an exact point value, a closed form);
// with it off, the answer is right.
//
// Cost when off: one read of a plain enum and a comparison at the mutated branch. Never set it
// outside tests; nothing in the program or the library sets it. Not thread-safe by design (tests
// set it on one thread around single-threaded calls).
#pragma once

namespace splinex::vrep_testing {

enum class Plant {
  none,
  // vrep/model/regularity_impl.hpp, certify_regularity:
  regularity_corners_only,    // a box is certified from its corner coefficients (interior ones not read)
  regularity_drops_upper_u,   // subdivision loses the children on the upper side of direction u
  regularity_sign_flipped,    // a regular verdict reports the opposite sign
  // vrep/boolean/boolean_impl.hpp, cells_containing and the Boolean's piece classification:
  classify_skips_plane,       // the second half-space (face u = end) of a cell is not tested
  // vrep/trimmed/trimmed_impl.hpp, classify_cell's localized region:
  classify_first_piece_only,  // a leaf decided on the first Bezier piece is taken as decided on the cell
  // vrep/trimmed/trimmed_impl.hpp, combine (Kleene's reading of a piecewise region, Region::cases):
  cases_ignore_pieces,        // in where some case's formula is in, whatever its piece (the cover not used)
  // vrep/topology/region_graph.cpp, count_region (the pieces of a face's part):
  region_arc_unchecked,       // a leaf is taken as one arc through a box without counting its boundary roots
  // vrep/topology/surface_graph.cpp, count_surface (the pieces of a trimming surface's part):
  surface_shape_unchecked,    // both sides of the surface in a box are taken as contractible without the check
  // vrep/topology/trimmed_euler.cpp:
  euler_monotone_sign,        // chi_c(S n C) = +chi_c(S n C_a) instead of -chi_c(S n C_a)
  euler_drops_mid_face,       // a halved cell's open face between the halves is not counted
  // vrep/topology/trimmed_glue.cpp:
  glue_counts_ignored,        // two contact halves are one set although their piece counts differ
  // vrep/model/vmodel_impl.hpp, glue:
  vmodel_twin_by_loop,        // half-V-surfaces with the same four V-curves are twins without comparing surfaces
  // vrep/model/validate.cpp:
  validate_sweep_bound,       // the pair sweep stops at cells starting at or after the current one's start
  validate_corner_in_edge,    // a corner inside another cell's edge is not a non-conforming contact
  validate_flat_skipped,      // a box with det J = 0 on it passes as decided instead of "flat"
  validate_interior_zero,     // a zero of det J inside the domain is taken for one on its boundary
};

/// The plant in force (Plant::none outside tests).
inline Plant planted = Plant::none;

/// Whether `p` is planted: the one read at each mutated branch.
inline bool is_planted(Plant p) { return planted == p; }

/// Plants `p` for its lifetime (tests only), restoring the previous one after.
class ScopedPlant {
 public:
  explicit ScopedPlant(Plant p) : previous_(planted) { planted = p; }
  ~ScopedPlant() { planted = previous_; }
  ScopedPlant(const ScopedPlant&) = delete;
  ScopedPlant& operator=(const ScopedPlant&) = delete;

 private:
  Plant previous_;
};

}  // namespace splinex::vrep_testing
