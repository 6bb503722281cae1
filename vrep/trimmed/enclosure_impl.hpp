// Adaptive certified enclosures of volumes, moments and field integrals over (trimmed) cells
// (vrep/trimmed/trimmed.hpp: integral_enclosures, trimmed_volume, trimmed_moment, trimmed_field_integral);
// the templates, instantiated in vrep/instances.cpp.
//
// One priority queue of parameter boxes over all cells, keyed by each box's share of the width
// (upper - lower, the moments' widths scaled to the volume's); the widest box is halved (exact de
// Casteljau) until the widths are within the requested relative width or the box budget is spent.
// Per box, with det J = N / W^4 and an integrand Q / W^p (Q = N: the volume; Q = X_c N, p = 5: a
// coordinate's moment; Q = F_k N, p = 4: a field's component):
//   - out (the trim's formula is false on the box, decided by the leaves' Bernstein coefficients):
//     0, dropped;
//   - in, polynomial cell: the exact integral (the mean of Q's coefficients), dropped;
//   - in, rational cell: Taylor's formula of f(w) = w^-p at a point w0 of order 6 with the
//     remainder f^(6)(xi) / 6! (W - w0)^6, f^(6) > 0 decreasing so between its values at the ends
//     of W's coefficient range, the moments int Q W^j exact (Gram matrices of Bernstein bases
//     contracted on integers); where Q has one sign also Jensen's lower bound and the chord's upper
//     bound (vrep/boolean/boolean.hpp's volume_enclosure), the tighter of each kept. The gap shrinks with
//     the seventh power of the box;
//   - cut by one trimming surface G whose sign the formula follows: where G is strictly monotone
//     along a direction k (its derivative's Bernstein coefficients of one strict sign, |dG/ds_k| >=
//     m) the part is one side of a graph s_k = phi(s_a, s_b) in every column. psi, a biquadratic
//     through approximate roots at a 3 x 3 grid (Newton in short dyadics), is certified within
//     eps = max |G(s, psi(s))| / m of phi (the Bernstein coefficients of the composition; where psi
//     leaves [0, 1], G monotone on the longer interval, by de Casteljau outside [0, 1]). The
//     integral of a polynomial P over the part is int int A(s, clamp(phi(s))) (A: P's antiderivative
//     along k), which is int int A(s, psi(s)) (exact: Gram contraction with B_l^q(psi)) within eps
//     max |P|, corrected where psi leaves [0, 1] by a subdivision of the face (exact where psi is on
//     one side, bounded where the level set still crosses after 5 halvings). Polynomial cells take
//     P = Q; rational ones Taylor's formula of order 2 at w0 (P = Q and Q (W - w0), the remainder
//     between 0 and the whole box's f''/2 Q (W - w0)^2). The gap shrinks with the cube of the box.
//     Otherwise an affine L with |G - L| <= e on the box bounds the part between the exact volumes
//     of {L >= e} and {L >= -e} (a half-space in a cube), the integrand between its coefficient
//     ratios; with several undecided surfaces the part holds between none and all of the box.
// Bounds are rounded outward to about 64 significant bits when their numbers grow beyond 128 bits
// (exact results are kept exact). Exact in exact arithmetic; in double and MPFR the same steps,
// uncertified.
#pragma once
#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <queue>
#include <type_traits>

#include "vrep/trimmed/trimmed_impl.hpp"

