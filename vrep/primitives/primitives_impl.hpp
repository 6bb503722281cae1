// Primitives (vrep/primitives/primitives.hpp): the templates, instantiated in vrep/instances.cpp.
#pragma once
#include "base/errors.hpp"
#include "exact/rational.hpp"
#include "spline/basis.hpp"
#include "spline/elevate.hpp"
#include "spline/knots.hpp"
#include "vrep/model/trivariate_impl.hpp"  // vrep_detail::solve_in_place
#include "vrep/primitives/primitives.hpp"

namespace splinex {

namespace vrep_detail {

template <class T>
void require_positive(const T& x, const std::string& field) {
  if (!(T(0) < x)) throw ValidationError(field, "must be positive", "give a positive size");
}

/// c_k = r (4/5, 3/5) rotated by k x 90 degrees.
template <class T>
std::array<T, 2> circle_point(const T& r, int k) {
  const T a = T(4) / T(5), b = T(3) / T(5);
  const T x[4] = {a, -b, -a, b}, y[4] = {b, a, -b, -a};
  return {r * x[k % 4], r * y[k % 4]};
}

/// floor(sqrt(x) 2^64) / 2^64 for a rational x >= 0: exact integer square root, no float.
inline Rational sqrt_down_2_64(const Rational& x) {
  Integer n = boost::multiprecision::numerator(x);
  n <<= 128;
  n /= boost::multiprecision::denominator(x);
  const Integer s = boost::multiprecision::sqrt(n);
  return Rational(s) / Rational(Integer(1) << 64);
}

/// The weight function of the cube-sphere patch (primitives.hpp): the uniform clamped knots of
/// `degree` with `pieces` spans on [0, 1], the Greville points mapped to s in [-1, 1], and the
/// coefficients P[i][j] of the tensor spline interpolating sqrt(1 + s^2 + t^2) (rounded down to
/// 2^-64) at the Greville points, solved exactly. Symmetric and even by construction: the data
/// and the collocation matrix are, and the solution of the exact system is unique.
struct CubeSphereWeights {
  std::vector<Rational> knots, s;
  std::vector<std::vector<Rational>> P;
};

inline CubeSphereWeights cube_sphere_weights(int degree, int pieces) {
  if (degree < 2 || degree > 9)
    throw ValidationError("degree", "the sphere patches' degree must be 2..9", "give --degree between 2 and 9");
  if (pieces < 1 || pieces > 32)
    throw ValidationError("pieces", "the sphere patches' pieces per direction must be 1..32", "give --pieces between 1 and 32");
  CubeSphereWeights W;
  W.knots.assign(static_cast<std::size_t>(degree) + 1, Rational(0));
  for (int k = 1; k < pieces; ++k) W.knots.push_back(Rational(k) / Rational(pieces));
  W.knots.insert(W.knots.end(), static_cast<std::size_t>(degree) + 1, Rational(1));
  const std::size_t n = W.knots.size() - degree - 1;
  const std::vector<Rational> xi = greville(W.knots, degree, n);
  for (const auto& x : xi) W.s.push_back(Rational(2) * x - Rational(1));
  std::vector<std::vector<Rational>> A(n, std::vector<Rational>(n, Rational(0)));
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t span = find_span(W.knots, degree, n, xi[k]);
    const auto N = basis_funs(span, xi[k], degree, W.knots);
    for (int l = 0; l <= degree; ++l) A[k][span - degree + l] = N[l];
  }
  // Rows first (direction s), then columns (direction t).
  std::vector<std::vector<Rational>> B(n, std::vector<Rational>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) B[i][j] = sqrt_down_2_64(Rational(1) + W.s[i] * W.s[i] + W.s[j] * W.s[j]);
  solve_in_place(A, B);
  std::vector<std::vector<Rational>> C(n, std::vector<Rational>(n));
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) C[j][i] = B[i][j];
  solve_in_place(A, C);  // C[j][i] = P[i][j]
  W.P.assign(n, std::vector<Rational>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      W.P[i][j] = C[j][i];
      // 0 < P < 2 on the whole patch (convex hull): the weights are positive and the ruled cells
      // from the cube of half side 1/2 are regular (sphere_cells).
      if (!(Rational(0) < W.P[i][j]) || !(W.P[i][j] < Rational(2)))
        throw ValidationError("pieces", "a weight of the sphere patch is outside (0, 2)", "give more pieces or another degree");
    }
  return W;
}

