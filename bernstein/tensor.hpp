// Scalar tensor-product polynomials in Bernstein form on the unit box [0, 1]^n, the public type
// Bernstein<T>: the one home of their products, derivatives, de Casteljau splits and values (used
// by composition, the V-rep's regularity and trimming, verification, the subdivision solver and
// the cutting checks). Boxes of them are examined by the engine of bernstein/subdivide.hpp.
#pragma once
#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "spline/bernstein.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// A scalar tensor-product Bernstein polynomial on [0, 1]^n: degrees per direction, coefficients
/// with direction 0 fastest.
template <class T>
struct Bernstein {
  std::vector<int> deg;
  std::vector<T> c;
};

/// The index arithmetic of coefficient arrays and the tensor binomials.
namespace detail {

inline std::size_t tensor_size(const std::vector<int>& deg) {
  std::size_t s = 1;
  for (int d : deg) s *= static_cast<std::size_t>(d) + 1;
  return s;
}

/// Multi-index of flat index i (direction 0 fastest).
inline void unflatten(std::size_t i, const std::vector<int>& deg, std::vector<int>& idx) {
  for (std::size_t l = 0; l < deg.size(); ++l) {
    idx[l] = static_cast<int>(i % (deg[l] + 1));
    i /= deg[l] + 1;
  }
}

/// The stride of direction l in a coefficient array of degrees deg.
inline std::size_t tensor_stride(const std::vector<int>& deg, int l) {
  std::size_t s = 1;
  for (int k = 0; k < l; ++k) s *= static_cast<std::size_t>(deg[k]) + 1;
  return s;
}

/// Offsets in a coefficient array of degrees `into` of the multi-indices of an array of degrees
/// `deg` (direction 0 fastest): the flat index of idx in `into` for every flat index of `deg`.
/// Built direction by direction (no division per entry).
inline std::vector<std::size_t> tensor_offsets(const std::vector<int>& deg, const std::vector<int>& into) {
  std::vector<std::size_t> off(tensor_size(deg));
  off[0] = 0;
  std::size_t n = 1, stride = 1;
  for (std::size_t l = 0; l < deg.size(); ++l) {
    for (std::size_t j = static_cast<std::size_t>(deg[l]); j-- > 0;)  // j = deg_l, ..., 1; j = 0 keeps off[i]
      for (std::size_t i = 0; i < n; ++i) off[(j + 1) * n + i] = off[i] + (j + 1) * stride;
    n *= static_cast<std::size_t>(deg[l]) + 1;
    stride *= static_cast<std::size_t>(into[l]) + 1;
  }
  return off;
}

/// prod_l C(deg_l, idx_l) for every flat index of an array of degrees deg, as T: the products
/// 1 * C(deg_0, idx_0) * C(deg_1, idx_1) * ... formed in the order of the directions.
template <class T>
std::vector<T> tensor_binomials(const std::vector<int>& deg) {
  std::vector<T> out(tensor_size(deg), T(1));
  std::size_t n = 1;
  for (std::size_t l = 0; l < deg.size(); ++l) {
    const std::vector<T> row = binomial_row<T>(deg[l]);
    for (std::size_t j = row.size(); j-- > 0;)  // high j first: out[i] (j = 0) is overwritten last
      for (std::size_t i = 0; i < n; ++i) {
        T v = out[i];
        v *= row[j];
        out[j * n + i] = std::move(v);
      }
    n *= row.size();
  }
  return out;
}

/// tensor_binomials, kept per thread for the degrees a thread has asked for (keyed also by the
/// precision, since an MPFR value keeps the precision it was made with). Composition asks for the
/// same few degree vectors millions of times; the cache holds at most 256 of them. A caller holds
/// what it got as a shared pointer, so a later call that empties the cache cannot pull it away.
template <class T>
std::shared_ptr<const std::vector<T>> cached_tensor_binomials(const std::vector<int>& deg) {
  thread_local std::map<std::pair<int, std::vector<int>>, std::shared_ptr<const std::vector<T>>> cache;
  std::pair<int, std::vector<int>> key{cache_precision_key<T>(), deg};
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  if (cache.size() >= 256) cache.clear();
  auto made = std::make_shared<const std::vector<T>>(tensor_binomials<T>(deg));
  cache.emplace(std::move(key), made);
  return made;
}

}  // namespace detail

/// Whether T offers the fraction-free product loop (spline/arith.hpp: ArithTraits<T>::tensor_convolve).
template <class T>
concept FractionFreeConvolve = requires(const std::vector<T>& v, const std::vector<std::size_t>& o, std::vector<T>& out) {
  ArithTraits<T>::tensor_convolve(v, v, v, v, o, o, v, out);
};

