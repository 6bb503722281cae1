// The exact regions of the primitives (vrep/trimmed/trimmed.hpp: box, ball, cylinder, cone, torus,
// the sphere of seven cells). Internal to vrep/trimmed/ (included by trimmed_impl.hpp).
#pragma once
#include "vrep/trimmed/region_impl.hpp"

namespace splinex {

template <class T>
Region<T> box_region(const std::vector<T>& lo, const std::vector<T>& hi) {
  using vrep_detail::poly_linear;
  if (lo.size() != 3 || hi.size() != 3) throw ValidationError("box", "needs three coordinates per corner", "give lo and hi as x,y,z");
  std::vector<Region<T>> parts;
  const char* axis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (!(lo[a] < hi[a])) throw ValidationError("box", "has lo >= hi", "give lo < hi in every coordinate");
    T e[3] = {T(0), T(0), T(0)};
    e[a] = T(1);
    parts.push_back(region_leaf(poly_linear(T(-lo[a]), e[0], e[1], e[2]), std::string("box: ") + axis[a] + " >= lo"));
    parts.push_back(region_leaf(poly_linear(hi[a], T(-e[0]), T(-e[1]), T(-e[2])), std::string("box: ") + axis[a] + " <= hi"));
  }
  return region_and(std::move(parts));
}

template <class T>
Region<T> ball_region(const std::array<T, 3>& c, const T& r) {
  Poly3<T> g;
  T k = r * r;
  for (int d = 0; d < 3; ++d) {
    std::array<int, 3> e{}, e2{};
    e[d] = 1;
    e2[d] = 2;
    g.terms[e2] = T(-1);
    g.terms[e] = T(2) * c[d];
    k -= c[d] * c[d];
  }
  g.terms[{0, 0, 0}] = k;
  return region_leaf(g, "ball");
}

template <class T>
Region<T> cylinder_region(const T& r, const T& h) {
  return cone_region(r, r, h);
}

template <class T>
Region<T> cone_region(const T& r0, const T& r1, const T& h) {
  using namespace vrep_detail;
  if (!(T(0) < r0) || !(T(0) < r1) || !(T(0) < h)) throw ValidationError("cone", "needs positive radii and height", "give r0, r1, h > 0");
  // (r0 h + (r1 - r0) z)^2 - h^2 (x^2 + y^2) >= 0 and 0 <= z <= h (the radius is positive on [0, h]).
  const Poly3<T> rz = poly_linear(T(r0 * h), T(0), T(0), T(r1 - r0));
  Poly3<T> g = poly_mul(rz, rz);
  Poly3<T> xy;
  xy.terms[{2, 0, 0}] = h * h;
  xy.terms[{0, 2, 0}] = h * h;
  g = poly_add(g, xy, T(-1));
  const std::string what = r0 == r1 ? "cylinder" : "cone";
  return region_and<T>({region_leaf(g, what + ": side"), region_leaf(poly_linear(T(0), T(0), T(0), T(1)), what + ": z >= 0"),
                        region_leaf(poly_linear(h, T(0), T(0), T(-1)), what + ": z <= h")});
}

template <class T>
Region<T> torus_region(const T& R, const T& r) {
  using namespace vrep_detail;
  if (!(T(0) < r) || !(r < R)) throw ValidationError("torus", "needs 0 < r < R", "give a tube radius below the major radius");
  // 4 R^2 (x^2 + y^2) - (x^2 + y^2 + z^2 + R^2 - r^2)^2 >= 0.
  Poly3<T> s;
  s.terms[{2, 0, 0}] = T(1);
  s.terms[{0, 2, 0}] = T(1);
  s.terms[{0, 0, 2}] = T(1);
  s.terms[{0, 0, 0}] = R * R - r * r;
  Poly3<T> xy;
  xy.terms[{2, 0, 0}] = T(4) * R * R;
  xy.terms[{0, 2, 0}] = T(4) * R * R;
  return region_and<T>({region_leaf(poly_add(xy, poly_mul(s, s), T(-1)), "torus")});
}

