// Strata and stationary-distance systems (solve/strata.hpp), for Rational and double.
#include "solve/strata.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "base/errors.hpp"
#include "exact/rational.hpp"
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "spline/knots.hpp"

namespace splinex::solve_detail {

namespace {

template <class T>
std::string text(const T& x) {
  return ArithTraits<T>::to_string(x);
}

template <class T>
Bernstein<T> constant(std::size_t vars, const T& value) {
  return Bernstein<T>{std::vector<int>(vars, 0), {value}};
}

/// b in n unknowns, its own at offset.. (degree 0 in the others: the coefficient layout is the same).
template <class T>
Bernstein<T> lift(Bernstein<T> b, std::size_t offset, std::size_t n) {
  std::vector<int> deg(n, 0);
  for (std::size_t l = 0; l < b.deg.size(); ++l) deg[offset + l] = b.deg[l];
  b.deg = std::move(deg);
  return b;
}

/// b elevated to the degrees `target` (>= its own): the product with 1 in Bernstein form.
template <class T>
Bernstein<T> elevate(const Bernstein<T>& b, const std::vector<int>& target) {
  std::vector<int> r(target.size());
  bool any = false;
  for (std::size_t l = 0; l < target.size(); ++l) {
    r[l] = target[l] - b.deg[l];
    any = any || r[l] > 0;
  }
  if (!any) return b;
  return bern_product(b, Bernstein<T>{r, std::vector<T>(detail::tensor_size(r), T(1))});
}

template <class T>
void set_hull(Stratum<T>& s) {
  for (std::size_t i = 0; i < s.X[0].c.size(); ++i) {
    const T& w = s.W.c.size() == 1 ? s.W.c[0] : s.W.c[i];
    for (int c = 0; c < 3; ++c) {
      const T x = s.X[c].c[i] / w;
      if (i == 0 || x < s.hull[c]) s.hull[c] = x;
      if (i == 0 || s.hull[c + 3] < x) s.hull[c + 3] = x;
    }
  }
}

/// The stratum `base` (a piece) with parameter d fixed at its side (0: lo, 1: hi).
template <class T>
Stratum<T> fix_side(const Stratum<T>& base, int d, int side) {
  Stratum<T> s = base;
  const int v = base.var[d];
  for (int c = 0; c < 3; ++c) s.X[c] = bern_face(base.X[c], v, side);
  s.W = base.rational ? bern_face(base.W, v, side) : constant<T>(base.k - 1, T(1));
  s.k = base.k - 1;
  if (s.k == 0) {  // bern_face leaves one direction of degree 0: no unknown
    for (int c = 0; c < 3; ++c) s.X[c].deg.clear();
    s.W.deg.clear();
    s.W.c.resize(1);
  }
  s.var[d] = -1;
  for (int e = 0; e < 2; ++e)
    if (s.var[e] > v) --s.var[e];
  s.lo[d] = s.hi[d] = side ? base.hi[d] : base.lo[d];
  set_hull(s);
  return s;
}

/// The stratum with its coefficients taken exactly as rationals (every float is one).
template <class T>
Stratum<Rational> exact_stratum(const Stratum<T>& s) {
  const auto conv = [](const Bernstein<T>& b) {
    Bernstein<Rational> o;
    o.deg = b.deg;
    o.c.reserve(b.c.size());
    for (const auto& x : b.c) o.c.push_back(ArithTraits<T>::to_rational(x));
    return o;
  };
  Stratum<Rational> r;
  r.dims = s.dims;
  r.k = s.k;
  for (int c = 0; c < 3; ++c) r.X[c] = conv(s.X[c]);
  r.W = conv(s.W);
  r.rational = s.rational;
  for (int d = 0; d < 2; ++d) {
    r.var[d] = s.var[d];
    r.lo[d] = ArithTraits<T>::to_rational(s.lo[d]);
    r.hi[d] = ArithTraits<T>::to_rational(s.hi[d]);
  }
  return r;
}

/// The difference's numerators D = X_A W_B - X_B W_A and its denominator W = W_A W_B in the
/// kA + kB unknowns of the pair.
template <class T>
void difference_forms(const Stratum<T>& A, const Stratum<T>& B, Bernstein<T> (&D)[3], Bernstein<T>& W) {
  const std::size_t n = static_cast<std::size_t>(A.k + B.k), oa = 0, ob = static_cast<std::size_t>(A.k);
  const Bernstein<T> WA = lift(A.W, oa, n), WB = lift(B.W, ob, n);
  for (int c = 0; c < 3; ++c) {
    const Bernstein<T> P = bern_product(lift(A.X[c], oa, n), WB), Q = bern_product(lift(B.X[c], ob, n), WA);
    std::vector<int> target(n);
    for (std::size_t l = 0; l < n; ++l) target[l] = std::max(P.deg[l], Q.deg[l]);
    D[c] = bern_sub(elevate(P, target), elevate(Q, target));
  }
  W = bern_product(WA, WB);
}

template <class T>
T next_toward(const T& y, bool up) {
  if constexpr (std::is_same_v<T, double>) {
    return std::nextafter(y, up ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity());
  } else if constexpr (std::is_same_v<T, Mpfr>) {
    Mpfr z = y;
    if (up)
      mpfr_nextabove(z.get());
    else
      mpfr_nextbelow(z.get());
    return z;
  } else {
    return y;
  }
}

}  // namespace

template <class T>
T round_directed(const Rational& x, bool up) {
  if constexpr (ArithTraits<T>::exact) {
    (void)up;
    return ArithTraits<T>::from_rational(x);
  } else {
    T y = ArithTraits<T>::from_rational(x);
    if (!is_finite_value(y)) {
      // Beyond the format's range: infinity on its own side, the largest finite value on the other.
      const bool positive = 0 < x;
      if (positive == up) return y;
      T big = next_toward(y, !up);
      return big;
    }
    const Rational r = ArithTraits<T>::to_rational(y);
    if (up && r < x) y = next_toward(y, true);
    if (!up && x < r) y = next_toward(y, false);
    return y;
  }
}

template <class T>
Stratum<T> stratum_face(const Stratum<T>& s, int d, int side) {
  return fix_side(s, d, side);
}

template <class T>
bool constant_along(const Stratum<T>& A, const std::vector<int>& dirs, const std::vector<T>& uv) {
  if constexpr (!ArithTraits<T>::exact) {
    (void)A;
    (void)dirs;
    (void)uv;
    return false;
  } else {
    Bernstein<T> X[3] = {A.X[0], A.X[1], A.X[2]}, W = A.W;
    for (int v = A.k - 1; v >= 0; --v) {
      int d = 0;
      while (d < A.dims && A.var[d] != v) ++d;
      if (d == A.dims || std::find(dirs.begin(), dirs.end(), d) != dirs.end()) continue;
      const T t = (uv[d] - A.lo[d]) / (A.hi[d] - A.lo[d]);
      for (auto& g : X) g = bern_fix(g, v, t);
      if (A.rational) W = bern_fix(W, v, t);
    }
    for (int c = 0; c < 3; ++c)
      for (std::size_t i = 0; i < X[c].c.size(); ++i) {
        const T& wi = W.c.size() == 1 ? W.c[0] : W.c[i];
        if (!(X[c].c[i] * W.c[0] == X[c].c[0] * wi)) return false;
      }
    return true;
  }
}

template <class T>
void require_surface(const BSpline<T>& S, const std::string& name, const Limits& limits, int degree_factor) {
  validate(S, limits);
  if (S.dim() != 2 || S.q < 3)
    throw ValidationError(name, "is not a surface in R^3", "give a spline with two parametric directions and points x,y,z");
  for (int d = 0; d < 2; ++d) {
    const std::string field = name + ".degrees[" + std::to_string(d) + "]";
    if (S.degrees[d] == 0)
      throw ValidationError(field, "is 0: the surface has no tangent plane, the distance equations are degenerate", "elevate the surface to degree >= 1");
    limits.check_degree(static_cast<long>(S.is_rational() ? 3 : 2) * S.degrees[d] * degree_factor / 2, field);
  }
}

template <class T>
Stratum<T> point_stratum(const std::vector<T>& P) {
  Stratum<T> s;
  for (int c = 0; c < 3; ++c) s.X[c] = constant<T>(0, P[c]);
  s.W = constant<T>(0, T(1));
  s.dims = 0;
  s.where = "point";
  s.label = "the point";
  for (int c = 0; c < 3; ++c) s.hull[c] = s.hull[c + 3] = P[c];
  return s;
}

template <class T>
std::vector<Stratum<T>> surface_strata(const BSpline<T>& S, const Limits& limits) {
  const BezierForm<T> F = bezier_form(S, limits);
  const std::size_t seg0 = F.breaks[0].size() - 1;
  // Knot lines where S is not C^1: 2 the domain's boundary, 1 a C^0 knot line, 3 a jump (C^-1).
  const auto crease = [&](int d, const T& x) {
    if (x == S.domain_lo(d) || x == S.domain_hi(d)) return 2;
    int m = 0;
    for (const auto& k : S.knots[d]) m += k == x ? 1 : 0;
    return m > S.degrees[d] ? 3 : m >= S.degrees[d] ? 1 : 0;
  };
  std::vector<Stratum<T>> out, corners;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto bp = F.piece(k);
    Stratum<T> face;
    face.k = 2;
    face.rational = S.is_rational();
    face.piece = k;
    for (int c = 0; c < 3; ++c) face.X[c] = bern_coordinate(bp.spline, c);
    face.W = face.rational ? bern_coordinate(bp.spline, bp.spline.q) : constant<T>(2, T(1));
    for (int d = 0; d < 2; ++d) {
      face.var[d] = d;
      face.lo[d] = bp.box[d].first;
      face.hi[d] = bp.box[d].second;
    }
    face.where = "interior";
    face.label = "piece [" + text(face.lo[0]) + ", " + text(face.hi[0]) + "] x [" + text(face.lo[1]) + ", " + text(face.hi[1]) + "]";
    set_hull(face);
    (void)seg0;
    for (int d = 0; d < 2; ++d)
      for (int side = 0; side < 2; ++side) {
        const T x = side ? face.hi[d] : face.lo[d];
        const int kind = crease(d, x);
        if (kind == 0 || (kind == 1 && side == 0)) continue;
        Stratum<T> edge = fix_side(face, d, side);
        const int e = 1 - d;
        edge.where = "edge";
        edge.label = std::string(d == 0 ? "u" : "v") + " = " + text(x) + ", " + (e == 0 ? "u" : "v") + " in [" + text(face.lo[e]) + ", " +
                     text(face.hi[e]) + "]" + (kind == 2 ? " (boundary)" : " (knot line, not C^1)");
        for (int end = 0; end < 2; ++end) {
          Stratum<T> corner = fix_side(edge, e, end);
          corner.where = "corner";
          corner.label = "corner (" + text(corner.lo[0]) + ", " + text(corner.lo[1]) + ")";
          bool seen = false;
          for (const auto& c : corners)
            seen = seen || (c.lo[0] == corner.lo[0] && c.lo[1] == corner.lo[1] && c.hull == corner.hull);
          if (!seen) corners.push_back(corner);
        }
        out.push_back(std::move(edge));
      }
    out.push_back(std::move(face));
  }
  out.insert(out.end(), corners.begin(), corners.end());
  return out;
}