namespace splinex {

namespace vrep_detail {

/// x rounded outward (up or down) to a dyadic rational of `bits` significant bits when its
/// numerator or denominator has more than `above` bits (Rational; other arithmetics: x as it is).
template <class T>
T round_dyadic(const T& x, bool up, long bits, long above) {
  if constexpr (std::is_same_v<T, Rational>) {
    mpz_srcptr n = mpq_numref(x.backend().data()), d = mpq_denref(x.backend().data());
    if (mpz_sgn(n) == 0) return x;
    const long bn = static_cast<long>(mpz_sizeinbase(n, 2)), bd = static_cast<long>(mpz_sizeinbase(d, 2));
    if (bn <= above && bd <= above && (above > 0 || mpz_popcount(d) == 1)) return x;
    const long s = bits - (bn - bd);  // x 2^s has about `bits` bits before the point
    Integer num, den, q;
    if (s >= 0) {
      mpz_mul_2exp(num.backend().data(), n, static_cast<mp_bitcnt_t>(s));
      mpz_set(den.backend().data(), d);
    } else {
      mpz_set(num.backend().data(), n);
      mpz_mul_2exp(den.backend().data(), d, static_cast<mp_bitcnt_t>(-s));
    }
    if (up) mpz_cdiv_q(q.backend().data(), num.backend().data(), den.backend().data());
    else mpz_fdiv_q(q.backend().data(), num.backend().data(), den.backend().data());
    Rational r(q);
    if (s >= 0) mpq_div_2exp(r.backend().data(), r.backend().data(), static_cast<mp_bitcnt_t>(s));
    else mpq_mul_2exp(r.backend().data(), r.backend().data(), static_cast<mp_bitcnt_t>(-s));
    return r;
  } else {
    (void)up, (void)bits, (void)above;
    return x;
  }
}
/// Bounds rounded outward to about 64 significant bits once their numbers pass 128 bits.
template <class T>
T round_outward(const T& x, bool up) {
  return round_dyadic(x, up, 64, 128);
}
/// A short dyadic near x (about 20 significant bits), for expansion points and fitted slopes whose
/// exact value does not matter.
template <class T>
T short_dyadic(const T& x) {
  return round_dyadic(x, false, 20, 0);
}

/// The coefficients of a scaled Bernstein polynomial: integers in exact arithmetic (the values are
/// coefficient times scale: the de Casteljau halving, products and Gram contractions run on
/// integers), the values themselves in float arithmetic (scale 1).
template <class T>
struct ScaledCoefficient {
  using type = T;
};
template <>
struct ScaledCoefficient<Rational> {
  using type = Integer;
};
template <class T>
using Coef = typename ScaledCoefficient<T>::type;
template <class T>
constexpr bool integer_coefficients = std::is_same_v<T, Rational>;

template <class T>
struct SBern {
  std::vector<int> deg;
  std::vector<Coef<T>> c;
  T scale{1};  // value_i = c_i scale, scale > 0
};

template <class T>
T as_value(const Coef<T>& x) {
  return T(x);
}

template <class T>
bool is_zero(const SBern<T>& b) {
  return b.c.empty();
}

/// Divides out the common power of 2 of the coefficients (exact arithmetic).
template <class T>
void normalize(SBern<T>& b) {
  if constexpr (integer_coefficients<T>) {
    mp_bitcnt_t k = ~mp_bitcnt_t(0);
    for (const auto& x : b.c)
      if (mpz_sgn(x.backend().data()) != 0) k = std::min(k, mpz_scan1(x.backend().data(), 0));
    if (k == 0 || k == ~mp_bitcnt_t(0)) return;
    for (auto& x : b.c) mpz_tdiv_q_2exp(x.backend().data(), x.backend().data(), k);
    mpq_mul_2exp(b.scale.backend().data(), b.scale.backend().data(), k);
  }
}

template <class T>
SBern<T> scaled(const Bernstein<T>& b) {
  SBern<T> s;
  s.deg = b.deg;
  if constexpr (integer_coefficients<T>) {
    Integer D(1);
    for (const auto& x : b.c) mpz_lcm(D.backend().data(), D.backend().data(), mpq_denref(x.backend().data()));
    s.c.resize(b.c.size());
    Integer g(0);
    for (std::size_t i = 0; i < b.c.size(); ++i) {
      mpz_divexact(s.c[i].backend().data(), D.backend().data(), mpq_denref(b.c[i].backend().data()));
      mpz_mul(s.c[i].backend().data(), s.c[i].backend().data(), mpq_numref(b.c[i].backend().data()));
      mpz_gcd(g.backend().data(), g.backend().data(), s.c[i].backend().data());
    }
    if (g == 0) g = 1;
    for (auto& x : s.c) mpz_divexact(x.backend().data(), x.backend().data(), g.backend().data());
    s.scale = Rational(g) / Rational(D);
  } else {
    s.c = b.c;
    s.scale = T(1);
  }
  return s;
}

/// The two parts of b at t_d = t (0 < t < 1; exact de Casteljau; on integers t = n / m: the
/// steps (m - n) w_i + n w_{i+1}, the divisions by m moved into the scale).
template <class T>
std::pair<SBern<T>, SBern<T>> split_at(const SBern<T>& b, int d, const T& t) {
  if constexpr (!integer_coefficients<T>) {
    auto [l, r] = bern_split(Bernstein<T>{b.deg, b.c}, d, t);
    return {SBern<T>{b.deg, std::move(l.c), b.scale}, SBern<T>{b.deg, std::move(r.c), b.scale}};
  } else {
    const Integer n = numerator(t), m = denominator(t), mn = m - n;
    SBern<T> L{b.deg, std::vector<Coef<T>>(b.c.size()), b.scale}, R{b.deg, std::vector<Coef<T>>(b.c.size()), b.scale};
    const int p = b.deg[d];
    std::size_t stride = 1;
    for (int k = 0; k < d; ++k) stride *= static_cast<std::size_t>(b.deg[k]) + 1;
    const std::size_t len = static_cast<std::size_t>(p) + 1;
    std::vector<Integer> mp(len, Integer(1));  // m^j
    for (std::size_t j = 1; j < len; ++j) mp[j] = mp[j - 1] * m;
    std::vector<Integer> w(len);
    Integer x;
    for (std::size_t i = 0; i < b.c.size(); ++i) {
      if ((i / stride) % len != 0) continue;
      for (std::size_t j = 0; j < len; ++j) w[j] = b.c[i + j * stride];
      for (int r = 0; r <= p; ++r) {
        // After r steps w holds m^r times the values; the children's scale is b's / m^p.
        L.c[i + r * stride] = w[0] * mp[p - r];
        R.c[i + (p - r) * stride] = w[p - r] * mp[p - r];
        for (int k = 0; k < p - r; ++k) {
          x = w[k] * mn;
          mpz_addmul(x.backend().data(), w[k + 1].backend().data(), n.backend().data());
          w[k] = x;
        }
      }
    }
    const Rational f = Rational(1) / Rational(mp[p]);
    L.scale *= f;
    R.scale *= f;
    normalize(L);
    normalize(R);
    return {std::move(L), std::move(R)};
  }
}

/// The two halves of b at t_d = 1/2 (exact de Casteljau; on integers: sums only, the halvings
/// moved into the scale).
template <class T>
std::pair<SBern<T>, SBern<T>> split_half(const SBern<T>& b, int d) {
  if constexpr (!integer_coefficients<T>) {
    auto [l, r] = bern_split(Bernstein<T>{b.deg, b.c}, d, T(1) / T(2));
    return {SBern<T>{b.deg, std::move(l.c), b.scale}, SBern<T>{b.deg, std::move(r.c), b.scale}};
  } else {
    SBern<T> L{b.deg, std::vector<Coef<T>>(b.c.size()), b.scale}, R{b.deg, std::vector<Coef<T>>(b.c.size()), b.scale};
    const int p = b.deg[d];
    std::size_t stride = 1;
    for (int k = 0; k < d; ++k) stride *= static_cast<std::size_t>(b.deg[k]) + 1;
    const std::size_t n = static_cast<std::size_t>(p) + 1;
    std::vector<Integer> w(n);
    for (std::size_t i = 0; i < b.c.size(); ++i) {
      if ((i / stride) % n != 0) continue;  // the first entry of a line along d
      for (std::size_t j = 0; j < n; ++j) w[j] = b.c[i + j * stride];
      for (int r = 0; r <= p; ++r) {
        // After r steps w holds 2^r times the values; the children's scale is b's / 2^p.
        mpz_mul_2exp(L.c[i + r * stride].backend().data(), w[0].backend().data(), static_cast<mp_bitcnt_t>(p - r));
        mpz_mul_2exp(R.c[i + (p - r) * stride].backend().data(), w[p - r].backend().data(), static_cast<mp_bitcnt_t>(p - r));
        for (int k = 0; k < p - r; ++k) w[k] += w[k + 1];
      }
    }
    mpq_div_2exp(L.scale.backend().data(), L.scale.backend().data(), static_cast<mp_bitcnt_t>(p));
    mpq_div_2exp(R.scale.backend().data(), R.scale.backend().data(), static_cast<mp_bitcnt_t>(p));
    normalize(L);
    normalize(R);
    return {std::move(L), std::move(R)};
  }
}

/// Integer tables for exact arithmetic (integer_binomials, tensor_binomial_integers: vrep/trimmed/trimmed_impl.hpp):
/// the least common multiple of a row of binomials.
inline const Integer& binomial_lcm(int n) {
  thread_local std::map<int, Integer> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Integer l(1);
  for (const auto& x : integer_binomials(n)) mpz_lcm(l.backend().data(), l.backend().data(), x.backend().data());
  return cache.emplace(n, std::move(l)).first->second;
}

/// For a product's degrees: L = prod_l lcm_k C(deg_l, k) and the factors L / prod_l C(deg_l, idx_l).
struct ProductFactors {
  std::vector<Integer> factor;
  Rational unit;  // 1 / L
};
inline const ProductFactors& product_factors(const std::vector<int>& deg) {
  thread_local std::map<std::vector<int>, ProductFactors> cache;
  auto it = cache.find(deg);
  if (it != cache.end()) return it->second;
  Integer L(1);
  for (int d : deg) L *= binomial_lcm(d);
  const auto& tb = tensor_binomial_integers(deg);
  ProductFactors pf;
  pf.factor.resize(tb.size());
  for (std::size_t i = 0; i < tb.size(); ++i) pf.factor[i] = L / tb[i];
  pf.unit = Rational(1) / Rational(L);
  return cache.emplace(deg, std::move(pf)).first->second;
}
inline const std::vector<std::size_t>& tensor_offsets_cached(const std::vector<int>& deg, const std::vector<int>& into) {
  thread_local std::map<std::pair<std::vector<int>, std::vector<int>>, std::vector<std::size_t>> cache;
  auto key = std::make_pair(deg, into);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache.emplace(std::move(key), detail::tensor_offsets(deg, into)).first->second;
}

/// a b in Bernstein form (any dimension) on raw coefficients: in exact arithmetic integers whose
/// values are h times `unit` times a's and b's scales (unit = 1 / L, L the product over the
/// directions of lcm_k C(a_d + b_d, k)); in float arithmetic the values (unit 1).
template <class T>
std::vector<Coef<T>> raw_product(const std::vector<Coef<T>>& a, const std::vector<int>& da, const std::vector<Coef<T>>& b,
                                 const std::vector<int>& db, std::vector<int>& dh, T& unit) {
  const std::size_t n = da.size();
  dh.resize(n);
  for (std::size_t l = 0; l < n; ++l) dh[l] = da[l] + db[l];
  if constexpr (!integer_coefficients<T>) {
    unit = T(1);
    return bern_product(Bernstein<T>{da, a}, Bernstein<T>{db, b}).c;
  } else {
    // h_k = sum_{i + j = k} C(a, i) C(b, j) / C(a + b, k) a_i b_j per direction: on integers
    // times L / C(a + b, k).
    const auto& ta = tensor_binomial_integers(da);
    const auto& tb = tensor_binomial_integers(db);
    const auto& th = product_factors(dh);
    std::vector<Integer> h(th.factor.size(), Integer(0));
    thread_local std::vector<Integer> as, bs;
    as.resize(a.size());
    bs.resize(b.size());
    for (std::size_t i = 0; i < a.size(); ++i) mpz_mul(as[i].backend().data(), a[i].backend().data(), ta[i].backend().data());
    for (std::size_t i = 0; i < b.size(); ++i) mpz_mul(bs[i].backend().data(), b[i].backend().data(), tb[i].backend().data());
    const auto& ao = tensor_offsets_cached(da, dh);
    const auto& bo = tensor_offsets_cached(db, dh);
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (mpz_sgn(as[i].backend().data()) == 0) continue;
      for (std::size_t j = 0; j < b.size(); ++j) mpz_addmul(h[ao[i] + bo[j]].backend().data(), as[i].backend().data(), bs[j].backend().data());
    }
    for (std::size_t k = 0; k < h.size(); ++k) mpz_mul(h[k].backend().data(), h[k].backend().data(), th.factor[k].backend().data());
    unit = th.unit;
    return h;
  }
}

/// a b in Bernstein form.
template <class T>
SBern<T> product(const SBern<T>& a, const SBern<T>& b) {
  SBern<T> h;
  T unit;
  h.c = raw_product<T>(a.c, a.deg, b.c, b.deg, h.deg, unit);
  h.scale = a.scale * b.scale * unit;
  normalize(h);
  return h;
}

/// The 2D coefficient arrays of b (three directions) along direction k: slice l holds the
/// coefficients with index l in k, over the other two directions in order. With `antiderivative`,
/// the slices of int_0^t b ds_k instead (degree one more in k; l = 0..p + 1: the sums of the
/// slices below l, the factor 1 / (p + 1) left to the caller).
template <class T>
std::vector<std::vector<Coef<T>>> slices_along(const SBern<T>& b, int k, bool antiderivative, std::vector<int>& dslice) {
  const int a = k == 0 ? 1 : 0, c = k == 2 ? 1 : 2;
  dslice = {b.deg[a], b.deg[c]};
  const std::size_t n[3] = {static_cast<std::size_t>(b.deg[0]) + 1, static_cast<std::size_t>(b.deg[1]) + 1,
                            static_cast<std::size_t>(b.deg[2]) + 1};
  const std::size_t stride[3] = {1, n[0], n[0] * n[1]};
  const std::size_t p = n[k] - 1;
  std::vector<std::vector<Coef<T>>> out(p + 1, std::vector<Coef<T>>(n[a] * n[c]));
  for (std::size_t l = 0; l <= p; ++l)
    for (std::size_t j = 0; j < n[c]; ++j)
      for (std::size_t i = 0; i < n[a]; ++i) out[l][i + n[a] * j] = b.c[l * stride[k] + i * stride[a] + j * stride[c]];
  if (!antiderivative) return out;
  std::vector<std::vector<Coef<T>>> A(p + 2, std::vector<Coef<T>>(n[a] * n[c], Coef<T>(0)));
  for (std::size_t l = 1; l <= p + 1; ++l)
    for (std::size_t i = 0; i < A[l].size(); ++i) A[l][i] = A[l - 1][i] + out[l - 1][i];
  return A;
}

/// f(s, psi(s)) for f(s, t) = sum_l f_l(s) B_l^q(t) (slices f_l in two directions, q + 1 of them)
/// and a graph psi (two directions; raw coefficients with values psi_raw psi_unit, where 1 =
/// one_raw psi_unit): de Casteljau in t with polynomial coefficients. Returns the raw coefficients,
/// their degrees and the factor (times the slices' own scale) that gives the values.
template <class T>
std::vector<Coef<T>> compose_graph(std::vector<std::vector<Coef<T>>> w, std::vector<int> dw, const std::vector<Coef<T>>& psi,
                                   const std::vector<Coef<T>>& one_minus_psi, const std::vector<int>& dpsi, const T& psi_unit,
                                   std::vector<int>& dout, T& factor) {
  factor = T(1);
  const std::size_t q = w.size() - 1;
  for (std::size_t r = 1; r <= q; ++r) {
    std::vector<int> dn;
    T unit(1);
    for (std::size_t l = 0; l + r <= q; ++l) {
      auto x = raw_product<T>(w[l], dw, one_minus_psi, dpsi, dn, unit);
      const auto y = raw_product<T>(w[l + 1], dw, psi, dpsi, dn, unit);
      for (std::size_t i = 0; i < x.size(); ++i) x[i] += y[i];
      w[l] = std::move(x);
    }
    w.resize(q - r + 1);
    dw = dn;
    factor *= unit * psi_unit;
  }
  dout = dw;
  return std::move(w.front());
}

/// Gram matrices of Bernstein bases on [0, 1]: int B_i^m B_j^q = C(m, i) C(q, j) / ((m + q + 1)
/// C(m + q, i + j)), row-major in i, per (m, q); on integers times their common denominator.
template <class T>
class GramCache {
 public:
  struct Table {
    std::vector<Coef<T>> g;
    T unit{1};  // the entries are g times unit
  };
  const Table& get(int m, int q) {
    auto it = cache_.find({m, q});
    if (it != cache_.end()) return it->second;
    Table t;
    t.g.resize(static_cast<std::size_t>(m + 1) * (q + 1));
    if constexpr (integer_coefficients<T>) {
      const Integer L = Integer(m + q + 1) * binomial_lcm(m + q);
      for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= q; ++j) {
          Integer x = L / (Integer(m + q + 1) * integer_binomials(m + q)[i + j]);
          x *= integer_binomials(m)[i];
          x *= integer_binomials(q)[j];
          t.g[static_cast<std::size_t>(i) * (q + 1) + j] = x;
        }
      t.unit = T(1) / T(L);
    } else {
      const auto bm = detail::binomial_row<T>(m), bq = detail::binomial_row<T>(q), bmq = detail::binomial_row<T>(m + q);
      for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= q; ++j) t.g[static_cast<std::size_t>(i) * (q + 1) + j] = bm[i] * bq[j] / (T(m + q + 1) * bmq[i + j]);
    }
    return cache_.emplace(std::make_pair(m, q), std::move(t)).first->second;
  }

 private:
  std::map<std::pair<int, int>, Table> cache_;
};

