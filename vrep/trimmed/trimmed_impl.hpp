// Trimmed V-cells on exact implicit regions (vrep/trimmed/trimmed.hpp): the templates, instantiated in
// vrep/instances.cpp.
#pragma once
#include <algorithm>
#include <functional>
#include <map>
#include <deque>
#include <iterator>
#include <optional>
#include <queue>

#include "base/verdict.hpp"
#include "spline/bezier.hpp"
#include "spline/insert.hpp"
#include "spline/knots.hpp"
#include "vrep/boolean/boolean_impl.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/primitives/primitives_impl.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

template <class T>
int Poly3<T>::degree() const {
  int k = -1;
  for (const auto& [e, c] : terms) k = std::max(k, e[0] + e[1] + e[2]);
  return k;
}

template <class T>
Region<T> region_leaf(Poly3<T> g, std::string label) {
  for (auto it = g.terms.begin(); it != g.terms.end();)
    it = it->second == T(0) ? g.terms.erase(it) : std::next(it);
  if (g.terms.empty()) throw ValidationError("region" + (label.empty() ? std::string() : " (" + label + ")"), "has the zero polynomial as a leaf",
                                             "give a non-zero polynomial g (the leaf is g >= 0)");
  for (const auto& [e, c] : g.terms)
    if (e[0] < 0 || e[1] < 0 || e[2] < 0) throw ValidationError("region", "has a negative exponent", "give exponents >= 0");
  Region<T> r;
  r.kind = Region<T>::leaf;
  r.g = std::move(g);
  r.label = std::move(label);
  return r;
}
namespace vrep_detail {
template <class T>
Region<T> region_of(typename Region<T>::Kind kind, std::vector<Region<T>> parts) {
  Region<T> r;
  r.kind = kind;
  r.parts = std::move(parts);
  return r;
}
}  // namespace vrep_detail
template <class T>
Region<T> region_and(std::vector<Region<T>> parts) {
  return vrep_detail::region_of(Region<T>::all_of, std::move(parts));
}
template <class T>
Region<T> region_or(std::vector<Region<T>> parts) {
  return vrep_detail::region_of(Region<T>::any_of, std::move(parts));
}
template <class T>
Region<T> region_not(Region<T> x) {
  if (x.kind == Region<T>::complement) return std::move(x.parts.front());
  Region<T> r;
  r.kind = Region<T>::complement;
  r.parts.push_back(std::move(x));
  return r;
}

template <class T>
Region<T> region_cases(std::vector<std::pair<Region<T>, Region<T>>> cases) {
  Region<T> r;
  r.kind = Region<T>::cases;
  for (auto& [piece, formula] : cases) {
    r.parts.push_back(std::move(piece));
    r.parts.push_back(std::move(formula));
  }
  return r;
}

namespace vrep_detail {

template <class T>
Poly3<T> poly_add(Poly3<T> a, const Poly3<T>& b, const T& s = T(1)) {
  for (const auto& [e, c] : b.terms) {
    T& x = a.terms[e];
    x += s * c;
  }
  for (auto it = a.terms.begin(); it != a.terms.end();)
    it = it->second == T(0) ? a.terms.erase(it) : std::next(it);
  return a;
}
template <class T>
Poly3<T> poly_mul(const Poly3<T>& a, const Poly3<T>& b) {
  Poly3<T> r;
  for (const auto& [e, c] : a.terms)
    for (const auto& [f, d] : b.terms) r.terms[{e[0] + f[0], e[1] + f[1], e[2] + f[2]}] += c * d;
  for (auto it = r.terms.begin(); it != r.terms.end();)
    it = it->second == T(0) ? r.terms.erase(it) : std::next(it);
  return r;
}
/// c0 + c1 x + c2 y + c3 z.
template <class T>
Poly3<T> poly_linear(const T& c0, const T& c1, const T& c2, const T& c3) {
  Poly3<T> p;
  if (c0 != T(0)) p.terms[{0, 0, 0}] = c0;
  if (c1 != T(0)) p.terms[{1, 0, 0}] = c1;
  if (c2 != T(0)) p.terms[{0, 1, 0}] = c2;
  if (c3 != T(0)) p.terms[{0, 0, 1}] = c3;
  return p;
}
template <class T>
Poly3<T> poly_pow(const Poly3<T>& p, int k) {
  Poly3<T> r = poly_linear(T(1), T(0), T(0), T(0));
  for (int i = 0; i < k; ++i) r = poly_mul(r, p);
  return r;
}

/// The leaves of a region in depth-first order.
template <class T>
void collect_leaves(const Region<T>& R, std::vector<const Poly3<T>*>& out) {
  if (R.kind == Region<T>::leaf) {
    if (R.alias < 0) out.push_back(&R.g);
    return;
  }
  for (const auto& p : R.parts) collect_leaves(p, out);
}

/// Kleene's three-valued combination of the leaves' truths (consumed in collect_leaves' order).
template <class T>
Truth combine(const Region<T>& R, const std::vector<Truth>& leaf, std::size_t& k) {
  switch (R.kind) {
    case Region<T>::leaf: {
      if (R.alias < 0) return leaf[k++];
      const Truth t = leaf[static_cast<std::size_t>(R.alias)];
      return !R.flip ? t : t == Truth::in ? Truth::out : t == Truth::out ? Truth::in : Truth::mixed;
    }
    case Region<T>::complement: {
      const Truth t = combine(R.parts.front(), leaf, k);
      return t == Truth::in ? Truth::out : t == Truth::out ? Truth::in : Truth::mixed;
    }
    case Region<T>::all_of: {
      Truth t = Truth::in;
      for (const auto& p : R.parts) t = std::min(t, combine(p, leaf, k));
      return t;
    }
    case Region<T>::any_of: {
      Truth t = Truth::out;
      for (const auto& p : R.parts) t = std::max(t, combine(p, leaf, k));
      return t;
    }
    case Region<T>::cases: {
      // In: every case has its piece out or its formula in; out: its piece out or its formula out.
      bool in = true, out = true, some_piece = false, some_in = false;
      const bool planted = vrep_testing::is_planted(vrep_testing::Plant::cases_ignore_pieces);
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2) {
        const Truth c = combine(R.parts[i], leaf, k), f = combine(R.parts[i + 1], leaf, k);
        some_in = some_in || f == Truth::in;
        if (planted) continue;
        if (c == Truth::out) continue;
        some_piece = true;
        in = in && f == Truth::in;
        out = out && f == Truth::out;
      }
      if (planted) return some_in ? Truth::in : Truth::mixed;
      // No piece at all (a sign pattern the pieces' cover rules out, which callers that force
      // leaves may ask about): the union reading, out.
      if (!some_piece) return Truth::out;
      return in ? Truth::in : out ? Truth::out : Truth::mixed;
    }
  }
  return Truth::mixed;
}

/// Which leaves can still change the formula's truth, given their truths on a box (`lt`, collect
/// order; mixed: open): not a leaf under a part the others decide (a false part of an all_of, a
/// true part of an any_of, the formula of a case whose piece is out). Marks the open leaves that
/// can in `marks`; returns the part's value (1 true, 0 false) or -1 (open). A leaf that is not live
/// may keep any truth Kleene's logic allows it (its last one): the formula's truth does not change.
template <class T>
int mark_live(const Region<T>& R, const std::vector<Truth>& lt, std::size_t& k, std::vector<std::size_t>& marks) {
  auto value = [](Truth t) { return t == Truth::in ? 1 : t == Truth::out ? 0 : -1; };
  switch (R.kind) {
    case Region<T>::leaf: {
      const std::size_t at = R.alias < 0 ? k++ : static_cast<std::size_t>(R.alias);
      const int v = value(lt[at]);
      if (v >= 0) return R.flip ? 1 - v : v;
      marks.push_back(at);
      return -1;
    }
    case Region<T>::complement: {
      const int v = mark_live(R.parts.front(), lt, k, marks);
      return v < 0 ? v : 1 - v;
    }
    case Region<T>::all_of:
    case Region<T>::any_of: {
      const int absorbing = R.kind == Region<T>::all_of ? 0 : 1;
      const std::size_t first = marks.size();
      bool open = false, absorbed = false;
      for (const auto& p : R.parts) {
        const int v = mark_live(p, lt, k, marks);  // (every part: k must pass all leaves)
        if (v == absorbing) absorbed = true;
        else if (v < 0) open = true;
      }
      if (absorbed || !open) {
        marks.resize(first);
        return absorbed ? absorbing : 1 - absorbing;
      }
      return -1;
    }
    case Region<T>::cases: {
      const std::size_t first = marks.size();
      int common = -2;  // the formulas' common value over the cases whose piece is not out (-1: differ or open)
      bool any = false;
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2) {
        const std::size_t before = marks.size();
        const int c = mark_live(R.parts[i], lt, k, marks);
        const int f = mark_live(R.parts[i + 1], lt, k, marks);
        if (c == 0) {
          marks.resize(before);
          continue;
        }
        any = true;
        common = common == -2 ? f : common == f ? f : -1;
      }
      if (!any || common >= 0) {
        marks.resize(first);
        return any ? common : 0;
      }
      return -1;
    }
  }
  return -1;
}

