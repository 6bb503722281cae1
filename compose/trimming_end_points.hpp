// The exact end points of trimming curves on the edges of inner pieces (papers/000, Step 2), by
// exact real root isolation (exact/root_isolation.hpp).
#pragma once
#include <vector>

#include "compose/trimmed_compose.hpp"
#include "exact/rational.hpp"
#include "exact/root_isolation.hpp"

namespace splinex {

/// Where trimming curves of a patch meet the edges of its inner piece's box: for every region
/// condition (s_c = bound) and every edge (one parameter free, the others at a box end), the
/// isolated parameters of the crossings. For surfaces (k = 2) these are the end points of the
/// trimming curves; for curves (k = 1) the trimming points themselves.
struct EdgeCrossing {
  int condition = 0;          // index into the patch's region
  bool at_upper_bound = false;  // s_c = hi (else s_c = lo)
  int free_dir = 0;           // the edge's free parameter
  std::vector<Rational> fixed;  // the other parameters' values (k entries, free_dir's unused)
  IsolatedRoot root;          // in the free parameter
};
std::vector<EdgeCrossing> trimming_edge_crossings(const TrimmedComposition<Rational>& C, std::size_t patch,
                                                  int refine_bits = 64);

}  // namespace splinex
