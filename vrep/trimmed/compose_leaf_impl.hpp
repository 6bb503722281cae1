// The leaves of a region composed with a trivariate's Bezier pieces, exactly: integer tensors,
// the powers of a piece's homogeneous coordinates, W^k g(X / W, Y / W, Z / W), and the checks
// before a trimmed cell's subdivision. Internal to vrep/trimmed/ (included by trimmed_impl.hpp).
#pragma once
#include "vrep/trimmed/region_impl.hpp"

namespace splinex {

namespace vrep_detail {

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

}  // namespace vrep_detail

}  // namespace splinex
