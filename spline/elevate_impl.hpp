#pragma once
#include <algorithm>
#include <string>

#include "spline/bernstein.hpp"
#include "spline/elevate.hpp"
#include "spline/insert_impl.hpp"

namespace splinex {
namespace detail {

/// NURBS Book A5.9 DegreeElevateCurve on a clamped curve block (n points of m coordinates).
template <class T>
CurveBlock<T> degree_elevate_curve(int p, const std::vector<T>& U, const T* Pw, std::size_t count, std::size_t mm,
                                   int t) {
  const int n = static_cast<int>(count) - 1;
  const int m = n + p + 1, ph = p + t, ph2 = ph / 2;
  std::vector<std::vector<T>> bezalfs(ph + 1, std::vector<T>(p + 1, T(0)));
  bezalfs[0][0] = T(1);
  bezalfs[ph][p] = T(1);
  for (int i = 1; i <= ph2; ++i) {
    const T inv = T(1) / binomial<T>(ph, i);
    const int mpi = std::min(p, i);
    for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = inv * binomial<T>(p, j) * binomial<T>(t, i - j);
  }
  for (int i = ph2 + 1; i <= ph - 1; ++i) {
    const int mpi = std::min(p, i);
    for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = bezalfs[ph - i][p - j];
  }
  /// Number of distinct interior knots s gives the result size n + 1 + t*(s+1).
  const int s_int = static_cast<int>(breakpoints(U, p, count).size()) - 2;
  const int nh_max = n + t * (s_int + 1);
  CurveBlock<T> out;
  out.p = ph;
  out.U.assign(nh_max + ph + 2, T(0));
  out.P.assign((nh_max + 1) * mm, T(0));
  std::vector<T>& Uh = out.U;
  T* Qw = out.P.data();
  std::vector<T> bpts((p + 1) * mm), ebpts((ph + 1) * mm), Nextbpts(std::max(p - 1, 1) * mm), alfs(std::max(p - 1, 1));
  auto pt = [mm](std::vector<T>& v, int i) { return v.data() + static_cast<std::size_t>(i) * mm; };
  auto qt = [mm, Qw](int i) { return Qw + static_cast<std::size_t>(i) * mm; };
  auto assign = [mm](T* dst, const T* src) { std::copy(src, src + mm, dst); };
  /// dst = a*dst + (1-a)*other  ==  other + a*(dst - other)
  auto blend = [mm](T* dst, const T& a, const T* other) {
    for (std::size_t c = 0; c < mm; ++c) dst[c] = other[c] + a * (dst[c] - other[c]);
  };

  int mh = ph, kind = ph + 1, r = -1, a = p, b = p + 1, cind = 1;
  T ua = U[0];
  assign(qt(0), Pw);
  for (int i = 0; i <= ph; ++i) Uh[i] = ua;
  for (int i = 0; i <= p; ++i) assign(pt(bpts, i), Pw + static_cast<std::size_t>(i) * mm);
  while (b < m) {
    int i = b;
    while (b < m && U[b] == U[b + 1]) ++b;
    const int mul = b - i + 1;
    mh += mul + t;
    const T ub = U[b];
    const int oldr = r;
    r = p - mul;
    const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
    const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
    if (r > 0) {  // insert knot u(b) r times to get the Bezier segment
      const T numer = ub - ua;
      for (int k = p; k > mul; --k) alfs[k - mul - 1] = numer / (U[a + k] - ua);
      for (int j = 1; j <= r; ++j) {
        const int save = r - j, s = mul + j;
        for (int k = p; k >= s; --k) blend(pt(bpts, k), alfs[k - s], pt(bpts, k - 1));
        assign(pt(Nextbpts, save), pt(bpts, p));
      }
    }
    for (int ii = lbz; ii <= ph; ++ii) {  // degree elevate the Bezier segment
      T* e = pt(ebpts, ii);
      std::fill(e, e + mm, T(0));
      const int mpi = std::min(p, ii);
      for (int j = std::max(0, ii - t); j <= mpi; ++j) {
        const T& f = bezalfs[ii][j];
        const T* src = pt(bpts, j);
        for (std::size_t c = 0; c < mm; ++c) e[c] += f * src[c];
      }
    }
    if (oldr > 1) {  // remove knot u = U[a] oldr times
      int first = kind - 2, last = kind;
      const T den = ub - ua;
      const T bet = (ub - Uh[kind - 1]) / den;
      for (int tr = 1; tr < oldr; ++tr) {
        int ii = first, j = last, kj = j - kind + 1;
        while (j - ii > tr) {
          if (ii < cind) {
            const T alf = (ub - Uh[ii]) / (ua - Uh[ii]);
            blend(qt(ii), alf, qt(ii - 1));
          }
          if (j >= lbz) {
            if (j - tr <= kind - ph + oldr) {
              const T gam = (ub - Uh[j - tr]) / den;
              blend(pt(ebpts, kj), gam, pt(ebpts, kj + 1));
            } else {
              blend(pt(ebpts, kj), bet, pt(ebpts, kj + 1));
            }
          }
          ++ii;
          --j;
          --kj;
        }
        --first;
        ++last;
      }
    }
    if (a != p)  // load the knot ua
      for (int ii = 0; ii < ph - oldr; ++ii) Uh[kind++] = ua;
    for (int j = lbz; j <= rbz; ++j) assign(qt(cind++), pt(ebpts, j));
    if (b < m) {  // set up for the next pass
      for (int j = 0; j < r; ++j) assign(pt(bpts, j), pt(Nextbpts, j));
      for (int j = r; j <= p; ++j) assign(pt(bpts, j), Pw + static_cast<std::size_t>(b - p + j) * mm);
      a = b;
      ++b;
      ua = ub;
    } else {
      for (int ii = 0; ii <= ph; ++ii) Uh[kind + ii] = ub;
    }
  }
  const int nh = mh - ph - 1;
  out.U.resize(nh + ph + 2);
  out.P.resize(static_cast<std::size_t>(nh + 1) * mm);
  return out;
}

/// Elevation of a clamped block by t with A5.9, extended to the whole legal input: A5.9 (like
/// the book's text) assumes degree p >= 1 and interior multiplicities <= p. A knot of
/// multiplicity p+1 separates two independent curves (the spline may jump there), and a degree-0
/// curve has such a knot at every breakpoint. So the block is cut at those knots, each part is
/// elevated on its own (a constant piece of degree 0 becomes t+1 equal points), and the parts are
/// joined again, the shared knot now of multiplicity p+t+1 (the inverse of split_at).
template <class T>
CurveBlock<T> degree_elevate_curve_any(int p, const std::vector<T>& U, const T* Pw, std::size_t count, std::size_t mm,
                                       int t) {
  const std::size_t run = static_cast<std::size_t>(p) + 1;
  /// Start indices (into U, = first control point of the part) of each part.
  std::vector<std::size_t> starts{0};
  for (std::size_t i = run; i < count;) {
    std::size_t j = i;
    while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
    if (j - i + 1 == run) starts.push_back(i);
    i = j + 1;
  }
  if (starts.size() == 1 && p > 0) return degree_elevate_curve(p, U, Pw, count, mm, t);
  starts.push_back(count);
  CurveBlock<T> out;
  out.p = p + t;
  for (std::size_t part = 0; part + 1 < starts.size(); ++part) {
    const std::size_t first = starts[part], n = starts[part + 1] - first;
    CurveBlock<T> piece;
    if (p == 0) {  // one constant span [U[first], U[first+1]]
      piece.U.assign(t + 1, U[first]);
      piece.U.insert(piece.U.end(), t + 1, U[first + 1]);
      for (int c = 0; c <= t; ++c) piece.P.insert(piece.P.end(), Pw + first * mm, Pw + (first + 1) * mm);
    } else {
      const std::vector<T> V(U.begin() + first, U.begin() + first + n + run);
      piece = degree_elevate_curve(p, V, Pw + first * mm, n, mm, t);
    }
    // Join: the part's leading run of p+t+1 knots is the previous part's trailing run.
    out.U.insert(out.U.end(), piece.U.begin() + (part == 0 ? 0 : p + t + 1), piece.U.end());
    out.P.insert(out.P.end(), std::make_move_iterator(piece.P.begin()), std::make_move_iterator(piece.P.end()));
  }
  return out;
}

/// The symmetrized blossom of one polynomial piece: sum over k of the degree-p blossom (polar
/// form) at x[0..p] with x[k] left out, for the piece of a degree-p block on span s. A blossom is
/// de Boor's triangle with a different argument at each level. The arguments are applied in
/// ascending order, as p+1 separate triangles would apply them: the order decides the rounding
/// (applying them in another order, which the symmetry of the blossom allows, lost 11 bits of 53
/// at degree 7 where this order loses about 1). The p+1 triangles share their prefixes: the state
/// after x[0..k) is kept and advanced by one level per k, and only the suffix x(k..p] is applied
/// to a copy, which halves the work of separate triangles. The reciprocals of the knot
/// differences of the span are cached. MM > 0 fixes the number of coordinates at compile time
/// (curves in R^1..R^4), 0 leaves it to mm.
template <class T, int MM = 0>
class LeaveOneOutBlossom {
 public:
  LeaveOneOutBlossom(int p, const std::vector<T>& U, const T* P, std::size_t mm)
      : p_(p), U_(U), P_(P), mm_(mm), prefix_(static_cast<std::size_t>(p + 1) * mm), work_(prefix_.size()),
        inv_(static_cast<std::size_t>(p + 1) * static_cast<std::size_t>(p + 1)) {}

