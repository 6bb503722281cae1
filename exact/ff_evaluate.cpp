// Fraction-free evaluation (exact/ffnet.hpp): de Boor's triangle (spline/evaluate_impl.hpp's
// evaluate_de_boor) on the active homogeneous net, one direction at a time, every entry an
// integer point over its own denominator. The parameter x = a/b of direction d is put over the
// knots' denominator K once: with g = gcd(K, b), x = (a K/g) / (b/g K), so every alpha of the
// triangle is s/t with integers s = a K/g - (b/g) k_i and t = (b/g)(k_j - k_i).
#include "exact/ff_common.hpp"

namespace splinex::ff {

using namespace detail;

namespace {

/// x (numerator xs over f*K) against knot k_j: the sign of xs - f*k_j.
int cmp_scaled(const fmpz* xs, const fmpz* f, const fmpz* kj, Z& tmp) {
  mul(tmp.get(), f, kj);
  return cmp(xs, tmp.get());
}

struct Param {
  Z xs, f;  // x = xs / (f K)
};

Param put_over(const FFKnots& U, const Rational& x) {
  Param P;
  Z a, b, g;
  fmpz_set_mpz(a.get(), mpq_numref(x.backend().data()));
  fmpz_set_mpz(b.get(), mpq_denref(x.backend().data()));
  fmpz_gcd(g.get(), U.den.data(), b.get());
  fmpz_divexact(P.f.get(), b.get(), g.get());
  fmpz_divexact(g.get(), U.den.data(), g.get());
  fmpz_mul(P.xs.get(), a.get(), g.get());
  return P;
}

/// A2.1 FindSpan for x = xs/(f K) (inside the domain).
std::size_t find_span(const FFKnots& U, int p, std::size_t n, const Param& x, Z& tmp) {
  if (cmp_scaled(x.xs.get(), x.f.get(), U.k + n, tmp) >= 0) {
    std::size_t s = n - 1;
    while (s > static_cast<std::size_t>(p) && cmp(U.k + s, U.k + s + 1) >= 0) --s;
    return s;
  }
  std::size_t lo = p, hi = n;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (cmp_scaled(x.xs.get(), x.f.get(), U.k + mid, tmp) < 0) hi = mid; else lo = mid;
  }
  return lo;
}

}  // namespace

FFPoints evaluate_points(const FFNet& F, const std::vector<Rational>& params) {
  const std::size_t k = F.dim();
  if (params.size() % k != 0)
    throw DomainError("params", "has " + std::to_string(params.size()) + " numbers, not a multiple of the dimension " +
                                    std::to_string(k),
                      "give dim() parameters per point");
  const std::size_t N = params.size() / k, w = F.stride(), m = F.m();
  std::vector<Param> x(params.size());
  Z tmp;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t d = 0; d < k; ++d) {
      const FFKnots& U = F.knots[d];
      x[i * k + d] = put_over(U, params[i * k + d]);
      const Param& P = x[i * k + d];
      if (cmp_scaled(P.xs.get(), P.f.get(), U.k + F.degrees[d], tmp) < 0 ||
          cmp_scaled(P.xs.get(), P.f.get(), U.k + F.count(d), tmp) > 0)
        throw DomainError("params[" + std::to_string(i) + "][" + std::to_string(d) + "]",
                          "lies outside the domain of direction " + std::to_string(d),
                          "give a parameter in [U[p], U[n]] of that direction");
    }
  FFPoints out;
  out.q = F.q;
  out.rational = F.rational;
  out.words = ZVec(N * w);
  std::size_t active = 1;
  std::vector<std::size_t> stride(k), span(k);
  std::size_t st = 1;
  for (std::size_t d = 0; d < k; ++d) {
    stride[d] = st;
    st *= F.count(d);
    active *= F.degrees[d] + 1;
  }
  ZVec net(active * w);
  std::vector<Z> s, t;
  std::vector<int> idx(k);
  Blend blend;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t d = 0; d < k; ++d) span[d] = find_span(F.knots[d], F.degrees[d], F.count(d), x[i * k + d], tmp);
    /// Gather the active net, direction 0 fastest.
    std::fill(idx.begin(), idx.end(), 0);
    for (std::size_t a = 0; a < active; ++a) {
      std::size_t at = 0;
      for (std::size_t d = 0; d < k; ++d) at += (span[d] - F.degrees[d] + idx[d]) * stride[d];
      for (std::size_t c = 0; c < w; ++c) set(net + a * w + c, F.words + at * w + c);
      for (std::size_t d = 0; d < k && ++idx[d] > F.degrees[d]; ++d) idx[d] = 0;
    }
    /// Reduce direction 0 first: each run of p+1 consecutive points collapses to its last.
    std::size_t size = active;
    for (std::size_t d = 0; d < k; ++d) {
      const int p = F.degrees[d];
      const FFKnots& U = F.knots[d];
      const Param& P = x[i * k + d];
      const std::size_t sp = span[d], runs = size / (p + 1);
      s.resize(static_cast<std::size_t>(p) * (p + 1));
      t.resize(s.size());
      for (int lev = 1; lev <= p; ++lev)
        for (int j = p; j >= lev; --j) {
          const std::size_t id = sp - p + j, c = static_cast<std::size_t>(lev - 1) * (p + 1) + j;
          mul(tmp.get(), P.f.get(), U.k + id);
          sub(s[c].get(), P.xs.get(), tmp.get());
          sub(tmp.get(), U.k + id + p - lev + 1, U.k + id);
          mul(t[c].get(), P.f.get(), tmp.get());
        }
      for (std::size_t r = 0; r < runs; ++r) {
        fmpz* tri = net + r * (p + 1) * w;
        for (int lev = 1; lev <= p; ++lev)
          for (int j = p; j >= lev; --j) {
            const std::size_t c = static_cast<std::size_t>(lev - 1) * (p + 1) + j;
            blend(tri + j * w, tri + (j - 1) * w, tri + j * w, s[c].get(), t[c].get(), m);
          }
        if (r != 0 || p != 0)
          for (std::size_t c = 0; c < w; ++c) fmpz_swap(net + r * w + c, tri + p * w + c);
      }
      size = runs;
    }
    for (std::size_t c = 0; c < w; ++c) set(out.words + i * w + c, net + c);
    reduce_if_long(out.words + i * w, m);
  }
  return out;
}

}  // namespace splinex::ff
