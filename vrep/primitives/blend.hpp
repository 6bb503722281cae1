// The distance blend of papers/002 Eq. 2 (Section 3.1.2, Figure 6), with certified enclosures.
//
// For the union of V-models V1 and V2 and a point p in both, with constant attributes A1 and A2
// (per model) and d1 = d(p, dV1 n V2), d2 = d(p, dV2 n V1) (the distance to the part of one
// model's boundary inside the other):
//   A(p) = (d1^k A1 + d2^k A2) / (d1^k + d2^k)   (k = 1: Eq. 2; k > 1: its higher-order variant),
// A1 in V1 only, A2 in V2 only. (As p approaches dV1 n V2 - leaving V1 for the part of V2 outside
// it - d1 -> 0 and A -> A2, so A is C^0 across the interfaces; where d1 = d2 = 0, the point r of
// Figure 6, it is undefined.)
//
// Built for models whose cells are convex with planar faces (vrep/boolean/boolean.hpp): dV1 n V2 is the
// union of V1's boundary faces clipped by V2's cells (convex polygons, exact); the squared distance
// from a rational point to a convex polygon is rational (plane or edge, exactly); the distance is
// its square root, enclosed by MPFI at `bits` bits; A(p) is evaluated in MPFI, and the enclosure's
// ends are returned as the exact rationals they are. Where d1 or d2 is exactly 0 the value is exact
// (A2 or A1); where both are, `singular`.
#pragma once
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/vmodel.hpp"

namespace splinex {

struct Enclosure {
  Rational lo, hi;
  bool exact() const { return lo == hi; }
};

struct BlendValue {
  std::vector<Enclosure> value;  // per attribute component; empty when singular
  Rational d1_squared, d2_squared;
  bool singular = false;
};

/// The attribute `name` of a model at a point x, exactly: from the first cell whose closure holds
/// x (convex planar cells), its constant of that name, or its field evaluated at the cell's
/// parameters of x where the cell is affine (x = alpha + B s, s = B^-1 (x - alpha), exact).
/// ValidationError when no cell holds x or none has the attribute, DomainError for a field on a
/// cell that is not affine (its inverse is not rational). `cell` receives the cell used.
std::vector<Rational> attribute_at(const VModel<Rational>& M, const std::vector<Rational>& x, const std::string& name, std::size_t* cell = nullptr);

class DistanceBlend {
 public:
  /// The clipped boundary polygons of both models (DomainError for a cell that is not convex with
  /// planar faces).
  DistanceBlend(const VModel<Rational>& V1, const VModel<Rational>& V2);
  /// A(p) for p in both models (ValidationError otherwise; outside both too), attributes of equal
  /// length.
  BlendValue at(const std::vector<Rational>& p, const std::vector<Rational>& A1, const std::vector<Rational>& A2, int k = 1,
                int bits = 128) const;
  /// Exact squared distances d(p, dV1 n V2)^2 and d(p, dV2 n V1)^2.
  Rational d1_squared(const std::vector<Rational>& p) const;
  Rational d2_squared(const std::vector<Rational>& p) const;
  bool in_first(const std::vector<Rational>& p) const;
  bool in_second(const std::vector<Rational>& p) const;
  std::size_t polygons_first() const { return boundary1_.size(); }
  std::size_t polygons_second() const { return boundary2_.size(); }

 private:
  using Polygon3 = std::vector<std::array<Rational, 3>>;
  std::vector<Polygon3> boundary1_, boundary2_;             // dV1 n V2, dV2 n V1
  std::vector<std::vector<HalfSpace<Rational>>> cells1_, cells2_;  // the cells' half-spaces

};

}  // namespace splinex