/// The integral over [0, 1]^3 of A B (three directions), exact: the Gram matrices contracted
/// direction by direction (no product polynomial is formed).
template <class T>
T product_integral(const SBern<T>& A, const SBern<T>& B, GramCache<T>& gram) {
  using C = Coef<T>;
  const std::size_t a0 = A.deg[0] + 1, a1 = A.deg[1] + 1, a2 = A.deg[2] + 1;
  const std::size_t b0 = B.deg[0] + 1, b1 = B.deg[1] + 1, b2 = B.deg[2] + 1;
  const auto& g0 = gram.get(A.deg[0], B.deg[0]);
  const auto& g1 = gram.get(A.deg[1], B.deg[1]);
  const auto& g2 = gram.get(A.deg[2], B.deg[2]);
  auto addmul = [](C& acc, const C& x, const C& y) {
    if constexpr (integer_coefficients<T>) mpz_addmul(acc.backend().data(), x.backend().data(), y.backend().data());
    else acc += x * y;
  };
  std::vector<C> t1(b0 * a1 * a2, C(0));
  for (std::size_t r = 0; r < a1 * a2; ++r)
    for (std::size_t i0 = 0; i0 < a0; ++i0) {
      const C& x = A.c[i0 + a0 * r];
      if (x == 0) continue;
      for (std::size_t j0 = 0; j0 < b0; ++j0) addmul(t1[j0 + b0 * r], x, g0.g[i0 * b0 + j0]);
    }
  std::vector<C> t2(b0 * b1 * a2, C(0));
  for (std::size_t i2 = 0; i2 < a2; ++i2)
    for (std::size_t i1 = 0; i1 < a1; ++i1)
      for (std::size_t j0 = 0; j0 < b0; ++j0) {
        const C& x = t1[j0 + b0 * (i1 + a1 * i2)];
        if (x == 0) continue;
        for (std::size_t j1 = 0; j1 < b1; ++j1) addmul(t2[j0 + b0 * (j1 + b1 * i2)], x, g1.g[i1 * b1 + j1]);
      }
  C s(0), t(0);
  for (std::size_t j2 = 0; j2 < b2; ++j2)
    for (std::size_t j1 = 0; j1 < b1; ++j1)
      for (std::size_t j0 = 0; j0 < b0; ++j0) {
        const C& bj = B.c[j0 + b0 * (j1 + b1 * j2)];
        if (bj == 0) continue;
        t = C(0);
        for (std::size_t i2 = 0; i2 < a2; ++i2) addmul(t, t2[j0 + b0 * (j1 + b1 * i2)], g2.g[i2 * b2 + j2]);
        addmul(s, bj, t);
      }
  return as_value<T>(s) * (A.scale * B.scale * g0.unit * g1.unit * g2.unit);
}

template <class T>
T coefficient_mean(const SBern<T>& b) {
  Coef<T> s(0);
  for (const auto& x : b.c) s += x;
  return as_value<T>(s) * b.scale / T(static_cast<long>(b.c.size()));
}

template <class T>
void coefficient_range(const SBern<T>& b, T& lo, T& hi) {
  const Coef<T>* mn = &b.c.front();
  const Coef<T>* mx = mn;
  for (const auto& x : b.c) {
    if (x < *mn) mn = &x;
    if (*mx < x) mx = &x;
  }
  lo = as_value<T>(*mn) * b.scale;
  hi = as_value<T>(*mx) * b.scale;
}

/// The truth of G >= 0 on the box from its coefficients' signs.
template <class T>
Truth coefficient_truth(const SBern<T>& G) {
  bool nonneg = true, nonpos = true;
  for (const auto& x : G.c) {
    nonneg = nonneg && !(x < 0);
    nonpos = nonpos && !(0 < x);
  }
  if (nonpos) return Truth::out;
  return nonneg ? Truth::in : Truth::mixed;
}

template <class T>
T power_of(const T& x, int k) {
  T r(1);
  for (int i = 0; i < k; ++i) r *= x;
  return r;
}

/// Bounds lo <= int Q / W^p <= hi over [0, 1]^3 from the coefficients' ranges only (the ratio of
/// extreme coefficients; W > 0).
template <class T>
void ratio_bounds(const T& qmin, const T& qmax, const T& wmin, const T& wmax, int p, T& lo, T& hi) {
  const T a = power_of(wmin, p), b = power_of(wmax, p);
  lo = T(0) < qmin ? T(qmin / b) : T(qmin / a);
  hi = T(0) < qmax ? T(qmax / a) : T(qmax / b);
}

/// Bounds lo <= int Q / W^p <= hi over [0, 1]^3 (W > 0 on the box), given the powers Wp[j] = W^(j+1),
/// j < n: exact when W is constant; otherwise Taylor's formula of f(w) = w^-p at w0 of order n
/// (even) with the remainder f^(n)(xi) / n! (W - w0)^n, f^(n) > 0 decreasing so between its values
/// at the ends of W's range, the moments int Q W^j exact; intersected with Jensen / chord where Q
/// has one sign and with the coefficient-ratio bounds.
template <class T>
void taylor_bounds(const SBern<T>& Q, const std::vector<SBern<T>>& Wp, int p, int n, GramCache<T>& gram, T& lo, T& hi) {
  const SBern<T>& W = Wp.front();
  T qmin, qmax, wmin, wmax;
  coefficient_range(Q, qmin, qmax);
  coefficient_range(W, wmin, wmax);
  if (!(T(0) < wmin)) throw DomainError("trivariate.weights", "has a weight bound that is not positive", "give positive weights");
  if (wmin == wmax) {
    lo = hi = coefficient_mean(Q) / power_of(wmin, p);
    return;
  }
  if (qmin == T(0) && qmax == T(0)) {
    lo = hi = T(0);
    return;
  }
  const bool one_sign = !(qmin < T(0)) || !(T(0) < qmax);
  const T sg = !(qmin < T(0)) ? T(1) : T(-1);  // Q's sign where it has one
  std::vector<T> M{coefficient_mean(Q)};  // M_j = int Q W^j
  for (int j = 1; j <= n; ++j) M.push_back(product_integral(Q, Wp[j - 1], gram));
  // The expansion point: Q's weighted mean of W where Q has one sign, W's mean otherwise; a short
  // dyadic within W's range.
  T w0 = one_sign && !(M[0] == T(0)) ? T(M[1] / M[0]) : coefficient_mean(W);
  w0 = short_dyadic(w0);
  if (w0 < wmin) w0 = wmin;
  if (wmax < w0) w0 = wmax;
  // E_k = int Q (W - w0)^k = sum_j C(k, j) (-w0)^(k - j) M_j.
  auto central = [&](const std::vector<T>& m, int k) -> T {
    const auto Ck = detail::binomial_row<T>(k);
    T s(0), pw(1);  // pw = (-w0)^(k - j), j from k down
    for (int j = k; j >= 0; --j) {
      s += Ck[j] * pw * m[j];
      pw *= -w0;
    }
    return s;
  };
  // f^(k)(w) / k! = (-1)^k C(p + k - 1, k) w^-(p + k).
  auto coefficient = [&](int k, const T& w) -> T {
    const T c = detail::binomial_row<T>(p + k - 1)[k] / power_of(w, p + k);
    return k % 2 ? T(-c) : c;
  };
  T taylor(0);
  for (int k = 0; k < n; ++k) taylor += coefficient(k, w0) * central(M, k);
  const T rlo = coefficient(n, wmax), rhi = coefficient(n, wmin);  // f^(n)(xi) / n!, xi in [wmin, wmax]
  ratio_bounds(qmin, qmax, wmin, wmax, p, lo, hi);
  if (one_sign) {
    const T E = central(M, n);  // Q's sign (n even)
    T tl = taylor + (sg > T(0) ? rlo : rhi) * E, th = taylor + (sg > T(0) ? rhi : rlo) * E;
    // Jensen (f convex, weight |Q|) and the chord of f over [wmin, wmax].
    if (!(M[0] == T(0))) {
      const T m = M[1] / M[0];
      const T jensen = M[0] / power_of(m, p);
      const T fa = T(1) / power_of(wmin, p), fb = T(1) / power_of(wmax, p);
      const T chord = fa * M[0] + (fb - fa) / (wmax - wmin) * (M[1] - wmin * M[0]);
      if (sg > T(0)) {
        tl = std::max(tl, jensen);
        th = std::min(th, chord);
      } else {
        tl = std::max(tl, chord);
        th = std::min(th, jensen);
      }
    }
    lo = std::max(lo, tl);
    hi = std::min(hi, th);
  } else {
    // The remainder Q f^(n)(xi) / n! (W - w0)^n between qmin and qmax times r (W - w0)^n >= 0.
    std::vector<T> mw{T(1)};
    for (int j = 1; j <= n; ++j) mw.push_back(coefficient_mean(Wp[j - 1]));
    const T E0 = central(mw, n);
    const T rl = std::min(qmin * rlo, qmin * rhi) * E0, rh = std::max(qmax * rlo, qmax * rhi) * E0;
    lo = std::max(lo, T(taylor + rl));
    hi = std::min(hi, T(taylor + rh));
  }
}

/// The share of the unit cube [0, 1]^3 where a . s <= b, exactly (a volume of a polytope by
/// inclusion-exclusion over the cube's corners).
template <class T>
T halfspace_share(const std::array<T, 3>& a, T b) {
  std::vector<T> A;
  for (int d = 0; d < 3; ++d) {
    if (a[d] == T(0)) continue;
    if (a[d] < T(0)) {
      b -= a[d];  // a s = a - |a| (1 - s)
      A.push_back(-a[d]);
    } else A.push_back(a[d]);
  }
  if (A.empty()) return T(0) <= b ? T(1) : T(0);
  T sum(0);
  for (const auto& x : A) sum += x;
  if (!(T(0) < b)) return T(0);
  if (!(b < sum)) return T(1);
  const std::size_t m = A.size();
  T acc(0);
  for (std::size_t v = 0; v < (std::size_t(1) << m); ++v) {
    T r = b;
    int bits = 0;
    for (std::size_t k = 0; k < m; ++k)
      if ((v >> k) & 1) {
        r -= A[k];
        ++bits;
      }
    if (!(T(0) < r)) continue;
    const T t = power_of(r, static_cast<int>(m));
    if (bits % 2) acc -= t;
    else acc += t;
  }
  T den(1);
  for (std::size_t k = 0; k < m; ++k) den *= A[k] * T(static_cast<long>(k + 1));
  T s = acc / den;
  if (s < T(0)) s = T(0);  // (float arithmetic)
  if (T(1) < s) s = T(1);
  return s;
}

/// An affine L(s) = a0 + a . s with |G - L| <= e on [0, 1]^3 in the units of G's coefficients
/// (G's scale left out: the sets {L >= +-e} do not depend on it): L from G's mean slopes (rounded
/// to short dyadics, or exact: then e = 0 for an affine G), e the largest coefficient of G - L (L
/// in G's degrees has the coefficients L(i / p)).
template <class T>
void affine_fit(const SBern<T>& G, T& a0, std::array<T, 3>& a, T& e, bool rounded = true) {
  const std::size_t n0 = G.deg[0] + 1, n1 = G.deg[1] + 1, n2 = G.deg[2] + 1;
  const std::size_t stride[3] = {1, n0, n0 * n1};
  for (int d = 0; d < 3; ++d) {
    a[d] = T(0);
    if (G.deg[d] == 0) continue;
    const std::size_t p = static_cast<std::size_t>(G.deg[d]);
    Coef<T> s(0);
    std::size_t lines = 0;
    for (std::size_t i = 0; i < G.c.size(); ++i) {
      if ((i / stride[d]) % (p + 1) != 0) continue;
      s += G.c[i + p * stride[d]];
      s -= G.c[i];
      ++lines;
    }
    a[d] = as_value<T>(s) / T(static_cast<long>(lines));
    if (rounded) a[d] = short_dyadic(a[d]);
  }
  Coef<T> total(0);
  for (const auto& x : G.c) total += x;
  a0 = as_value<T>(total) / T(static_cast<long>(G.c.size())) - (a[0] + a[1] + a[2]) / T(2);
  if (rounded) a0 = short_dyadic(a0);
  // L's coefficient at (i, j, k): a0 + a_0 i / p_0 + ... ; e = max |c - L|.
  std::array<std::vector<T>, 3> step;
  for (int d = 0; d < 3; ++d) {
    const std::size_t n = static_cast<std::size_t>(G.deg[d]) + 1;
    step[d].resize(n);
    for (std::size_t i = 0; i < n; ++i) step[d][i] = G.deg[d] > 0 ? T(a[d] * T(static_cast<long>(i)) / T(G.deg[d])) : T(0);
  }
  e = T(0);
  T r;
  for (std::size_t k = 0; k < n2; ++k)
    for (std::size_t j = 0; j < n1; ++j) {
      const T base = a0 + step[1][j] + step[2][k];
      for (std::size_t i = 0; i < n0; ++i) {
        r = as_value<T>(G.c[i + n0 * (j + n1 * k)]);
        r -= base;
        r -= step[0][i];
        if (r < T(0)) r = -r;
        if (e < r) e = r;
      }
    }
}

