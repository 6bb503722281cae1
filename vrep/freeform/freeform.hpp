// Trimming by freeform solids (issue 18, What to build 1: "freeform-vs-freeform boundaries without
// an implicit form", papers/002 Figures 10 and 14: the teapot's handle and body).
//
// A FreeformSolid is a solid given by its trivariates (cells), with no implicit form. What it offers
// instead, exactly:
//   - its boundary: the Bezier pieces of the cells' faces that no other face covers (faces equal
//     as surfaces, same_surface: glued faces between cells and seams of closed trivariates such as
//     a body of revolution's u = 0 / u = 4 are inside, not boundary);
//   - point membership: x lies in the solid iff T(u, v, w) = x has a root in some cell's domain:
//     three polynomial equations X_c - x_c W = 0 per Bezier piece, solved by the certified solver
//     (solve/solver.hpp). "in" needs a root certified (or exact) away from the boundary faces; "out"
//     needs every piece proved root-free; anything else (x on the boundary, a singular point
//     where Krawczyk's test cannot certify) is "mixed".
//
// freeform_cell trims a trivariate V by conditions "inside S" / "outside S" for freeform solids S
// (Algorithms 1-3 of papers/002 for cells that are not cut by implicit surfaces). It subdivides V's
// parameter domain (exact de Casteljau). A box of V is *clear* of S when the bounding box of its
// image (the extreme control points, weights positive) meets no bounding box of S's boundary
// pieces; S's pieces are halved alongside (a candidate list per box, pieces larger than the box's
// image are split) until they are no larger than the box's image. A clear box's image is
// connected and misses S's boundary, so it lies wholly inside S or wholly outside; clear boxes
// that touch (closed boxes with a common point) share the answer. So after the subdivision each
// connected group of clear boxes needs one point query (a corner of one of its boxes, whose image
// is an exact control point), and a box is in (every condition holds), out (one fails) or mixed
// (its image may meet a boundary: near the trimming surface, or a query that stayed undecided).
//
// What is certified (exact arithmetic): the kind whole / empty / cut (cut: an in-box and an out-box);
// the volume enclosure (in-boxes' integral of det J, exact for a polynomial V; mixed boxes
// between none and all); and a lower bound on the number of connected components of the cell:
// the components of the non-out boxes (touching closed boxes, plus the identifications of V's
// own domain: a face equal to another face of V, a face collapsed to a curve or a point) that
// contain an in-box. Each holds points of the cell, and two of them cannot be joined inside the cell
// provided V is injective apart from those identifications (a valid V-cell, papers/002 Section 3).
// The number of cover components is shown beside it and is not certified (two true components
// can share a cover component whose mixed boxes were not resolved).
//
// Validity: the arguments above need the solids' boundaries to be their faces, so a cell whose det
// J takes both strict signs is refused: a fold seen on a 5 x 5 x 5 grid per piece by two exact
// values (DomainError), and in exact arithmetic every other cell goes through certify_cell_shape
// (vrep/model/validate.hpp): det J of one sign certified (zeros only on the domain's boundary, as
// on collapsed faces), a fold or an interior zero refuted (DomainError), undecided refused
// (DomainError). A non-injective cell without a fold is not detected (valid V-cells are assumed,
// as in the paper). A point whose preimage lies on an inner knot plane
// with irrational coordinates is decided by the face's two-equation system when the third vanishes
// identically there (a symmetry plane at a patch boundary); otherwise it stays mixed.
//
// In double the same steps run with rounding and the solver's float answers: nothing is certified,
// which is the float Boolean the exact one is compared with (Table 1's double column); the fold
// check is skipped (a rounded zero could fake one).
#pragma once
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "bernstein/tensor.hpp"
#include "solve/solver.hpp"
#include "spline/bspline.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

template <class T>
struct FreeformSolid {
  /// A Bezier piece of a boundary face: the homogeneous coordinates (W, wx, wy, wz) in Bernstein
  /// form on [0, 1]^2, and the bounds of its points.
  struct Patch {
    std::array<Bernstein<T>, 4> h;
    std::array<T, 6> box;
  };
  /// A Bezier piece of a cell: (W, wx, wy, wz) on [0, 1]^3 standing for the parameter box [lo, hi],
  /// the bounds of its points, and which of its faces lie on the solid's boundary.
  struct Piece {
    std::size_t cell = 0;
    std::array<Bernstein<T>, 4> h;
    std::vector<T> lo, hi;
    std::array<T, 6> box;
    std::array<std::array<bool, 2>, 3> on_boundary{};
  };
  std::string name;
  std::vector<BSpline<T>> cells;
  std::vector<Patch> boundary;
  std::vector<Piece> pieces;
  std::size_t faces = 0, inner_faces = 0;  // cell faces in all; of them covered by another face (not boundary)
  std::array<T, 6> box{};                  // bounds of all control points
};