template <class T>
std::vector<Stratum<T>> curve_strata(const BSpline<T>& C, const Limits& limits) {
  const BezierForm<T> F = bezier_form(C, limits);
  std::vector<Stratum<T>> out;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto bp = F.piece(k);
    Stratum<T> s;
    s.dims = 1;
    s.k = 1;
    s.rational = C.is_rational();
    s.piece = k;
    for (int c = 0; c < 3; ++c) s.X[c] = bern_coordinate(bp.spline, c);
    s.W = s.rational ? bern_coordinate(bp.spline, bp.spline.q) : constant<T>(1, T(1));
    s.var[0] = 0;
    s.lo[0] = bp.box[0].first;
    s.hi[0] = bp.box[0].second;
    s.where = "curve";
    s.label = "curve piece [" + text(s.lo[0]) + ", " + text(s.hi[0]) + "]";
    set_hull(s);
    out.push_back(std::move(s));
  }
  return out;
}

template <class T>
PairSystem<T> pair_system(const Stratum<T>& A, const Stratum<T>& B) {
  PairSystem<T> sys;
  const std::size_t n = static_cast<std::size_t>(A.k + B.k), oa = 0, ob = static_cast<std::size_t>(A.k);
  sys.n = n;
  const Bernstein<T> WA = lift(A.W, oa, n), WB = lift(B.W, ob, n);
  for (int c = 0; c < 3; ++c) {
    const Bernstein<T> P = bern_product(lift(A.X[c], oa, n), WB), Q = bern_product(lift(B.X[c], ob, n), WA);
    std::vector<int> target(n);
    for (std::size_t l = 0; l < n; ++l) target[l] = std::max(P.deg[l], Q.deg[l]);
    sys.D[c] = bern_sub(elevate(P, target), elevate(Q, target));
  }
  // Tangent numerators of a stratum: d X_c W - X_c d W (d X_c when polynomial).
  const auto tangent = [](const Stratum<T>& s, int i, int c) {
    if (!s.rational) return bern_derivative(s.X[c], i);
    return bern_sub(bern_product(bern_derivative(s.X[c], i), s.W),
                            bern_product(s.X[c], bern_derivative(s.W, i)));
  };
  for (const auto* s : {&A, &B})
    for (int i = 0; i < s->k; ++i) {
      Bernstein<T> sum;
      for (int c = 0; c < 3; ++c) {
        const Bernstein<T> term = bern_product(sys.D[c], lift(tangent(*s, i, c), s == &A ? oa : ob, n));
        sum = c == 0 ? term : bern_add(sum, term);
      }
      sys.equations.push_back(std::move(sum));
    }
  sys.D2 = bern_product(sys.D[0], sys.D[0]);
  for (int c = 1; c < 3; ++c) sys.D2 = bern_add(sys.D2, bern_product(sys.D[c], sys.D[c]));
  sys.W = bern_product(WA, WB);
  sys.WW = bern_product(sys.W, sys.W);
  for (const auto* s : {&A, &B})
    for (int v = 0; v < s->k; ++v)
      for (int d = 0; d < s->dims; ++d)
        if (s->var[d] == v) {
          sys.lo.push_back(s->lo[d]);
          sys.hi.push_back(s->hi[d]);
        }
  return sys;
}

