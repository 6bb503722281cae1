#include "base/errors.hpp"
#include "base/point.hpp"
#include "cut/examples.hpp"
#include "spline/factories.hpp"

namespace splinex {

namespace {

using P3 = Point3<Rational>;
Rational q(long a, long b = 1) { return Rational(a, b); }

// The bilinear patch with corners a (u0 v0), b (u1 v0), c (u1 v1), d (u0 v1): normal (b-a) x (d-a).
BSpline<Rational> quad(const P3& a, const P3& b, const P3& c, const P3& d) {
  const auto U = clamped_knots<Rational>(1, q(0), q(1));
  std::vector<Rational> pts;
  for (const P3* p : {&a, &b, &d, &c})
    for (int k = 0; k < 3; ++k) pts.push_back((*p)[k]);
  return make_spline<Rational>({1, 1}, {U, U}, 3, pts);
}

P3 centre(const BSpline<Rational>& F) {
  P3 c{q(0), q(0), q(0)};
  for (std::size_t i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) c[k] += F.points[3 * i + k] / 4;
  return c;
}

P3 inward_normal(const BSpline<Rational>& F) {
  // minus (P10 - P00) x (P01 - P00)
  P3 a, b;
  for (int k = 0; k < 3; ++k) a[k] = F.points[3 + k] - F.points[k], b[k] = F.points[6 + k] - F.points[k];
  const P3 n = cross(a, b);
  return {-n[0], -n[1], -n[2]};
}

// The cutting data: b = facets whose centre satisfies `in_b`; each loop side gets the inward
// normal of its b facet (the loop sides lie inside flat faces in these examples).
CutData3 cut_by(const Solid3<Rational>& S, const std::function<bool(const P3&)>& in_b) {
  CutData3 C;
  for (std::size_t i = 0; i < S.facets.size(); ++i)
    if (in_b(centre(S.facets[i]))) C.positive.push_back(i);
  // The loop sides: sides of b facets whose neighbour (the solid's adjacency) is in b-bar.
  const auto adj = validate_solid(S);
  std::vector<char> b(S.facets.size(), 0);
  for (auto i : C.positive) b[i] = 1;
  for (std::size_t i = 0; i < S.facets.size(); ++i)
    for (int s = 0; s < 4; ++s)
      if (b[i] && !b[adj.facet[i][s]]) C.tangents.push_back({i, s, inward_normal(S.facets[i])});
  return C;
}

std::vector<Rational> grid(std::initializer_list<Rational> v) { return std::vector<Rational>(v); }

}  // namespace

Solid3<Rational> box_solid(const std::vector<Rational>& xs, const std::vector<Rational>& ys, const std::vector<Rational>& zs,
                           const std::function<bool(std::size_t, std::size_t, std::size_t)>& filled) {
  const std::size_t nx = xs.size() - 1, ny = ys.size() - 1, nz = zs.size() - 1;
  auto full = [&](long i, long j, long k) {
    return i >= 0 && j >= 0 && k >= 0 && i < static_cast<long>(nx) && j < static_cast<long>(ny) && k < static_cast<long>(nz) && filled(i, j, k);
  };
  Solid3<Rational> S;
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t k = 0; k < nz; ++k) {
        if (!filled(i, j, k)) continue;
        const Rational x0 = xs[i], x1 = xs[i + 1], y0 = ys[j], y1 = ys[j + 1], z0 = zs[k], z1 = zs[k + 1];
        const long I = i, J = j, K = k;
        // each face: b - a and d - a span it with (b - a) x (d - a) outwards
        if (!full(I - 1, J, K)) S.facets.push_back(quad({x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}));  // -x: z x y
        if (!full(I + 1, J, K)) S.facets.push_back(quad({x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}));  // +x: y x z
        if (!full(I, J - 1, K)) S.facets.push_back(quad({x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}));  // -y: x x z
        if (!full(I, J + 1, K)) S.facets.push_back(quad({x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}));  // +y: z x x
        if (!full(I, J, K - 1)) S.facets.push_back(quad({x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}));  // -z: y x x
        if (!full(I, J, K + 1)) S.facets.push_back(quad({x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}));  // +z: x x y
      }
  return S;
}

std::vector<std::string> cut_example3_names() { return {"tower", "cube", "slotted", "maiden", "vase", "twisted-vase"}; }