/// The leaves live on a box (mark_live over the whole formula); true when the formula is open.
template <class T>
bool live_leaves(const Region<T>& R, const std::vector<Truth>& lt, std::vector<char>& live) {
  live.assign(lt.size(), 0);
  std::vector<std::size_t> marks;
  std::size_t k = 0;
  const int v = mark_live(R, lt, k, marks);
  for (std::size_t at : marks) live[at] = 1;
  return v < 0;
}

/// Whether the formula, the leaves outside `which` fixed at `fixed`, is decided for every sign
/// pattern of the leaves in `which` and depends on each of them (they meet at a corner or along
/// an edge of the cell's boundary there, rather than one passing the other by).
template <class T>
bool depends_on_each(const Region<T>& R, std::vector<Truth> fixed, const std::vector<std::size_t>& which) {
  const std::size_t m = which.size();
  std::vector<Truth> value(std::size_t(1) << m);
  for (std::size_t pattern = 0; pattern < value.size(); ++pattern) {
    for (std::size_t q = 0; q < m; ++q) fixed[which[q]] = (pattern >> q) & 1 ? Truth::in : Truth::out;
    std::size_t k = 0;
    value[pattern] = combine(R, fixed, k);
    if (value[pattern] == Truth::mixed) return false;
  }
  for (std::size_t q = 0; q < m; ++q) {
    bool depends = false;
    for (std::size_t pattern = 0; pattern < value.size(); ++pattern) depends = depends || value[pattern] != value[pattern ^ (std::size_t(1) << q)];
    if (!depends) return false;
  }
  return true;
}

template <class T>
Truth value_truth(const T& v, const T& eps) {
  return eps < v ? Truth::in : v < -eps ? Truth::out : Truth::mixed;
}

/// The truth of G >= 0 on a box from its Bernstein coefficients (within eps in float).
template <class T>
Truth coefficient_truth(const Bernstein<T>& G, const T& eps) {
  bool nonneg = true, nonpos = true;
  for (const auto& x : G.c) {
    nonneg = nonneg && !(x < -eps);
    nonpos = nonpos && !(eps < x);
  }
  if (nonpos) return Truth::out;  // also when G = 0 within eps: no interior there
  return nonneg ? Truth::in : Truth::mixed;
}

/// The coefficients of the region's leaves that the subdivision boxes alive carry, against the
/// limit (counted as they are made: a box carries only the leaves that can still change its truth).
struct CarriedCoefficients {
  const Limits& limits;
  std::size_t n = 0;
  template <class Leaves>
  static std::size_t of(const Leaves& G) {
    std::size_t k = 0;
    for (const auto& g : G) k += g.c.size();
    return k;
  }
  void add(std::size_t k, const std::string& who = "the boxes") {
    n += k;
    if (n > limits.max_control_points)
      throw SizeLimitError("region composed on the subdivision boxes",
                           who + " would carry " + std::to_string(n) + " coefficients of the region's leaves, above the limit of " +
                               std::to_string(limits.max_control_points),
                           "lower --boxes, or raise the limit with --max-control-points");
  }
  void remove(std::size_t k) { n -= k; }
};

/// Whether every Bernstein coefficient is > eps or every one < -eps (then every value is too).
template <class T>
bool strictly_signed(const Bernstein<T>& G, const T& eps) {
  bool pos = true, neg = true;
  for (const auto& x : G.c) {
    pos = pos && eps < x;
    neg = neg && x < -eps;
  }
  return !G.c.empty() && (pos || neg);
}

/// Positive weights: then the sign of g o T is the sign of the composed numerator W^k g(X/W, ...).
template <class T>
void require_positive_weights(const BSpline<T>& V) {
  for (const auto& w : V.weights)
    if (!(T(0) < w))
      throw DomainError("trivariate.weights", "has a weight that is not positive: the sign of g o T is not the sign of its numerator", "give positive weights");
}

/// Clamped in every direction, so that the faces and edges of V's domain are layers of its net.
template <class T>
void require_clamped(const BSpline<T>& V) {
  for (int d = 0; d < V.dim(); ++d)
    if (!is_clamped(V.knots[d], V.degrees[d], V.count(d)))
      throw ValidationError("trivariate.knots[" + std::to_string(d) + "]", "is not clamped: its faces and edges are not layers of the net",
                            "clamp the trivariate first");
}

template <class T>
bool all_zero(const Bernstein<T>& G) {
  return std::all_of(G.c.begin(), G.c.end(), [](const T& x) { return x == T(0); });
}

/// Limits before the work: each leaf composed with V has prod (k p_d + 1) coefficients per Bezier
/// piece; all leaves together are bounded like one spline's control points. Returns that count.
template <class T>
std::size_t composed_leaves_size(const BSpline<T>& V, const std::vector<const Poly3<T>*>& leaves, const Limits& limits) {
  std::size_t per_piece = 0;
  for (const auto* g : leaves) {
    if (g->degree() > 8) throw SizeLimitError("region", "has a leaf of degree " + std::to_string(g->degree()) + " (at most 8)", "give polynomials of degree <= 8");
    std::size_t n = 1;
    for (int d = 0; d < 3; ++d) {
      limits.check_degree(static_cast<long>(g->degree()) * V.degrees[d], "region composed with the trivariate");
      n = checked_product(n, static_cast<std::size_t>(g->degree() * V.degrees[d] + 1), limits, "region composed with the trivariate");
    }
    per_piece += n;
  }
  limits.check_count(per_piece, "region composed with the trivariate");
  return per_piece;
}

/// A tensor polynomial in the scaled Bernstein form with integer coefficients: s_i = c_i prod_d
/// C(n_d, i_d) times a common positive factor. Products are plain convolutions (no division, no
/// gcd: the exact composition's cost is integer multiplication, as in fraction-free elimination).
struct IntTensor {
  std::array<int, 3> deg{0, 0, 0};
  std::vector<Integer> c;
};

inline IntTensor int_product(const IntTensor& a, const IntTensor& b) {
  IntTensor r;
  for (int d = 0; d < 3; ++d) r.deg[d] = a.deg[d] + b.deg[d];
  const std::size_t a0 = a.deg[0] + 1, a1 = a.deg[1] + 1, a2 = a.deg[2] + 1;
  const std::size_t b0 = b.deg[0] + 1, b1 = b.deg[1] + 1, b2 = b.deg[2] + 1;
  const std::size_t r0 = r.deg[0] + 1, r1 = r.deg[1] + 1;
  r.c.assign(r0 * r1 * (r.deg[2] + 1), Integer(0));
  for (std::size_t i2 = 0; i2 < a2; ++i2)
    for (std::size_t i1 = 0; i1 < a1; ++i1)
      for (std::size_t i0 = 0; i0 < a0; ++i0) {
        const Integer& x = a.c[i0 + a0 * (i1 + a1 * i2)];
        if (x == 0) continue;
        for (std::size_t j2 = 0; j2 < b2; ++j2)
          for (std::size_t j1 = 0; j1 < b1; ++j1) {
            Integer* out = &r.c[i0 + r0 * ((i1 + j1) + r1 * (i2 + j2))];
            const Integer* y = &b.c[b0 * (j1 + b1 * j2)];
            for (std::size_t j0 = 0; j0 < b0; ++j0)
              mpz_addmul(out[j0].backend().data(), x.backend().data(), y[j0].backend().data());
          }
      }
  return r;
}

/// Integer tables for exact arithmetic: binomials (kept per thread).
inline const std::vector<Integer>& integer_binomials(int n) {
  thread_local std::map<int, std::vector<Integer>> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  std::vector<Integer> row(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) mpz_bin_uiui(row[k].backend().data(), static_cast<unsigned long>(n), static_cast<unsigned long>(k));
  return cache.emplace(n, std::move(row)).first->second;
}

