// Trivariate constructors (vrep/model/trivariate.hpp): the templates, instantiated in vrep/instances.cpp.
#pragma once
#include <algorithm>
#include <string>

#include "base/errors.hpp"
#include "spline/basis.hpp"
#include "spline/bezier.hpp"
#include "spline/elevate.hpp"
#include "spline/insert.hpp"
#include "spline/integrate.hpp"
#include "spline/knots.hpp"
#include "vrep/model/trivariate.hpp"

namespace splinex {

namespace vrep_detail {

inline std::size_t at3(std::size_t i, std::size_t j, std::size_t k, std::size_t n0, std::size_t n1) { return i + n0 * (j + n1 * k); }

template <class T>
void require_surface(const BSpline<T>& S, const std::string& name) {
  validate(S);
  if (S.dim() != 2)
    throw ValidationError(name + ".degrees", "has " + std::to_string(S.dim()) + " parametric directions, a surface has 2",
                          "give a surface S(u, v)");
  if (S.q < 3)
    throw ValidationError(name + ".points", "has points with " + std::to_string(S.q) + " coordinates",
                          "give points in R^3 (attribute coordinates may follow)");
}

/// S with unit weights when it has none (to combine with rational surfaces).
template <class T>
BSpline<T> as_rational(BSpline<T> S) {
  if (!S.is_rational()) S.weights.assign(S.size(), T(1));
  return S;
}

/// The trivariate of degree 1 in w whose layers w = 0 and w = 1 are the surfaces A and B (same
/// degrees, knots and form: one function space), checked against the limits before it is built.
template <class T>
BSpline<T> two_layers(const BSpline<T>& A, const BSpline<T>& B, const Limits& limits) {
  limits.check_count(2 * A.size(), "trivariate");
  BSpline<T> R;
  R.degrees = {A.degrees[0], A.degrees[1], 1};
  R.knots = {A.knots[0], A.knots[1], {T(0), T(0), T(1), T(1)}};
  R.q = A.q;
  R.points = A.points;
  R.points.insert(R.points.end(), B.points.begin(), B.points.end());
  if (A.is_rational()) {
    R.weights = A.weights;
    R.weights.insert(R.weights.end(), B.weights.begin(), B.weights.end());
  }
  validate(R, limits);
  return R;
}

/// The Greville abscissae (U[i+1] + ... + U[i+p]) / p of n basis functions of degree p >= 1:
/// the coefficients of the identity, so a spline is linear in its parameter exactly when its
/// coefficients are an affine function of them.
template <class T>
std::vector<T> greville(const std::vector<T>& U, int p, std::size_t n) {
  std::vector<T> g(n);
  for (std::size_t i = 0; i < n; ++i) {
    T s(0);
    for (int k = 1; k <= p; ++k) s += U[i + k];
    g[i] = s / T(p);
  }
  return g;
}

/// Greville abscissae of direction d mapped affinely to [0, 1] (the coefficients of the linear
/// function that is 0 at the domain's start and 1 at its end; degree >= 1).
template <class T>
std::vector<T> unit_greville(const BSpline<T>& S, int d) {
  const T lo = S.domain_lo(d), hi = S.domain_hi(d);
  auto g = greville(S.knots[d], S.degrees[d], S.count(d));
  for (auto& x : g) x = (x - lo) / (hi - lo);
  return g;
}

/// S in direction d raised to `degree` and refined to contain the knots of `target` (a knot
/// vector of that degree on the same domain).
template <class T>
BSpline<T> to_space(BSpline<T> S, int d, int degree, const std::vector<T>& target, const Limits& limits) {
  if (S.degrees[d] < degree) S = elevate_degree(S, d, degree - S.degrees[d], ElevationMethod::automatic, limits);
  std::vector<T> X;
  for (std::size_t i = 0; i < target.size();) {
    std::size_t j = i;
    while (j < target.size() && target[j] == target[i]) ++j;
    const std::size_t have = multiplicity(S.knots[d], target[i]);
    for (std::size_t c = have; c < j - i; ++c) X.push_back(target[i]);
    i = j;
  }
  if (!X.empty()) S = refine_knots(S, d, X, limits);
  return S;
}

/// The union (maximum multiplicities) of knot vectors of one degree.
template <class T>
std::vector<T> knot_union(const std::vector<std::vector<T>>& Us) {
  std::vector<T> out;
  for (const auto& U : Us) {
    std::vector<T> merged;
    std::size_t a = 0, b = 0;
    while (a < out.size() || b < U.size()) {
      if (b == U.size() || (a < out.size() && out[a] < U[b])) merged.push_back(out[a++]);
      else if (a == out.size() || U[b] < out[a]) merged.push_back(U[b++]);
      else {
        merged.push_back(out[a++]);
        ++b;
      }
    }
    out = std::move(merged);
  }
  return out;
}

/// Solves A X = B (A square, rows of B are right-hand sides' entries) by Gaussian elimination with
/// partial pivoting on |a| (exact in exact arithmetic; B is overwritten by X).
template <class T>
void solve_in_place(std::vector<std::vector<T>> A, std::vector<std::vector<T>>& B) {
  const std::size_t n = A.size();
  auto mag = [](const T& x) { return x < T(0) ? T(-x) : x; };
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (mag(A[piv][c]) < mag(A[r][c])) piv = r;
    if (A[piv][c] == T(0))
      throw ValidationError("at", "the interpolation matrix is singular", "give increasing parameters w_k, at least degree + 1 surfaces");
    std::swap(A[c], A[piv]);
    std::swap(B[c], B[piv]);
    for (std::size_t r = c + 1; r < n; ++r) {
      if (A[r][c] == T(0)) continue;
      const T f = A[r][c] / A[c][c];
      for (std::size_t k = c; k < n; ++k) A[r][k] -= f * A[c][k];
      for (std::size_t k = 0; k < B[r].size(); ++k) B[r][k] -= f * B[c][k];
    }
  }
  for (std::size_t c = n; c-- > 0;) {
    for (std::size_t k = 0; k < B[c].size(); ++k) {
      T s = B[c][k];
      for (std::size_t j = c + 1; j < n; ++j) s -= A[c][j] * B[j][k];
      B[c][k] = s / A[c][c];
    }
  }
}

}  // namespace vrep_detail

