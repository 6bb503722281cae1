// Tensor-product B-splines of any parametric dimension k >= 1 (curves k=1, surfaces k=2,
// trivariates k=3), control points in R^q (q >= 1; coordinates past the geometry are
// attributes), polynomial or rational. Generic over the scalar T (see spline/arith.hpp).
//
// Storage: control point i = (i_0, ..., i_{k-1}) has flat index i_0 + n_0*(i_1 + n_1*(...)),
// direction 0 varying fastest (the JSON order); its q coordinates are contiguous.
// Rational splines store Cartesian points plus weights; operations work on the homogeneous form
// (w*P, w), NURBS Book ch. 4.
#pragma once
#include <array>
#include <cstddef>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/limits.hpp"
#include "spline/arith.hpp"
#include "spline/knots.hpp"

namespace splinex {

template <Arithmetic T>
struct BSpline {
  std::vector<int> degrees;           // one per direction
  std::vector<std::vector<T>> knots;  // one knot vector per direction
  int q = 0;                          // coordinates per control point
  std::vector<T> points;              // q * size() values
  std::vector<T> weights;             // empty: polynomial; else size() positive weights

  int dim() const { return static_cast<int>(degrees.size()); }
  std::size_t count(int d) const { return knots[d].size() - degrees[d] - 1; }
  std::size_t size() const {
    std::size_t s = 1;
    for (int d = 0; d < dim(); ++d) s *= count(d);
    return s;
  }
  bool is_rational() const { return !weights.empty(); }
  T domain_lo(int d) const { return knots[d][degrees[d]]; }
  T domain_hi(int d) const { return knots[d][count(d)]; }
};

/// A spline in homogeneous form (papers/000 Observation 1; The NURBS Book Section 4.2): `net` is a
/// polynomial spline. When `weighted`, its last coordinate is the weight w and the others are w*P
/// (q() = net.q - 1 Cartesian coordinates, the weight not required to be positive); otherwise `net`
/// is the polynomial spline itself. The type carries the convention, so a polynomial net with q+1
/// coordinates is never mistaken for a spline with q.
template <class T>
struct Homogeneous {
  BSpline<T> net;
  bool weighted = false;

