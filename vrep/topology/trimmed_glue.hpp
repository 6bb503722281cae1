// The gluing of a trimmed V-model (vrep/topology/trimmed_glue.cpp): halves, twins, V-surface counts.
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

/// The gluing of a trimmed V-model (issue 18: Definition 3.9 for trimmed cells), exact where
/// decided. The halves are every cell's faces of its domain (not collapsed) and its distinct
/// trimming surfaces (proportional leaves are one surface). Per half, by certified subdivision
/// (count_region on the face, count_surface on the surface; vrep/topology/curve_graph.hpp), the pieces of
/// its part where the other side lies in the model (`internal`: a V-surface shared with another
/// cell, or the cell itself across a seam) and where it does not (`boundary`). The twins:
///   - one trivariate, the two sides of one trimming surface (a cell and its complement in a
///     Boolean): the pieces of the surface where one cell lies on each side, exact;
///   - faces of two trivariates equal as surfaces (exact same_surface; seams of one trivariate
///     too): the pieces of the face where both cells lie, exact;
///   - contacts: a face half's internal part not on an exact twin (a cell of one operand against
///     the trimming surface of a cell of the other, which is not a parameter face of both), matched
///     at exact witness points: rational points of the face part, each located exactly on a
///     trimming surface's part of a cell of another trivariate (its leaves' exact signs; inside its
///     trivariate by the exact affine inverse or the certified solver). Decided when the two halves
///     met only each other and their unmatched parts have equal piece counts: a sampled match,
///     said so (`witness_points`), not a proof that the two parts are one set.
/// Counts are in the trivariates' parameters, like trimmed_topology's. The V-model counts:
/// `boundary_v_surfaces` (the boundary pieces) and `internal_v_surfaces` (the twins' pieces).
struct TrimmedGlueOptions {
  std::size_t max_boxes = 4096;  // per count and attempt (count_region / count_surface)
  std::size_t witnesses = 16;    // per face half with an unmatched part
};

template <class T>
struct TrimmedGluing {
  struct Half {
    std::size_t cell = 0;
    std::string what;
    int dir = -1, side = -1;  // a face of the cell's domain
    int leaf = -1;            // or a trimming surface (collect order in the cell's trim)
    bool decided = false;
    std::size_t internal = 0, boundary = 0;  // pieces of the part with the other side in / out of the model
    std::size_t unmatched = 0;               // pieces of the internal part on no exact twin
    std::string undecided_reason;
  };
  struct Twin {
    std::size_t a = 0, b = 0;  // halves
    std::string how;
    bool decided = false;
    std::size_t pieces = 0;     // of the shared part (V-surfaces)
    std::size_t witnesses = 0;  // contacts: the witness points located on both
    std::string undecided_reason;
  };
  std::vector<Half> halves;
  std::vector<Twin> twins;
  std::size_t part_pieces = 0;          // internal + boundary pieces over the halves (before twins split them)
  std::size_t half_v_surfaces = 0;      // of the glued V-model: boundary + 2 internal
  std::size_t boundary_v_surfaces = 0;  // boundary pieces
  std::size_t internal_v_surfaces = 0;  // pieces of the twins' shared parts
  std::size_t contacts = 0, witness_points = 0;  // of them matched at witness points
  std::size_t unmatched_halves = 0;     // halves with an unmatched part and no partner found
  bool decided = false;                 // every count above decided
};

template <class T>
TrimmedGluing<T> trimmed_glue(const TrimmedModel<T>& M, const TrimmedGlueOptions& options = {}, const Limits& limits = {});

}  // namespace splinex