template <class T>
BSpline<T> face(const BSpline<T>& V, int d, int side) {
  if (V.dim() != 3) throw ValidationError("degrees", "face() needs a trivariate", "give a spline with three directions");
  if (d < 0 || d > 2 || side < 0 || side > 1) throw UsageError("face", "direction 0..2, side 0 or 1", "give d in 0..2, side 0|1");
  if (!is_clamped(V.knots[d], V.degrees[d], V.count(d)))
    throw ValidationError("knots[" + std::to_string(d) + "]", "is not clamped, so its boundary is not a layer of the net",
                          "clamp the trivariate first");
  const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
  BSpline<T> F;
  F.degrees = {V.degrees[a], V.degrees[b]};
  F.knots = {V.knots[a], V.knots[b]};
  F.q = V.q;
  const std::size_t n[3] = {V.count(0), V.count(1), V.count(2)};
  const std::size_t layer = side == 0 ? 0 : n[d] - 1;
  for (std::size_t y = 0; y < n[b]; ++y)
    for (std::size_t x = 0; x < n[a]; ++x) {
      std::size_t idx[3];
      idx[d] = layer;
      idx[a] = x;
      idx[b] = y;
      const std::size_t k = vrep_detail::at3(idx[0], idx[1], idx[2], n[0], n[1]);
      for (int c = 0; c < V.q; ++c) F.points.push_back(V.points[k * V.q + c]);
      if (V.is_rational()) F.weights.push_back(V.weights[k]);
    }
  return F;
}