/// The rotations of the cube taking face +z to the faces +z, -z, +x, -x, +y, -y (det +1): the
/// signed permutations x'_a = sign_a x_{perm_a}, shared by the sphere's cells and its region.
/// +z (s, t, 1), -z (s, -t, -1), +x (1, s, t), -x (-1, -s, t), +y (t, 1, s), -y (-t, -1, s).
inline constexpr std::array<std::array<int, 3>, 6> cube_face_perm{{{0, 1, 2}, {0, 1, 2}, {2, 0, 1}, {2, 0, 1}, {1, 2, 0}, {1, 2, 0}}};
inline constexpr std::array<std::array<int, 3>, 6> cube_face_sign{{{1, 1, 1}, {1, -1, -1}, {1, 1, 1}, {-1, -1, 1}, {1, 1, 1}, {-1, -1, 1}}};

/// The points' first three coordinates mapped by the signed permutation x'_a = sign_a x_{perm_a}.
template <class T>
BSpline<T> rotated(BSpline<T> V, const std::array<int, 3>& perm, const std::array<int, 3>& sign) {
  for (std::size_t i = 0; i < V.size(); ++i) {
    T* x = &V.points[i * V.q];
    const T old[3] = {x[0], x[1], x[2]};
    for (int a = 0; a < 3; ++a) x[a] = sign[a] < 0 ? T(-old[perm[a]]) : old[perm[a]];
  }
  return V;
}

}  // namespace vrep_detail