/// How far G is from affine along each direction: its largest second difference along d, and
/// half its largest mixed difference with each other direction, in the scale of derivatives
/// (units of G's coefficients).
template <class T>
std::array<T, 3> curvature_along(const SBern<T>& G) {
  using C = Coef<T>;
  const std::size_t n[3] = {static_cast<std::size_t>(G.deg[0]) + 1, static_cast<std::size_t>(G.deg[1]) + 1,
                            static_cast<std::size_t>(G.deg[2]) + 1};
  const std::size_t stride[3] = {1, n[0], n[0] * n[1]};
  std::array<C, 3> best{C(0), C(0), C(0)};
  C v;
  for (std::size_t i = 0; i < G.c.size(); ++i) {
    const std::size_t idx[3] = {i % n[0], (i / n[0]) % n[1], i / (n[0] * n[1])};
    for (int d = 0; d < 3; ++d) {
      if (idx[d] + 2 < n[d]) {
        v = G.c[i + 2 * stride[d]];
        v -= G.c[i + stride[d]];
        v -= G.c[i + stride[d]];
        v += G.c[i];
        if (v < 0) v = -v;
        v *= C(G.deg[d] * (G.deg[d] - 1) * 2);
        if (best[d] < v) best[d] = v;
      }
      for (int e = d + 1; e < 3; ++e) {
        if (idx[d] + 1 >= n[d] || idx[e] + 1 >= n[e]) continue;
        v = G.c[i + stride[d] + stride[e]];
        v -= G.c[i + stride[d]];
        v -= G.c[i + stride[e]];
        v += G.c[i];
        if (v < 0) v = -v;
        v *= C(G.deg[d] * G.deg[e]);
        if (best[d] < v) best[d] = v;
        if (best[e] < v) best[e] = v;
      }
    }
  }
  return {as_value<T>(best[0]), as_value<T>(best[1]), as_value<T>(best[2])};
}

/// The largest difference of neighbouring coefficients along each direction (in units of b's
/// coefficients).
template <class T>
std::array<T, 3> variation_along(const SBern<T>& b) {
  using C = Coef<T>;
  const std::size_t n[3] = {static_cast<std::size_t>(b.deg[0]) + 1, static_cast<std::size_t>(b.deg[1]) + 1,
                            static_cast<std::size_t>(b.deg[2]) + 1};
  const std::size_t stride[3] = {1, n[0], n[0] * n[1]};
  std::array<C, 3> best{C(0), C(0), C(0)};
  C v;
  for (std::size_t i = 0; i < b.c.size(); ++i) {
    const std::size_t idx[3] = {i % n[0], (i / n[0]) % n[1], i / (n[0] * n[1])};
    for (int d = 0; d < 3; ++d) {
      if (idx[d] + 1 >= n[d]) continue;
      v = b.c[i + stride[d]];
      v -= b.c[i];
      if (v < 0) v = -v;
      if (best[d] < v) best[d] = v;
    }
  }
  return {as_value<T>(best[0]), as_value<T>(best[1]), as_value<T>(best[2])};
}

/// The direction where b varies most (best: that variation times b's scale; 0 if constant).
template <class T>
int most_varying(const SBern<T>& b, T* best_out = nullptr) {
  const auto v = variation_along(b);
  int dir = 0;
  for (int d = 1; d < 3; ++d)
    if (v[dir] < v[d]) dir = d;
  if (best_out) *best_out = v[dir] * b.scale;
  return dir;
}

/// A cut box's part as the region on one side of a graph s_k = phi(s_a, s_b) (a, b the other two
/// directions in order): G strictly monotone along k (its derivative's coefficients of one strict
/// sign, |dG/ds_k| >= m), phi its root along k. psi is a biquadratic through approximate roots at
/// the 3 x 3 grid of the face (Newton in short dyadics), and |phi - psi| <= eps = max |G(s,
/// psi(s))| / m (the coefficients of the composition G(s, psi(s))); psi +- eps within (0, 1) so
/// the part over every point of the face is one interval of the column.
template <class T>
struct GraphCut {
  int k = 0;
  bool below = false;  // the part is {s_k <= phi} (else {s_k >= phi})
  std::vector<Coef<T>> psi, one_minus_psi;
  std::vector<int> dpsi{2, 2};
  T psi_unit{1};
  T eps{0};
  std::array<T, 2> curvature{T(0), T(0)};  // of psi along a and b
  int monotone = -1;                       // the flattest direction where G is monotone (-1: none)
  int steepest = -1;                       // then the other direction where G varies most
  bool exits = false;                      // psi +- eps leaves [0, 1]: the part's columns are clamped
  T ext_lo{0}, ext_hi{1};                  // an interval of t holding psi +- eps, where G is monotone
  /// int int (psi - 1)_+ and (-psi)_+ over the face, each between two bounds: subdivision of
  /// psi's coefficients, exact on sub-squares wholly on one side, between 0 and the largest
  /// overshoot times the area where the level set still crosses after 8 halvings.
  std::optional<std::array<T, 4>> overshoot_;
  const std::array<T, 4>& overshoot() {
    if (overshoot_) return *overshoot_;
    std::array<T, 4> o{T(0), T(0), T(0), T(0)};
    Bernstein<T> p{dpsi, std::vector<T>(psi.size())};
    for (std::size_t i = 0; i < p.c.size(); ++i) p.c[i] = as_value<T>(psi[i]) * psi_unit;
    // f = psi - 1 (top) or -psi (bottom) on a sub-square of the given area.
    std::function<void(const Bernstein<T>&, bool, int, const T&)> walk = [&](const Bernstein<T>& q, bool top, int depth, const T& area) {
      std::vector<T> f(q.c.size());
      for (std::size_t i = 0; i < f.size(); ++i) f[i] = top ? T(q.c[i] - T(1)) : T(-q.c[i]);
      T mn = f.front(), mx = mn, sum(0);
      for (const auto& x : f) {
        if (x < mn) mn = x;
        if (mx < x) mx = x;
        sum += x;
      }
      T& lo = o[top ? 0 : 2];
      T& hi = o[top ? 1 : 3];
      if (!(T(0) < mx)) return;  // not above
      if (!(mn < T(0))) {        // wholly above: exact
        const T v = sum / T(static_cast<long>(q.c.size())) * area;
        lo += v;
        hi += v;
        return;
      }
      if (depth == 0) {
        hi += mx * area;
        return;
      }
      T va(0), vb(0);  // halve across the direction where psi varies more
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 2; ++i) {
          T d1 = q.c[i + 1 + 3 * j] - q.c[i + 3 * j], d2 = q.c[j + 3 * (i + 1)] - q.c[j + 3 * i];
          if (d1 < T(0)) d1 = -d1;
          if (d2 < T(0)) d2 = -d2;
          if (va < d1) va = d1;
          if (vb < d2) vb = d2;
        }
      auto [q0, q1] = bern_split(q, va < vb ? 1 : 0, T(1) / T(2));
      walk(q0, top, depth - 1, area / T(2));
      walk(q1, top, depth - 1, area / T(2));
    };
    walk(p, true, 8, T(1));
    walk(p, false, 8, T(1));
    overshoot_ = o;
    return *overshoot_;
  }
  /// psi^j, j = 0, 1, ..., in two directions (raw coefficients; values times unit[j]).
  std::vector<std::vector<Coef<T>>> powers{std::vector<Coef<T>>{Coef<T>(1)}};
  std::vector<std::vector<int>> power_deg{std::vector<int>{0, 0}};
  std::vector<T> power_unit{T(1)};
  void ensure_powers(int q) {
    while (static_cast<int>(powers.size()) <= q) {
      std::vector<int> dn;
      T u(1);
      auto next = raw_product<T>(powers.back(), power_deg.back(), psi, dpsi, dn, u);
      power_unit.push_back(power_unit.back() * u * psi_unit);
      powers.push_back(std::move(next));
      power_deg.push_back(dn);
    }
  }
};

template <class T>
T univariate_value(const std::vector<T>& u, const T& t) {
  std::vector<T> w = u;
  const T s = T(1) - t;
  for (std::size_t r = w.size() - 1; r > 0; --r)
    for (std::size_t i = 0; i < r; ++i) w[i] = w[i] * s + w[i + 1] * t;
  return w[0];
}

template <class T>
bool graph_along(const SBern<T>& G, int k, int sign_k, const T& m, bool part_is_nonneg, GraphCut<T>& g);
/// part_is_nonneg: the part is {G >= 0} (else {G <= 0}).
template <class T>
bool graph_cut(const SBern<T>& G, bool part_is_nonneg, GraphCut<T>& g) {
  using C = Coef<T>;
  const std::size_t n[3] = {static_cast<std::size_t>(G.deg[0]) + 1, static_cast<std::size_t>(G.deg[1]) + 1,
                            static_cast<std::size_t>(G.deg[2]) + 1};
  const std::size_t stride[3] = {1, n[0], n[0] * n[1]};
  // Per direction: the derivative's coefficients (without the factor p) and their range.
  std::array<T, 3> mins{T(0), T(0), T(0)}, maxabs{T(0), T(0), T(0)};
  std::array<int, 3> sign{0, 0, 0};
  C diff;
  for (int d = 0; d < 3; ++d) {
    if (G.deg[d] == 0) continue;
    bool pos = true, neg = true;
    C lo(0), hi(0);
    bool first = true;
    for (std::size_t i = 0; i < G.c.size(); ++i) {
      if ((i / stride[d]) % n[d] == n[d] - 1) continue;
      diff = G.c[i + stride[d]];
      diff -= G.c[i];
      pos = pos && 0 < diff;
      neg = neg && diff < 0;
      if (first || diff < lo) lo = diff;
      if (first || hi < diff) hi = diff;
      first = false;
    }
    const T p(G.deg[d]);
    maxabs[d] = std::max(T(-as_value<T>(lo)), as_value<T>(hi)) * p;
    if (pos || neg) {
      sign[d] = pos ? 1 : -1;
      mins[d] = (pos ? as_value<T>(lo) : T(-as_value<T>(hi))) * p;
    }
  }
  // The directions where G is monotone, the flattest graph first: m_k against the other
  // directions' slopes.
  std::vector<std::pair<T, int>> order;
  for (int d = 0; d < 3; ++d) {
    if (sign[d] == 0) continue;
    T other(0);
    for (int e = 0; e < 3; ++e)
      if (e != d && other < maxabs[e]) other = maxabs[e];
    // (The composition's cost grows with G's degree along d: prefer the lower degrees.)
    order.push_back({(T(0) < other ? T(mins[d] / other) : T(mins[d] * T(1000000))) / T(G.deg[d] * G.deg[d]), d});
  }
  if (order.empty()) return false;
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return y.first < x.first; });
  g.monotone = order.front().second;
  for (int d = 0; d < 3; ++d)
    if (d != g.monotone && (g.steepest < 0 || maxabs[g.steepest] < maxabs[d])) g.steepest = d;
  for (const auto& [score, k] : order)
    if (graph_along(G, k, sign[k], mins[k], part_is_nonneg, g)) return true;
  return false;
}