template <class T>
BSpline<T> extrude(const BSpline<T>& S, const std::vector<T>& V, const Limits& limits) {
  vrep_detail::require_surface(S, "surface");
  if (V.size() != static_cast<std::size_t>(S.q))
    throw ValidationError("vector", "has " + std::to_string(V.size()) + " coordinates, the surface's points " + std::to_string(S.q),
                          "give the extrusion vector with one entry per point coordinate (0 for attributes)");
  BSpline<T> top = S;
  for (std::size_t i = 0; i < S.size(); ++i)
    for (int c = 0; c < S.q; ++c) top.points[i * S.q + c] += V[c];
  return vrep_detail::two_layers(S, top, limits);
}

template <class T>
BSpline<T> ruled(const BSpline<T>& S1, const BSpline<T>& S2, const Limits& limits) {
  vrep_detail::require_surface(S1, "first");
  vrep_detail::require_surface(S2, "second");
  if (S1.q != S2.q)
    throw ValidationError("second.points", "has points with " + std::to_string(S2.q) + " coordinates, the first surface " +
                                               std::to_string(S1.q),
                          "give two surfaces with the same point size");
  const bool rational = S1.is_rational() || S2.is_rational();
  auto [A, B] = make_compatible(rational ? vrep_detail::as_rational(S1) : S1, rational ? vrep_detail::as_rational(S2) : S2, limits);
  return vrep_detail::two_layers(A, B, limits);
}

template <class T>
BSpline<T> rational_circle(int quarters) {
  if (quarters < 1 || quarters > 4) throw ValidationError("quarters", "must be 1..4", "give the angle in quarter turns");
  BSpline<T> C;
  C.degrees = {2};
  C.q = 2;
  std::vector<T> U(3, T(0));
  for (int a = 1; a < quarters; ++a) U.insert(U.end(), 2, T(a) / T(quarters));
  U.insert(U.end(), 3, T(1));
  C.knots = {U};
  const int ex[4] = {1, 0, -1, 0}, ey[4] = {0, 1, 0, -1};
  for (int a = 0; a <= quarters; ++a) {
    C.points.push_back(T(ex[a % 4]));
    C.points.push_back(T(ey[a % 4]));
    C.weights.push_back(a % 2 == 0 ? T(1) : T(2));
    if (a == quarters) break;
    C.points.push_back(T(ex[a % 4] + ex[(a + 1) % 4]));  // the corner e_a + e_{a+1}
    C.points.push_back(T(ey[a % 4] + ey[(a + 1) % 4]));
    C.weights.push_back(T(1));
  }
  return C;
}

template <class T>
BSpline<T> revolve(const BSpline<T>& S, int axis, int quarters, const Limits& limits) {
  vrep_detail::require_surface(S, "surface");
  if (axis < 0 || axis > 2) throw ValidationError("axis", "must be 0, 1 or 2 (x, y, z)", "give a coordinate axis");
  const BSpline<T> C = rational_circle<T>(quarters);
  limits.check_count(S.size() * C.size(), "trivariate");
  // The plane rotated: (a, b) -> (a cx - b cy, a cy + b cx); about z: (x, y); about x: (y, z); about y: (z, x).
  const int ia = (axis + 1) % 3, ib = (axis + 2) % 3;
  BSpline<T> R;
  R.degrees = {S.degrees[0], S.degrees[1], 2};
  R.knots = {S.knots[0], S.knots[1], C.knots[0]};
  R.q = S.q;
  const std::size_t n = S.size(), m = C.size();
  R.points.reserve(n * m * static_cast<std::size_t>(S.q));
  R.weights.reserve(n * m);
  for (std::size_t l = 0; l < m; ++l) {
    const T cx = C.points[2 * l], cy = C.points[2 * l + 1];
    for (std::size_t i = 0; i < n; ++i) {
      const T* P = &S.points[i * S.q];
      for (int c = 0; c < S.q; ++c) {
        if (c == ia) R.points.push_back(P[ia] * cx - P[ib] * cy);
        else if (c == ib) R.points.push_back(P[ia] * cy + P[ib] * cx);
        else R.points.push_back(P[c]);
      }
      R.weights.push_back((S.is_rational() ? S.weights[i] : T(1)) * C.weights[l]);
    }
  }
  validate(R, limits);
  return R;
}