template <class T>
T hull_distance2(const Stratum<T>& A, const Stratum<T>& B) {
  T d2(0);
  for (int c = 0; c < 3; ++c) {
    T gap(0);
    if (A.hull[c + 3] < B.hull[c]) gap = B.hull[c] - A.hull[c + 3];
    if (B.hull[c + 3] < A.hull[c]) gap = A.hull[c] - B.hull[c + 3];
    d2 += gap * gap;
  }
  return d2;
}

template <class T>
std::vector<T> surface_parameters(const Stratum<T>& A, const std::vector<T>& x, std::size_t offset) {
  std::vector<T> uv(static_cast<std::size_t>(A.dims));
  for (int d = 0; d < A.dims; ++d) uv[d] = A.var[d] < 0 ? A.lo[d] : x[offset + A.var[d]];
  return uv;
}

template <class T>
std::vector<T> stratum_point(const Stratum<T>& A, const std::vector<T>& x, std::size_t offset) {
  std::vector<T> t(A.k);
  for (int d = 0; d < A.dims; ++d)
    if (A.var[d] >= 0) t[A.var[d]] = (x[offset + A.var[d]] - A.lo[d]) / (A.hi[d] - A.lo[d]);
  const T w = bern_value(A.W, t);
  std::vector<T> p(3);
  for (int c = 0; c < 3; ++c) p[c] = bern_value(A.X[c], t) / w;
  return p;
}

