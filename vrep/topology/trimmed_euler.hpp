// The Euler characteristic of trimmed cells and models, exactly (vrep/topology/trimmed_euler.cpp).
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

/// The Euler characteristic of a trimmed cell, exactly (vrep/topology/trimmed_euler.cpp has the method):
/// chi_c is additive over the open cells of a box subdivision of V's parameter domain; on an open
/// cell where every undecided leaf is monotone along one direction and the formula closed that
/// way, chi_c is minus that of one open face (the fibres are half-open or whole intervals), where
/// the formula is decided it is (-1)^dim or 0, otherwise the cell is halved. The set is the
/// closed one (leaves read g >= 0, complements g <= 0): the regularized cell wherever the trimming
/// surfaces are regular.
///   - chi: of the cell in V's parameter domain;
///   - image_chi: of T(cell), V's own identifications counted once (faces equal by same_surface,
///     edges by same_curve, corners at one point; collapsed faces and edges not at all); V is
///     assumed injective otherwise (valid trivariate);
///   - interior_chi_c: chi_c of the open set (strict leaves on the open domain); for a compact
///     3-manifold with boundary it is -chi (duality: a necessary check, not a proof of regularity).
/// Undecided (a singular point of a trimming surface, a tangency with the domain or with a split
/// plane; the split fraction 1/2 is retried at 7/16 and 13/32) when no cell's direction is
/// monotone within max_level halvings or the cell budget is spent. Exact in exact arithmetic; in
/// double the same steps on rounded signs, uncertified.
struct EulerOptions {
  std::size_t max_cells = 400000;  // open cells visited per attempt
  int max_level = 24;              // halvings per direction
};
template <class T>
struct TrimmedEuler {
  bool decided = false;
  long chi = 0, image_chi = 0, interior_chi_c = 0;
  bool duality = false;  // interior_chi_c == -chi
  std::size_t identified_faces = 0, identified_edges = 0, identified_corners = 0;  // not counted in the image
  std::size_t resolved_contacts = 0;    // boundary strata on a trimming surface read from inside
  std::size_t unresolved_contacts = 0;  // ... where the sign inside is not one strict sign (left as 0)
  std::size_t cells = 0;  // open cells visited (all attempts)
  T split = T(0);         // the split fraction that decided it
  std::string undecided_reason;
};
template <class T>
TrimmedEuler<T> trimmed_euler(const BSpline<T>& V, const Region<T>& trim, const EulerOptions& options = {}, const Limits& limits = {});

/// The Euler characteristic of a region of space inside the box [lo, hi] (the region as the trim
/// of the box's identity trivariate), and of a trimmed model's point set (its region in its
/// cells' control-point box grown by a sixteenth of its largest side, at least 1/16, all round,
/// so no face of the box meets it): the model's chi after a Boolean, with the regularized
/// Booleans' inclusion-exclusion chi(A u B) = chi(A) + chi(B) - chi(A n B) to check it by.
template <class T>
TrimmedEuler<T> region_euler(const Region<T>& R, const std::vector<T>& lo, const std::vector<T>& hi, const EulerOptions& options = {},
                             const Limits& limits = {});
template <class T>
TrimmedEuler<T> model_euler(const TrimmedModel<T>& M, const EulerOptions& options = {}, const Limits& limits = {});

}  // namespace splinex