/// graph_cut along direction k (G's derivative along k of sign `sign`, at least m).
template <class T>
bool graph_along(const SBern<T>& G, int k, int sign_k, const T& m, bool part_is_nonneg, GraphCut<T>& g) {
  using C = Coef<T>;
  g.k = k;
  std::vector<int> ds;
  const auto sl = slices_along(G, k, false, ds);
  // Approximate roots at the 3 x 3 grid, then psi's Bernstein coefficients.
  const T half = T(1) / T(2);
  const T grid[3] = {T(0), half, T(1)};
  T f[3][3];
  for (int ia = 0; ia < 3; ++ia)
    for (int ib = 0; ib < 3; ++ib) {
      std::vector<T> u(sl.size());
      for (std::size_t l = 0; l < sl.size(); ++l) {
        Bernstein<T> b2{ds, std::vector<T>(sl[l].size())};
        for (std::size_t i = 0; i < sl[l].size(); ++i) b2.c[i] = as_value<T>(sl[l][i]);
        u[l] = bern_value(b2, std::vector<T>{grid[ia], grid[ib]});
      }
      std::vector<T> du(u.size() - 1);
      for (std::size_t l = 0; l + 1 < u.size(); ++l) du[l] = (u[l + 1] - u[l]) * T(static_cast<long>(u.size() - 1));
      // Start: the chord's root; then Newton.
      T t = (u.front() == u.back()) ? half : T(u.front() / (u.front() - u.back()));
      for (int it = 0; it < 8; ++it) {
        const T dv = univariate_value(du, t);
        if (dv == T(0)) return false;
        const T next = round_dyadic(T(t - univariate_value(u, t) / dv), false, 40, 0);
        if (next == t) break;
        t = next;
        if (t < T(-1) || T(2) < t) return false;
      }
      f[ia][ib] = t;
    }
  // Values at 0, 1/2, 1 to Bernstein coefficients of degree 2, per direction.
  T bcoef[3][3];
  for (int ib = 0; ib < 3; ++ib) {
    T v0 = f[0][ib], v1 = f[1][ib], v2 = f[2][ib];
    f[0][ib] = v0;
    f[1][ib] = T(2) * v1 - (v0 + v2) / T(2);
    f[2][ib] = v2;
  }
  for (int ia = 0; ia < 3; ++ia) {
    T v0 = f[ia][0], v1 = f[ia][1], v2 = f[ia][2];
    bcoef[ia][0] = round_dyadic(v0, false, 24, 0);
    bcoef[ia][1] = round_dyadic(T(T(2) * v1 - (v0 + v2) / T(2)), false, 24, 0);
    bcoef[ia][2] = round_dyadic(v2, false, 24, 0);
  }
  T pmin = bcoef[0][0], pmax = pmin;
  for (int ia = 0; ia < 3; ++ia)
    for (int ib = 0; ib < 3; ++ib) {
      pmin = std::min(pmin, bcoef[ia][ib]);
      pmax = std::max(pmax, bcoef[ia][ib]);
    }
  // Where psi leaves [0, 1] (the surface leaves the box through a face across k), G is needed
  // monotone on a longer interval [lo, hi] of t: its coefficients there (de Casteljau at
  // parameters outside [0, 1]).
  T m_used = m;
  const T eighth = T(1) / T(8);
  T ext_lo(0), ext_hi(1);
  while (!(ext_lo + eighth < pmin)) ext_lo -= eighth;
  while (!(pmax < ext_hi - eighth)) ext_hi += eighth;
  if (ext_lo < T(-1) || T(2) < ext_hi) return false;
  if (ext_lo < T(0) || T(1) < ext_hi) {
    Bernstein<T> v{G.deg, std::vector<T>(G.c.size())};
    for (std::size_t i = 0; i < v.c.size(); ++i) v.c[i] = as_value<T>(G.c[i]);
    v = bern_split(v, k, ext_lo).second;                                           // over [ext_lo, 1]
    v = bern_split(v, k, T((ext_hi - ext_lo) / (T(1) - ext_lo))).first;          // over [ext_lo, ext_hi]
    const std::size_t n[3] = {static_cast<std::size_t>(G.deg[0]) + 1, static_cast<std::size_t>(G.deg[1]) + 1,
                              static_cast<std::size_t>(G.deg[2]) + 1};
    const std::size_t stride[3] = {1, n[0], n[0] * n[1]};
    T lo, hi;
    bool first = true;
    for (std::size_t i = 0; i < v.c.size(); ++i) {
      if ((i / stride[k]) % n[k] == n[k] - 1) continue;
      const T dlt = v.c[i + stride[k]] - v.c[i];
      if (first || dlt < lo) lo = dlt;
      if (first || hi < dlt) hi = dlt;
      first = false;
    }
    if (sign_k > 0 ? !(T(0) < lo) : !(hi < T(0))) return false;
    // d/dt over [ext_lo, ext_hi] is p (c_{l+1} - c_l) / (ext_hi - ext_lo).
    m_used = (sign_k > 0 ? lo : T(-hi)) * T(G.deg[k]) / (ext_hi - ext_lo);
  }
  // psi's raw coefficients (a fastest).
  g.psi.assign(9, C(0));
  g.one_minus_psi.assign(9, C(0));
  if constexpr (integer_coefficients<T>) {
    mp_bitcnt_t K = 0;
    for (int ia = 0; ia < 3; ++ia)
      for (int ib = 0; ib < 3; ++ib) K = std::max<mp_bitcnt_t>(K, mpz_sizeinbase(mpq_denref(bcoef[ia][ib].backend().data()), 2) - 1);
    Integer one(1);
    mpz_mul_2exp(one.backend().data(), one.backend().data(), K);
    for (int ia = 0; ia < 3; ++ia)
      for (int ib = 0; ib < 3; ++ib) {
        Rational x = bcoef[ia][ib];
        mpq_mul_2exp(x.backend().data(), x.backend().data(), K);
        g.psi[ia + 3 * ib] = numerator(x);
        g.one_minus_psi[ia + 3 * ib] = one - numerator(x);
      }
    g.psi_unit = T(1) / T(one);
  } else {
    for (int ia = 0; ia < 3; ++ia)
      for (int ib = 0; ib < 3; ++ib) {
        g.psi[ia + 3 * ib] = bcoef[ia][ib];
        g.one_minus_psi[ia + 3 * ib] = T(1) - bcoef[ia][ib];
      }
    g.psi_unit = T(1);
  }
  // eps = max |G(s, psi(s))| / m.
  std::vector<int> dh;
  T factor;
  const auto H = compose_graph<T>(sl, ds, g.psi, g.one_minus_psi, g.dpsi, g.psi_unit, dh, factor);
  C hmax(0), x;
  for (const auto& h : H) {
    x = h;
    if (x < 0) x = -x;
    if (hmax < x) hmax = x;
  }
  g.eps = round_outward(T(as_value<T>(hmax) * factor / m_used), true);
  if (!(ext_lo < pmin - g.eps) || !(pmax + g.eps < ext_hi)) return false;
  g.exits = pmin - g.eps < T(0) || T(1) < pmax + g.eps;
  g.ext_lo = ext_lo;
  g.ext_hi = ext_hi;
  g.below = (sign_k > 0) != part_is_nonneg;
  for (int ib = 0; ib < 3; ++ib) {
    T v = bcoef[0][ib] - T(2) * bcoef[1][ib] + bcoef[2][ib];
    if (v < T(0)) v = -v;
    if (g.curvature[0] < v) g.curvature[0] = v;
  }
  for (int ia = 0; ia < 3; ++ia) {
    T v = bcoef[ia][0] - T(2) * bcoef[ia][1] + bcoef[ia][2];
    if (v < T(0)) v = -v;
    if (g.curvature[1] < v) g.curvature[1] = v;
  }
  return true;
}

/// The integral over [0, 1]^2 of a b (two directions, raw coefficients; the values times the
/// Gram units times a's and b's units), by the Gram matrices contracted direction by direction.
template <class T>
Coef<T> contract_2d(const std::vector<Coef<T>>& a, const std::vector<int>& da, const std::vector<Coef<T>>& b, const std::vector<int>& db,
                    GramCache<T>& gram, T& unit) {
  using C = Coef<T>;
  const std::size_t a0 = da[0] + 1, a1 = da[1] + 1, b0 = db[0] + 1, b1 = db[1] + 1;
  const auto& g0 = gram.get(da[0], db[0]);
  const auto& g1 = gram.get(da[1], db[1]);
  unit = g0.unit * g1.unit;
  auto addmul = [](C& acc, const C& x, const C& y) {
    if constexpr (integer_coefficients<T>) mpz_addmul(acc.backend().data(), x.backend().data(), y.backend().data());
    else acc += x * y;
  };
  thread_local std::vector<C> t1;
  t1.assign(b0 * a1, C(0));
  for (std::size_t i1 = 0; i1 < a1; ++i1)
    for (std::size_t i0 = 0; i0 < a0; ++i0) {
      const C& x = a[i0 + a0 * i1];
      if (x == 0) continue;
      for (std::size_t j0 = 0; j0 < b0; ++j0) addmul(t1[j0 + b0 * i1], x, g0.g[i0 * b0 + j0]);
    }
  C s(0), t(0);
  for (std::size_t j1 = 0; j1 < b1; ++j1)
    for (std::size_t j0 = 0; j0 < b0; ++j0) {
      const C& bj = b[j0 + b0 * j1];
      if (bj == 0) continue;
      t = C(0);
      for (std::size_t i1 = 0; i1 < a1; ++i1) addmul(t, t1[j0 + b0 * i1], g1.g[i1 * b1 + j1]);
      addmul(s, bj, t);
    }
  return s;
}

