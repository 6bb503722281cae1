// The V-model of papers/002 (Definitions 3.1-3.9): a complex of V-cells with the topology of a
// half-edge structure one dimension up.
//
//  - V-cell: a zone of one or more trivariates (`trivariates`: indices into VModel::trivariates);
//    the cells built here are whole trivariates (their trimming surfaces are the six faces); cells
//    on trimmed sub-domains come with the Booleans (papers/002 Section 4).
//  - half-V-surface: a boundary surface of one cell (here: face (dir, side) of the cell's first
//    trivariate), with its twin in the neighbouring cell if any, its V-surface and its trimming loop
//    (the V-curves around it).
//  - V-surface: one or two half-V-surfaces (boundary or internal).
//  - V-curve: a boundary curve (an edge of a face) shared by any number of V-surfaces, with its two
//    end V-points.
//  - V-point: a location with the V-curves that start or end there.
//
// glue() builds the topology of a set of cells (Definition 3.9, Section 3.1.1): V-points equal by
// location; V-curves equal when their end points are and their curves are the same after a common
// function space (elevation + insertion, no reparametrization), also reversed; half-V-surfaces
// equal after a common space under all reversal/flip variants. With eps = 0 equality is exact
// (exact arithmetic); eps > 0 is IRIT's float test: every control point within eps.
// check_invariants() is run after every construction: twins consistent and oppositely oriented,
// every V-curve ends in V-points that list it, every loop closed, the Euler characteristic
// #V-points - #V-curves + #V-surfaces - #V-cells reported (1 for a ball, 0 for a solid torus).
#pragma once
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// Attributes (papers/002 Section 3.1.2) attached to a V-model entity: named constant values (a
/// boundary condition, a material number) and, for cells, attribute trivariates ("fields") on the
/// cell's parameter domain. Attribute coordinates of the geometry (point coordinates beyond the
/// third) are a third kind, carried by the trivariate itself.
template <class T>
struct Attributes {
  std::map<std::string, std::vector<T>> constants;
  std::map<std::string, BSpline<T>> fields;
  /// After a Boolean: the other model's fields a cell in both models could not take over exactly
  /// (its source cell is not affine, or the pull-back crosses a knot line of the field).
  std::vector<std::string> not_carried;
  bool empty() const { return constants.empty() && fields.empty() && not_carried.empty(); }
};

template <class T>
struct VModel {
  struct Cell {
    std::vector<std::size_t> trivariates;      // the trivariates that contain the cell (first: its geometry)
    std::vector<std::size_t> half_surfaces;    // its boundary (six faces for a whole trivariate)
    std::string name;
    std::array<std::size_t, 12> edges{};       // V-curve of edge (along d, sides of the others): 4 d + 2 s_high + s_low
    std::array<std::size_t, 8> corners{};      // V-point of corner (s0, s1, s2): s0 + 2 s1 + 4 s2
    Attributes<T> attributes;
  };
  struct HalfSurface {
    std::size_t cell = 0;
    std::size_t trivariate = 0;
    int dir = 0, side = 0;                     // the face of that trivariate
    std::optional<std::size_t> twin;           // the half-V-surface of the neighbouring cell
    std::size_t surface = 0;                   // its V-surface
    std::vector<std::size_t> loop;             // the V-curves around it (four edges of a face)
  };
  struct Surface {
    std::vector<std::size_t> halves;           // 1 (boundary) or 2 (internal)
    Attributes<T> attributes;
  };
  struct Curve {
    BSpline<T> curve;                          // the geometry (an edge of a trivariate)
    std::array<std::size_t, 2> ends{};         // V-points at its start and end
    std::vector<std::size_t> surfaces;         // V-surfaces that share it
    Attributes<T> attributes;
  };
  struct Point {
    std::vector<T> at;
    std::vector<std::size_t> curves;
    Attributes<T> attributes;
  };
  std::vector<BSpline<T>> trivariates;
  std::vector<Cell> cells;
  std::vector<HalfSurface> half_surfaces;
  std::vector<Surface> surfaces;
  std::vector<Curve> curves;
  std::vector<Point> points;