template <class T>
std::pair<T, T> distance2_bounds(const Bernstein<T>* D, const Bernstein<T>& W) {
  T gap2(0), far2(0);
  for (int c = 0; c < 3; ++c) {
    const auto [lo, hi] = bern_range(D[c]);
    const T gap = T(0) < lo ? lo : hi < T(0) ? T(T(0) - hi) : T(0);
    const T far = hi < T(T(0) - lo) ? T(T(0) - lo) : hi;
    gap2 += gap * gap;
    far2 += far * far;
  }
  const auto [wlo, whi] = bern_range(W);
  return {gap2 / (whi * whi), far2 / (wlo * wlo)};
}

template <class T>
std::pair<T, T> distance2_range(const PairSystem<T>& sys, const std::vector<T>& a, const std::vector<T>& b) {
  Bernstein<T> D2 = sys.D2, WW = sys.WW, W = sys.W, D[3] = {sys.D[0], sys.D[1], sys.D[2]};
  const auto each = [&](auto&& op) {
    D2 = op(D2);
    WW = op(WW);
    W = op(W);
    for (auto& g : D) g = op(g);
  };
  std::vector<T> fixed(sys.n);
  std::vector<bool> zero(sys.n, false);
  for (std::size_t l = 0; l < sys.n; ++l) {
    const T w = sys.hi[l] - sys.lo[l];
    const T la = (a[l] - sys.lo[l]) / w, lb = (b[l] - sys.lo[l]) / w;
    if (la < lb) {
      each([&](const Bernstein<T>& g) { return bern_restrict(g, static_cast<int>(l), la, lb); });
    } else {
      zero[l] = true;
      fixed[l] = la;
    }
  }
  for (std::size_t l = sys.n; l-- > 0;) {  // sides of width 0, last first (bern_face drops the direction)
    if (!zero[l]) continue;
    const auto face = [&](const Bernstein<T>& g) { return bern_fix(g, static_cast<int>(l), fixed[l]); };
    each(face);
  }
  const auto [dlo, dhi] = bern_range(D2);
  const auto [wlo, whi] = bern_range(WW);
  auto [lo, hi] = distance2_bounds(D, W);
  if (lo < T(dlo / whi)) lo = dlo / whi;
  if (T(dhi / wlo) < hi) hi = dhi / wlo;
  return {lo, hi};
}