template <class T>
BSpline<T> boolean_sum(const std::array<std::array<BSpline<T>, 2>, 3>& faces, const Limits& limits) {
  using vrep_detail::at3;
  std::array<std::array<BSpline<T>, 2>, 3> F = faces;
  const char* names[3][2] = {{"u0", "u1"}, {"v0", "v1"}, {"w0", "w1"}};
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) {
      vrep_detail::require_surface(F[d][s], names[d][s]);
      if (F[d][s].is_rational())
        throw ValidationError(std::string(names[d][s]) + ".weights", "is rational; the Boolean sum blends control points linearly",
                              "give polynomial faces (or build the volume as a ruled or swept one)");
      if (F[d][s].q != F[0][0].q)
        throw ValidationError(std::string(names[d][s]) + ".points", "has another point size than u0", "give faces in the same space");
      F[d][s] = clamp_all(F[d][s], limits);
    }
  // The faces that carry each direction D, with the local direction: u in v*, w* (first); v in
  // u* (first), w* (second); w in u*, v* (second).
  struct Use {
    int d, s, local;
  };
  const std::vector<Use> carriers[3] = {{{1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}},
                                        {{0, 0, 0}, {0, 1, 0}, {2, 0, 1}, {2, 1, 1}},
                                        {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}}};
  const char* dir_name[3] = {"u", "v", "w"};
  for (int D = 0; D < 3; ++D) {
    const auto& first = F[carriers[D][0].d][carriers[D][0].s];
    const T lo = first.domain_lo(carriers[D][0].local), hi = first.domain_hi(carriers[D][0].local);
    int degree = 1;  // linear precision needs degree >= 1
    for (const Use& c : carriers[D]) {
      const auto& S = F[c.d][c.s];
      if (!(S.domain_lo(c.local) == lo) || !(S.domain_hi(c.local) == hi))
        throw ValidationError(std::string(names[c.d][c.s]) + ".knots", std::string("has another ") + dir_name[D] + " domain than " +
                                                                           names[carriers[D][0].d][carriers[D][0].s],
                              "give faces whose shared directions have the same parameter interval");
      degree = std::max(degree, S.degrees[c.local]);
    }
    for (const Use& c : carriers[D]) {
      auto& S = F[c.d][c.s];
      if (S.degrees[c.local] < degree) S = elevate_degree(S, c.local, degree - S.degrees[c.local], ElevationMethod::automatic, limits);
    }
    std::vector<std::vector<T>> Us;
    for (const Use& c : carriers[D]) Us.push_back(F[c.d][c.s].knots[c.local]);
    const auto U = vrep_detail::knot_union(Us);
    for (const Use& c : carriers[D]) F[c.d][c.s] = vrep_detail::to_space(F[c.d][c.s], c.local, degree, U, limits);
  }
  const int q = F[0][0].q;
  const std::size_t nu = F[2][0].count(0), nv = F[2][0].count(1), nw = F[0][0].count(1);
  limits.check_count(nu * nv * nw, "trivariate");
  // Control point accessors of the faces: F0(a)(j, k), F1(b)(i, k), F2(c)(i, j).
  auto f0 = [&](int a, std::size_t j, std::size_t k) { return &F[0][a].points[(j + nv * k) * q]; };
  auto f1 = [&](int b, std::size_t i, std::size_t k) { return &F[1][b].points[(i + nu * k) * q]; };
  auto f2 = [&](int c, std::size_t i, std::size_t j) { return &F[2][c].points[(i + nu * j) * q]; };
  auto same = [&](const T* x, const T* y) {
    for (int c = 0; c < q; ++c)
      if (!(x[c] == y[c])) return false;
    return true;
  };
  // The twelve edges must agree (each edge is a curve of two faces).
  const std::size_t ends_u[2] = {0, nu - 1}, ends_v[2] = {0, nv - 1}, ends_w[2] = {0, nw - 1};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      for (std::size_t i = 0; i < nu; ++i)  // parallel to u at v = a, w = b
        if (!same(f1(a, i, ends_w[b]), f2(b, i, ends_v[a])))
          throw ValidationError(std::string(names[1][a]) + "," + names[2][b], "the two faces do not share their common edge (parallel to u)",
                                "give faces that meet exactly along their edges");
      for (std::size_t j = 0; j < nv; ++j)  // parallel to v at u = a, w = b
        if (!same(f0(a, j, ends_w[b]), f2(b, ends_u[a], j)))
          throw ValidationError(std::string(names[0][a]) + "," + names[2][b], "the two faces do not share their common edge (parallel to v)",
                                "give faces that meet exactly along their edges");
      for (std::size_t k = 0; k < nw; ++k)  // parallel to w at u = a, v = b
        if (!same(f0(a, ends_v[b], k), f1(b, ends_u[a], k)))
          throw ValidationError(std::string(names[0][a]) + "," + names[1][b], "the two faces do not share their common edge (parallel to w)",
                                "give faces that meet exactly along their edges");
    }
  const auto s = vrep_detail::unit_greville(F[2][0], 0), t = vrep_detail::unit_greville(F[2][0], 1),
             r = vrep_detail::unit_greville(F[0][0], 1);
  BSpline<T> R;
  R.degrees = {F[2][0].degrees[0], F[2][0].degrees[1], F[0][0].degrees[1]};
  R.knots = {F[2][0].knots[0], F[2][0].knots[1], F[0][0].knots[1]};
  R.q = q;
  R.points.assign(nu * nv * nw * q, T(0));
  for (std::size_t k = 0; k < nw; ++k)
    for (std::size_t j = 0; j < nv; ++j)
      for (std::size_t i = 0; i < nu; ++i) {
        const T ls[2] = {T(1) - s[i], s[i]}, lt[2] = {T(1) - t[j], t[j]}, lr[2] = {T(1) - r[k], r[k]};
        T* out = &R.points[at3(i, j, k, nu, nv) * q];
        for (int c = 0; c < q; ++c) {
          T v(0);
          for (int a = 0; a < 2; ++a) {
            v += ls[a] * f0(a, j, k)[c] + lt[a] * f1(a, i, k)[c] + lr[a] * f2(a, i, j)[c];
            for (int b = 0; b < 2; ++b) {
              v -= ls[a] * lt[b] * f0(a, ends_v[b], k)[c];  // edges parallel to w
              v -= lt[a] * lr[b] * f1(a, i, ends_w[b])[c];  // edges parallel to u
              v -= ls[a] * lr[b] * f0(a, j, ends_w[b])[c];  // edges parallel to v
              for (int e = 0; e < 2; ++e) v += ls[a] * lt[b] * lr[e] * f0(a, ends_v[b], ends_w[e])[c];  // corners
            }
          }
          out[c] = v;
        }
      }
  validate(R, limits);
  return R;
}