CutExample3 cut_example3(const std::string& name) {
  CutExample3 e;
  e.name = name;
  if (name == "tower") {
    e.description = "two unit boxes stacked, [0,1]^2 x [0,2] (10 unit-square facets), b: the facets above z = 1; the smallest example";
    const auto g = grid({q(0), q(1)});
    e.solid = box_solid(g, g, grid({q(0), q(1), q(2)}), [](std::size_t, std::size_t, std::size_t) { return true; });
    e.cut = cut_by(e.solid, [](const P3& c) { return c[2] > 1; });
  } else if (name == "cube") {
    e.description = "the cube [0,2]^3 of 2 x 2 x 2 unit boxes (24 unit-square facets), b: the facets above z = 1; the loop runs around at z = 1";
    const auto g = grid({q(0), q(1), q(2)});
    e.solid = box_solid(g, g, g, [](std::size_t, std::size_t, std::size_t) { return true; });
    e.cut = cut_by(e.solid, [](const P3& c) { return c[2] > 1; });
  } else if (name == "slotted") {
    e.description =
        "a block [0,5] x [0,2] x [0,2] with two slots [1,2] x [0,2] x [1,2] and [3,4] x [0,2] x [1,2] from the top (modelled on Figure 13's "
        "bi-slotted cube), b: the facets left of x = 3/2; the loop runs around the base below the first slot";
    const auto xs = grid({q(0), q(1), q(3, 2), q(2), q(3), q(4), q(5)});
    e.solid = box_solid(xs, grid({q(0), q(2)}), grid({q(0), q(1), q(2)}), [](std::size_t i, std::size_t, std::size_t k) {
      return k == 0 || i == 0 || i == 3 || i == 5;  // teeth over [0,1], [2,3], [4,5]
    });
    e.cut = cut_by(e.solid, [](const P3& c) { return c[0] < Rational(3, 2); });
  } else if (name == "maiden") {
    e.description =
        "the gap [0,5] x [0,1] x [0,4] between two walls, with a spike [1,2] x [0,1] x [0,5/2] from the bottom wall and a spike "
        "[3,4] x [0,1] x [3/2,4] from the top wall, each reaching past the middle z = 2 (modelled on Figure 11's iron maiden); b: the "
        "facets above the wave w(x) = 2 (x < 1/2), 13/4 (1/2 < x < 5/2), 3/4 (5/2 < x < 9/2), 2 (x > 9/2), so the loop runs at z = 2 on "
        "the end walls and weaves over the bottom spike and under the top spike on the front and back";
    const auto xs = grid({q(0), q(1, 2), q(1), q(2), q(5, 2), q(3), q(4), q(9, 2), q(5)});
    const auto zs = grid({q(0), q(3, 4), q(3, 2), q(2), q(5, 2), q(13, 4), q(4)});
    e.solid = box_solid(xs, grid({q(0), q(1)}), zs, [&](std::size_t i, std::size_t, std::size_t k) {
      const bool bottom_spike = xs[i] >= 1 && xs[i + 1] <= 2 && zs[k + 1] <= Rational(5, 2);
      const bool top_spike = xs[i] >= 3 && xs[i + 1] <= 4 && zs[k] >= Rational(3, 2);
      return !bottom_spike && !top_spike;
    });
    e.cut = cut_by(e.solid, [](const P3& c) {
      const Rational& x = c[0];
      const Rational w = x < Rational(1, 2) ? q(2) : x < Rational(5, 2) ? q(13, 4) : x < Rational(9, 2) ? q(3, 4) : q(2);
      return c[2] > w;
    });
  } else if (name == "vase") {
    e.description =
        "a cube-shaped vase [0,5]^2 x [0,4] with the cavity [2,3]^2 x [1,4] open at the top (modelled on Figure 12's vase), b: the "
        "facets above z = 2 on the outside, the rim and the whole cavity; the loop runs around the outer walls at z = 2, above the "
        "cavity's floor (z = 1), so the plane of the loop cuts through the cavity: a valid cutting surface must bend below it";
    const auto g = grid({q(0), q(2), q(3), q(5)});
    e.solid = box_solid(g, g, grid({q(0), q(1), q(2), q(4)}), [](std::size_t i, std::size_t j, std::size_t k) { return !(i == 1 && j == 1 && k >= 1); });
    e.cut = cut_by(e.solid, [](const P3& c) {
      const bool cavity = c[0] >= 2 && c[0] <= 3 && c[1] >= 2 && c[1] <= 3 && c[2] >= 1;
      return c[2] > 2 || cavity;
    });
  } else if (name == "twisted-vase") {
    e = cut_example3("vase");
    e.name = name;
    e.description =
        "the vase with every vertex moved by the polynomial map (x + (y - 5/2)(z - 2)/20, y - (x - 5/2)(z - 2)/20, z + (x - 5/2)(y - 5/2)/10) "
        "and its faces the bilinear patches through the moved corners (modelled on Figure 1's vase: non-planar faces, and a non-planar "
        "loop, a saddle from z = 11/8 to 21/8 at the corners); b as for the vase; each loop side's tangent is the b facet's inward "
        "normal at the side's midpoint";
    auto phi = [](const P3& p) {
      const Rational &x = p[0], &y = p[1], &z = p[2];
      return P3{x + (y - q(5, 2)) * (z - 2) / 20, y - (x - q(5, 2)) * (z - 2) / 20, z + (x - q(5, 2)) * (y - q(5, 2)) / 10};
    };
    for (auto& F : e.solid.facets)
      for (std::size_t i = 0; i < 4; ++i) {
        const P3 m = phi({F.points[3 * i], F.points[3 * i + 1], F.points[3 * i + 2]});
        for (int k = 0; k < 3; ++k) F.points[3 * i + k] = m[k];
      }
    for (auto& t : e.cut.tangents) {
      // the midpoint of the side in the facet's domain [0,1]^2 (sides 0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0)
      static const Rational mid[4][2] = {{q(1, 2), q(0)}, {q(1), q(1, 2)}, {q(1, 2), q(1)}, {q(0), q(1, 2)}};
      const auto& F = e.solid.facets[t.facet];
      const Rational u = mid[t.side][0], v = mid[t.side][1];
      P3 Fu, Fv;
      // F = (1-u)(1-v) P00 + u (1-v) P10 + (1-u) v P01 + u v P11, control points in the order P00, P10, P01, P11
      for (int k = 0; k < 3; ++k) {
        const Rational &p00 = F.points[k], &p10 = F.points[3 + k], &p01 = F.points[6 + k], &p11 = F.points[9 + k];
        Fu[k] = (1 - v) * (p10 - p00) + v * (p11 - p01);
        Fv[k] = (1 - u) * (p01 - p00) + u * (p11 - p10);
      }
      const P3 n = cross(Fu, Fv);
      t.tangent = {-n[0], -n[1], -n[2]};
    }
  } else {
    std::string names;
    for (const auto& n : cut_example3_names()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("example", "'" + name + "' is not a 3D example", "give one of " + names);
  }
  return e;
}

}  // namespace splinex