/// The integral of P over a cut box's part given by a graph, lo <= int <= hi (on the box's unit
/// cube): int_{s_k <= phi} P = int int A(s, clamp(phi(s))) for P's antiderivative A along k, which
/// is int int A(s, psi(s)) within eps max |P|, minus, where psi leaves [0, 1], F = A(s, psi) -
/// A(s, 1) over {psi > 1} and A(s, psi) over {psi < 0}.
template <class T>
void graph_integral(const SBern<T>& P, GraphCut<T>& g, GramCache<T>& gram, T& lo, T& hi) {
  std::vector<int> ds;
  const auto A = slices_along(P, g.k, true, ds);
  const int q = static_cast<int>(A.size()) - 1;
  const T aunit = P.scale / T(q);  // A's slices: sums of P's, times 1 / (p + 1)
  // A(s, t) = sum_l a_l(s) B_l^q(t) = sum_j alpha_j(s) t^j, alpha_j = sum_{l <= j} (-1)^(j - l)
  // C(q, l) C(q - l, j - l) a_l; then int int alpha_j psi^j by Gram contraction.
  g.ensure_powers(q);
  T total(0);
  for (int j = 0; j <= q; ++j) {
    std::vector<Coef<T>> alpha(A[0].size(), Coef<T>(0));
    for (int l = 0; l <= j; ++l) {
      const T c = detail::binomial_row<T>(q)[l] * detail::binomial_row<T>(q - l)[j - l];
      Coef<T> cc;
      if constexpr (integer_coefficients<T>) cc = numerator(c);
      else cc = c;
      if ((j - l) % 2) cc = -cc;
      for (std::size_t i = 0; i < alpha.size(); ++i) alpha[i] += cc * A[l][i];
    }
    T gu(1);
    const Coef<T> v = contract_2d<T>(alpha, ds, g.powers[j], g.power_deg[j], gram, gu);
    total += as_value<T>(v) * gu * g.power_unit[j];
  }
  T blo = total * aunit, bhi = blo;
  if (g.exits) {
    // Where psi > 1, A(s, 1) instead of C(s) = A(s, psi(s)): C - A(s, 1) = int_1^psi P dt lies
    // between (psi - 1) times P's extremes over the longer interval; where psi < 0, 0 instead of
    // C = -int_psi^0 P dt. int int (psi - 1)_+ and (-psi)_+ are the graph's (overshoot).
    Bernstein<T> v{P.deg, std::vector<T>(P.c.size())};
    for (std::size_t i = 0; i < v.c.size(); ++i) v.c[i] = as_value<T>(P.c[i]) * P.scale;
    if (g.ext_lo < T(0)) v = bern_split(v, g.k, g.ext_lo).second;
    if (T(1) < g.ext_hi) v = bern_split(v, g.k, T((g.ext_hi - g.ext_lo) / (T(1) - g.ext_lo))).first;
    T emin = v.c.front(), emax = emin;
    for (const auto& x : v.c) {
      if (x < emin) emin = x;
      if (emax < x) emax = x;
    }
    const auto& o = g.overshoot();
    const T top_lo = std::min(emin * o[0], emin * o[1]), top_hi = std::max(emax * o[0], emax * o[1]);
    const T bottom_lo = -std::max(emax * o[2], emax * o[3]), bottom_hi = -std::min(emin * o[2], emin * o[3]);
    blo -= top_hi + bottom_hi;
    bhi -= top_lo + bottom_lo;
  }
  T pmin, pmax;
  coefficient_range(P, pmin, pmax);
  const T err = g.eps * std::max(T(-pmin), pmax);
  if (g.below) {
    lo = blo - err;
    hi = bhi + err;
  } else {
    const T whole = coefficient_mean(P);
    lo = whole - bhi - err;
    hi = whole - blo + err;
  }
}

/// One unit in the 64th significant bit of x: 2^(floor(log2 |x|) - 63) (2^-64 for 0).
template <class T>
T last_bit_unit(const T& x) {
  const T ax = x < T(0) ? T(-x) : x;
  T u(1);
  if (!(ax == T(0))) {
    while (!(ax < u)) u *= T(2);
    while (ax < u) u /= T(2);
  }
  for (int i = 0; i < 63 + (ax == T(0) ? 1 : 0); ++i) u /= T(2);
  return u;
}

}  // namespace vrep_detail