template <class T>
BSpline<T> coons_surface(const std::array<std::array<BSpline<T>, 2>, 2>& curves, const Limits& limits) {
  std::array<std::array<BSpline<T>, 2>, 2> C = curves;
  const char* names[2][2] = {{"u0", "u1"}, {"v0", "v1"}};
  for (int d = 0; d < 2; ++d)
    for (int s = 0; s < 2; ++s) {
      const std::string name = names[d][s];
      validate(C[d][s], limits);
      if (C[d][s].dim() != 1)
        throw ValidationError(name + ".degrees", "has " + std::to_string(C[d][s].dim()) + " parametric directions, a boundary curve has 1",
                              "give a curve C(t)");
      if (C[d][s].is_rational())
        throw ValidationError(name + ".weights", "is rational; the Coons surface blends control points linearly", "give polynomial curves");
      if (C[d][s].q != C[0][0].q) throw ValidationError(name + ".points", "has another point size than u0", "give curves in the same space");
      C[d][s] = clamp_all(C[d][s], limits);
    }
  // The corners, on the clamped curves before any elevation (in floating point an elevation need not
  // keep an end point to the last bit): the curve at u = a ends where the curve at v = b starts or
  // ends.
  const int q = C[0][0].q;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const T* x = &C[0][a].points[(b == 0 ? 0 : C[0][a].count(0) - 1) * q];
      const T* y = &C[1][b].points[(a == 0 ? 0 : C[1][b].count(0) - 1) * q];
      for (int c = 0; c < q; ++c)
        if (!(x[c] == y[c]))
          throw ValidationError(std::string(names[0][a]) + "," + names[1][b], "the two curves do not meet at their common corner",
                                "give curves whose ends meet exactly");
    }
  // Direction v is carried by the curves at u = 0, 1; direction u by those at v = 0, 1.
  for (int d = 0; d < 2; ++d) {
    auto& A = C[d][0];
    auto& B = C[d][1];
    if (!(A.domain_lo(0) == B.domain_lo(0)) || !(A.domain_hi(0) == B.domain_hi(0)))
      throw ValidationError(std::string(names[d][1]) + ".knots", std::string("has another parameter interval than ") + names[d][0],
                            "give opposite curves on the same interval");
    const int degree = std::max({1, A.degrees[0], B.degrees[0]});  // linear precision needs degree >= 1
    A = vrep_detail::to_space(A, 0, degree, {}, limits);
    B = vrep_detail::to_space(B, 0, degree, {}, limits);
    const auto U = vrep_detail::knot_union(std::vector<std::vector<T>>{A.knots[0], B.knots[0]});
    A = vrep_detail::to_space(A, 0, degree, U, limits);
    B = vrep_detail::to_space(B, 0, degree, U, limits);
  }
  const std::size_t nu = C[1][0].count(0), nv = C[0][0].count(0);
  limits.check_count(checked_product(nu, nv, limits, "surface"), "surface");
  auto cu = [&](int a, std::size_t j) { return &C[0][a].points[j * q]; };  // at u = a, point j along v
  auto cv = [&](int b, std::size_t i) { return &C[1][b].points[i * q]; };  // at v = b, point i along u
  const std::size_t ends_v[2] = {0, nv - 1};
  const auto s = vrep_detail::unit_greville(C[1][0], 0), t = vrep_detail::unit_greville(C[0][0], 0);
  BSpline<T> R;
  R.degrees = {C[1][0].degrees[0], C[0][0].degrees[0]};
  R.knots = {C[1][0].knots[0], C[0][0].knots[0]};
  R.q = q;
  R.points.assign(nu * nv * q, T(0));
  for (std::size_t j = 0; j < nv; ++j)
    for (std::size_t i = 0; i < nu; ++i) {
      const T ls[2] = {T(1) - s[i], s[i]}, lt[2] = {T(1) - t[j], t[j]};
      for (int c = 0; c < q; ++c) {
        T v(0);
        for (int a = 0; a < 2; ++a) {
          v += ls[a] * cu(a, j)[c] + lt[a] * cv(a, i)[c];
          for (int b = 0; b < 2; ++b) v -= ls[a] * lt[b] * cu(a, ends_v[b])[c];
        }
        R.points[(i + nu * j) * q + c] = v;
      }
    }
  // The boundary rows and columns are the curves themselves (the blend gives them back exactly in
  // exact arithmetic; copied, they are the curves' own values in floating point too, so that
  // boolean_sum's exact edge comparison meets them).
  for (int b = 0; b < 2; ++b)
    for (std::size_t i = 0; i < nu; ++i)
      for (int c = 0; c < q; ++c) R.points[(i + nu * ends_v[b]) * q + c] = cv(b, i)[c];
  for (int a = 0; a < 2; ++a)
    for (std::size_t j = 0; j < nv; ++j)
      for (int c = 0; c < q; ++c) R.points[((a == 0 ? 0 : nu - 1) + nu * j) * q + c] = cu(a, j)[c];
  validate(R, limits);
  return R;
}