  /// #V-points - #V-curves + #V-surfaces - #V-cells.
  long euler_characteristic() const {
    return static_cast<long>(points.size()) - static_cast<long>(curves.size()) + static_cast<long>(surfaces.size()) -
           static_cast<long>(cells.size());
  }
  std::size_t boundary_surfaces() const;
  std::size_t internal_surfaces() const;
  /// Topology queries (papers/002 Section 3.1).
  std::vector<std::size_t> cells_of_curve(std::size_t curve) const;
  std::vector<std::size_t> neighbours_of_cell(std::size_t cell) const;
  /// "surface", "curve", "point" or "none": the highest-dimensional entity two cells share.
  std::string shared(std::size_t a, std::size_t b) const;
};

/// The V-model of whole trivariates glued (Definition 3.9); eps = 0: exact equality. Each input
/// trivariate must be clamped with points in R^3 (attribute coordinates may follow; geometry only
/// is compared). Throws ValidationError when a V-surface would have more than two halves.
template <class T>
VModel<T> glue(const std::vector<BSpline<T>>& trivariates, const T& eps = T(0), const std::vector<std::string>& names = {},
               const Limits& limits = {});

/// The V-surface of face (dir, side) of a cell; the V-curve of edge `along` at sides[d] of the other
/// directions; the V-point of a corner (sides of all three).
template <class T>
std::size_t surface_of_face(const VModel<T>& M, std::size_t cell, int dir, int side);
template <class T>
std::size_t curve_of_edge(const VModel<T>& M, std::size_t cell, int along, const std::array<int, 3>& sides);

/// Attaches an attribute trivariate to a cell: a trivariate (any point size) whose domain is the
/// cell's trivariate's (ValidationError otherwise).
template <class T>
void attach_field(VModel<T>& M, std::size_t cell, const std::string& name, BSpline<T> field, const Limits& limits = {});
/// That F is a valid trivariate on V's parameter domain (ValidationError naming `where` otherwise).
template <class T>
void require_field_on(const BSpline<T>& V, const BSpline<T>& F, const std::string& where, const Limits& limits = {});

/// Geometry and attributes of a cell at a parameter point, exactly in exact arithmetic: the
/// point (first three coordinates), the attribute coordinates (the rest), every field's value and
/// the cell's constants.
template <class T>
struct CellValue {
  std::vector<T> point, coordinates;
  std::map<std::string, std::vector<T>> fields, constants;
};
template <class T>
CellValue<T> evaluate_cell(const VModel<T>& M, std::size_t cell, const std::vector<T>& x);

/// The result of the invariant checks (empty `failures`: every invariant holds).
struct VModelCheck {
  std::vector<std::string> failures;
  long euler = 0;
  bool ok() const { return failures.empty(); }
};

template <class T>
VModelCheck check_invariants(const VModel<T>& M, const Limits& limits = {});

/// The edge of a clamped trivariate along direction `along` at the given sides of the other two
/// directions (sides[d] for d != along), as a curve with the trivariate's point coordinates.
template <class T>
BSpline<T> edge_curve(const BSpline<T>& V, int along, const std::array<int, 3>& sides);

/// The same curve or surface after a common function space (elevation + insertion), compared
/// control point by control point (geometry: the first three coordinates) within eps (0: exactly);
/// surfaces also under reversal of either direction and the swap of the two.
template <class T>
bool same_curve(const BSpline<T>& a, const BSpline<T>& b, const T& eps, bool allow_reverse, const Limits& limits = {});
template <class T>
bool same_surface(const BSpline<T>& a, const BSpline<T>& b, const T& eps, const Limits& limits = {});

}  // namespace splinex