namespace {

/// The bounds of distance2_bounds over [a, b] (local coordinates of the system's box, la <= lb).
template <class T>
std::pair<T, T> bounds_on_box(Bernstein<T> (&D)[3], Bernstein<T>& W, const std::vector<T>& la, const std::vector<T>& lb) {
  const std::size_t n = la.size();
  for (std::size_t l = 0; l < n; ++l)
    if (la[l] < lb[l]) {
      for (auto& g : D) g = bern_restrict(g, static_cast<int>(l), la[l], lb[l]);
      W = bern_restrict(W, static_cast<int>(l), la[l], lb[l]);
    }
  for (std::size_t l = n; l-- > 0;)
    if (!(la[l] < lb[l])) {
      for (auto& g : D) g = bern_fix(g, static_cast<int>(l), la[l]);
      W = bern_fix(W, static_cast<int>(l), la[l]);
    }
  return distance2_bounds(D, W);
}

}  // namespace

template <class T>
std::pair<T, T> distance2_enclosure(const Stratum<T>& A, const Stratum<T>& B, const PairSystem<T>& sys, const std::vector<T>& a,
                                    const std::vector<T>& b) {
  if constexpr (ArithTraits<T>::exact) {
    (void)A;
    (void)B;
    auto r = distance2_range(sys, a, b);
    round_enclosure(r.first, r.second);
    return r;
  } else {
    // Round-to-nearest de Casteljau on |D|^2 can give a negative or inverted range (a point on the
    // surface: [5.9e-32, -9.9e-17]); the exact rational value of the float data cannot.
    const Stratum<Rational> EA = exact_stratum(A), EB = exact_stratum(B);
    Bernstein<Rational> D[3], W;
    difference_forms(EA, EB, D, W);
    const std::size_t n = sys.n;
    std::vector<Rational> la(n), lb(n);
    for (std::size_t l = 0; l < n; ++l) {
      const Rational lo = ArithTraits<T>::to_rational(sys.lo[l]), w = ArithTraits<T>::to_rational(sys.hi[l]) - lo;
      la[l] = (ArithTraits<T>::to_rational(a[l]) - lo) / w;
      lb[l] = (ArithTraits<T>::to_rational(b[l]) - lo) / w;
      if (la[l] < 0) la[l] = 0;
      if (lb[l] > 1) lb[l] = 1;
      if (lb[l] < la[l]) lb[l] = la[l];
    }
    const auto [lo, hi] = bounds_on_box(D, W, la, lb);
    T tlo = round_directed<T>(lo, false), thi = round_directed<T>(hi, true);
    if (tlo < T(0)) tlo = T(0);
    return {tlo, thi};
  }
}