template <class T>
std::vector<BSpline<T>> disk_cells(const T& r) {
  vrep_detail::require_positive(r, "radius");
  const T s = T(1) / T(2);
  std::array<std::array<T, 2>, 4> c, sq;
  for (int k = 0; k < 4; ++k) {
    c[k] = vrep_detail::circle_point(r, k);
    sq[k] = {s * c[k][0], s * c[k][1]};
  }
  std::vector<BSpline<T>> out;
  // The square: (0,0) = sq2, (1,0) = sq3, (0,1) = sq1, (1,1) = sq0 (positively oriented).
  BSpline<T> Q;
  Q.degrees = {1, 1};
  Q.knots = {{T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
  Q.q = 3;
  for (int k : {2, 3, 1, 0}) Q.points.insert(Q.points.end(), {sq[k][0], sq[k][1], T(0)});
  out.push_back(Q);
  // Sector k: u from c_k to c_{k+1}; v = 0 the arc, v = 1 the square's side (u along it).
  for (int k = 0; k < 4; ++k) {
    const auto& a = c[k];
    const auto& b = c[(k + 1) % 4];
    const auto& sa = sq[k];
    const auto& sb = sq[(k + 1) % 4];
    BSpline<T> S;
    S.degrees = {2, 1};
    S.knots = {{T(0), T(0), T(0), T(1), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
    S.q = 3;
    S.points = {a[0], a[1], T(0), a[0] + b[0], a[1] + b[1], T(0), b[0], b[1], T(0),
                sa[0], sa[1], T(0), (sa[0] + sb[0]) / T(2), (sa[1] + sb[1]) / T(2), T(0), sb[0], sb[1], T(0)};
    // Arc weights (1, 1, 2) and (2, 1, 1) alternately, so that the spoke shared by sectors k and
    // k + 1 has the same weights (2 at the circle, 1 at the square, or 1 and 1) in both.
    if (k % 2 == 0) S.weights = {T(1), T(1), T(2), T(1), T(1), T(1)};
    else S.weights = {T(2), T(1), T(1), T(1), T(1), T(1)};
    out.push_back(S);
  }
  return out;
}

template <class T>
std::vector<BSpline<T>> cylinder_cells(const T& r, const T& h) {
  vrep_detail::require_positive(h, "height");
  std::vector<BSpline<T>> out;
  for (const auto& D : disk_cells(r)) out.push_back(extrude(D, std::vector<T>{T(0), T(0), h}));
  return out;
}

template <class T>
std::vector<BSpline<T>> cone_cells(const T& r0, const T& r1, const T& h) {
  vrep_detail::require_positive(h, "height");
  const auto bottom = disk_cells(r0), top = disk_cells(r1);
  std::vector<BSpline<T>> out;
  for (std::size_t k = 0; k < bottom.size(); ++k) {
    BSpline<T> t = top[k];
    for (std::size_t i = 0; i < t.size(); ++i) t.points[i * 3 + 2] = h;
    out.push_back(ruled(bottom[k], t));
  }
  return out;
}

template <class T>
std::vector<BSpline<T>> torus_cells(const T& R, const T& r) {
  vrep_detail::require_positive(r, "minor radius");
  if (!(r < R)) throw ValidationError("major radius", "must exceed the minor radius", "give R > r (the tube may not touch the axis)");
  std::vector<BSpline<T>> out;
  for (auto D : disk_cells(r)) {
    // (x, y, 0) -> (R + x, 0, y): the disk in the xz-plane around (R, 0, 0).
    for (std::size_t i = 0; i < D.size(); ++i) {
      const T x = D.points[i * 3], y = D.points[i * 3 + 1];
      D.points[i * 3] = R + x;
      D.points[i * 3 + 1] = T(0);
      D.points[i * 3 + 2] = y;
    }
    out.push_back(revolve(D, 2, 4));
  }
  return out;
}

template <class T>
std::vector<BSpline<T>> box_cells(const std::vector<T>& lo, const std::vector<T>& hi) {
  if (lo.size() != 3 || hi.size() != 3) throw ValidationError("box", "needs three coordinates per corner", "give lo and hi in R^3");
  for (int d = 0; d < 3; ++d)
    if (!(lo[d] < hi[d])) throw ValidationError("box", "lo must be below hi in every coordinate", "give lo < hi");
  BSpline<T> B;
  B.degrees = {1, 1, 1};
  B.knots = {{T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
  B.q = 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) B.points.insert(B.points.end(), {i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]});
  return {B};
}

template <class T>
std::vector<BSpline<T>> sphere_cells(const T& r, int degree, int pieces) {
  vrep_detail::require_positive(r, "radius");
  const auto W = vrep_detail::cube_sphere_weights(degree, pieces);
  auto num = [](const Rational& x) { return ArithTraits<T>::from_rational(x); };
  const T c = r / T(2);
  std::vector<T> U, s;
  for (const auto& k : W.knots) U.push_back(num(k));
  for (const auto& x : W.s) s.push_back(num(x));
  const std::size_t n = s.size();
  // Patch +z and the cube's face z = c below it, in one function space (the linear functions s,
  // t, 1 have the coefficients s_i, s_j, 1 there: linear precision of the Greville points).
  BSpline<T> S, F;
  S.degrees = F.degrees = {degree, degree};
  S.knots = F.knots = {U, U};
  S.q = F.q = 3;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const T P = num(W.P[i][j]);
      S.points.insert(S.points.end(), {r * s[i] / P, r * s[j] / P, r / P});
      S.weights.push_back(P);
      F.points.insert(F.points.end(), {c * s[i], c * s[j], c});
    }
  // Homogeneous interpolation: every point of the cell is lambda (s, t, 1) with
  // lambda = ((1 - w) c + w r) / ((1 - w) + w P), increasing in w because c P < r (every coefficient of P is in (0, 2): checked).
  const BSpline<T> cell = ruled(F, S);
  std::vector<BSpline<T>> out = box_cells(std::vector<T>{-c, -c, -c}, std::vector<T>{c, c, c});
  // The six faces by rotations of the cube (det +1, so every cell keeps det J > 0):
  // +z (s, t, 1), -z (s, -t, -1), +x (1, s, t), -x (-1, -s, t), +y (t, 1, s), -y (-t, -1, s).
  for (int f = 0; f < 6; ++f) out.push_back(vrep_detail::rotated(cell, vrep_detail::cube_face_perm[f], vrep_detail::cube_face_sign[f]));
  return out;
}

template <class T>
BSpline<T> singular_cylinder(const T& r, const T& h) {
  vrep_detail::require_positive(r, "radius");
  vrep_detail::require_positive(h, "height");
  BSpline<T> rect;
  rect.degrees = {1, 1};
  rect.knots = {{T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
  rect.q = 3;
  rect.points = {T(0), T(0), T(0), r, T(0), T(0), T(0), T(0), h, r, T(0), h};
  return revolve(rect, 2, 4);
}

template <class T>
BSpline<T> singular_sphere(const T& r) {
  vrep_detail::require_positive(r, "radius");
  const BSpline<T> arc = rational_circle<T>(2);  // (1, 0) -> (0, 1) -> (-1, 0), mapped to (y, 0, -x): south to north pole
  BSpline<T> disk;
  disk.degrees = {2, 1};
  disk.knots = {arc.knots[0], {T(0), T(0), T(1), T(1)}};
  disk.q = 3;
  for (int side = 0; side < 2; ++side)
    for (std::size_t i = 0; i < arc.size(); ++i) {
      const T x = arc.points[2 * i], y = arc.points[2 * i + 1];
      disk.points.insert(disk.points.end(), {side ? r * y : T(0), T(0), -r * x});
      disk.weights.push_back(arc.weights[i]);
    }
  return revolve(disk, 2, 4);
}

}  // namespace splinex