  /// Cartesian coordinates per point.
  int q() const { return weighted ? net.q - 1 : net.q; }
};

/// The box of the control points' first three coordinates, {min x, min y, min z, max x, max y,
/// max z}: it holds the spline (the convex hull property; Euclidean points, positive weights).
template <class T>
std::array<T, 6> control_bounds(const BSpline<T>& S) {
  std::array<T, 6> b;
  for (int a = 0; a < 3; ++a) b[a] = b[a + 3] = S.points[a];
  for (std::size_t i = 0; i < S.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      const T& x = S.points[i * S.q + a];
      if (x < b[a]) b[a] = x;
      if (b[a + 3] < x) b[a + 3] = x;
    }
  return b;
}

/// The same representation: degrees, knot vectors, homogeneous flag and every stored number equal
/// (not the same function: use the proofs' identity checker for that).
template <class T>
bool same_net(const BSpline<T>& A, const BSpline<T>& B) {
  return A.degrees == B.degrees && A.knots == B.knots && A.q == B.q && A.points == B.points && A.weights == B.weights;
}

/// Checks every structural rule and throws ValidationError/DomainError naming the field.
/// Weights must be positive (zero or negative weights make the homogeneous form degenerate).
template <class T>
void validate(const BSpline<T>& S, const Limits& limits = {}) {
  if (S.degrees.empty()) throw ValidationError("degrees", "is empty", "give one degree per parametric direction");
  if (S.knots.size() != S.degrees.size())
    throw ValidationError("knots",
                          "has " + std::to_string(S.knots.size()) + " knot vectors for " +
                              std::to_string(S.degrees.size()) + " degrees",
                          "give one knot vector per entry of \"degrees\"");
  if (S.q < 1) throw ValidationError("points", "control points have no coordinates", "give points in R^q, q >= 1");
  std::size_t total = 1;
  for (int d = 0; d < S.dim(); ++d) {
    const std::string f = "knots[" + std::to_string(d) + "]";
    limits.check_degree(S.degrees[d], "degrees[" + std::to_string(d) + "]");
    if (S.degrees[d] < 0) throw ValidationError("degrees[" + std::to_string(d) + "]", "is negative", "use a degree >= 0");
    if (S.knots[d].size() < static_cast<std::size_t>(2 * S.degrees[d] + 2))
      throw ValidationError(f,
                            "has " + std::to_string(S.knots[d].size()) + " knots; degree " +
                                std::to_string(S.degrees[d]) + " needs at least 2*(degree+1) = " +
                                std::to_string(2 * S.degrees[d] + 2),
                            "add knots or lower the degree");
    validate_knots(S.knots[d], S.degrees[d], S.count(d), f);
    total = checked_product(total, S.count(d), limits, "points");
  }
  if (S.points.size() != total * static_cast<std::size_t>(S.q))
    throw ValidationError("points",
                          "has " + std::to_string(S.points.size() / S.q) +
                              " control points but the knot vectors and degrees need " + std::to_string(total),
                          "give prod_d (#knots_d - degree_d - 1) points, direction 0 varying fastest");
  if (S.is_rational()) {
    if (S.weights.size() != total)
      throw ValidationError("weights",
                            "has " + std::to_string(S.weights.size()) + " weights for " + std::to_string(total) +
                                " control points",
                            "give one weight per control point, or omit \"weights\"");
    for (std::size_t i = 0; i < total; ++i)
      if (!(T(0) < S.weights[i]))
        throw ValidationError("weights[" + std::to_string(i) + "]", "is not positive",
                              "weights must be > 0");
  }
}

/// Homogeneous coordinates: q+1 values (w*P, w) per control point for rational splines,
/// the q Cartesian values otherwise.
template <class T>
std::vector<T> homogeneous_points(const BSpline<T>& S) {
  if (!S.is_rational()) return S.points;
  const std::size_t n = S.size(), q = S.q;
  std::vector<T> H(n * (q + 1));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < q; ++c) H[i * (q + 1) + c] = S.points[i * q + c] * S.weights[i];
    H[i * (q + 1) + q] = S.weights[i];
  }
  return H;
}

template <class T>
void set_from_homogeneous(BSpline<T>& S, std::vector<T>&& H, bool rational) {
  if (!rational) { S.points = std::move(H); S.weights.clear(); return; }
  const std::size_t q = S.q, n = H.size() / (q + 1);
  S.points.resize(n * q);
  S.weights.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const T& w = H[i * (q + 1) + q];
    if (!(T(0) < w))
      throw ValidationError("weights[" + std::to_string(i) + "]", "became non-positive in the homogeneous form",
                            "use positive weights");
    for (std::size_t c = 0; c < q; ++c) S.points[i * q + c] = H[i * (q + 1) + c] / w;
    S.weights[i] = w;
  }
}

namespace detail {
/// Every operation along one parametric direction checks it first (a direction past the end
/// would read outside the spline's degrees and knots).
template <class T>
void check_direction(const BSpline<T>& S, int d) {
  if (d < 0 || d >= S.dim())
    throw UsageError("dir", "direction " + std::to_string(d) + " does not exist in a spline of dimension " +
                                std::to_string(S.dim()),
                     "give a direction in [0, " + std::to_string(S.dim() - 1) + "]");
}
}  // namespace detail

/// The storage seen from direction d: `before` control points of lower directions per step in d
/// (contiguous), n = count(d) steps, and `after` such fibres of higher directions.
struct FibreLayout {
  std::size_t before = 1, n = 0, after = 1;
};
template <class T>
FibreLayout fibre_layout(const BSpline<T>& S, int d) {
  detail::check_direction(S, d);
  FibreLayout f;
  for (int e = 0; e < d; ++e) f.before *= S.count(e);
  for (int e = d + 1; e < S.dim(); ++e) f.after *= S.count(e);
  f.n = S.count(d);
  return f;
}

