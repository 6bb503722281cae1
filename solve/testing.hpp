// Test-only seam (issue 47, "Prove it: planted bugs for every certificate"): each Plant switches
// one certificate of solve/ into an unsound variant, so tests can show that their exact checks
// refute it (tests/solve/test_planted.cpp). Modelled on proofs/suite.hpp's ScopedPlantedBug.
//
// NEVER set outside tests. When off (Plant::none, the default) every site costs one read of a
// plain variable and a comparison; nothing else changes. Not thread-safe by design: a plant is a
// process-wide switch for a single-threaded test.
#pragma once
#include <cstddef>
#include <string>

namespace splinex::solve_testing {

enum class Plant {
  none,
  /// solve_system, the branch that decides a merged group of boxes (a cluster hull): "exactly one
  /// root" without Krawczyk's contraction test, both in the hull's closed test (K(X) inside the
  /// closed X suffices) and for an exact root found in the hull (unique without
  /// ||I - Y J(X)|| < 1 about it).
  skip_krawczyk_contraction_merged,
  /// solve_system, during the search: an exact rational root recognised in a box is taken as the
  /// only root of the box around it without the contraction test (the boxes inside are skipped).
  skip_krawczyk_contraction_known,
  /// krawczyk(): the strict-interior test K(X) inside the OPEN box made closed (<= instead of <).
  closed_interior,
  /// krawczyk(): a wrong sign, K(X) centred at c + Y F(c) instead of c - Y F(c).
  krawczyk_wrong_sign,
  /// solve_system: the boxes still queued when max_boxes is reached are dropped instead of being
  /// reported undecided.
  drop_box,
  /// stationary_pairs (projection, contact): the closest candidate certified although an
  /// undecided box may hold a closer point (undecided_closest ignored by the verdict).
  closest_ignores_undecided,
  /// round_enclosure (Rational): each end of a squared-distance enclosure moved inward by one unit
  /// of the precision it is rounded to, instead of outward.
  shrink_enclosure,
  /// contact's branch and bound: a box pruned when its upper bound (instead of its lower bound)
  /// is above the smallest distance found so far U: a box that may hold the minimum is dropped.
  contact_prune_wrong_bound,
  /// project_curve: the counts certified without the solver's completeness (undecided boxes,
  /// roots not certified simple, slices not complete are ignored).
  curve_counts_unchecked,
};

/// The plant switched on (Plant::none: the shipped, sound code).
extern Plant active_plant;
/// How many times the active plant changed a decision (counted only while a plant is on): a test
/// asserts it is > 0, i.e. that its input reaches the mutated branch and the mutation matters.
extern std::size_t plant_hits;

inline bool planted(Plant p) { return active_plant == p; }
/// Records that the planted variant decided differently from the sound one.
inline void plant_hit() { ++plant_hits; }

/// The plant's name as in the enum ("closed_interior"); Plant::none: "none".
std::string plant_name(Plant p);
/// The plant named `name` (plant_name's inverse); an unknown name throws std::invalid_argument.
Plant plant_from_name(const std::string& name);

/// While alive, `p` is the active plant and plant_hits counts from 0; the previous state is
/// restored on destruction.
class ScopedPlant {
 public:
  explicit ScopedPlant(Plant p);
  ~ScopedPlant();
  ScopedPlant(const ScopedPlant&) = delete;
  ScopedPlant& operator=(const ScopedPlant&) = delete;

 private:
  Plant previous_;
  std::size_t previous_hits_;
};

}  // namespace splinex::solve_testing