template <class T>
IntegralEnclosures<T> integral_enclosures(const std::vector<IntegrandCell<T>>& cells, const std::vector<int>& components, const T& rel_width,
                                          std::size_t max_boxes, const Limits& limits) {
  using namespace vrep_detail;
  if (max_boxes < 1) throw ValidationError("boxes", "must be at least 1", "give a positive box budget");
  if (rel_width < T(0)) throw ValidationError("rel_width", "is negative", "give a relative width >= 0 (0: spend the whole budget)");
  const std::size_t K = components.size();
  struct Cell {
    const Region<T>* trim = nullptr;
    std::vector<const Poly3<T>*> leaves;
    bool rational = false;
    int power = 5;
    T vlo{0}, vhi{0};
    std::vector<T> mlo, mhi;
    std::size_t boxes = 0;
    int orientation = 0;  // the sign of det J (of a regular cell): of N's integral over a piece, exactly
  };
  const Region<T> whole = region_and<T>({});
  std::vector<Cell> C(cells.size());
  IntegralEnclosures<T> out;
  out.scale.assign(K, T(0));
  struct Box {
    std::size_t cell = 0;
    std::vector<Truth> lt;   // every leaf's truth on the box
    std::vector<SBern<T>> G;  // the undecided leaves' compositions (decided: emptied)
    SBern<T> N, W;
    std::vector<SBern<T>> Q;  // per component: the integrand's numerator
    T vol{1};                // share of its piece's unit cube
    T vlo{0}, vhi{0};
    std::vector<T> mlo, mhi;
    T key{0};
    int dir = 0;
    std::array<unsigned char, 3> splits{0, 0, 0};  // halvings per direction so far
    T at{0};  // > 0: cut at this parameter of direction dir before anything else (a parameter plane)
  };
  std::vector<Box> pool;
  std::vector<std::size_t> free_slots;
  GramCache<T> gram;
  const int order = 6;  // Taylor's order in the rational in-boxes (even)
  const vrep_testing::EnclosurePlant plant = vrep_testing::planted_enclosure;

  // The checks and the initial boxes: every Bezier piece of every cell.
  std::vector<Box> initial;
  CarriedCoefficients initial_carried{limits};
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string who = cells.size() == 1 ? std::string() : "cells[" + std::to_string(c) + "].";
    if (!cells[c].trivariate) throw ValidationError(who + "trivariate", "is missing", "give the cell's trivariate");
    const BSpline<T>& V0 = *cells[c].trivariate;
    const BSpline<T>* field = cells[c].field;
    require_jacobian_input(V0, limits);
    std::optional<std::pair<BSpline<T>, BSpline<T>>> refined;
    for (int k : components) {
      if (k < 0) throw ValidationError(field ? "component" : "coordinate", "is negative", "give 0 <= coordinate < q");
      if (!field && k >= V0.q) throw ValidationError("coordinate", "is not a point coordinate of the trivariate", "give 0 <= coordinate < q");
      if (field) require_field(V0, *field, k, "field", limits);
    }
    if (field && K > 0) refined = common_breakpoints(V0, *field, limits);
    const BSpline<T>& V = refined ? refined->first : V0;
    require_positive_weights(V);
    Cell& cell = C[c];
    cell.trim = cells[c].trim ? cells[c].trim : &whole;
    collect_leaves(*cell.trim, cell.leaves);
    cell.rational = V.is_rational();
    cell.power = field ? 4 : 5;
    cell.mlo.assign(K, T(0));
    cell.mhi.assign(K, T(0));
    // Limits before the work: all leaves composed on one piece; the boxes' compositions are
    // counted as they are made (a box carries only the leaves that can still change its truth).
    composed_leaves_size(V, cell.leaves, limits);
    // The moments' scales: the largest |coordinate| (or |field component|) of the control points.
    for (std::size_t k = 0; k < K; ++k) {
      const BSpline<T>& S = field ? *field : V;
      for (std::size_t i = 0; i < S.size(); ++i) {
        T x = S.points[i * S.q + components[k]];
        if (x < T(0)) x = -x;
        if (out.scale[k] < x) out.scale[k] = x;
      }
    }
    const BezierForm<T> F = bezier_form(V, limits);
    std::optional<BezierForm<T>> FF;
    if (field && K > 0) FF = bezier_form(refined->second, limits);
    for (std::size_t p = 0; p < F.size(); ++p) {
      const auto pc = F.piece(p);
      Box b;
      b.cell = c;
      b.lt.assign(cell.leaves.size(), Truth::mixed);
      // The planes first (cheap); then only the leaves the formula may still depend on.
      b.G.resize(cell.leaves.size());
      PiecePowers<T> powers(pc.spline);
      for (std::size_t l = 0; l < cell.leaves.size(); ++l)
        if (cell.leaves[l]->degree() <= 1) {
          b.G[l] = scaled(compose_leaf(*cell.leaves[l], powers));
          b.lt[l] = coefficient_truth(b.G[l]);
          if (b.lt[l] != Truth::mixed) b.G[l] = SBern<T>{};
        }
      std::vector<char> live;
      live_leaves(*cell.trim, b.lt, live);
      for (std::size_t l = 0; l < cell.leaves.size(); ++l)
        if (cell.leaves[l]->degree() > 1 && live[l]) b.G[l] = scaled(compose_leaf(*cell.leaves[l], powers));
      initial_carried.add(CarriedCoefficients::of(b.G), "the cells' pieces");  // as they are made
      const Bernstein<T> N = jacobian_numerator(pc.spline);
      if (cell.orientation == 0) {
        // N's mean is its integral over the piece, W^4 > 0: a regular cell's orientation.
        T sum(0);
        for (const auto& x : N.c) sum += x;
        cell.orientation = sum < T(0) ? -1 : T(0) < sum ? 1 : 0;
      }
      b.N = scaled(N);
      b.W = scaled(homogeneous(pc.spline, 0));
      for (std::size_t k = 0; k < K; ++k)
        b.Q.push_back(scaled(mul(FF ? homogeneous(FF->piece(p).spline, components[k] + 1) : homogeneous(pc.spline, components[k] + 1), N)));
      b.mlo.assign(K, T(0));
      b.mhi.assign(K, T(0));
      initial.push_back(std::move(b));
    }
  }
  out.budget = checked_product(max_boxes, std::max<std::size_t>(cells.size(), 1), limits, "box budget");
  if (initial.size() > out.budget) out.budget = initial.size();

  // The moments' widths count in the volume's units: width / scale.
  std::vector<T> inv_scale(K, T(0));
  for (std::size_t k = 0; k < K; ++k)
    if (T(0) < out.scale[k]) inv_scale[k] = round_outward(T(T(1) / out.scale[k]), true);

  // Where the integrands vary most relative to their size (N, the moments' numerators, W to the
  // power 4): the direction to halve a box whose width comes from them.
  auto density_direction = [&](const Box& b) {
    std::array<T, 3> score{T(0), T(0), T(0)};
    auto add = [&](const SBern<T>& P, const T& weight) {
      T lo, hi;
      coefficient_range(P, lo, hi);
      const T m = std::max(T(-lo), hi);
      if (!(T(0) < m)) return;
      const auto v = variation_along(P);
      for (int d = 0; d < 3; ++d) score[d] += weight * v[d] * P.scale / m;
    };
    add(b.N, T(1));
    for (const auto& q : b.Q) add(q, T(1));
    if (C[b.cell].rational) add(b.W, T(4));
    int dir = 0;
    for (int d = 1; d < 3; ++d)
      if (score[dir] < score[d]) dir = d;
    return dir;
  };

  // Bounds, priority and split direction of a box; false when the box is done (no width left to
  // gain from it: out, or exact).
  auto evaluate = [&](Box& b) -> bool {
    Cell& cell = C[b.cell];
    // A leaf not carried (empty) is decided, or one the formula no longer depends on (kept mixed).
    for (std::size_t l = 0; l < b.G.size(); ++l) {
      if (b.lt[l] != Truth::mixed || b.G[l].c.empty()) continue;
      b.lt[l] = coefficient_truth(b.G[l]);
      if (b.lt[l] != Truth::mixed) b.G[l] = SBern<T>{};
    }
    std::size_t k0 = 0;
    const Truth truth = cell.leaves.empty() ? Truth::in : combine(*cell.trim, b.lt, k0);
    std::size_t open = 0, last_open = 0;
    if (truth == Truth::mixed) {
      std::vector<char> live;
      live_leaves(*cell.trim, b.lt, live);
      for (std::size_t l = 0; l < b.G.size(); ++l) {
        if (b.lt[l] != Truth::mixed || b.G[l].c.empty()) continue;
        if (!live[l]) b.G[l] = SBern<T>{};
        else {
          ++open;
          last_open = l;
        }
      }
    }
    b.vlo = b.vhi = T(0);
    for (std::size_t k = 0; k < K; ++k) b.mlo[k] = b.mhi[k] = T(0);
    b.key = T(0);
    if (truth == Truth::out) return false;
    if (truth == Truth::in) {
      // The formula is in whatever its undecided leaves do (Kleene's logic is monotone): they
      // count as in from here on, for the box's parts too.
      for (std::size_t l = 0; l < b.G.size(); ++l) {
        b.G[l] = SBern<T>{};
        if (b.lt[l] == Truth::mixed) b.lt[l] = Truth::in;
      }
      if (!cell.rational) {
        b.vlo = b.vhi = b.vol * coefficient_mean(b.N);
        for (std::size_t k = 0; k < K; ++k) b.mlo[k] = b.mhi[k] = b.vol * coefficient_mean(b.Q[k]);
        return false;
      }
      T lo, hi;
      std::vector<SBern<T>> Wp{b.W};  // W, W^2, ..., W^order
      for (int j = 2; j <= order; ++j) Wp.push_back(product(Wp.back(), b.W));
      taylor_bounds(b.N, Wp, 4, order, gram, lo, hi);
      b.vlo = round_outward(T(b.vol * lo), false);
      b.vhi = round_outward(T(b.vol * hi), true);
      for (std::size_t k = 0; k < K; ++k) {
        taylor_bounds(b.Q[k], Wp, cell.power, order, gram, lo, hi);
        b.mlo[k] = round_outward(T(b.vol * lo), false);
        b.mhi[k] = round_outward(T(b.vol * hi), true);
      }
      // Across the direction where W varies most (N's where W is constant).
      T best;
      b.dir = most_varying(b.W, &best);
      if (!(T(0) < best)) b.dir = most_varying(b.N);
    } else {
      // Cut. One undecided leaf the formula follows: the part is {G >= 0} or {G <= 0} on the box.
      T wmin, wmax;
      coefficient_range(b.W, wmin, wmax);
      if (!(T(0) < wmin)) throw DomainError("trivariate.weights", "has a weight bound that is not positive", "give positive weights");
      int sense = 0;  // +1: {G >= 0}, -1: {G <= 0}
      if (open == 1 && plant != vrep_testing::EnclosurePlant::drop_crossing) {
        auto lt = b.lt;
        lt[last_open] = Truth::in;
        std::size_t k1 = 0;
        const Truth t_in = combine(*cell.trim, lt, k1);
        lt[last_open] = Truth::out;
        k1 = 0;
        const Truth t_out = combine(*cell.trim, lt, k1);
        if (t_in == Truth::in && t_out == Truth::out) sense = 1;
        if (t_in == Truth::out && t_out == Truth::in) sense = -1;
      }
      // The whole box's integral of Q / W^p between none and all of it (the coefficient ratios).
      auto trivial = [&](const SBern<T>& Q, int p, T& lo, T& hi) {
        T qmin, qmax;
        coefficient_range(Q, qmin, qmax);
        if (cell.rational) ratio_bounds(qmin, qmax, wmin, wmax, p, lo, hi);
        else {
          lo = qmin;
          hi = qmax;
        }
        lo = std::min(T(0), lo);
        hi = std::max(T(0), hi);
      };
      GraphCut<T> graph;
      bool done = false;
      T geometric(0);  // the width the graph's eps causes (volume's units)
      // A surface affine in the parameters (a plane of an affine cell) is cut exactly below.
      bool planar = false;
      if (sense != 0) {
        const auto cv = curvature_along(b.G[last_open]);
        planar = cv[0] == T(0) && cv[1] == T(0) && cv[2] == T(0);
      }
      if (planar) {
        // A parameter plane s_d = c: the box is cut there exactly (both parts then decided).
        T a0, e;
        std::array<T, 3> a;
        affine_fit(b.G[last_open], a0, a, e, false);
        int nonzero = 0, d0 = 0;
        for (int d = 0; d < 3; ++d)
          if (!(a[d] == T(0))) {
            ++nonzero;
            d0 = d;
          }
        if (nonzero == 1) {
          const T c = -a0 / a[d0];
          if (T(0) < c && c < T(1)) {
            b.dir = d0;
            b.at = c;
            return true;
          }
        }
      }
      if (sense != 0 && !planar && graph_cut(b.G[last_open], sense > 0, graph)) {
        // int_part Q / W^p: polynomial cells int_part Q directly; rational ones Taylor's formula of
        // order 2 at w0 with int_part Q, Q (W - w0), Q (W - w0)^2, the remainder f''(xi) / 2 between
        // its values at the ends of W's range.
        T w0 = short_dyadic(coefficient_mean(b.W));
        if (w0 < wmin) w0 = wmin;
        if (wmax < w0) w0 = wmax;
        SBern<T> Wm, Wm2;
        if (cell.rational) {
          Bernstein<T> v{b.W.deg, std::vector<T>(b.W.c.size())};
          for (std::size_t i = 0; i < v.c.size(); ++i) v.c[i] = as_value<T>(b.W.c[i]) * b.W.scale - w0;
          Wm = scaled(v);
          Wm2 = product(Wm, Wm);
        }
        auto through_graph = [&](const SBern<T>& Q, int p, T& lo, T& hi) {
          T l0, h0;
          graph_integral(Q, graph, gram, l0, h0);
          if (!cell.rational) {
            lo = l0;
            hi = h0;
            geometric += h0 - l0;
            return;
          }
          T l1, h1;
          graph_integral(product(Q, Wm), graph, gram, l1, h1);
          T qmin, qmax;
          coefficient_range(Q, qmin, qmax);
          const T c0 = T(1) / power_of(w0, p), c1 = -T(p) / power_of(w0, p + 1);
          const T r = T(p * (p + 1)) / T(2);
          const T rhi = r / power_of(std::min(wmin, w0), p + 2);  // f''(xi) / 2 at most this (xi >= wmin)
          T Rlo, Rhi;
          if (!(qmin < T(0)) || !(T(0) < qmax)) {
            // Q of one sign: int_part Q (W - w0)^2 has it, and is at most the box's.
            const bool pos = !(qmin < T(0));
            const T E2 = product_integral(Q, Wm2, gram);
            Rlo = pos ? T(0) : T(rhi * E2);
            Rhi = pos ? T(rhi * E2) : T(0);
          } else {
            // Q f''(xi) / 2 (W - w0)^2 with the part's int of (W - w0)^2 between 0 and the box's.
            const T E0 = coefficient_mean(Wm2);
            Rlo = std::min(T(0), qmin) * rhi * E0;
            Rhi = std::max(T(0), qmax) * rhi * E0;
          }
          lo = c0 * l0 + c1 * h1 + Rlo;
          hi = c0 * h0 + c1 * l1 + Rhi;
          geometric += c0 * (h0 - l0) - c1 * (h1 - l1);
        };
        T tl, th;
        through_graph(b.N, 4, b.vlo, b.vhi);
        trivial(b.N, 4, tl, th);
        b.vlo = std::max(b.vlo, tl);
        b.vhi = std::min(b.vhi, th);
        const T geo_volume = geometric;
        for (std::size_t k = 0; k < K; ++k) {
          through_graph(b.Q[k], cell.power, b.mlo[k], b.mhi[k]);
          trivial(b.Q[k], cell.power, tl, th);
          b.mlo[k] = std::max(b.mlo[k], tl);
          b.mhi[k] = std::min(b.mhi[k], th);
        }
        for (T* x : {&b.vlo, &b.vhi}) *x *= b.vol;
        for (std::size_t k = 0; k < K; ++k) {
          b.mlo[k] *= b.vol;
          b.mhi[k] *= b.vol;
        }
        // Across the face direction where psi curves most when the graph's error dominates, else
        // where W varies most.
        const int fa = graph.k == 0 ? 1 : 0, fb = graph.k == 2 ? 1 : 2;
        if (!cell.rational || (b.vhi - b.vlo) < T(2) * geo_volume * b.vol) b.dir = graph.curvature[1] < graph.curvature[0] ? fa : graph.curvature[0] < graph.curvature[1] ? fb : (b.splits[fa] <= b.splits[fb] ? fa : fb);
        else b.dir = density_direction(b);
        done = true;
      }
      if (!done) {
        // Otherwise the affine fit: with |G - L| <= e on the box, {L >= e} lies in the part and
        // the part in {L >= -e}: its share of the box is between their exact volumes, and the
        // integrand between its coefficient-ratio bounds. Several undecided leaves: between none
        // and all of the box.
        T f_lo(0), f_hi(1);
        bool fitted = false;
        std::array<T, 3> curv{T(0), T(0), T(0)};
        if (sense != 0) {
          T a0, e;
          std::array<T, 3> a;
          affine_fit(b.G[last_open], a0, a, e, !planar);
          e = round_outward(e, true);
          std::array<T, 3> na{-a[0], -a[1], -a[2]};
          if (sense > 0) {
            // a . s >= e - a0 is -a . s <= a0 - e.
            f_lo = halfspace_share(na, T(a0 - e));
            f_hi = halfspace_share(na, T(a0 + e));
          } else {
            f_lo = halfspace_share(a, T(-a0 - e));
            f_hi = halfspace_share(a, T(-a0 + e));
          }
          fitted = true;
          curv = curvature_along(b.G[last_open]);
        }
        T dmin, dmax;
        auto part = [&](const SBern<T>& Q, int p, T& lo, T& hi) {
          T qmin, qmax;
          coefficient_range(Q, qmin, qmax);
          if (cell.rational) ratio_bounds(qmin, qmax, wmin, wmax, p, dmin, dmax);
          else {
            dmin = qmin;
            dmax = qmax;
          }
          lo = b.vol * (f_lo * dmin + (f_hi - f_lo) * std::min(T(0), dmin));
          hi = b.vol * (f_lo * dmax + (f_hi - f_lo) * std::max(T(0), dmax));
          if (plant == vrep_testing::EnclosurePlant::drop_crossing) lo = hi = T(0);
          return std::make_pair(T(b.vol * (f_hi - f_lo) * std::max(T(-dmin), dmax)), T(b.vol * f_lo * (dmax - dmin)));
        };
        const auto [slab, density] = part(b.N, 4, b.vlo, b.vhi);
        for (std::size_t k = 0; k < K; ++k) part(b.Q[k], cell.power, b.mlo[k], b.mhi[k]);
        // Across the cut where the fit's error (the part's slab) dominates, else where the
        // integrand varies most.
        if (fitted && density < slab && (T(0) < curv[0] || T(0) < curv[1] || T(0) < curv[2])) {
          // Across the surface's curvature; where G is monotone along k (the surface a graph over
          // the other two directions, leaving the box through a face across k), not across k.
          // (Where the graph could not be built along k, the surface is steep over the face:
          // halve the face where G varies most.)
          b.dir = -1;
          for (int d = 0; d < 3; ++d)
            if (d != graph.monotone && (b.dir < 0 || curv[b.dir] < curv[d])) b.dir = d;
          // Unless G bends most along k itself (the box long across the surface): the fit's error
          // then shrinks only when k is cut. The steepest direction only while its curvature is
          // comparable (the fit's error comes from the curvature).
          if (graph.monotone >= 0 && T(4) * curv[b.dir] < curv[graph.monotone]) b.dir = graph.monotone;
          else if (graph.steepest >= 0 && curv[b.dir] <= T(4) * curv[graph.steepest]) b.dir = graph.steepest;
        } else if (!fitted && density < slab) {
          // Several surfaces (or one the formula does not simply follow): where they vary most.
          T best(-1);
          for (std::size_t l = 0; l < b.G.size(); ++l) {
            if (b.lt[l] != Truth::mixed || b.G[l].c.empty()) continue;
            T gmin, gmax;
            coefficient_range(b.G[l], gmin, gmax);
            const T scale = std::max(T(-gmin), gmax);
            const auto var = variation_along(b.G[l]);
            for (int d = 0; d < 3; ++d) {
              if (b.G[l].deg[d] == 0 || !(T(0) < scale)) continue;
              const T v = var[d] * b.G[l].scale / scale;
              if (best < v) {
                best = v;
                b.dir = d;
              }
            }
          }
        } else b.dir = density_direction(b);
      }
      if (!(b.vlo == b.vhi)) {
        b.vlo = round_outward(b.vlo, false);
        b.vhi = round_outward(b.vhi, true);
      }
      for (std::size_t k = 0; k < K; ++k)
        if (!(b.mlo[k] == b.mhi[k])) {
          b.mlo[k] = round_outward(b.mlo[k], false);
          b.mhi[k] = round_outward(b.mhi[k], true);
        }
    }
    T key = b.vhi - b.vlo;
    for (std::size_t k = 0; k < K; ++k) key += (b.mhi[k] - b.mlo[k]) * inv_scale[k];
    b.key = round_outward(key, true);
    return T(0) < b.key;
  };

  using Entry = std::pair<T, std::size_t>;
  std::priority_queue<Entry> queue;
  std::size_t leaves = 0;
  auto add_bounds = [&](const Box& b, bool sub) {
    Cell& cell = C[b.cell];
    if (sub) {
      cell.vlo -= b.vlo;
      cell.vhi -= b.vhi;
      for (std::size_t k = 0; k < K; ++k) {
        cell.mlo[k] -= b.mlo[k];
        cell.mhi[k] -= b.mhi[k];
      }
    } else {
      cell.vlo += b.vlo;
      cell.vhi += b.vhi;
      for (std::size_t k = 0; k < K; ++k) {
        cell.mlo[k] += b.mlo[k];
        cell.mhi[k] += b.mhi[k];
      }
    }
    // Exact box integrals with unlike denominators make the sums grow by digits with every box
    // (and every addition a gcd of that size): past 256 bits a sum is rounded outward to 96 bits.
    // It stays a bound of the boxes it holds, also after a box's own bounds are taken out again.
    cell.vlo = round_dyadic(cell.vlo, false, 96, 256);
    cell.vhi = round_dyadic(cell.vhi, true, 96, 256);
    for (std::size_t k = 0; k < K; ++k) {
      cell.mlo[k] = round_dyadic(cell.mlo[k], false, 96, 256);
      cell.mhi[k] = round_dyadic(cell.mhi[k], true, 96, 256);
    }
  };
  // The leaves' coefficients carried by the boxes in the pool, against the limit.
  CarriedCoefficients carried{limits};
  // The two parts of b across b.dir at 1/2 (or at b.at for a parameter plane).
  auto split = [&](Box& b, Box* c) {
    const int dir = b.dir;
    const bool half = b.at == T(0);
    const T t = half ? T(1) / T(2) : b.at;
    for (int h = 0; h < 2; ++h) {
      c[h].cell = b.cell;
      c[h].lt = b.lt;
      c[h].vol = h == 0 ? T(b.vol * t) : T(b.vol * (T(1) - t));
      c[h].splits = b.splits;
      c[h].splits[dir] = static_cast<unsigned char>(std::min(255, b.splits[dir] + 1));
      c[h].G.resize(b.G.size());
      c[h].Q.resize(K);
      c[h].mlo.assign(K, T(0));
      c[h].mhi.assign(K, T(0));
    }
    auto cut = [&](const SBern<T>& x, SBern<T>& l, SBern<T>& r) { std::tie(l, r) = half ? split_half(x, dir) : split_at(x, dir, t); };
    for (std::size_t l = 0; l < b.G.size(); ++l)
      if (b.lt[l] == Truth::mixed && !b.G[l].c.empty()) cut(b.G[l], c[0].G[l], c[1].G[l]);
    cut(b.N, c[0].N, c[1].N);
    cut(b.W, c[0].W, c[1].W);
    for (std::size_t k = 0; k < K; ++k) cut(b.Q[k], c[0].Q[k], c[1].Q[k]);
  };
  std::function<void(Box&&)> place = [&](Box&& b) {
    const bool alive = evaluate(b);
    if (!(b.at == T(0))) {
      // A parameter plane: its two parts in its place.
      Box c[2];
      split(b, c);
      b = Box{};
      place(std::move(c[0]));
      place(std::move(c[1]));
      return;
    }
    ++leaves;
    ++C[b.cell].boxes;
    add_bounds(b, false);
    if (!alive) return;
    carried.add(CarriedCoefficients::of(b.G));
    std::size_t slot;
    if (!free_slots.empty()) {
      slot = free_slots.back();
      free_slots.pop_back();
      pool[slot] = std::move(b);
    } else {
      slot = pool.size();
      pool.push_back(std::move(b));
    }
    queue.push({pool[slot].key, slot});
  };
  for (auto& b : initial) place(std::move(b));
  initial.clear();

  // The target: the summed widths within rel_width of the summed volumes' lower bound (the
  // moments' within rel_width of it times their scales).
  auto reached = [&]() {
    T low(0), wv(0);
    std::vector<T> wm(K, T(0));
    for (const auto& c : C) {
      low += T(0) < c.vlo ? c.vlo : c.vhi < T(0) ? T(-c.vhi) : T(0);
      wv += c.vhi - c.vlo;
      for (std::size_t k = 0; k < K; ++k) wm[k] += c.mhi[k] - c.mlo[k];
    }
    const T budget = rel_width * low;
    if (budget < wv) return false;
    for (std::size_t k = 0; k < K; ++k)
      if (budget * out.scale[k] < wm[k]) return false;
    return true;
  };
  while (!queue.empty() && leaves < out.budget && !reached()) {
    const std::size_t slot = queue.top().second;
    queue.pop();
    Box b = std::move(pool[slot]);
    free_slots.push_back(slot);
    carried.remove(CarriedCoefficients::of(b.G));
    add_bounds(b, true);
    --leaves;
    --C[b.cell].boxes;
    Box c[2];
    split(b, c);
    b = Box{};
    place(std::move(c[0]));
    place(std::move(c[1]));
  }

  out.reached = reached();
  out.volume.resize(C.size());
  out.moment.assign(C.size(), std::vector<VolumeEnclosure<T>>(K));
  out.total_moment.assign(K, VolumeEnclosure<T>{});
  for (std::size_t c = 0; c < C.size(); ++c) {
    Cell& cell = C[c];
    // Negatively oriented (det J < 0): the volume is the integral's magnitude, the moments flip.
    // The orientation is decided exactly (not from the enclosure, which may straddle 0 while
    // the integral is negative); then the volume is at least 0. Orientation unknown (N's integral
    // over the first piece 0, so not a regular cell): whichever sign the integral has.
    auto flip = [&]() {
      std::swap(cell.vlo, cell.vhi);
      cell.vlo = -cell.vlo;
      cell.vhi = -cell.vhi;
      for (std::size_t k = 0; k < K; ++k) {
        std::swap(cell.mlo[k], cell.mhi[k]);
        cell.mlo[k] = -cell.mlo[k];
        cell.mhi[k] = -cell.mhi[k];
      }
    };
    if (cell.orientation < 0) flip();
    if (cell.orientation != 0) {
      if (cell.vlo < T(0)) cell.vlo = T(0);
    } else if (cell.vhi < T(0) || (cell.vhi == T(0) && cell.vlo < T(0))) {
      flip();
    } else if (cell.vlo < T(0)) {
      // The integral's sign undecided: its magnitude and the moments of either sign.
      cell.vhi = std::max(cell.vhi, T(-cell.vlo));
      cell.vlo = T(0);
      for (std::size_t k = 0; k < K; ++k) {
        const T lo = std::min(cell.mlo[k], T(-cell.mhi[k])), hi = std::max(cell.mhi[k], T(-cell.mlo[k]));
        cell.mlo[k] = lo;
        cell.mhi[k] = hi;
      }
    }
    // Sums of exact box integrals can carry thousands of digits: what is not exact is rounded
    // outward here (about 64 significant bits once past 128), so the totals stay short too.
    if (cell.vlo != cell.vhi) {
      cell.vlo = round_outward(cell.vlo, false);
      cell.vhi = round_outward(cell.vhi, true);
    }
    for (std::size_t k = 0; k < K; ++k)
      if (cell.mlo[k] != cell.mhi[k]) {
        cell.mlo[k] = round_outward(cell.mlo[k], false);
        cell.mhi[k] = round_outward(cell.mhi[k], true);
      }
    if (plant == vrep_testing::EnclosurePlant::shrink_last_bit) cell.vhi -= last_bit_unit(cell.vhi);
    out.volume[c] = {cell.vlo, cell.vhi, cell.boxes};
    out.total.lower += cell.vlo;
    out.total.upper += cell.vhi;
    out.total.boxes += cell.boxes;
    for (std::size_t k = 0; k < K; ++k) {
      out.moment[c][k] = {cell.mlo[k], cell.mhi[k], cell.boxes};
      out.total_moment[k].lower += cell.mlo[k];
      out.total_moment[k].upper += cell.mhi[k];
      out.total_moment[k].boxes += cell.boxes;
    }
  }
  auto outward = [](VolumeEnclosure<T>& e) {
    if (e.lower == e.upper) return;
    e.lower = round_outward(e.lower, false);
    e.upper = round_outward(e.upper, true);
  };
  outward(out.total);
  for (auto& e : out.total_moment) outward(e);
  return out;
}

