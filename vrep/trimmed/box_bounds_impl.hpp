// The scaled Bernstein form of the enclosures (vrep/trimmed/enclosure_impl.hpp): SBern (integer
// coefficients times one scale in exact arithmetic), exact de Casteljau splits, products and Gram
// contractions, the coefficient bounds, Taylor's bounds of w^-p, the share of a half-space in a
// cube, the affine fit of a surface with its error, and the directions a box varies or bends
// most. Internal to vrep/trimmed/ (included by enclosure_impl.hpp).
#pragma once
#include <algorithm>
#include <array>
#include <map>
#include <type_traits>
#include <utility>
#include <vector>

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

}  // namespace vrep_detail

}  // namespace splinex