template <class T>
T distance2_at(const PairSystem<T>& sys, const std::vector<T>& x) {
  std::vector<T> t(sys.n);
  for (std::size_t l = 0; l < sys.n; ++l) t[l] = (x[l] - sys.lo[l]) / (sys.hi[l] - sys.lo[l]);
  return bern_value(sys.D2, t) / bern_value(sys.WW, t);
}

#define SPLINEX_STRATA(T)                                                                                                 \
  template std::vector<Stratum<T>> surface_strata(const BSpline<T>&, const Limits&);                                     \
  template void require_surface(const BSpline<T>&, const std::string&, const Limits&, int);                             \
  template Stratum<T> point_stratum(const std::vector<T>&);                                                              \
  template std::vector<Stratum<T>> curve_strata(const BSpline<T>&, const Limits&);                                       \
  template PairSystem<T> pair_system(const Stratum<T>&, const Stratum<T>&);                                              \
  template T hull_distance2(const Stratum<T>&, const Stratum<T>&);                                                       \
  template std::vector<T> surface_parameters(const Stratum<T>&, const std::vector<T>&, std::size_t);                     \
  template std::vector<T> stratum_point(const Stratum<T>&, const std::vector<T>&, std::size_t);                          \
  template std::pair<T, T> distance2_bounds(const Bernstein<T>*, const Bernstein<T>&);                                            \
  template std::pair<T, T> distance2_range(const PairSystem<T>&, const std::vector<T>&, const std::vector<T>&);          \
  template T distance2_at(const PairSystem<T>&, const std::vector<T>&);                                                 \
  template std::pair<T, T> distance2_enclosure(const Stratum<T>&, const Stratum<T>&, const PairSystem<T>&, const std::vector<T>&, \
                                               const std::vector<T>&);                                                  \
  template T round_directed<T>(const Rational&, bool);                                                                   \
  template Stratum<T> stratum_face(const Stratum<T>&, int, int);                                                         \
  template bool constant_along(const Stratum<T>&, const std::vector<int>&, const std::vector<T>&);
SPLINEX_STRATA(Rational)
SPLINEX_STRATA(double)
SPLINEX_STRATA(Mpfr)
#undef SPLINEX_STRATA

}  // namespace splinex::solve_detail