/// prod_l C(deg_l, idx_l) for every flat index (integers), kept per thread.
inline const std::vector<Integer>& tensor_binomial_integers(const std::vector<int>& deg) {
  thread_local std::map<std::vector<int>, std::vector<Integer>> cache;
  auto it = cache.find(deg);
  if (it != cache.end()) return it->second;
  std::vector<Integer> out(detail::tensor_size(deg), Integer(1));
  std::vector<int> idx(deg.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    detail::unflatten(i, deg, idx);
    for (std::size_t l = 0; l < deg.size(); ++l) out[i] *= integer_binomials(deg[l])[idx[l]];
  }
  return cache.emplace(deg, std::move(out)).first->second;
}

/// The powers 0..k of a Bezier piece's homogeneous coordinates W, X, Y, Z and their products,
/// made once per piece and extended as leaves of higher degree ask (a piece's many leaves share
/// them). In exact arithmetic as integer tensors (IntTensor) over the piece's common denominator.
template <class T>
struct PiecePowers {
  const BSpline<T>* piece = nullptr;
  std::array<std::vector<Bernstein<T>>, 4> pw;  // pw[c][i]: coordinate c (0 = W) to the power i
  // Exact arithmetic: the coordinates times D (the lcm of their denominators) as integer tensors;
  // products X^a Y^b and Z^c W^d by their exponents.
  Integer D{1};
  std::array<IntTensor, 4> base;
  std::map<std::pair<int, int>, IntTensor> xy, zw;
  bool integer_ready = false;
  explicit PiecePowers(const BSpline<T>& p) : piece(&p) {}
  const Bernstein<T>& at(int c, int i) {
    if (pw[c].empty()) pw[c].push_back(Bernstein<T>{{0, 0, 0}, {T(1)}});
    while (static_cast<int>(pw[c].size()) <= i) {
      if (pw[c].size() == 1) pw[c].push_back(homogeneous(*piece, c));
      else pw[c].push_back(mul(pw[c].back(), pw[c][1]));
    }
    return pw[c][static_cast<std::size_t>(i)];
  }
  void prepare_integer() {
    if (integer_ready) return;
    integer_ready = true;
    std::array<const Bernstein<T>*, 4> h;
    for (int c = 0; c < 4; ++c) {
      h[c] = &at(c, 1);
      for (const auto& x : h[c]->c) mpz_lcm(D.backend().data(), D.backend().data(), boost::multiprecision::denominator(x).backend().data());
    }
    for (int c = 0; c < 4; ++c) {
      for (int d = 0; d < 3; ++d) base[c].deg[d] = h[c]->deg[d];
      const auto& binom = tensor_binomial_integers({base[c].deg[0], base[c].deg[1], base[c].deg[2]});
      for (std::size_t i = 0; i < h[c]->c.size(); ++i) {
        const T v = h[c]->c[i] * T(D);
        base[c].c.push_back(boost::multiprecision::numerator(v) * binom[i]);
      }
    }
  }
  /// a^i b^j for coordinates a, b (IntTensor; i = j = 0: the constant 1).
  const IntTensor& pair_power(std::map<std::pair<int, int>, IntTensor>& cache, int a, int b, int i, int j) {
    const auto key = std::make_pair(i, j);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    IntTensor r;
    r.c = {Integer(1)};
    if (i > 0) r = pair_power(cache, a, b, i - 1, j), r = int_product(r, base[a]);
    else if (j > 0) r = pair_power(cache, a, b, i, j - 1), r = int_product(r, base[b]);
    return cache.emplace(key, std::move(r)).first->second;
  }
};

/// W^k g(X / W, Y / W, Z / W) on a Bezier piece (k the degree of g), exact.
template <class T>
Bernstein<T> compose_leaf(const Poly3<T>& g, PiecePowers<T>& P) {
  const int k = g.degree();
  std::vector<int> deg(3);
  for (int d = 0; d < 3; ++d) deg[d] = k * P.piece->degrees[d];
  Bernstein<T> G{deg, std::vector<T>(detail::tensor_size(deg), T(0))};
  if (k == 1) {  // a plane: c0 W + c1 X + c2 Y + c3 Z, no products
    for (const auto& [e, c] : g.terms) {
      const int coord = e[0] ? 1 : e[1] ? 2 : e[2] ? 3 : 0;
      const Bernstein<T>& h = P.at(coord, 1);
      for (std::size_t i = 0; i < G.c.size(); ++i) G.c[i] += c * h.c[i];
    }
    return G;
  }
  if constexpr (std::is_same_v<T, Rational>) {
    // Integer tensors: g's coefficients times E (the lcm of their denominators); the terms grouped
    // by their Z and W exponents, sum c X^a Y^b within a group, one product with Z^c W^d each.
    P.prepare_integer();
    Integer E(1);
    for (const auto& [e, c] : g.terms) mpz_lcm(E.backend().data(), E.backend().data(), boost::multiprecision::denominator(c).backend().data());
    std::map<std::pair<int, int>, IntTensor> groups;
    for (const auto& [e, c] : g.terms) {
      const IntTensor& xy = P.pair_power(P.xy, 1, 2, e[0], e[1]);
      IntTensor& sum = groups[{e[2], k - e[0] - e[1] - e[2]}];
      if (sum.c.empty()) {
        sum.deg = xy.deg;
        sum.c.assign(xy.c.size(), Integer(0));
      }
      const Integer ci = boost::multiprecision::numerator(T(c * T(E)));
      for (std::size_t i = 0; i < xy.c.size(); ++i) mpz_addmul(sum.c[i].backend().data(), ci.backend().data(), xy.c[i].backend().data());
    }
    std::vector<Integer> S(G.c.size(), Integer(0));
    for (const auto& [zw, sum] : groups) {
      const IntTensor t = int_product(sum, P.pair_power(P.zw, 3, 0, zw.first, zw.second));
      for (std::size_t i = 0; i < S.size(); ++i) S[i] += t.c[i];
    }
    // Back to the Bernstein coefficients' exact values: S / (prod C(k n_d, i_d) D^k E).
    const auto& binom = tensor_binomial_integers(deg);
    Integer scale = E;
    for (int i = 0; i < k; ++i) scale *= P.D;
    for (std::size_t i = 0; i < S.size(); ++i) G.c[i] = T(S[i]) / T(binom[i] * scale);
    return G;
  } else {
    for (const auto& [e, c] : g.terms) {
      const Bernstein<T> t = mul(mul(P.at(1, e[0]), P.at(2, e[1])), mul(P.at(3, e[2]), P.at(0, k - e[0] - e[1] - e[2])));
      for (std::size_t i = 0; i < G.c.size(); ++i) G.c[i] += c * t.c[i];
    }
    return G;
  }
}
template <class T>
Bernstein<T> compose_leaf(const Poly3<T>& g, const BSpline<T>& piece) {
  PiecePowers<T> P(piece);
  return compose_leaf(g, P);
}

/// The corner coefficient (s0, s1, s2) of a tensor Bernstein polynomial: its value there.
/// No inner knot of multiplicity above the degree: a trivariate that jumps there (C^-1) has a cell
/// that is not a closed set, and its pieces' polynomials do not meet across the joint.
template <class T>
void require_continuous(const BSpline<T>& V) {
  for (int d = 0; d < 3; ++d)
    for (const T& b : breakpoints(V.knots[d], V.degrees[d], V.count(d)))
      if (V.domain_lo(d) < b && b < V.domain_hi(d) && multiplicity(V.knots[d], b) > static_cast<std::size_t>(V.degrees[d]))
        throw DomainError("trivariate.knots", "has an inner knot of multiplicity above the degree: the trivariate jumps there and its cell is not a closed set",
                          "give a trivariate continuous across its inner knots");
}

/// The checks before a trimmed cell's subdivision, before any work (trimmed_topology,
/// trimmed_curves): V a valid Jacobian input, clamped, with positive weights, continuous across
/// its inner knots; a box budget of at least 8; the region composed on every box within the
/// limits. The region's leaves (collect order).
template <class T>
std::vector<const Poly3<T>*> checked_trim_leaves(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes, const Limits& limits) {
  require_jacobian_input(V, limits);
  if (max_boxes < 8) throw ValidationError("boxes", "must be at least 8", "give a larger box budget");
  require_clamped(V);
  require_positive_weights(V);
  require_continuous(V);
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(trim, leaves);
  checked_product(composed_leaves_size(V, leaves, limits) + 1, max_boxes, limits, "region composed on the subdivision boxes");
  return leaves;
}

