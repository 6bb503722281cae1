// Boolean operations on V-models (papers/002 Section 4, Algorithms 1-3), exact where the cuts are
// exact: issue 18, first part.
//
// What is built: models whose cells are convex and bounded by planar faces (boxes, and any
// hexahedral trivariate whose six faces are planar: its control points of a face on one plane, all
// its control points on the inner side of every face plane). Such a cell has an exact implicit
// form, six half-spaces n.x + d >= 0 (vrep/boolean/boolean.hpp: convex_planes). A half-space on another
// cell's trivariate T is a convex combination of its values c_i = n.P_i + d at T's control points
// (positive weights), so all c_i >= 0 is inside, all <= 0 outside, touching included: coplanar
// contact is decided exactly. When the signs are mixed, the c_i depend on one parameter only and
// linearly (c_k = alpha + beta g_k on the Greville abscissae g_k of that direction) and the weights
// do not vary along it, n.T + d is that linear function and the plane cuts T exactly at the parameter
// t = -alpha/beta, a rational number, and T is split there (knot insertion, exact): untrimming by
// a cuboid tiling of the parameter domain (papers/002 Section 7). A cut that is not such a
// parameter plane (a curved trimming surface in T's parameters) is not built yet: DomainError
// naming both cells. Only the cells that cut need the implicit form: in intersect and subtract A's
// cells may be curved (a cylinder's sectors cut by a slab along w).
//
// The algorithms (Section 4): a cell a of A is split by the planes of every cell b of B that
// overlaps it (no plane of b has a wholly outside); each piece of the grid is inside exactly one b
// or none, by the exact sign at its parameter centre. Intersection (Algorithm 1): the pieces of
// A's cells inside a cell of B, each holding both trivariates. Subtraction (Algorithm 2): the
// pieces inside none. Union (Algorithm 3): the intersection, A - B and B - A. The pieces are glued
// (vrep/model/vmodel.hpp) and checked: no boundary face of a piece may lie on another piece (that would
// be a T-junction, a face glued to nothing although the solid continues there). Where one does
// (a cut that splits a cell's face but not the neighbour's), the two source cells take each
// other's splitting planes and the tiling is recomputed, until none is left (DomainError if that
// does not settle it).
// In float arithmetic the same runs with IRIT-style tolerances: |c| <= eps counts as 0, the
// dependence on one parameter and the linearity within eps, the gluing within eps.
//
// Cells of the result: name "A3*B1" (both), "A3" (only A), "B1" (only B) with the index of the
// source cells; `trivariates` = {its piece, the source trivariates} (a cell in both models holds
// the trivariates of both, Section 4); constants inherited by category (A: A's cell, B: B's cell,
// both: the union, a name in both combined by `blend`: Figure 5's summing blend, clipped to
// [0, 1] or not, or A's value).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/limits.hpp"
#include "spline/bspline.hpp"
#include "vrep/model/vmodel.hpp"

namespace splinex {

enum class BooleanOp { intersect, subtract, unite };

/// The planar path cannot do it (a cut that is not a parameter plane, a cell without the half-space
/// form, a T-junction the tiling does not resolve): vrep/trimmed/trimmed.hpp can, on exact regions.
class NotPlanarError : public DomainError {
  using DomainError::DomainError;
};
enum class Blend { sum_clipped, sum, first };

const char* to_string(BooleanOp op);
BooleanOp parse_boolean_op(const std::string& name);  // "intersect", "subtract", "union"
Blend parse_blend(const std::string& name);          // "sum-clipped", "sum", "first"

/// n.x + d >= 0 on the inner side.
template <class T>
struct HalfSpace {
  std::array<T, 3> n;
  T d;
};

/// The six inner half-spaces of a convex cell with planar faces, or nothing when a face is not
/// planar (within eps) or a control point lies outside a face plane (the cell is not convex).
template <class T>
std::optional<std::vector<HalfSpace<T>>> convex_planes(const BSpline<T>& V, const T& eps = T(0));

/// The plane of face (dir, side) of a trivariate oriented to the trivariate's side (its centre), if
/// every control point of the face lies on it (within eps).
template <class T>
std::optional<HalfSpace<T>> face_plane(const BSpline<T>& V, int dir, int side, const T& eps = T(0));

/// The four corners of face (dir, side) of a trivariate, in the order (0, 0), (1, 0), (1, 1),
/// (0, 1) of the face's two directions (a convex quadrilateral for a convex planar cell).
template <class T>
std::vector<std::vector<T>> face_corners(const BSpline<T>& V, int dir, int side);

template <class T>
struct BooleanStats {
  std::size_t pieces = 0;   // pieces cut before gluing
  std::size_t cuts = 0;     // parameter planes inserted
  std::size_t rounds = 0;   // tilings computed (more than 1 when T-junctions forced more cuts)
};

template <class T>
VModel<T> boolean_op(const VModel<T>& A, const VModel<T>& B, BooleanOp op, const T& eps = T(0), Blend blend = Blend::sum_clipped,
                     const Limits& limits = {}, BooleanStats<T>* stats = nullptr);

/// The volume of a cell: exact for a polynomial trivariate (the integral of det J, a polynomial,
/// in closed form); for a rational one DomainError (the enclosure is not built yet).
template <class T>
T cell_volume(const VModel<T>& M, std::size_t cell, const Limits& limits = {});

/// A certified enclosure lower <= volume <= upper of a trivariate (regular, either orientation):
/// per Bezier piece det J = N / W^4 in Bernstein form; on a box where N's coefficients have one
/// sign, f(W) = W^-4 is convex, so with the weight |N| Jensen's inequality gives the lower bound
/// I f(J / I) and the chord of f over [min W, max W] the upper bound (I = int |N|, J = int |N| W,
/// exact as means of Bernstein coefficients; the gap shrinks with the square of the box);
/// elsewhere the integral lies between vol(box) min N / W^4 and vol(box) max N / W^4; the
/// widest box is halved across the direction where W varies most (exact de Casteljau) until
/// `max_boxes` are alive. Polynomial trivariates: exact (lower ==
/// upper), the mean of N's Bernstein coefficients per piece. A box where N changes sign gives the
/// integral of det J, not of |det J|: give regular trivariates (vrep certify).
template <class T>
struct VolumeEnclosure {
  T lower{0}, upper{0};
  std::size_t boxes = 0;
};
template <class T>
VolumeEnclosure<T> volume_enclosure(const BSpline<T>& V, std::size_t max_boxes = 4096, const Limits& limits = {});

/// The cells whose closure contains x (exact: the half-spaces of convex planar cells;
/// DomainError for a cell without them).
template <class T>
std::vector<std::size_t> cells_containing(const VModel<T>& M, const std::vector<T>& x, const T& eps = T(0));

}  // namespace splinex