template <class T>
Bernstein<T> bern_product(const Bernstein<T>& f, const Bernstein<T>& g) {
  const std::size_t k = f.deg.size();
  Bernstein<T> h;
  h.deg.resize(k);
  for (std::size_t l = 0; l < k; ++l) h.deg[l] = f.deg[l] + g.deg[l];
  h.c.assign(detail::tensor_size(h.deg), T(0));
  /// Scaled coefficients f_I binom(a, I), multiplied as a plain tensor polynomial, then divided
  /// by binom(a+b, K).
  const std::vector<std::size_t> fo = detail::tensor_offsets(f.deg, h.deg), go = detail::tensor_offsets(g.deg, h.deg);
  const auto fbp = detail::cached_tensor_binomials<T>(f.deg), gbp = detail::cached_tensor_binomials<T>(g.deg),
             hbp = detail::cached_tensor_binomials<T>(h.deg);
  const std::vector<T>&fb = *fbp, &gb = *gbp, &hb = *hbp;
  if constexpr (FractionFreeConvolve<T>) {
    // Exact: integers over one denominator per factor, one reduction per coefficient of h.
    ArithTraits<T>::tensor_convolve(f.c, fb, g.c, gb, fo, go, hb, h.c);
    return h;
  }
  auto scaled = [&](const Bernstein<T>& p, const std::vector<T>& b) {
    std::vector<T> s(p.c);
    for (std::size_t i = 0; i < s.size(); ++i) s[i] *= b[i];
    return s;
  };
  const std::vector<T> fs = scaled(f, fb), gs = scaled(g, gb);
  T t(0);  // one scratch product: t = fs[a]; t *= gs[b] rounds as fs[a] * gs[b] does
  for (std::size_t a = 0; a < fs.size(); ++a) {
    if (fs[a] == T(0)) continue;
    for (std::size_t b = 0; b < gs.size(); ++b) {
      t = fs[a];
      t *= gs[b];
      h.c[fo[a] + go[b]] += t;
    }
  }
  for (std::size_t i = 0; i < h.c.size(); ++i) h.c[i] /= hb[i];
  return h;
}

/// Whether T offers the fraction-free weighted sums (spline/arith.hpp: ArithTraits<T>::weighted_sums).
template <class T>
concept FractionFreeSums = requires(const std::vector<const std::vector<T>*>& v, const std::vector<T>& s, std::vector<T>& out) {
  ArithTraits<T>::weighted_sums(v, s, s, std::size_t{1}, out);
};

/// out[i*cols + c] += sum over t of v[t][i] a[t] b[t*cols + c], every v[t] of out.size() / cols
/// values: composition's sum over the outer control points (a: weights, b: coordinates). In
/// floating point each term is (v[t][i] a[t]) b[t*cols + c], added to out in the order of t, and a
/// term with v[t][i] = 0 is skipped; an exact arithmetic may sum on integers (same values).
template <class T>
void weighted_sums(const std::vector<const std::vector<T>*>& v, const std::vector<T>& a, const std::vector<T>& b,
                   std::size_t cols, std::vector<T>& out) {
  if constexpr (FractionFreeSums<T>) {
    ArithTraits<T>::weighted_sums(v, a, b, cols, out);
  } else {
    const std::size_t len = out.size() / cols;
    for (std::size_t t = 0; t < v.size(); ++t)
      for (std::size_t i = 0; i < len; ++i) {
        if ((*v[t])[i] == T(0)) continue;
        const T f = (*v[t])[i] * a[t];
        for (std::size_t c = 0; c < cols; ++c) out[i * cols + c] += f * b[t * cols + c];
      }
  }
}

/// Whether T offers the fused product sums (spline/arith.hpp: ArithTraits<T>::product_sums).
template <class T>
concept FractionFreeProductSums = requires(const std::vector<const std::vector<T>*>& v, const std::vector<T>& s,
                                           const std::vector<std::size_t>& o, std::vector<T>& out) {
  ArithTraits<T>::product_sums(v, s, v, s, o, o, s, s, s, std::size_t{1}, out);
};