/// The leaves composed with V on each Bezier piece of V, with the piece's parameter box.
template <class T>
struct LeafPiece {
  std::vector<Bernstein<T>> G;  // per leaf (collect order), Bernstein form on the piece
  std::array<T, 3> lo, hi;
};
template <class T>
std::vector<LeafPiece<T>> leaf_pieces(const BSpline<T>& V, const std::vector<const Poly3<T>*>& leaves, const Limits& limits) {
  const BezierForm<T> F = bezier_form(V, limits);
  std::vector<LeafPiece<T>> pieces(F.size());
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto pc = F.piece(k);
    for (const auto* g : leaves) pieces[k].G.push_back(compose_leaf(*g, pc.spline));
    for (int d = 0; d < 3; ++d) {
      pieces[k].lo[d] = pc.box[d].first;
      pieces[k].hi[d] = pc.box[d].second;
    }
  }
  return pieces;
}

template <class T>
const T& corner(const Bernstein<T>& b, int s0, int s1, int s2) {
  const std::size_t n0 = b.deg[0] + 1, n1 = b.deg[1] + 1;
  return b.c[(s0 ? b.deg[0] : 0) + n0 * ((s1 ? b.deg[1] : 0) + n1 * (s2 ? b.deg[2] : 0))];
}

/// Subdivision of one trivariate against a region: classification and, optionally, the volume.
template <class T>
struct TrimRun {
  CellClass<T> cls;
  VolumeEnclosure<T> volume, moment;  // moment: of the point coordinate `coordinate` (if >= 0)
};

/// V and a field on its domain refined to the same breakpoints (each missing breakpoint inserted
/// once; bezier_form raises the multiplicities), so that their Bezier pieces correspond one to one.
template <class T>
std::pair<BSpline<T>, BSpline<T>> common_breakpoints(const BSpline<T>& V, const BSpline<T>& F, const Limits& limits) {
  BSpline<T> a = V, b = F;
  for (int d = 0; d < 3; ++d) {
    const auto ba = breakpoints(V.knots[d], V.degrees[d], V.count(d)), bb = breakpoints(F.knots[d], F.degrees[d], F.count(d));
    std::vector<T> to_a, to_b;
    std::set_difference(bb.begin(), bb.end(), ba.begin(), ba.end(), std::back_inserter(to_a));
    std::set_difference(ba.begin(), ba.end(), bb.begin(), bb.end(), std::back_inserter(to_b));
    if (!to_a.empty()) a = refine_knots(a, d, to_a, limits);
    if (!to_b.empty()) b = refine_knots(b, d, to_b, limits);
  }
  return {std::move(a), std::move(b)};
}

/// The checks of an integrand field against its cell's trivariate (`name` for messages).
template <class T>
void require_field(const BSpline<T>& V, const BSpline<T>& F, int component, const std::string& name, const Limits& limits) {
  require_field_on(V, F, name, limits);
  if (component < 0 || component >= F.q)
    throw ValidationError(name + ".component", "is not a component of the field (it has " + std::to_string(F.q) + ")",
                          "give 0 <= component < " + std::to_string(F.q));
  if (F.is_rational())
    throw DomainError(name, "is rational: the integrand F N / (w W^4) has a second denominator and its enclosure is not built",
                      "give a polynomial field");
}