/// The sub-spline of control points [first, first + n_new) in direction d, with the given knot
/// vector for that direction (the caller makes knots and points consistent).
template <class T>
BSpline<T> slice_direction(const BSpline<T>& S, int d, std::size_t first, std::size_t n_new, std::vector<T> knots) {
  const FibreLayout f = fibre_layout(S, d);
  BSpline<T> R;
  R.degrees = S.degrees;
  R.knots.reserve(S.knots.size());  // not a copy of all knots: slicing n pieces stays O(n)
  for (int e = 0; e < S.dim(); ++e) R.knots.push_back(e == d ? std::move(knots) : S.knots[e]);
  R.q = S.q;
  auto cut = [&](const std::vector<T>& V, std::size_t width, std::vector<T>& W) {
    W.reserve(f.before * n_new * f.after * width);
    for (std::size_t b = 0; b < f.after; ++b) {
      const T* src = V.data() + ((b * f.n + first) * f.before) * width;
      W.insert(W.end(), src, src + n_new * f.before * width);
    }
  };
  cut(S.points, S.q, R.points);
  if (S.is_rational()) cut(S.weights, 1, R.weights);
  return R;
}

/// A curve operation on a block of n "points" of m coordinates each (contiguous, point-major),
/// with degree p and knot vector U. It returns the new degree, knots and points.
template <class T>
struct CurveBlock {
  int p = 0;
  std::vector<T> U;
  std::vector<T> P;  // n' * m
};

/// Applies a univariate operation along direction d of a tensor-product spline: every fibre in
/// direction d is one curve whose "point" gathers the q(+1) homogeneous coordinates of all control
/// points before d. With the storage order above such a fibre is one contiguous block, so no
/// copying into temporaries is needed. `op(p, U, P, n, m)` depends on the points only linearly, so
/// every fibre gets the same new degree and knot vector; the first fibre's are kept.
template <class T, class Op>
BSpline<T> apply_along(const BSpline<T>& S, int d, Op&& op) {
  const bool rational = S.is_rational();
  const std::size_t qq = S.q + (rational ? 1 : 0);
  const auto [before, n, after] = fibre_layout(S, d);
  const std::size_t m = qq * before;
  /// Polynomial splines are worked on in place; only rational ones need the homogeneous copy.
  std::vector<T> H;
  if (rational) H = homogeneous_points(S);
  const T* src = rational ? H.data() : S.points.data();
  std::vector<T> out;
  BSpline<T> R;
  for (std::size_t b = 0; b < after; ++b) {
    CurveBlock<T> r = op(S.degrees[d], S.knots[d], src + b * n * m, n, m);
    if (b == 0) {
      R.degrees = S.degrees;
      R.degrees[d] = r.p;
      R.knots.reserve(S.knots.size());
      for (int e = 0; e < S.dim(); ++e) R.knots.push_back(e == d ? std::move(r.U) : S.knots[e]);
      if (after == 1) {
        out = std::move(r.P);
        break;
      }
      out.reserve(r.P.size() * after);
    }
    std::move(r.P.begin(), r.P.end(), std::back_inserter(out));
  }
  R.q = S.q;
  set_from_homogeneous(R, std::move(out), rational);
  return R;
}

/// Converts every scalar with `conv` (e.g. exact -> double by correct rounding).
template <class U, class T, class Conv>
BSpline<U> convert(const BSpline<T>& S, Conv&& conv) {
  BSpline<U> R;
  R.degrees = S.degrees;
  R.q = S.q;
  for (const auto& K : S.knots) {
    std::vector<U> k;
    k.reserve(K.size());
    for (const auto& x : K) k.push_back(conv(x));
    R.knots.push_back(std::move(k));
  }
  for (const auto& x : S.points) R.points.push_back(conv(x));
  for (const auto& x : S.weights) R.weights.push_back(conv(x));
  return R;
}

}  // namespace splinex