/// out[i*cols + c] += sum over t of h_t[i] a[t] b[t*cols + c] with h_t = bern_product(*f[t], *g[t]):
/// composition's sum over the outer control points with its last product fused. Every f[t] has one
/// degree vector and every g[t] one. In floating point it is bern_product, then weighted_sums (the
/// same operations in the same order); an exact arithmetic may sum the products on integers without
/// forming their coefficients (same values).
template <class T>
void product_sums(const std::vector<const Bernstein<T>*>& f, const std::vector<const Bernstein<T>*>& g, const std::vector<T>& a,
                  const std::vector<T>& b, std::size_t cols, std::vector<T>& out) {
  if (f.empty()) return;
  if constexpr (FractionFreeProductSums<T>) {
    const std::vector<int>&fd = f[0]->deg, &gd = g[0]->deg;
    std::vector<int> hd(fd.size());
    for (std::size_t l = 0; l < hd.size(); ++l) hd[l] = fd[l] + gd[l];
    std::vector<const std::vector<T>*> fc, gc;
    for (std::size_t t = 0; t < f.size(); ++t) {
      if (f[t]->deg != fd || g[t]->deg != gd) throw std::logic_error("product_sums: factors of different degrees");
      fc.push_back(&f[t]->c);
      gc.push_back(&g[t]->c);
    }
    if (out.size() != detail::tensor_size(hd) * cols) throw std::logic_error("product_sums: out is not cols values per product coefficient");
    const auto fbp = detail::cached_tensor_binomials<T>(fd), gbp = detail::cached_tensor_binomials<T>(gd),
               hbp = detail::cached_tensor_binomials<T>(hd);
    ArithTraits<T>::product_sums(fc, *fbp, gc, *gbp, detail::tensor_offsets(fd, hd), detail::tensor_offsets(gd, hd), *hbp, a, b,
                                 cols, out);
  } else {
    std::vector<Bernstein<T>> h;
    h.reserve(f.size());
    std::vector<const std::vector<T>*> hc;
    for (std::size_t t = 0; t < f.size(); ++t) {
      h.push_back(bern_product(*f[t], *g[t]));
      hc.push_back(&h.back().c);
    }
    weighted_sums(hc, a, b, cols, out);
  }
}

/// a + b and a - b (same degrees).
template <class T>
Bernstein<T> bern_add(Bernstein<T> a, const Bernstein<T>& b) {
  for (std::size_t i = 0; i < a.c.size(); ++i) a.c[i] += b.c[i];
  return a;
}
template <class T>
Bernstein<T> bern_sub(Bernstein<T> a, const Bernstein<T>& b) {
  for (std::size_t i = 0; i < a.c.size(); ++i) a.c[i] -= b.c[i];
  return a;
}

/// a + b (or a - b with `minus`) of any degrees: each raised to the larger degree per direction
/// (times the polynomial 1 in Bernstein form of the difference) first.
template <class T>
Bernstein<T> bern_combine(const Bernstein<T>& a, const Bernstein<T>& b, bool minus) {
  std::vector<int> deg(a.deg.size());
  for (std::size_t l = 0; l < deg.size(); ++l) deg[l] = std::max(a.deg[l], b.deg[l]);
  auto up = [&](const Bernstein<T>& x) {
    Bernstein<T> one;
    one.deg.resize(deg.size());
    bool same = true;
    for (std::size_t l = 0; l < deg.size(); ++l) {
      one.deg[l] = deg[l] - x.deg[l];
      same = same && one.deg[l] == 0;
    }
    if (same) return x;
    one.c.assign(detail::tensor_size(one.deg), T(1));
    return bern_product(x, one);
  };
  return minus ? bern_sub(up(a), up(b)) : bern_add(up(a), up(b));
}

/// Whether T offers the fraction-free differences (spline/arith.hpp: ArithTraits<T>::differences).
template <class T>
concept FractionFreeDifferences = requires(const std::vector<T>& v, std::vector<T>& out) {
  ArithTraits<T>::differences(v, std::size_t{1}, 1, out);
};

/// d/dt_l on [0, 1]^n: degree deg_l - 1, coefficients deg_l (c_{i+1} - c_i). Degree 0 gives the
/// zero polynomial of degree 0.
template <class T>
Bernstein<T> bern_derivative(const Bernstein<T>& b, int l) {
  Bernstein<T> out;
  out.deg = b.deg;
  if (b.deg[l] == 0) {
    out.c.assign(b.c.size(), T(0));
    return out;
  }
  out.deg[l] -= 1;
  out.c.resize(detail::tensor_size(out.deg));
  const std::size_t n = b.deg.size(), stride = detail::tensor_stride(b.deg, static_cast<int>(l));
  if constexpr (FractionFreeDifferences<T>) {
    ArithTraits<T>::differences(b.c, stride, b.deg[l], out.c);  // on integers, one reduction per coefficient
    return out;
  }
  std::vector<int> idx(n);
  const T p(b.deg[l]);
  for (std::size_t i = 0; i < out.c.size(); ++i) {
    detail::unflatten(i, out.deg, idx);
    std::size_t src = 0;
    for (std::size_t k = 0; k < n; ++k) src += idx[k] * detail::tensor_stride(b.deg, static_cast<int>(k));
    out.c[i] = p * (b.c[src + stride] - b.c[src]);
  }
  return out;
}