template <class T>
TrimRun<T> run_trim(const BSpline<T>& V0, const Region<T>& trim, std::size_t max_boxes, bool want_volume, const T& eps, const Limits& limits,
                    int coordinate = -1, const BSpline<T>* field = nullptr) {
  require_jacobian_input(V0, limits);
  // With a field the integrand is its component `coordinate` times det J = N / W^4 (power 4);
  // without one, the point coordinate X_c / W times det J (power 5).
  std::optional<std::pair<BSpline<T>, BSpline<T>>> refined;
  if (field) {
    require_field(V0, *field, coordinate, "field", limits);
    refined = common_breakpoints(V0, *field, limits);
  }
  const BSpline<T>& V = refined ? refined->first : V0;
  const int power = field ? 4 : 5;
  if (max_boxes < 1) throw ValidationError("boxes", "must be at least 1", "give a positive box budget");
  require_positive_weights(V);
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(trim, leaves);
  // Limits before the work: all leaves composed on one piece; the boxes' compositions are counted
  // as they are made (a box carries only the leaves that can still change its truth).
  const std::size_t per_piece = composed_leaves_size(V, leaves, limits);
  if (!field && coordinate >= V.q) throw ValidationError("coordinate", "is not a point coordinate of the trivariate", "give 0 <= coordinate < q");
  struct Box {
    std::vector<Bernstein<T>> G;   // per leaf: its composition, or empty where it is not carried
    std::vector<Truth> lt;    // per leaf: its truth on the box (not carried: its last one)
    Bernstein<T> N, W, Q;  // Q = X_c N: the moment's numerator (over W^5)
    std::array<T, 3> lo, hi;  // in the trivariate's parameters
    T vol;                    // share of its piece's unit cube
    Truth truth = Truth::mixed;
  };
  TrimRun<T> out;
  auto& cls = out.cls;
  bool has_in = false, has_out = false;
  CarriedCoefficients carried{limits};
  auto count = [](const Box& b) { return CarriedCoefficients::of(b.G); };
  auto take = [&](std::size_t n) { carried.add(n); };
  auto evaluate = [&](Box& b) {
    for (std::size_t l = 0; l < b.G.size(); ++l)
      if (!b.G[l].c.empty()) b.lt[l] = coefficient_truth(b.G[l], eps);
    std::size_t k = 0;
    b.truth = combine(trim, b.lt, k);
    if (b.truth == Truth::in) has_in = true;
    if (b.truth == Truth::out) has_out = true;
    if (b.truth != Truth::mixed) {
      b.G.clear();  // decided: its leaves are not needed again (an in-box stays in)
      return;
    }
    // Exact witnesses at the corners (the corner coefficients are G's values there; a leaf not
    // carried has one strict sign on the box, or does not change the formula's truth).
    for (int s = 0; s < 8; ++s) {
      if (!cls.inside.empty() && !cls.outside.empty()) break;
      std::vector<Truth> pt(b.lt);
      for (std::size_t l = 0; l < b.G.size(); ++l)
        if (!b.G[l].c.empty()) pt[l] = value_truth(corner(b.G[l], s & 1, (s >> 1) & 1, s >> 2), eps);
      std::size_t j = 0;
      const Truth t = combine(trim, pt, j);
      if (t == Truth::mixed) continue;
      auto& w = t == Truth::in ? cls.inside : cls.outside;
      if (!w.empty()) continue;
      w = {s & 1 ? b.hi[0] : b.lo[0], (s >> 1) & 1 ? b.hi[1] : b.lo[1], s >> 2 ? b.hi[2] : b.lo[2]};
    }
    // Release the leaves that no longer matter on the box and its parts: those the formula does not
    // depend on any more, and those of one strict sign (every corner value has that sign too).
    std::vector<char> live;
    live_leaves(trim, b.lt, live);
    // (A leaf decided with a zero coefficient keeps its values: a corner may lie on its surface.)
    for (std::size_t l = 0; l < b.G.size(); ++l) {
      if (b.G[l].c.empty() || live[l]) continue;
      if (b.lt[l] == Truth::mixed || strictly_signed(b.G[l], eps)) b.G[l] = Bernstein<T>{};
    }
  };
  std::deque<Box> todo;
  std::vector<Box> done;
  // Halves of a box across direction dir (exact de Casteljau on everything it carries).
  auto split_box = [&](const Box& b, int dir, Box* c) {
    for (int h = 0; h < 2; ++h) {
      c[h].lo = b.lo;
      c[h].hi = b.hi;
      c[h].vol = b.vol / T(2);
      c[h].G.resize(b.G.size());
      c[h].lt = b.lt;
    }
    for (std::size_t l = 0; l < b.G.size(); ++l)
      if (!b.G[l].c.empty()) std::tie(c[0].G[l], c[1].G[l]) = split_half(b.G[l], dir);
    if (want_volume) {
      std::tie(c[0].N, c[1].N) = split_half(b.N, dir);
      std::tie(c[0].W, c[1].W) = split_half(b.W, dir);
      if (coordinate >= 0) std::tie(c[0].Q, c[1].Q) = split_half(b.Q, dir);
    }
    const T mid = (b.lo[dir] + b.hi[dir]) / T(2);
    c[0].hi[dir] = mid;
    c[1].lo[dir] = mid;
  };
  const BezierForm<T> F = bezier_form(V, limits);
  std::optional<BezierForm<T>> FF;
  if (field && want_volume) FF = bezier_form(refined->second, limits);
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto pc = F.piece(k);
    Box b;
    // The planes first (cheap); then only the leaves the formula may still depend on.
    b.G.resize(leaves.size());
    b.lt.assign(leaves.size(), Truth::mixed);
    PiecePowers<T> powers(pc.spline);
    for (std::size_t l = 0; l < leaves.size(); ++l)
      if (leaves[l]->degree() <= 1) {
        b.G[l] = compose_leaf(*leaves[l], powers);
        b.lt[l] = coefficient_truth(b.G[l], eps);
      }
    std::vector<char> live;
    live_leaves(trim, b.lt, live);
    for (std::size_t l = 0; l < leaves.size(); ++l)
      if (leaves[l]->degree() > 1 && live[l]) b.G[l] = compose_leaf(*leaves[l], powers);
    if (want_volume) {
      b.N = jacobian_numerator(pc.spline);
      b.W = homogeneous(pc.spline, 0);
      if (FF) b.Q = mul(homogeneous(FF->piece(k).spline, coordinate + 1), b.N);
      else if (coordinate >= 0) b.Q = mul(homogeneous(pc.spline, coordinate + 1), b.N);
    }
    for (int d = 0; d < 3; ++d) {
      b.lo[d] = pc.box[d].first;
      b.hi[d] = pc.box[d].second;
    }
    b.vol = T(1);
    evaluate(b);
    take(count(b));
    (b.truth == Truth::mixed ? todo.push_back(std::move(b)) : done.push_back(std::move(b)));
  }
  // Breadth first: halve mixed boxes across their widest parameter side until none is left or
  // the budget is spent.
  // (Classification only: stop as soon as both sides are certified.)
  while (!todo.empty() && todo.size() + done.size() < max_boxes &&
         (want_volume || !((has_in || !cls.inside.empty()) && (has_out || !cls.outside.empty())))) {
    Box b = std::move(todo.front());
    todo.pop_front();
    carried.remove(count(b));
    int dir = 0;
    for (int d = 1; d < 3; ++d)
      if ((b.hi[dir] - b.lo[dir]) < (b.hi[d] - b.lo[d])) dir = d;
    Box c[2];
    split_box(b, dir, c);
    for (auto& x : c) {
      evaluate(x);
      take(count(x));
      (x.truth == Truth::mixed ? todo.push_back(std::move(x)) : done.push_back(std::move(x)));
    }
  }
  // The moment's bounds on a box: exact for a polynomial cell's in-box (the mean of Q's
  // coefficients), else the bounds of Q / W^power (Jensen / chord where Q has one sign, the extreme
  // coefficients' ratios otherwise); a mixed box holds between none and all of it.
  auto moment_bounds = [&](const Box& b, T& lo, T& hi) {
    if (!V.is_rational() && b.truth == Truth::in) {
      T sum(0);
      for (const auto& x : b.Q.c) sum += x;
      lo = hi = b.vol * sum / T(static_cast<long>(b.Q.c.size()));
      return;
    }
    // Jensen / chord of W^-power with the weight |Q| where Q has one sign (box_integral_bounds), the
    // plain ratio of extreme coefficients otherwise.
    box_integral_bounds(b.Q, b.W, b.vol, lo, hi, power);
    if (b.truth == Truth::mixed) {
      lo = std::min(T(0), lo);
      hi = std::max(T(0), hi);
    }
  };
  if (want_volume && coordinate >= 0) {
    // The rest of the budget: split the boxes (in or mixed) whose moment bounds are widest.
    struct Wide {
      T gap;
      std::size_t at;
      bool operator<(const Wide& o) const { return gap < o.gap; }
    };
    std::vector<Box> all;
    for (auto& b : done)
      if (b.truth != Truth::out) all.push_back(std::move(b));
    for (auto& b : todo) all.push_back(std::move(b));
    done.clear();
    todo.clear();
    std::priority_queue<Wide> wide;
    auto push = [&](std::size_t i) {
      if (all[i].truth == Truth::out) return;  // holds nothing: never split again
      T lo, hi;
      moment_bounds(all[i], lo, hi);
      wide.push({hi - lo, i});
    };
    for (std::size_t i = 0; i < all.size(); ++i) push(i);
    while (!wide.empty() && all.size() < max_boxes && T(0) < wide.top().gap) {
      const std::size_t i = wide.top().at;
      wide.pop();
      Box b = std::move(all[i]);
      // Across the direction where Q and W vary most (the moment's bounds are widest there).
      int dir = 0;
      T best(-1);
      for (int d = 0; d < 3; ++d) {
        T v = b.Q.deg[d] > 0 ? coefficient_variation(b.Q, d) : T(0);
        if (b.W.deg[d] > 0) v += coefficient_variation(b.W, d);
        if (best < v) {
          best = v;
          dir = d;
        }
      }
      Box c[2];
      carried.remove(count(b));
      split_box(b, dir, c);
      for (int h = 0; h < 2; ++h) {
        if (b.truth == Truth::in) c[h].truth = Truth::in;  // in stays in
        else evaluate(c[h]);
        take(count(c[h]));
      }
      all[i] = std::move(c[0]);
      push(i);
      if (c[1].truth != Truth::out) {
        all.push_back(std::move(c[1]));
        push(all.size() - 1);
      }
    }
    for (auto& b : all) (b.truth == Truth::mixed ? todo.push_back(std::move(b)) : done.push_back(std::move(b)));
    for (const auto& b : done) {
      if (b.truth != Truth::in) continue;
      T lo, hi;
      moment_bounds(b, lo, hi);
      out.moment.lower += lo;
      out.moment.upper += hi;
    }
    for (const auto& b : todo) {
      T lo, hi;
      moment_bounds(b, lo, hi);
      out.moment.lower += lo;
      out.moment.upper += hi;
    }
  }
  cls.boxes = todo.size() + done.size();
  cls.mixed = todo.size();
  const bool some_in = has_in || !cls.inside.empty(), some_out = has_out || !cls.outside.empty();
  cls.kind = todo.empty() ? cell_kind<T>(true, has_in, has_out) : cell_kind<T>(false, some_in, some_out);
  if (want_volume) {
    auto& v = out.volume;
    for (const auto& b : done) {
      if (b.truth != Truth::in) continue;
      T lo, hi;
      box_integral_bounds(b.N, b.W, b.vol, lo, hi);
      v.lower += lo;
      v.upper += hi;
    }
    // A mixed box holds between none and all of its volume: [min(0, lo), max(0, hi)] with the plain
    // bounds vol min N / max W^4 .. vol max N / min W^4 (no product: these boxes are many and small).
    for (const auto& b : todo) {
      T lo, hi;
      box_integral_bounds(b.N, b.W, b.vol, lo, hi, 4, true);
      v.lower += std::min(T(0), lo);
      v.upper += std::max(T(0), hi);
    }
    if (v.upper < T(0) || (v.upper == T(0) && v.lower < T(0))) {  // negatively oriented: det J < 0
      const T l = -v.upper;
      v.upper = -v.lower;
      v.lower = l;
      const T m = -out.moment.upper;
      out.moment.upper = -out.moment.lower;
      out.moment.lower = m;
    }
    out.moment.boxes = cls.boxes;
    v.boxes = cls.boxes;
  }
  return out;
}

template <class T>
bool trivially_true(const Region<T>& R) {
  return R.kind == Region<T>::all_of && R.parts.empty();
}

/// trim and extra, flattened into one all_of.
template <class T>
Region<T> conjoin(const Region<T>& trim, Region<T> extra) {
  if (trivially_true(trim)) return extra;
  std::vector<Region<T>> parts;
  if (trim.kind == Region<T>::all_of) parts = trim.parts;
  else parts.push_back(trim);
  parts.push_back(std::move(extra));
  return region_and(std::move(parts));
}

}  // namespace vrep_detail

template <class T>
const char* to_string(const Uncertain<typename CellClass<T>::Kind>& k) {
  using K = typename CellClass<T>::Kind;
  return k == K::whole ? "whole" : k == K::empty ? "empty" : k == K::cut ? "cut" : status_name(Status::undecided);
}