  /// acc[0..mm) += sum_k blossom(x without x[k]) on span s.
  void add_sum(std::size_t s, const T* x, T* acc) {
    if (s != span_) set_span(s);
    const std::size_t w = width(), all = static_cast<std::size_t>(p_ + 1) * w;
    const T* src = P_ + (s - p_) * w;
    for (std::size_t k = 0; k < all; ++k) prefix_[k] = src[k];
    for (int k = 0; k <= p_; ++k) {  // prefix_ has x[0..k) applied at levels 1..k
      if (k == p_) {
        add(prefix_.data(), acc);
        break;
      }
      T* e = work_.data();
      apply(prefix_.data(), e, k, x[k + 1]);  // skip x[k]: its suffix starts from the prefix, no copy
      for (int r = k + 2; r <= p_; ++r) apply(e, e, r - 1, x[r]);
      add(e, acc);
      apply(prefix_.data(), prefix_.data(), k, x[k]);
    }
  }

 private:
  std::size_t width() const {
    if constexpr (MM > 0) return static_cast<std::size_t>(MM);
    return mm_;
  }
  void add(const T* d, T* acc) const {
    const std::size_t w = width();
    const T* v = d + static_cast<std::size_t>(p_) * w;
    for (std::size_t c = 0; c < w; ++c) acc[c] += v[c];
  }
  void set_span(std::size_t s) {
    span_ = s;
    for (int r = 1; r <= p_; ++r)
      for (int i = r; i <= p_; ++i) {
        const std::size_t idx = s - p_ + i;
        inv_[static_cast<std::size_t>(r * (p_ + 1) + i)] = T(1) / (U_[idx + p_ - r + 1] - U_[idx]);
      }
  }
  /// Level `level` + 1 of de Boor's triangle with argument xv, from src into dst (which may be
  /// src: the points are updated from the last down).
  void apply(const T* src, T* dst, int level, const T& xv) const {
    const int r = level + 1;
    const std::size_t w = width();
    for (int i = p_; i >= r; --i) {
      const std::size_t idx = span_ - p_ + i;
      const T alpha = (xv - U_[idx]) * inv_[static_cast<std::size_t>(r * (p_ + 1) + i)];
      const T* si = src + i * w;
      const T* sm = src + (i - 1) * w;
      T* di = dst + i * w;
      for (std::size_t c = 0; c < w; ++c) di[c] = sm[c] + alpha * (si[c] - sm[c]);
    }
  }