template <class T>
Region<T> sphere_region(const T& r, int degree, int pieces) {
  using namespace vrep_detail;
  if (!(T(0) < r)) throw ValidationError("radius", "must be positive", "give a positive radius");
  const CubeSphereWeights W = cube_sphere_weights(degree, pieces);  // checks degree and pieces
  if (degree > 4)
    throw ValidationError("degree", "the sphere's exact region needs patches of degree <= 4 (its leaves have degree 2 degree, at most 8)",
                          "give --degree 2, 3 or 4");
  auto num = [](const Rational& x) { return ArithTraits<T>::from_rational(x); };
  // The weight function P(u, v) on [0, 1]^2 (s = 2u - 1, t = 2v - 1) and its Bezier pieces.
  BSpline<Rational> P;
  P.degrees = {degree, degree};
  P.knots = {W.knots, W.knots};
  P.q = 1;
  const std::size_t n = W.s.size();
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) P.points.push_back(W.P[i][j]);
  // Univariate polynomials in s (coefficients of s^0, s^1, ...).
  using Upoly = std::vector<Rational>;
  auto umul = [](const Upoly& a, const Upoly& b) {
    Upoly c(a.size() + b.size() - 1, Rational(0));
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t k = 0; k < b.size(); ++k) c[i + k] += a[i] * b[k];
    return c;
  };
  // The Bernstein polynomials of degree p on the parameter interval [ua, ub], in s.
  auto bernstein_in_s = [&](const Rational& ua, const Rational& ub) {
    const Rational sa = Rational(2) * ua - Rational(1), sb = Rational(2) * ub - Rational(1), h = sb - sa;
    const Upoly sigma{Rational(-sa / h), Rational(Rational(1) / h)}, rest{Rational(sb / h), Rational(Rational(-1) / h)};
    std::vector<Upoly> B;
    for (int k = 0; k <= degree; ++k) {
      Upoly b{Rational(integer_binomials(degree)[static_cast<std::size_t>(k)])};
      for (int e = 0; e < k; ++e) b = umul(b, sigma);
      for (int e = k; e < degree; ++e) b = umul(b, rest);
      B.push_back(std::move(b));
    }
    return std::make_pair(std::array<Rational, 2>{sa, sb}, B);
  };
  // Face +z: per piece, its cone's four planes and its leaf.
  struct Piece {
    std::array<Poly3<T>, 4> planes;
    Poly3<T> leaf;
    int i = 0, j = 0;
  };
  std::vector<Piece> top;
  const int p2 = 2 * degree;
  for (const auto& pc : extract_bezier(P)) {
    const auto [srange, Bs] = bernstein_in_s(pc.box[0].first, pc.box[0].second);
    const auto [trange, Bt] = bernstein_in_s(pc.box[1].first, pc.box[1].second);
    std::vector<std::vector<Rational>> m(degree + 1, std::vector<Rational>(degree + 1, Rational(0)));  // P = sum m[a][b] s^a t^b
    for (int l = 0; l <= degree; ++l)
      for (int k = 0; k <= degree; ++k) {
        const Rational& b = pc.spline.points[static_cast<std::size_t>(k + (degree + 1) * l)];
        for (int a = 0; a <= degree; ++a)
          for (int c = 0; c <= degree; ++c) m[a][c] += b * Bs[k][a] * Bt[l][c];
      }
    Piece x;
    x.planes = {poly_linear(T(0), T(1), T(0), num(-srange[0])), poly_linear(T(0), T(-1), T(0), num(srange[1])),
                poly_linear(T(0), T(0), T(1), num(-trange[0])), poly_linear(T(0), T(0), T(-1), num(trange[1]))};
    // r z^(2p - 1) - sum m[a][b] x^a y^b z^(2p - a - b) >= 0.
    x.leaf.terms[{0, 0, p2 - 1}] = r;
    for (int a = 0; a <= degree; ++a)
      for (int c = 0; c <= degree; ++c)
        if (m[a][c] != Rational(0)) x.leaf.terms[{a, c, p2 - a - c}] = num(-m[a][c]);
    x.i = static_cast<int>(top.size()) % pieces;
    x.j = static_cast<int>(top.size()) / pieces;
    top.push_back(std::move(x));
  }
  // The faces by the rotations of sphere_cells: x'_a = sign_a x_perm_a, so g'(x') has the exponent
  // e[perm_a] at a and the sign prod sign_a^e[perm_a].
  const auto& perm = cube_face_perm;
  const auto& sign = cube_face_sign;
  const char* face_name[6] = {"+z", "-z", "+x", "-x", "+y", "-y"};
  auto rotate = [&](const Poly3<T>& g, int f) {
    Poly3<T> out;
    for (const auto& [e, c] : g.terms) {
      std::array<int, 3> e2{};
      bool negate = false;
      for (int a = 0; a < 3; ++a) {
        e2[a] = e[perm[f][a]];
        if (sign[f][a] < 0 && e2[a] % 2 == 1) negate = !negate;
      }
      out.terms[e2] = negate ? T(-c) : c;
    }
    return out;
  };
  std::vector<std::pair<Region<T>, Region<T>>> cases;
  for (int f = 0; f < 6; ++f)
    for (const auto& x : top) {
      const std::string where = std::string("sphere: face ") + face_name[f] + " piece (" + std::to_string(x.i) + ", " + std::to_string(x.j) + ")";
      std::vector<Region<T>> planes;
      for (const auto& h : x.planes) planes.push_back(region_leaf(rotate(h, f), where + " cone"));
      cases.emplace_back(region_and(std::move(planes)), region_leaf(rotate(x.leaf, f), where));
    }
  Region<T> piecewise = region_cases(std::move(cases));
  piecewise.label = "sphere: faces";
  const T c = r / T(2);
  Region<T> cube = box_region(std::vector<T>{-c, -c, -c}, std::vector<T>{c, c, c});
  cube.label = "sphere: cube";
  Region<T> out = region_or<T>({std::move(cube), std::move(piecewise)});
  out.label = "sphere";
  return out;
}

}  // namespace splinex