template <class T>
T poly_at(const Poly3<T>& g, const T* x) {
  T s(0);
  for (const auto& [e, c] : g.terms) {
    T t = c;
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < e[a]; ++i) t *= x[a];
    s += t;
  }
  return s;
}

template <class T>
Truth classify_point(const Region<T>& R, const std::vector<T>& x, const T& eps) {
  if (x.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  std::vector<const Poly3<T>*> leaves;
  vrep_detail::collect_leaves(R, leaves);
  std::vector<Truth> t;
  for (const auto* g : leaves) t.push_back(vrep_detail::value_truth(poly_at(*g, x.data()), eps));
  std::size_t k = 0;
  return vrep_detail::combine(R, t, k);
}

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

template <class T>
std::optional<Region<T>> planar_region(const VModel<T>& M, const T& eps) {
  using vrep_detail::poly_linear;
  std::vector<Region<T>> cells;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto P = convex_planes(M.trivariates[M.cells[c].trivariates.front()], eps);
    if (!P) return std::nullopt;
    std::vector<Region<T>> faces;
    for (const auto& H : *P) faces.push_back(region_leaf(poly_linear(H.d, H.n[0], H.n[1], H.n[2]), M.cells[c].name + ": face"));
    cells.push_back(region_and(std::move(faces)));
  }
  return cells.size() == 1 ? cells.front() : region_or(std::move(cells));
}