namespace vrep_detail {

/// The boundary curve of a clamped surface at v = side (a curve in u): a row of the net.
template <class T>
BSpline<T> row_curve(const BSpline<T>& S, int side) {
  BSpline<T> C;
  C.degrees = {S.degrees[0]};
  C.knots = {S.knots[0]};
  C.q = S.q;
  const std::size_t n0 = S.count(0), j = side == 0 ? 0 : S.count(1) - 1, q = static_cast<std::size_t>(S.q);
  C.points.assign(S.points.begin() + static_cast<std::ptrdiff_t>(j * n0 * q), S.points.begin() + static_cast<std::ptrdiff_t>((j + 1) * n0 * q));
  return C;
}

}  // namespace vrep_detail

template <class T>
BSpline<T> tube_boolean_sum(const BSpline<T>& surface, const Limits& limits) {
  vrep_detail::require_surface(surface, "surface");
  if (surface.is_rational())
    throw ValidationError("surface.weights", "is rational; the Boolean sum blends control points linearly", "give a polynomial tube");
  const BSpline<T> S = clamp_all(surface, limits);
  const std::size_t n0 = S.count(0), q = static_cast<std::size_t>(S.q);
  for (std::size_t j = 0; j < S.count(1); ++j)
    for (std::size_t c = 0; c < q; ++c)
      if (!(S.points[j * n0 * q + c] == S.points[(j * n0 + n0 - 1) * q + c]))
        throw ValidationError("surface", "is not closed around: its curves u = lo and u = hi differ",
                              "give a tube whose first and last columns of control points are equal");
  const T lo = S.domain_lo(0), hi = S.domain_hi(0);
  // The four strips u in [lo + k (hi - lo)/4, lo + (k+1) (hi - lo)/4], on [0, 1] x [0, 1].
  std::array<BSpline<T>, 4> strip;
  BSpline<T> rest = S;
  for (int k = 0; k < 4; ++k) {
    BSpline<T> part = rest;
    if (k < 3) std::tie(part, rest) = split_at(rest, 0, lo + (hi - lo) * T(k + 1) / T(4), limits);
    part = reparametrize(part, 0, T(0), T(1));
    strip[k] = reparametrize(part, 1, T(0), T(1));
  }
  std::array<std::array<BSpline<T>, 2>, 3> F;
  F[1][0] = strip[0];              // v = 0: u runs along the first strip
  F[0][1] = strip[1];              // u = 1: v along the second
  F[1][1] = reverse(strip[2], 0);  // v = 1: the third strip, backwards
  F[0][0] = reverse(strip[3], 0);  // u = 0: the fourth, backwards
  for (int w = 0; w < 2; ++w)
    F[2][w] = coons_surface<T>({{{vrep_detail::row_curve(F[0][0], w), vrep_detail::row_curve(F[0][1], w)},
                                 {vrep_detail::row_curve(F[1][0], w), vrep_detail::row_curve(F[1][1], w)}}},
                               limits);
  return boolean_sum(F, limits);
}

