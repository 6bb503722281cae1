// The V-rep's primitives, one row each (issue 48 item 7): `splinex vrep primitive` takes its names,
// its help and its builders from this table. A new primitive is its builder (primitives.hpp, and
// its exact region in vrep/trimmed/trimmed.hpp where it has one) and one row here.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "exact/rational.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "spline/bspline.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

/// The parameters a primitive may read, in the exact input's numbers; a row converts the ones it
/// reads to the arithmetic of the run (round_checked: a number that does not fit names its field).
struct PrimitiveParameters {
  Rational radius{1}, radius2{1, 2}, height{2}, major{3};
  std::vector<Rational> lo{Rational(0), Rational(0), Rational(0)}, hi{Rational(1), Rational(1), Rational(1)};
  int degree = 3, pieces = 4;
};

/// A primitive's cells and its exact region where it has one (the Booleans' trimmed path uses it).
template <class F>
struct Primitive {
  std::vector<BSpline<F>> cells;
  std::optional<Region<F>> region;
};

/// The parameters as a row reads them, in the arithmetic F.
template <class F>
struct PrimitiveInput {
  const PrimitiveParameters& p;
  static F round(const Rational& x, const std::string& field) { return round_checked<F>(x, field); }
  F radius() const { return round(p.radius, "radius"); }
  F radius2() const { return round(p.radius2, "radius2"); }
  F height() const { return round(p.height, "height"); }
  F major() const { return round(p.major, "major"); }
  std::vector<F> list(const std::vector<Rational>& v, const std::string& field) const {
    std::vector<F> out;
    for (const auto& x : v) out.push_back(round(x, field));
    return out;
  }
};

template <class F>
struct PrimitiveRow {
  const char* name;
  const char* cells;  // how many cells, for the help
  const char* reads;  // the parameters its builder reads (a reader of text parses just these)
  Primitive<F> (*build)(const PrimitiveInput<F>&);
};

/// The table: one row per primitive, in the order the help lists them.
template <class F>
const std::vector<PrimitiveRow<F>>& primitive_table() {
  static const std::vector<PrimitiveRow<F>> rows{
      {"cylinder", "five cells", "radius height",
       [](const PrimitiveInput<F>& in) -> Primitive<F> { return {cylinder_cells(in.radius(), in.height()), cylinder_region(in.radius(), in.height())}; }},
      {"cone", "five cells", "radius radius2 height",
       [](const PrimitiveInput<F>& in) -> Primitive<F> {
         return {cone_cells(in.radius(), in.radius2(), in.height()), cone_region(in.radius(), in.radius2(), in.height())};
       }},
      {"torus", "five cells", "major radius",
       [](const PrimitiveInput<F>& in) -> Primitive<F> { return {torus_cells(in.major(), in.radius()), torus_region(in.major(), in.radius())}; }},
      // The sphere of seven cells has its exact region for patches of degree <= 4 (sphere_region:
      // leaves of degree 2 degree <= 8) and at most 11 pieces (above, its 30 pieces^2 + 6 leaves
      // pass the documents' 4096), in exact arithmetic only (rounded, the region would not describe
      // the rounded cells exactly).
      {"sphere", "seven cells", "radius degree pieces",
       [](const PrimitiveInput<F>& in) -> Primitive<F> {
         auto cells = sphere_cells(in.radius(), in.p.degree, in.p.pieces);  // checks degree and pieces
         if (in.p.degree > 4 || in.p.pieces > 11 || !ArithTraits<F>::exact) return {std::move(cells), std::nullopt};
         return {std::move(cells), sphere_region(in.radius(), in.p.degree, in.p.pieces)};
       }},
      {"box", "one cell", "lo hi",
       [](const PrimitiveInput<F>& in) -> Primitive<F> {
         return {box_cells(in.list(in.p.lo, "lo"), in.list(in.p.hi, "hi")), box_region(in.list(in.p.lo, "lo"), in.list(in.p.hi, "hi"))};
       }},
      // The singular trivariates (Figure 8) are not offered for Booleans: no region.
      {"singular-cylinder", "one cell", "radius height",
       [](const PrimitiveInput<F>& in) -> Primitive<F> { return {{singular_cylinder(in.radius(), in.height())}, std::nullopt}; }},
      {"singular-sphere", "one cell", "radius", [](const PrimitiveInput<F>& in) -> Primitive<F> { return {{singular_sphere(in.radius())}, std::nullopt}; }},
  };
  return rows;
}

/// The primitives' names, in the table's order.
inline std::vector<std::string> primitive_names() {
  std::vector<std::string> out;
  for (const auto& r : primitive_table<Rational>()) out.push_back(r.name);
  return out;
}

/// "cylinder (five cells), cone (five cells), ...": the help's list.
inline std::string primitive_help() {
  std::string out;
  for (const auto& r : primitive_table<Rational>()) out += (out.empty() ? "" : ", ") + std::string(r.name) + " (" + r.cells + ")";
  return out;
}

/// The row of the primitive `name`; an unknown name is a ValidationError naming the known ones.
template <class F>
const PrimitiveRow<F>& primitive_row(const std::string& name) {
  for (const auto& r : primitive_table<F>())
    if (name == r.name) return r;
  throw ValidationError("name", "is not a primitive", "give one of: " + primitive_help());
}

/// The primitive `name` built in F.
template <class F>
Primitive<F> build_primitive(const std::string& name, const PrimitiveParameters& p) {
  return primitive_row<F>(name).build(PrimitiveInput<F>{p});
}

}  // namespace splinex