template <class T>
Region<T> place_region(const Region<T>& R, int axis, const std::vector<T>& offset) {
  using namespace vrep_detail;
  if (axis < 0 || axis > 2) throw ValidationError("axis", "must be x, y or z", "give --axis x, y or z");
  if (offset.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  Region<T> out = R;
  if (R.kind != Region<T>::leaf) {
    for (auto& p : out.parts) p = place_region(p, axis, offset);
    return out;
  }
  // new = P old + t with (P old)_j = old_{(j + s) % 3}, s = (2 - axis) mod 3 (s = 0: identity);
  // old_i = (new - t)_{(i - s) mod 3}.
  const int s = (5 - axis) % 3;  // new_axis = old_z
  std::array<Poly3<T>, 3> old;
  for (int i = 0; i < 3; ++i) {
    const int j = (i - s + 3) % 3;
    T e[3] = {T(0), T(0), T(0)};
    e[j] = T(1);
    old[i] = poly_linear(T(-offset[j]), e[0], e[1], e[2]);
  }
  Poly3<T> g;
  for (const auto& [e, c] : R.g.terms) {
    Poly3<T> t = poly_mul(poly_mul(poly_pow(old[0], e[0]), poly_pow(old[1], e[1])), poly_pow(old[2], e[2]));
    g = poly_add(g, t, c);
  }
  out.g = std::move(g);
  return out;
}

template <class T>
BSpline<T> place_trivariate(const BSpline<T>& V, int axis, const std::vector<T>& offset) {
  if (axis < 0 || axis > 2) throw ValidationError("axis", "must be x, y or z", "give --axis x, y or z");
  if (offset.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  if (V.q < 3) throw ValidationError("trivariate", "has points with fewer than three coordinates", "give points in R^3");
  const int s = (5 - axis) % 3;  // new_axis = old_z
  BSpline<T> out = V;
  for (std::size_t i = 0; i < V.size(); ++i)
    for (int j = 0; j < 3; ++j) out.points[i * V.q + j] = V.points[i * V.q + (j + s) % 3] + offset[j];
  return out;
}

template <class T>
TrimmedModel<T> placed_primitive(std::vector<BSpline<T>> cells, const Region<T>& region, int axis, const std::vector<T>& offset) {
  for (auto& V : cells) V = place_trivariate(V, axis, offset);
  return as_trimmed(glue(cells), place_region(region, axis, offset));
}

template <class T>
TrimmedModel<T> as_trimmed(const VModel<T>& M, Region<T> region) {
  TrimmedModel<T> out;
  out.trivariates = M.trivariates;
  out.region = std::move(region);
  for (const auto& c : M.cells) {
    typename TrimmedModel<T>::Cell x;
    x.trivariate = c.trivariates.front();
    x.trim = region_and<T>({});
    x.name = c.name;
    x.inherited.assign(c.trivariates.begin() + 1, c.trivariates.end());
    x.constants = c.attributes.constants;
    x.fields = c.attributes.fields;
    x.not_carried = c.attributes.not_carried;
    out.cells.push_back(std::move(x));
  }
  return out;
}

namespace vrep_detail {

template <class T>
bool has_alias(const Region<T>& R) {
  if (R.kind == Region<T>::leaf) return R.alias >= 0;
  for (const auto& p : R.parts)
    if (has_alias(p)) return true;
  return false;
}

/// R with the leaves fixed in `fixed` (collect order; mixed: kept) replaced by constants (true: an
/// all_of without parts, false: an any_of without parts) and the constants folded.
template <class T>
Region<T> fold_constants(const Region<T>& R, const std::vector<Truth>& fixed, std::size_t& k) {
  auto constant = [](bool t) { return t ? region_and<T>({}) : region_or<T>({}); };
  auto value = [](const Region<T>& x) -> int {  // 1 true, 0 false, -1 not a constant
    if (x.kind != Region<T>::all_of && x.kind != Region<T>::any_of) return -1;
    if (!x.parts.empty()) return -1;
    return x.kind == Region<T>::all_of ? 1 : 0;
  };
  switch (R.kind) {
    case Region<T>::leaf: {
      const Truth t = fixed[k++];
      return t == Truth::mixed ? R : constant(t == Truth::in);
    }
    case Region<T>::complement: {
      Region<T> x = fold_constants(R.parts.front(), fixed, k);
      const int v = value(x);
      return v < 0 ? region_not(std::move(x)) : constant(v == 0);
    }
    case Region<T>::all_of:
    case Region<T>::any_of: {
      const bool all = R.kind == Region<T>::all_of;
      std::vector<Region<T>> kept;
      bool absorbed = false;  // a false part of an all_of, a true part of an any_of
      for (const auto& p : R.parts) {
        Region<T> x = fold_constants(p, fixed, k);  // (every part: k must pass all leaves)
        const int v = value(x);
        if (v < 0) kept.push_back(std::move(x));
        else if (v == (all ? 0 : 1)) absorbed = true;
      }
      if (absorbed) return constant(!all);
      if (kept.size() == 1) return std::move(kept.front());
      Region<T> out = all ? region_and<T>(std::move(kept)) : region_or<T>(std::move(kept));
      out.label = R.label;
      return out;
    }
    case Region<T>::cases: {
      // Cases whose piece is out drop; a piece that is all there is leaves its formula; formulas
      // that are one constant on every piece left are that constant (the pieces cover).
      std::vector<std::pair<Region<T>, Region<T>>> kept;
      int common = -2;
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2) {
        Region<T> c = fold_constants(R.parts[i], fixed, k);
        Region<T> f = fold_constants(R.parts[i + 1], fixed, k);
        const int cv = value(c);
        if (cv == 0) continue;
        const int fv = value(f);
        common = common == -2 ? fv : common == fv ? fv : -1;
        kept.emplace_back(std::move(c), std::move(f));
      }
      if (kept.empty()) return constant(false);
      if (common >= 0) return constant(common == 1);
      if (kept.size() == 1 && value(kept.front().first) == 1) return std::move(kept.front().second);
      Region<T> out = region_cases<T>(std::move(kept));
      out.label = R.label;
      return out;
    }
  }
  return R;
}

/// Bounds lo <= g <= hi of a polynomial on the box b = {min x, min y, min z, max x, max y, max z}
/// (interval arithmetic per monomial, exact in exact arithmetic; wider than g's range in general).
template <class T>
std::pair<T, T> poly_bounds(const Poly3<T>& g, const std::array<T, 6>& b) {
  T lo(0), hi(0);
  for (const auto& [e, c] : g.terms) {
    T mlo(1), mhi(1);
    for (int a = 0; a < 3; ++a) {
      if (e[a] == 0) continue;
      T plo(1), phi(1);  // x^e on [b[a], b[a + 3]]
      for (int k = 0; k < e[a]; ++k) {
        plo *= b[a];
        phi *= b[a + 3];
      }
      if (phi < plo) std::swap(plo, phi);
      if (e[a] % 2 == 0 && b[a] < T(0) && T(0) < b[a + 3]) plo = T(0);
      // [mlo, mhi] * [plo, phi]
      const T p[4] = {mlo * plo, mlo * phi, mhi * plo, mhi * phi};
      mlo = *std::min_element(p, p + 4);
      mhi = *std::max_element(p, p + 4);
    }
    if (c < T(0)) {
      lo += c * mhi;
      hi += c * mlo;
    } else {
      lo += c * mlo;
      hi += c * mhi;
    }
  }
  return {lo, hi};
}

/// R with every leaf of strict sign on the box b (poly_bounds) replaced by its truth and the
/// formula folded: the same set on any set of points whose closure lies in the box, and just
/// outside that set too when it lies in the box's interior or the sign is strict on a
/// neighbourhood (a strict sign on a compact set holds on a neighbourhood of it). Exact arithmetic
/// only; regions with alias leaves are returned as they are.
template <class T>
Region<T> localized_by_box(const Region<T>& R, const std::array<T, 6>& b) {
  if (has_alias(R)) return R;
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(R, leaves);
  std::map<std::map<std::array<int, 3>, T>, Truth> seen;
  std::vector<Truth> fixed;
  for (const auto* g : leaves) {
    auto it = seen.find(g->terms);
    if (it == seen.end()) {
      const auto [lo, hi] = poly_bounds(*g, b);
      it = seen.emplace(g->terms, T(0) < lo ? Truth::in : hi < T(0) ? Truth::out : Truth::mixed).first;
    }
    fixed.push_back(it->second);
  }
  std::size_t k = 0;
  return fold_constants(R, fixed, k);
}

/// The region on one trivariate V (exact arithmetic): every leaf that has one truth on all of V
/// is replaced by it and the formula folded, where "one truth" is either (a) g > 0 or g < 0 on
/// V's control-point box (interval bounds; V lies in it by the convex hull property), so g o T
/// has that strict sign everywhere on the cell, or (b) the composition's Bernstein coefficients
/// have one weak sign with the same coefficient_truth on every Bezier piece of V, which the
/// subdivision boxes of a piece keep (their coefficients are convex combinations of the piece's,
/// and a polynomial that is 0 on a box is 0 on the piece). Either way the leaf's truth on every
/// part of the cell is the fixed one as a set, so the classification stays sound, and with (b)
/// alone it is unchanged. Equal leaves are decided once. The localized formula holds the leaves V
/// meets: the cost of a cell of a model of many cells (a grid of boxes with the union of their
/// regions, issue 47) is that of its neighbourhood, not of the model. Float arithmetic and regions
/// with alias leaves (built by trimmed_glue) are returned as they are.
template <class T>
Region<T> localized_region(const BSpline<T>& V, const Region<T>& R, const T& eps, const Limits& limits) {
  if (!(eps == T(0)) || has_alias(R)) return R;
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(R, leaves);
  if (leaves.empty()) return R;
  require_jacobian_input(V, limits);
  require_positive_weights(V);
  const auto box = control_bounds(V);
  std::vector<Truth> fixed(leaves.size(), Truth::mixed);
  std::map<std::map<std::array<int, 3>, T>, Truth> seen;
  std::vector<std::size_t> open;  // leaves (first of equal ones) the bounds do not decide
  std::vector<const Poly3<T>*> open_leaves;
  for (std::size_t l = 0; l < leaves.size(); ++l) {
    const auto it = seen.find(leaves[l]->terms);
    if (it != seen.end()) continue;
    const auto [lo, hi] = poly_bounds(*leaves[l], box);
    const Truth t = T(0) < lo ? Truth::in : hi < T(0) ? Truth::out : Truth::mixed;
    seen.emplace(leaves[l]->terms, t);
    if (t == Truth::mixed) {
      open.push_back(l);
      open_leaves.push_back(leaves[l]);
    }
  }
  // (b) for the planes always; for curved leaves only when they are few (a piecewise region's many
  // pieces are left to the subdivision, which composes a leaf only where it may matter).
  std::size_t curved = 0;
  for (const auto* g : open_leaves) curved += g->degree() > 1;
  if (curved > 16) {
    std::vector<std::size_t> o;
    std::vector<const Poly3<T>*> ol;
    for (std::size_t q = 0; q < open.size(); ++q)
      if (open_leaves[q]->degree() <= 1) {
        o.push_back(open[q]);
        ol.push_back(open_leaves[q]);
      }
    open = std::move(o);
    open_leaves = std::move(ol);
  }
  if (!open.empty()) {
    const std::size_t per_piece = composed_leaves_size(V, open_leaves, limits);
    const BezierForm<T> F = bezier_form(V, limits);
    checked_product(per_piece, F.size(), limits, "region composed with the trivariate's pieces");
    std::vector<Truth> t(open.size(), Truth::mixed);
    std::vector<char> alive(open.size(), 1);
    // Planted (tests only, vrep/model/planted.hpp): the first Bezier piece decides for all.
    const std::size_t pieces =
        vrep_testing::is_planted(vrep_testing::Plant::classify_first_piece_only) ? std::min<std::size_t>(1, F.size()) : F.size();
    for (std::size_t k = 0; k < pieces; ++k) {
      const auto pc = F.piece(k);
      PiecePowers<T> powers(pc.spline);
      for (std::size_t q = 0; q < open.size(); ++q) {
        if (!alive[q]) continue;
        const Truth here = coefficient_truth(compose_leaf(*open_leaves[q], powers), eps);
        if (here == Truth::mixed || (k > 0 && here != t[q])) {
          alive[q] = 0;
          t[q] = Truth::mixed;
          continue;
        }
        t[q] = here;
      }
    }
    for (std::size_t q = 0; q < open.size(); ++q) seen[leaves[open[q]]->terms] = t[q];
  }
  for (std::size_t l = 0; l < leaves.size(); ++l) fixed[l] = seen.at(leaves[l]->terms);
  std::size_t k = 0;
  return fold_constants(R, fixed, k);
}

}  // namespace vrep_detail

template <class T>
CellClass<T> classify_cell(const BSpline<T>& V, const Region<T>& trim, const TrimOptions& options, const T& eps, const Limits& limits) {
  // On the region localized to V: a cell of a large model costs what it meets (issue 47).
  return vrep_detail::run_trim(V, vrep_detail::localized_region(V, trim, eps, limits), options.max_boxes, false, eps, limits).cls;
}

// trimmed_volume, trimmed_moment, trimmed_field_integral: vrep/trimmed/enclosure_impl.hpp.

template <class T>
TrimmedModel<T> trimmed_boolean(const TrimmedModel<T>& A, const TrimmedModel<T>& B, BooleanOp op, Blend blend, const TrimOptions& options,
                                const T& eps, const Limits& limits) {
  using namespace vrep_detail;
  TrimmedModel<T> out;
  std::vector<std::size_t> tb;  // B's trivariates in out
  out.trivariates = A.trivariates;
  for (const auto& V : B.trivariates) {
    tb.push_back(out.trivariates.size());
    out.trivariates.push_back(V);
  }
  std::vector<std::array<T, 6>> boundsA, boundsB;
  for (const auto& c : A.cells) boundsA.push_back(control_bounds(A.trivariates[c.trivariate]));
  for (const auto& c : B.cells) boundsB.push_back(control_bounds(B.trivariates[c.trivariate]));
  auto meets = [](const std::array<T, 6>& a, const std::array<T, 6>& b) {
    for (int k = 0; k < 3; ++k)
      if (a[k + 3] < b[k] || b[k + 3] < a[k]) return false;
    return true;
  };
  // One side's cells restricted to `with` (the other model's region or its complement).
  auto pass = [&](const TrimmedModel<T>& M, bool from_a, const Region<T>& with, const std::string& category) {
    for (std::size_t c = 0; c < M.cells.size(); ++c) {
      const auto& cell = M.cells[c];
      const auto& V = M.trivariates[cell.trivariate];
      const std::string who = std::string(from_a ? "first" : "second") + ".cells[" + std::to_string(c) + "] (" + cell.name + ")";
      // The new condition alone first: a cell wholly inside it needs no new trim.
      using K = typename CellClass<T>::Kind;
      const auto alone = classify_cell(V, with, options, eps, limits);
      auto refuse = [&](const CellClass<T>& k) {
        throw DomainError(who, "meets the other model's boundary tangentially or nearly so: " + std::to_string(k.mixed) + " of " +
                                   std::to_string(k.boxes) + " subdivision boxes stay undecided and no exact witness of both sides was found",
                          "the paper excludes tangential contact; move the models apart or through each other, or raise --boxes");
      };
      if (!alone.kind.is_certain()) refuse(alone);
      if (alone.kind == K::empty) continue;
      Region<T> trim = alone.kind == K::whole ? cell.trim : conjoin(cell.trim, with);
      auto cls = alone;
      if (!trivially_true(trim)) cls = classify_cell(V, trim, options, eps, limits);
      if (!cls.kind.is_certain()) refuse(cls);
      if (cls.kind == K::empty) continue;
      typename TrimmedModel<T>::Cell x;
      x.trivariate = from_a ? cell.trivariate : tb[cell.trivariate];
      x.trim = std::move(trim);
      x.status = cls.kind == K::whole ? Truth::in : Truth::mixed;
      // A subtraction only trims A's cells: they keep the category an earlier Boolean gave them.
      x.category = op == BooleanOp::subtract && !cell.category.empty() ? cell.category : category;
      for (std::size_t t : cell.inherited) x.inherited.push_back(from_a ? t : tb[t]);
      x.constants = cell.constants;
      // Trimming keeps the trivariate and its parameters: the cell's fields stay as they are.
      x.fields = cell.fields;
      x.not_carried = cell.not_carried;
      x.name = cell.name.empty() ? (from_a ? "A" : "B") + std::to_string(c) : cell.name;
      if (category == "both") {
        const auto& mine = from_a ? boundsA[c] : boundsB[c];
        const auto& other = from_a ? B : A;
        const auto& ob = from_a ? boundsB : boundsA;
        for (std::size_t o = 0; o < other.cells.size(); ++o) {
          if (!meets(mine, ob[o])) continue;
          x.inherited.push_back(from_a ? tb[other.cells[o].trivariate] : other.cells[o].trivariate);
          Attributes<T> into, from;
          into.constants = std::move(x.constants);
          from.constants = other.cells[o].constants;
          merge_constants(into, from, blend);
          x.constants = std::move(into.constants);
          // The other cell's fields live on its trivariate's parameters; on this cell they would
          // need that trivariate's inverse (only the part inside it is known by the region).
          for (const auto& [n, F] : other.cells[o].fields)
            if (std::find(x.not_carried.begin(), x.not_carried.end(), n) == x.not_carried.end()) x.not_carried.push_back(n);
          x.name += "*" + (other.cells[o].name.empty() ? std::string(from_a ? "B" : "A") + std::to_string(o) : other.cells[o].name);
        }
      }
      out.cells.push_back(std::move(x));
    }
  };
  if (op == BooleanOp::intersect || op == BooleanOp::unite) pass(A, true, B.region, "both");
  if (op == BooleanOp::subtract || op == BooleanOp::unite) pass(A, true, region_not(B.region), "A");
  if (op == BooleanOp::unite) pass(B, false, region_not(A.region), "B");
  out.region = op == BooleanOp::intersect ? region_and<T>({A.region, B.region})
               : op == BooleanOp::subtract ? region_and<T>({A.region, region_not(B.region)})
                                           : region_or<T>({A.region, B.region});
  if (out.cells.empty())
    throw DomainError(std::string(to_string(op)), "gives an empty model (no cell has a part of positive volume)", "check the operands' placement");
  // Keep only the trivariates the cells use.
  std::vector<std::size_t> map(out.trivariates.size(), SIZE_MAX);
  std::vector<BSpline<T>> used;
  auto use = [&](std::size_t t) {
    if (map[t] == SIZE_MAX) {
      map[t] = used.size();
      used.push_back(out.trivariates[t]);
    }
    return map[t];
  };
  for (auto& c : out.cells) {
    c.trivariate = use(c.trivariate);
    for (auto& t : c.inherited) t = use(t);
  }
  out.trivariates = std::move(used);
  return out;
}

template <class T>
std::optional<std::vector<T>> cases_cover_gap(const Region<T>& R, const std::vector<BSpline<T>>& cells, int n) {
  if (n < 1) throw ValidationError("samples", "must be at least 1", "give n >= 1");
  std::vector<const Region<T>*> nodes;
  std::function<void(const Region<T>&)> walk = [&](const Region<T>& x) {
    if (x.kind == Region<T>::cases) nodes.push_back(&x);
    for (const auto& p : x.parts) walk(p);
  };
  walk(R);
  // The box of the cells' control points (those in R^3).
  std::optional<std::array<T, 6>> bounds;
  for (const auto& V : cells) {
    if (V.q < 3 || V.points.empty()) continue;
    const auto b = control_bounds(V);
    if (!bounds) bounds = b;
    for (int d = 0; d < 3; ++d) {
      (*bounds)[d] = std::min((*bounds)[d], b[d]);
      (*bounds)[d + 3] = std::max((*bounds)[d + 3], b[d + 3]);
    }
  }
  if (nodes.empty() || !bounds) return std::nullopt;
  const auto& box = *bounds;
  std::vector<T> x(3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const int at[3] = {i, j, k};
        for (int d = 0; d < 3; ++d) x[d] = box[d] + (box[d + 3] - box[d]) * T(at[d]) / T(n);
        for (const auto* c : nodes) {
          bool covered = false;
          for (std::size_t q = 0; q + 1 < c->parts.size() && !covered; q += 2) covered = classify_point(c->parts[q], x) != Truth::out;
          if (!covered) return x;
        }
      }
  return std::nullopt;
}

template <class T>
std::vector<std::string> check_region(const VModel<T>& M, const Region<T>& R, const TrimOptions& options, const Limits& limits) {
  using namespace vrep_detail;
  std::vector<std::string> fails;
  // The cover a piecewise region claims, at a grid of points over the cells (sampled).
  if (const auto gap = cases_cover_gap(R, M.trivariates, 8))
    fails.push_back("its cases' pieces do not cover the point (" + ArithTraits<T>::to_string((*gap)[0]) + ", " + ArithTraits<T>::to_string((*gap)[1]) +
                    ", " + ArithTraits<T>::to_string((*gap)[2]) + ") (the cover checked at 729 points over the cells)");
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(R, leaves);
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto cls = classify_cell(M.trivariates[M.cells[c].trivariates.front()], R, options, T(0), limits);
    if (cls.kind != CellClass<T>::whole)
      fails.push_back("cells[" + std::to_string(c) + "] (" + M.cells[c].name + ") is " + to_string<T>(cls.kind) + " against the region, not whole");
  }
  for (std::size_t h = 0; h < M.half_surfaces.size(); ++h) {
    const auto& hs = M.half_surfaces[h];
    if (hs.twin) continue;
    const BSpline<T> S = face(M.trivariates[hs.trivariate], hs.dir, hs.side);
    // Each Bezier piece of the face on the zero set of some leaf (a piecewise surface, such as the
    // sphere's patches, has one leaf per piece).
    bool on = true;
    std::size_t last = 0;  // the leaf the previous piece lies on: neighbouring pieces' leaves are near it
    for (const auto& pc : extract_bezier(S, limits)) {
      const auto box = control_bounds(pc.spline);
      // The piece as a degenerate trivariate: g o S vanishes iff every coefficient of W^k g(X/W, ...) does.
      BSpline<T> P = pc.spline;
      P.degrees.push_back(0);
      P.knots.push_back({T(0), T(1)});
      bool here = false;
      // The piece's corner (its first control point, a point of the face).
      const T* corner_point = pc.spline.points.data();
      for (std::size_t q = 0; q < leaves.size() && !here; ++q) {
        const std::size_t l = (last + q) % leaves.size();
        const Poly3<T>& g = *leaves[l];
        // A leaf that is not 0 at the corner, or whose bounds on the piece's control-point box
        // exclude 0, does not vanish on it.
        if (!(poly_at(g, corner_point) == T(0))) continue;
        if (const auto [lo, hi] = poly_bounds(g, box); T(0) < lo || hi < T(0)) continue;
        const Bernstein<T> G = compose_leaf(g, P);
        if (std::all_of(G.c.begin(), G.c.end(), [](const T& x) { return x == T(0); })) {
          here = true;
          last = l;
        }
      }
      if (!here) {
        on = false;
        break;
      }
    }
    if (!on)
      fails.push_back("boundary face (" + std::to_string(hs.dir) + ", " + std::to_string(hs.side) + ") of cells[" + std::to_string(hs.cell) +
                      "] lies on no surface g = 0 of the region");
  }
  return fails;
}

}  // namespace splinex
