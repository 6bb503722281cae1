// The independent check of the polyhedral Booleans (issue 18): the same Boolean by CGAL's exact
// Nef_polyhedron_3 (regularized), its volume and the counts of its boundary, and the same counts
// read off a V-model's boundary with coplanar neighbouring V-surfaces merged.
#pragma once
#include <cstddef>

#include "exact/rational.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/vmodel.hpp"

namespace splinex {

struct PolyhedronCounts {
  Rational volume{0};
  std::size_t vertices = 0, edges = 0, facets = 0;
  bool manifold = true;  // Nef: is_simple(); V-model: every merged crease has two facets
};

/// A op B in CGAL::Nef_polyhedron_3 over exact rationals: every cell of A and B (convex, planar
/// faces: its eight corners' convex hull) unioned per model, the operation, then regularization.
/// DomainError for a cell that is not convex with planar faces.
PolyhedronCounts nef_boolean(const VModel<Rational>& A, const VModel<Rational>& B, BooleanOp op);

/// The V-model's boundary as a polyhedron: boundary V-surfaces that share a V-curve and lie in one
/// plane are one facet; a vertex is a boundary V-point where three or more facets meet; an edge a
/// chain of boundary V-curves between two facets from vertex to vertex. The volume is the sum of
/// the cells' volumes (exact; polynomial cells).
PolyhedronCounts boundary_counts(const VModel<Rational>& M);

}  // namespace splinex
