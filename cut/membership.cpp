#include "cut/membership.hpp"

#include <array>

#include "base/errors.hpp"

namespace splinex {
namespace cut_detail {

namespace {

// A quadratic irrational p + s sqrt(D), D >= 0 rational, and its exact sign.
struct QuadIrr {
  Rational p, s;
};
int sgn(const Rational& x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }
int sign_of(const QuadIrr& x, const Rational& D) {
  const int sp = sgn(x.p), ss = D == 0 ? 0 : sgn(x.s);
  if (ss == 0) return sp;
  if (sp == 0 || sp == ss) return ss;
  const Rational l = x.p * x.p, r = x.s * x.s * D;
  return l > r ? sp : l < r ? ss : 0;
}
QuadIrr mul(const QuadIrr& x, const QuadIrr& y, const Rational& D) { return {x.p * y.p + x.s * y.s * D, x.p * y.s + x.s * y.p}; }
QuadIrr lin(const Rational& k0, const Rational& k1, const QuadIrr& u) { return {k0 + k1 * u.p, k1 * u.s}; }  // k0 + k1 u

// The ray x + t r (t > 0) against a non-planar bilinear facet: adds its crossings to hits; 2 when x
// lies on the facet, -1 when the ray is degenerate for it (through its border, tangent, or along a
// ruling), else 0. With n1, n2 spanning the plane normal to r, the two equations (B - x) . n_k = 0
// are bilinear, A_k + B_k u + C_k v + D_k u v = 0; eliminating v leaves the quadratic
// (A1 + B1 u)(C2 + D2 u) - (A2 + B2 u)(C1 + D1 u) = 0, whose roots are exact quadratic irrationals.
int bilinear_crossings(const Bilinear& F, const P3& x, const P3& r, std::size_t& hits) {
  int ax = 0;
  for (int k = 1; k < 3; ++k)
    if (abs(r[k]) < abs(r[ax])) ax = k;
  P3 e{Rational(0), Rational(0), Rational(0)};
  e[ax] = 1;
  const P3 n1 = cross(r, e), n2 = cross(r, n1);
  const P3 ax0 = sub(F.a, x);
  const Rational A1 = dot(ax0, n1), B1 = dot(F.b, n1), C1 = dot(F.c, n1), D1 = dot(F.d, n1);
  const Rational A2 = dot(ax0, n2), B2 = dot(F.b, n2), C2 = dot(F.c, n2), D2 = dot(F.d, n2);
  const Rational al = B1 * D2 - B2 * D1, be = A1 * D2 + B1 * C2 - A2 * D1 - B2 * C1, ga = A1 * C2 - A2 * C1;
  std::vector<QuadIrr> roots;
  Rational D(0);
  if (al == 0) {
    if (be == 0) return ga == 0 ? -1 : 0;
    roots.push_back({-ga / be, Rational(0)});
  } else {
    D = be * be - 4 * al * ga;
    if (D < 0) return 0;
    const QuadIrr u0{-be / (2 * al), Rational(0)};
    if (D == 0) {  // tangent: degenerate when the touching point is on the facet
      const bool in = u0.p >= 0 && u0.p <= 1;
      return in ? -1 : 0;
    }
    roots.push_back({-be / (2 * al), 1 / (2 * al)});
    roots.push_back({-be / (2 * al), -1 / (2 * al)});
  }
  const Rational re = dot(F.a, r) - dot(x, r), rb = dot(F.b, r), rc = dot(F.c, r), rd = dot(F.d, r);
  for (const auto& u : roots) {
    const int su0 = sign_of(u, D), su1 = sign_of(lin(Rational(1), Rational(-1), u), D);
    if (su0 < 0 || su1 < 0) continue;
    // v = num / den from the first equation, else the second
    QuadIrr num = lin(-A1, -B1, u), den = lin(C1, D1, u);
    if (sign_of(den, D) == 0) {
      if (sign_of(num, D) != 0) continue;  // the first equation has no v: no crossing
      num = lin(-A2, -B2, u), den = lin(C2, D2, u);
      if (sign_of(den, D) == 0) return -1;  // a whole segment u = u* solves both
    }
    const int sd = sign_of(den, D);
    const int sv0 = sign_of(num, D) * sd;
    const int sv1 = sign_of(QuadIrr{den.p - num.p, den.s - num.s}, D) * sd;
    if (sv0 < 0 || sv1 < 0) continue;
    // t has the sign of (B(u, v) - x) . r; times den: (re + rb u) den + (rc + rd u) num
    const QuadIrr td1 = mul(lin(re, rb, u), den, D), td2 = mul(lin(rc, rd, u), num, D);
    const int st = sign_of(QuadIrr{td1.p + td2.p, td1.s + td2.s}, D) * sd;
    if (st == 0) return 2;
    if (st > 0) {
      if (su0 == 0 || su1 == 0 || sv0 == 0 || sv1 == 0) return -1;
      ++hits;
    }
  }
  return 0;
}

// Exact ray parity. 0: inside, 1: outside, 2: on the boundary, -1: degenerate ray.
int parity(const MembershipModel& model, const P3& x, const P3& r) {
  std::size_t hits = 0;
  for (const auto& B : model.bilinears) {
    const int c = bilinear_crossings(B, x, r, hits);
    if (c != 0) return c;
  }
  for (const auto& T : model.triangles) {
    const P3 e1 = sub(T.b, T.a), e2 = sub(T.c, T.a), s = sub(x, T.a);
    const P3 h = cross(r, e2);
    const Rational det = dot(e1, h);
    if (det == 0) {
      const P3 n = cross(e1, e2);
      if (dot(s, n) != 0) continue;  // parallel, off the plane
      // x in the triangle's plane: on the triangle (barycentric by areas) or a degenerate ray
      const Rational A = dot(n, n);
      const Rational beta = dot(cross(s, e2), n) / A, gamma = dot(cross(e1, s), n) / A;
      if (beta >= 0 && gamma >= 0 && beta + gamma <= 1) return 2;
      return -1;
    }
    const Rational beta = dot(s, h) / det;
    const P3 q = cross(s, e1);
    const Rational gamma = dot(r, q) / det, t = dot(e2, q) / det;
    const bool closed = beta >= 0 && gamma >= 0 && beta + gamma <= 1;
    if (t == 0 && closed) return 2;
    if (t > 0 && closed) {
      if (beta == 0 || gamma == 0 || beta + gamma == 1) return -1;
      ++hits;
    }
  }
  return hits % 2 ? 0 : 1;
}

}  // namespace

std::optional<MembershipModel> membership_model(const Solid3<Rational>& S, std::string& why) {
  MembershipModel M;
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const auto& F = S.facets[i];
    if (F.degrees != std::vector<int>{1, 1} || F.count(0) != 2 || F.count(1) != 2) {
      why = "facets[" + std::to_string(i) + "] is not a bilinear quadrilateral";
      return std::nullopt;
    }
    auto P = [&](std::size_t k) { return P3{F.points[3 * k], F.points[3 * k + 1], F.points[3 * k + 2]}; };
    const P3 a = P(0), b = P(1), d = P(2), c = P(3);  // P00, P10, P01, P11
    const P3 n = cross(sub(b, a), sub(d, a));
    if (dot(n, sub(c, a)) != 0) {
      // B = a + (b - a) u + (d - a) v + (c - b - d + a) u v
      M.bilinears.push_back({a, sub(b, a), sub(d, a), sub(sub(c, b), sub(d, a))});
      continue;
    }
    // convex: the corners a b c d turn the same way as n
    const std::array<P3, 4> q{a, b, c, d};
    for (int k = 0; k < 4; ++k)
      if (!(dot(cross(sub(q[(k + 1) % 4], q[k]), sub(q[(k + 2) % 4], q[(k + 1) % 4])), n) > 0)) {
        why = "facets[" + std::to_string(i) + "] is a planar quadrilateral that is not convex";
        return std::nullopt;
      }
    M.triangles.push_back({a, b, c});
    M.triangles.push_back({a, c, d});
  }
  return M;
}

std::optional<Membership> membership_of(const MembershipModel& tris, const P3& x) {
  static const std::array<P3, 6> rays{P3{Rational(1), Rational(17, 4099), Rational(29, 8191)},
                                      P3{Rational(-31, 7919), Rational(1), Rational(13, 6007)},
                                      P3{Rational(19, 5003), Rational(-23, 9001), Rational(1)},
                                      P3{Rational(-1), Rational(37, 7901), Rational(-41, 8839)},
                                      P3{Rational(43, 9973), Rational(-1), Rational(-47, 9967)},
                                      P3{Rational(-53, 9949), Rational(59, 9941), Rational(-1)}};
  for (const auto& r : rays) {
    const int p = parity(tris, x, r);
    if (p == 0) return Membership::inside;
    if (p == 1) return Membership::outside;
    if (p == 2) return Membership::boundary;
  }
  return std::nullopt;
}


}  // namespace cut_detail

std::optional<Membership> point_in_solid(const Solid3<Rational>& solid, const Point3<Rational>& x) {
  std::string why;
  const auto model = cut_detail::membership_model(solid, why);
  if (!model) return std::nullopt;
  return cut_detail::membership_of(*model, x);
}

}  // namespace splinex