template <class T>
VolumeEnclosure<T> trimmed_volume(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes, const Limits& limits, const T& rel_width) {
  return integral_enclosures<T>({IntegrandCell<T>{&V, &trim, nullptr}}, {}, rel_width, max_boxes, limits).volume.front();
}

template <class T>
MomentEnclosure<T> trimmed_moment(const BSpline<T>& V, const Region<T>& trim, int coordinate, std::size_t max_boxes, const Limits& limits,
                                  const T& rel_width) {
  if (coordinate < 0) throw ValidationError("coordinate", "is negative", "give 0 <= coordinate < q");
  const auto r = integral_enclosures<T>({IntegrandCell<T>{&V, &trim, nullptr}}, {coordinate}, rel_width, max_boxes, limits);
  return {r.volume.front(), r.moment.front().front()};
}

template <class T>
MomentEnclosure<T> trimmed_field_integral(const BSpline<T>& V, const Region<T>& trim, const BSpline<T>& field, int component,
                                          std::size_t max_boxes, const Limits& limits, const T& rel_width) {
  const auto r = integral_enclosures<T>({IntegrandCell<T>{&V, &trim, &field}}, {component}, rel_width, max_boxes, limits);
  return {r.volume.front(), r.moment.front().front()};
}

}  // namespace splinex