/// The two parts of b at t_l = t (0 < t < 1), each reparametrized onto [0, 1] in direction l (de
/// Casteljau along every line of direction l).
template <class T>
concept FractionFreeDeCasteljau = requires(const std::vector<T>& v, const std::vector<int>& d, const T& t, std::vector<T>* out) {
  ArithTraits<T>::de_casteljau(v, std::size_t{1}, 1, t, out, out);
  { ArithTraits<T>::tensor_value(v, d, v) } -> std::convertible_to<T>;
};

template <class T>
std::pair<Bernstein<T>, Bernstein<T>> bern_split(const Bernstein<T>& b, int l, const T& t) {
  if constexpr (FractionFreeDeCasteljau<T>) {  // exact: on integers, one reduction per coefficient
    Bernstein<T> L{b.deg, std::vector<T>(b.c.size())}, R{b.deg, std::vector<T>(b.c.size())};
    ArithTraits<T>::de_casteljau(b.c, detail::tensor_stride(b.deg, l), b.deg[l], t, &L.c, &R.c);
    return {std::move(L), std::move(R)};
  }
  Bernstein<T> L = b, R = b;
  const int p = b.deg[l];
  const std::size_t n = b.deg.size(), stride = detail::tensor_stride(b.deg, l), lines = b.c.size() / (p + 1);
  std::vector<T> w(p + 1);
  const T s = T(1) - t, two(2);
  // At t = 1/2 one sum and one halving per step (the same value: halving is exact in binary
  // floats and rationals); not in double, where the sum could overflow where the products do not.
  const bool half = !std::is_floating_point_v<T> && t * two == T(1);
  std::vector<int> idx(n);
  auto reduced = b.deg;
  reduced[l] = 0;
  for (std::size_t line = 0; line < lines; ++line) {
    detail::unflatten(line, reduced, idx);
    std::size_t base = 0;
    for (std::size_t k = 0; k < n; ++k) base += idx[k] * detail::tensor_stride(b.deg, static_cast<int>(k));
    for (int i = 0; i <= p; ++i) w[i] = b.c[base + i * stride];
    for (int r = 0; r <= p; ++r) {
      L.c[base + r * stride] = w[0];
      R.c[base + (p - r) * stride] = w[p - r];
      if (half)
        for (int i = 0; i < p - r; ++i) {
          w[i] += w[i + 1];
          w[i] /= two;
        }
      else
        for (int i = 0; i < p - r; ++i) w[i] = w[i] * s + w[i + 1] * t;
    }
  }
  return {std::move(L), std::move(R)};
}

/// Whether T offers the fraction-free halving (spline/arith.hpp: ArithTraits<T>::halves).
template <class T>
concept FractionFreeHalves = requires(const std::vector<T>& v, const std::vector<int>& d, std::vector<std::vector<T>>& out) {
  ArithTraits<T>::halves(v, d, out);
};

/// The 2^k parts of b (k = b.deg.size()) halved at 1/2 in every direction, each reparametrized
/// onto [0, 1]^k: part K has side (K >> (k-1-l)) & 1 in direction l (0 the lower half), the order
/// of bern_split at 1/2 in direction 0, then 1, ... (which floats run; an exact arithmetic may
/// halve on integers with one reduction per coefficient: the same values).
template <class T>
std::vector<Bernstein<T>> bern_halves(const Bernstein<T>& b) {
  const std::size_t k = b.deg.size();
  std::vector<Bernstein<T>> parts;
  if constexpr (FractionFreeHalves<T>) {
    std::vector<std::vector<T>> out(std::size_t{1} << k, std::vector<T>(b.c.size()));
    ArithTraits<T>::halves(b.c, b.deg, out);
    parts.reserve(out.size());
    for (auto& c : out) parts.push_back(Bernstein<T>{b.deg, std::move(c)});
  } else {
    parts.push_back(b);
    const T half = T(1) / T(2);
    for (std::size_t l = 0; l < k; ++l) {
      std::vector<Bernstein<T>> next;
      next.reserve(2 * parts.size());
      for (const auto& g : parts) {
        auto [L, R] = bern_split(g, static_cast<int>(l), half);
        next.push_back(std::move(L));
        next.push_back(std::move(R));
      }
      parts = std::move(next);
    }
  }
  return parts;
}