  int p_;
  const std::vector<T>& U_;
  const T* P_;
  std::size_t mm_;
  std::vector<T> prefix_, work_, inv_;
  std::size_t span_ = static_cast<std::size_t>(-1);
};

template <class T, int MM>
CurveBlock<T> elevate_by_one_blossom_fixed(int p, const std::vector<T>& U, const T* P, std::size_t count, std::size_t mm) {
  CurveBlock<T> out;
  out.p = p + 1;
  // Elevated knots: every distinct knot once more.
  out.U.reserve(U.size() + U.size() / 2 + 2);
  for (std::size_t i = 0; i < U.size(); ++i) {
    out.U.push_back(U[i]);
    if (i + 1 == U.size() || U[i] < U[i + 1]) out.U.push_back(U[i]);
  }
  const std::vector<T>& V = out.U;
  const std::size_t nbar = V.size() - (p + 1) - 1;
  out.P.assign(nbar * mm, T(0));
  LeaveOneOutBlossom<T, MM> sum(p, U, P, mm);
  const T scale(p + 1);
  std::size_t s = p;
  for (std::size_t j = 0; j < nbar; ++j) {
    /// A non-empty elevated interval [V_l, V_{l+1}) with j <= l <= j+p+1 inside the domain.
    std::size_t l = j + p + 1;
    while (l > std::max<std::size_t>(j, p + 1) && !(V[l] < V[l + 1])) --l;
    // Its span in U: the spans only move right as j grows, so walk instead of searching.
    while (s + 1 < count && !(V[l] < U[s + 1])) ++s;
    T* Q = out.P.data() + j * mm;
    sum.add_sum(s, V.data() + j + 1, Q);
    for (std::size_t c = 0; c < mm; ++c) Q[c] = Q[c] / scale;
  }
  return out;
}

/// Elevation by one via the blossom on a clamped block.
template <class T>
CurveBlock<T> elevate_by_one_blossom(int p, const std::vector<T>& U, const T* P, std::size_t count, std::size_t mm) {
  switch (mm) {
    case 1: return elevate_by_one_blossom_fixed<T, 1>(p, U, P, count, mm);
    case 2: return elevate_by_one_blossom_fixed<T, 2>(p, U, P, count, mm);
    case 3: return elevate_by_one_blossom_fixed<T, 3>(p, U, P, count, mm);
    case 4: return elevate_by_one_blossom_fixed<T, 4>(p, U, P, count, mm);
    default: return elevate_by_one_blossom_fixed<T, 0>(p, U, P, count, mm);
  }
}

}  // namespace detail

template <class T>
std::size_t elevated_count(const BSpline<T>& S, int d, int t) {
  const std::size_t segments = breakpoints(S.knots[d], S.degrees[d], S.count(d)).size() - 1;
  // Clamped: every segment gains t control points. Clamping an unclamped direction first gives
  // count' <= count, so this is an upper bound there.
  return S.count(d) + static_cast<std::size_t>(t) * segments;
}

template <class T>
BSpline<T> elevate_degree(const BSpline<T>& S, int d, int t, ElevationMethod method, const Limits& limits) {
  detail::check_direction(S, d);
  if (t < 0) throw UsageError("by", "elevation amount " + std::to_string(t) + " is negative", "elevate by t >= 0");
  limits.check_degree(static_cast<long>(S.degrees[d]) + t, "by");
  if (t == 0) return S;
  const std::size_t per = S.size() / S.count(d);
  limits.check_count(checked_product(per, elevated_count(S, d, t), limits, "by"), "by");
  BSpline<T> C = clamp(S, d, limits);
  if (resolve_elevation_method<T>(method) == ElevationMethod::bezier_pieces)
    return apply_along(C, d, [&](int p, const std::vector<T>& U, const T* P, std::size_t n, std::size_t m) {
      return detail::degree_elevate_curve_any(p, U, P, n, m, t);
    });
  for (int step = 0; step < t; ++step)
    C = apply_along(C, d, [&](int p, const std::vector<T>& U, const T* P, std::size_t n, std::size_t m) {
      return detail::elevate_by_one_blossom(p, U, P, n, m);
    });
  return C;
}

}  // namespace splinex