template <class T>
BSpline<T> sweep(const std::vector<BSpline<T>>& surfaces, const std::vector<T>& at, int degree, const Limits& limits) {
  const std::size_t m1 = surfaces.size();
  if (m1 < 2) throw ValidationError("surfaces", "a sweep needs at least two surfaces", "give surfaces S_0, ..., S_m");
  if (at.size() != m1)
    throw ValidationError("at", "has " + std::to_string(at.size()) + " parameters for " + std::to_string(m1) + " surfaces",
                          "give one parameter w_k per surface");
  for (std::size_t k = 0; k + 1 < m1; ++k)
    if (!(at[k] < at[k + 1]))
      throw ValidationError("at[" + std::to_string(k + 1) + "]", "is not greater than the parameter before it",
                            "give strictly increasing parameters w_k");
  if (degree < 1) throw ValidationError("degree", "must be at least 1", "give the degree in w (3 by default)");
  const int d = std::min<int>(degree, static_cast<int>(m1) - 1);
  bool rational = false;
  for (std::size_t k = 0; k < m1; ++k) {
    vrep_detail::require_surface(surfaces[k], "surfaces[" + std::to_string(k) + "]");
    if (surfaces[k].q != surfaces[0].q)
      throw ValidationError("surfaces[" + std::to_string(k) + "].points", "has another point size than surfaces[0]",
                            "give surfaces in the same space");
    rational = rational || surfaces[k].is_rational();
  }
  // A common space: fold make_compatible, then bring each surface to the final space.
  std::vector<BSpline<T>> S(surfaces);
  if (rational)
    for (auto& s : S) s = vrep_detail::as_rational(s);
  BSpline<T> common = S[0];
  for (std::size_t k = 1; k < m1; ++k) common = make_compatible(common, S[k], limits).first;
  for (auto& s : S) s = make_compatible(common, s, limits).second;
  limits.check_count(S[0].size() * m1, "trivariate");
  // Knots by averaging (NURBS Book eq. 9.8).
  const std::size_t m = m1 - 1;
  std::vector<T> W(static_cast<std::size_t>(d) + 1, at.front());
  for (std::size_t j = 1; j + d <= m; ++j) {
    T sum(0);
    for (std::size_t i = j; i < j + static_cast<std::size_t>(d); ++i) sum += at[i];
    W.push_back(sum / T(d));
  }
  W.insert(W.end(), static_cast<std::size_t>(d) + 1, at.back());
  std::vector<std::vector<T>> A(m1, std::vector<T>(m1, T(0)));
  for (std::size_t k = 0; k < m1; ++k) {
    const std::size_t span = find_span(W, d, m1, at[k]);
    const auto N = basis_funs(span, at[k], d, W);
    for (int l = 0; l <= d; ++l) A[k][span - d + l] = N[l];
  }
  // Right-hand sides: the homogeneous coordinates of every control point of every surface.
  const int q = S[0].q, hq = rational ? q + 1 : q;
  const std::size_t n = S[0].size();
  std::vector<std::vector<T>> B(m1, std::vector<T>(n * hq));
  for (std::size_t k = 0; k < m1; ++k)
    for (std::size_t i = 0; i < n; ++i) {
      const T w = rational ? S[k].weights[i] : T(1);
      for (int c = 0; c < q; ++c) B[k][i * hq + c] = w * S[k].points[i * q + c];
      if (rational) B[k][i * hq + q] = w;
    }
  vrep_detail::solve_in_place(A, B);
  BSpline<T> R;
  R.degrees = {S[0].degrees[0], S[0].degrees[1], d};
  R.knots = {S[0].knots[0], S[0].knots[1], W};
  R.q = q;
  for (std::size_t l = 0; l < m1; ++l)
    for (std::size_t i = 0; i < n; ++i) {
      const T w = rational ? B[l][i * hq + q] : T(1);
      if (rational && !(T(0) < w))
        throw ValidationError("surfaces.weights", "the interpolated weight of control point " + std::to_string(i) + " in layer " +
                                                      std::to_string(l) + " is not positive",
                              "give surfaces with closer weights, or more of them");
      for (int c = 0; c < q; ++c) R.points.push_back(B[l][i * hq + c] / w);
      if (rational) R.weights.push_back(w);
    }
  validate(R, limits);
  return R;
}

}  // namespace splinex