/// b restricted to [a, c] in direction l (0 <= a < c <= 1), reparametrized onto [0, 1].
template <class T>
Bernstein<T> bern_restrict(Bernstein<T> b, int l, const T& a, const T& c) {
  if (T(0) < a) b = bern_split(b, l, a).second;
  const T top = (c - a) / (T(1) - a);  // c in the coordinates of [a, 1]
  if (top < T(1)) b = bern_split(b, l, top).first;
  return b;
}

/// b with direction l fixed at its end (side 0: t_l = 0, side 1: t_l = 1): one direction fewer.
template <class T>
Bernstein<T> bern_face(const Bernstein<T>& b, int l, int side) {
  Bernstein<T> out;
  const std::size_t n = b.deg.size();
  for (std::size_t k = 0; k < n; ++k)
    if (static_cast<int>(k) != l) out.deg.push_back(b.deg[k]);
  if (out.deg.empty()) out.deg.push_back(0);  // a constant
  out.c.resize(detail::tensor_size(out.deg));
  std::vector<int> idx(n), odx(out.deg.size());
  for (std::size_t i = 0; i < b.c.size(); ++i) {
    detail::unflatten(i, b.deg, idx);
    if (idx[l] != (side ? b.deg[l] : 0)) continue;
    std::size_t o = 0, s = 1;
    for (std::size_t k = 0; k < n; ++k) {
      if (static_cast<int>(k) == l) continue;
      o += idx[k] * s;
      s *= b.deg[k] + 1;
    }
    out.c[o] = b.c[i];
  }
  return out;
}

/// b with direction l fixed at t in [0, 1] (one direction fewer): the face at an end, else the
/// face of the part above t.
template <class T>
Bernstein<T> bern_fix(const Bernstein<T>& b, int l, const T& t) {
  if (T(0) < t && t < T(1)) return bern_face(bern_split(b, l, t).second, l, 0);
  return bern_face(b, l, t == T(0) ? 0 : 1);
}

/// The value at x in [0, 1]^n (de Casteljau, direction by direction).
template <class T>
T bern_value(const Bernstein<T>& b, const std::vector<T>& x) {
  if constexpr (FractionFreeDeCasteljau<T>) return ArithTraits<T>::tensor_value(b.c, b.deg, x);
  std::vector<T> cur = b.c;
  std::vector<int> deg = b.deg;
  for (std::size_t l = 0; l < deg.size(); ++l) {
    // Reduce direction l (now the fastest of the remaining ones) to its value at x[l].
    const int p = deg[l];
    const std::size_t lines = cur.size() / (p + 1);
    std::vector<T> next(lines);
    const T s = T(1) - x[l];
    std::vector<T> w(p + 1);
    for (std::size_t line = 0; line < lines; ++line) {
      for (int i = 0; i <= p; ++i) w[i] = cur[line * (p + 1) + i];
      for (int r = p; r > 0; --r)
        for (int i = 0; i < r; ++i) w[i] = w[i] * s + w[i + 1] * x[l];
      next[line] = w[0];
    }
    cur = std::move(next);
  }
  return cur[0];
}

/// +1 when every coefficient is > 0, -1 when every one is < 0, else 0 (the convex hull property:
/// a definite sign is a certificate that b has no zero on the box).
template <class T>
int bern_sign(const Bernstein<T>& b) {
  bool pos = true, neg = true;
  for (const T& x : b.c) {
    pos = pos && T(0) < x;
    neg = neg && x < T(0);
  }
  return pos ? 1 : neg ? -1 : 0;
}

/// The smallest and largest coefficient: a range of b's values on the box.
template <class T>
std::pair<T, T> bern_range(const Bernstein<T>& b) {
  T lo = b.c[0], hi = b.c[0];
  for (const T& x : b.c) {
    if (x < lo) lo = x;
    if (hi < x) hi = x;
  }
  return {lo, hi};
}

/// One homogeneous coordinate of a Bezier piece as a tensor Bernstein polynomial: c < q the
/// coordinate times the weight (w P_c; P_c for a polynomial spline), c == q the weight (1 for a
/// polynomial spline).
template <class T>
Bernstein<T> bern_coordinate(const BSpline<T>& piece, int c) {
  Bernstein<T> b;
  b.deg = piece.degrees;
  const std::size_t n = piece.size(), q = static_cast<std::size_t>(piece.q);
  b.c.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const T w = piece.is_rational() ? piece.weights[i] : T(1);
    b.c[i] = c == piece.q ? w : T(w * piece.points[i * q + c]);
  }
  return b;
}

}  // namespace splinex
