// The documents of `splinex cut` (papers/004), read exactly:
//   solid: {"type": "solid2d", "facets": [<spline document>, ...]}  (curves in R^2, counter-clockwise)
//   cut:   {"type": "cut2d", "points": [{"facet": i, "parameter": s, "tangent": [tx, ty]}, {...}]}
//   solid: {"type": "solid3d", "facets": [<spline document>, ...]}  (surfaces in R^3, F_u x F_v outwards)
//   cut:   {"type": "cut3d", "positive": [i, ...], "tangents": [{"facet": i, "side": s, "tangent": [tx, ty, tz]}, ...]}
// Numbers as in every document: integers, fractions "p/q" or decimals, exactly.
#pragma once
#include "cut/solid.hpp"
#include "cut/solid3.hpp"
#include "io/json_io.hpp"

namespace splinex {

/// Reads and validates (validate_solid) a solid document.
Solid2<Rational> solid2_from_json(const Json& doc, const Limits& limits = {});
/// Reads a cutting-data document (validated against the solid by validate_cut).
CutData2<Rational> cut2_from_json(const Json& doc);

Json solid2_to_json(const Solid2<Rational>& S);
Json cut2_to_json(const CutData2<Rational>& C);

/// The d = 3 documents (validate_solid on reading; the cutting data are validated by validate_cut).
Solid3<Rational> solid3_from_json(const Json& doc, const Limits& limits = {});
CutData3 cut3_from_json(const Json& doc);
Json solid3_to_json(const Solid3<Rational>& S);
Json cut3_to_json(const CutData3& C);

/// Legacy VTK (ASCII) for ParaView: the facets tessellated (each Bezier piece on an 8 x 8 grid,
/// in double) as POLYDATA; f* on an (n+1)^3 grid of the solid's bounding cube as STRUCTURED_POINTS
/// in the solid's coordinates (lo, scale: the normalization frame), to be contoured at 0.
std::string solid3_vtk(const Solid3<Rational>& S);
std::string guide3_vtk(const BSpline<Rational>& f, const std::array<Rational, 3>& lo, const Rational& scale, int n);

/// A cutting surface: {"type": "cutting_surface", "patch": <spline document: a polynomial surface in
/// R^3>, "domain": [[u, v], ...] (Omega, counter-clockwise, vertex j <-> loop side j's start)} in the
/// solid's coordinates. Read exactly; the domain's shape is checked by certify_cutting_surface.
struct CuttingSurfaceDoc {
  BSpline<Rational> patch;
  std::vector<std::array<Rational, 2>> domain;
};
CuttingSurfaceDoc cutting_surface_from_json(const Json& doc, const Limits& limits = {});
Json cutting_surface_to_json(const BSpline<Rational>& patch, const std::vector<std::array<Rational, 2>>& domain);

/// The trimmed patch for ParaView: the cells of an n x n grid of Omega's bounding box whose four
/// corners lie in Omega, as quadrilaterals (POLYDATA, in double), and the boundary p(dOmega) as a line.
std::string surface3_vtk(const BSpline<Rational>& patch, const std::vector<std::array<Rational, 2>>& domain, int n);

/// The "type" of a solid document ("solid2d" or "solid3d"); ParseError otherwise.
std::string solid_document_type(const Json& doc);

}  // namespace splinex
