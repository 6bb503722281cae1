// Exact membership of a point in a solid bounded by bilinear facets (papers/004, the cutting
// surface's collision certificate): exact ray parity, planar convex quadrilaterals as two triangles,
// non-planar bilinear ones as themselves with their crossings as exact quadratic irrationals.
// Internal to cut/ (surface_certificate.cpp); the public entry is point_in_solid (cut/surface_facet.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/point.hpp"
#include "cut/surface_facet.hpp"

namespace splinex {
namespace cut_detail {

using P3 = Point3<Rational>;

struct Triangle {
  P3 a, b, c;
};

// A non-planar bilinear facet B(u, v) = a + b u + c v + d u v on [0, 1]^2. Its corners are not
// coplanar, so b, c, d are independent and B is injective: a ray's crossings are the solutions.
struct Bilinear {
  P3 a, b, c, d;
};

// The facets for exact ray parity: planar convex quadrilaterals as two triangles, non-planar
// bilinear quadrilaterals as themselves.
struct MembershipModel {
  std::vector<Triangle> triangles;
  std::vector<Bilinear> bilinears;
};

/// The membership model of a solid, or nullopt with `why` when a facet is not bilinear.
std::optional<MembershipModel> membership_model(const Solid3<Rational>& S, std::string& why);

/// Where x lies, by exact ray parity along up to six fixed rays; nullopt when every ray is
/// degenerate for some facet.
std::optional<Membership> membership_of(const MembershipModel& model, const P3& x);

}  // namespace cut_detail
}  // namespace splinex