/// The solid of the given cells (trivariates in R^3, clamped, positive weights): boundary pieces
/// and cell pieces as described above. ValidationError names the cell and field; the pieces are
/// checked against `limits` before they are built.
template <class T>
FreeformSolid<T> freeform_solid(std::string name, std::vector<BSpline<T>> cells, const Limits& limits = {});

/// A point against a freeform solid: in, out, or mixed (on the boundary, or undecided by the
/// solver); `systems` counts the 3 x 3 systems solved.
template <class T>
Truth classify_point_freeform(const FreeformSolid<T>& S, const std::vector<T>& x, const SolveOptions& options = {},
                              std::size_t* systems = nullptr);

/// One condition of a trimmed cell: the cell's points inside (or outside) `solid`.
template <class T>
struct FreeformCondition {
  const FreeformSolid<T>* solid = nullptr;
  bool inside = true;
};

struct FreeformOptions {
  std::size_t max_boxes = 4096;      // subdivision boxes of the cell's domain (the budget)
  std::size_t max_candidates = 512;  // boundary pieces kept per box and condition before a box stays mixed
  SolveOptions solve{12, 4000, 20, true, {}};  // point queries: shallower than the solver's defaults
  std::function<void(const std::string&)> progress;  // a line about every two seconds; empty: silent
};

template <class T>
struct FreeformCell {
  CellClass<T> cls;            // whole / empty / cut / undecided, boxes, mixed boxes, witnesses
  VolumeEnclosure<T> volume;   // certified in exact arithmetic
  std::size_t components = 0;        // lower bound on the cell's connected components (see above)
  std::size_t cover_components = 0;  // components of the non-out boxes (not certified)
  std::size_t queries = 0, undecided_queries = 0, systems = 0;  // point queries, of them undecided; systems solved
  struct Box {
    std::array<T, 3> lo, hi;  // in V's parameters
    Truth truth = Truth::mixed;
    int component = -1;       // index among the cover components
  };
  std::vector<Box> boxes;  // the boxes that are not out
};

/// V (a trivariate in R^3, positive weights) restricted to the points that satisfy every condition.
template <class T>
FreeformCell<T> freeform_cell(const BSpline<T>& V, const std::vector<FreeformCondition<T>>& conditions, const FreeformOptions& options = {},
                              const Limits& limits = {});

/// Whether a double run of freeform_cell decided every box as the exact run did: the same boxes
/// (the double bounds exactly equal to the exact ones) with the same truths, in any order.
/// Where it holds, the runs' volume bounds differ by rounding only.
bool same_boxes(const FreeformCell<Rational>& exact, const FreeformCell<double>& dbl);

/// The edges of a freeform-trimmed cell, exactly (the part of the cell's topology on V's edges, as
/// trimmed_topology gives it for implicit trims): the corners of V's domain inside the cell (every
/// condition decided by a point query), and per edge of V's domain its V-curves (runs inside the
/// cell) and V-points (their ends strictly inside the edge). The crossings of an edge with a
/// solid's boundary are the roots of S_face(s, t) = E(tau), three polynomial equations per pair of
/// a boundary piece and an edge piece, solved by the certified solver; between crossings one
/// point query decides. An edge collapsed to a point is said so; a crossing or a query the solver
/// leaves undecided (tangency, an edge on the boundary) makes the edge undecided.
template <class T>
struct FreeformEdges {
  struct Edge {
    int along = 0;
    std::array<int, 3> sides{};
    enum Status { curve, collapsed };
    Uncertain<Status> status = curve;  // undecided: a solver box left (tangency, an edge on the boundary)
    std::size_t pieces = 0, points = 0;
    std::vector<std::pair<T, T>> cuts;  // enclosures of the V-points' parameters
  };
  std::size_t corners = 0, corners_undecided = 0;
  std::vector<Edge> edges;
  std::size_t systems = 0;  // systems solved (crossings and point queries)
};

template <class T>
FreeformEdges<T> freeform_edges(const BSpline<T>& V, const std::vector<FreeformCondition<T>>& conditions, const FreeformOptions& options = {},
                                const Limits& limits = {});

}  // namespace splinex
