#include "exact/root_isolation.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <stdexcept>

#include "spline/errors.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

using AK = CGAL::Algebraic_kernel_d_1<CGAL::Gmpz>;
using Poly = AK::Polynomial_1;

Rational from_gmpq(const CGAL::Gmpq& q) {
  Rational r;
  mpq_set(r.backend().data(), q.mpq());
  return r;
}
CGAL::Gmpz to_gmpz(const Integer& z) { return CGAL::Gmpz(z.backend().data()); }

// sum_i c_i x^i, by Horner.
Rational eval_power(const std::vector<Rational>& c, const Rational& x) {
  Rational v = 0;
  for (std::size_t i = c.size(); i-- > 0;) v = v * x + c[i];
  return v;
}

}  // namespace

std::vector<Rational> bernstein_to_power(const std::vector<Rational>& b) {
  // sum_i b_i C(n,i) t^i (1-t)^(n-i) = sum_k t^k sum_{i<=k} b_i C(n,i) C(n-i,k-i) (-1)^(k-i)
  const int n = static_cast<int>(b.size()) - 1;
  auto binom = [](int N, int K) {
    Integer r = 1;
    for (int i = 1; i <= K; ++i) r = r * (N - K + i) / i;
    return Rational(r);
  };
  std::vector<Rational> c(n + 1, Rational(0));
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= k; ++i) {
      Rational term = b[i] * binom(n, i) * binom(n - i, k - i);
      c[k] += ((k - i) % 2) ? Rational(-term) : term;
    }
  return c;
}

std::vector<IsolatedRoot> isolate_real_roots(const std::vector<Rational>& coeffs, const Rational& a, const Rational& b,
                                             int refine_bits) {
  // Clear denominators: multiply by the lcm of the denominators.
  Integer l = 1;
  for (const auto& c : coeffs) l = boost::multiprecision::lcm(l, denominator(c));
  std::vector<CGAL::Gmpz> zc;
  bool zero = true;
  for (const auto& c : coeffs) {
    const Rational s = c * Rational(l);
    zc.push_back(to_gmpz(numerator(s)));
    zero = zero && numerator(s) == 0;
  }
  if (zero) throw DomainError("polynomial", "is identically zero", "a trimming condition holds on a whole edge; no isolated crossing");
  AK ak;
  const Poly p(zc.begin(), zc.end());
  std::vector<std::pair<AK::Algebraic_real_1, AK::Multiplicity_type>> roots;
  ak.solve_1_object()(p, std::back_inserter(roots));
  std::vector<IsolatedRoot> out;
  const CGAL::Gmpq A(a.str()), B(b.str());
  for (const auto& [r, m] : roots) {
    if (ak.compare_1_object()(r, AK::Algebraic_real_1(A)) == CGAL::SMALLER ||
        ak.compare_1_object()(r, AK::Algebraic_real_1(B)) == CGAL::LARGER)
      continue;
    const auto iv = ak.approximate_absolute_1_object()(r, refine_bits);
    IsolatedRoot ir;
    ir.lo = from_gmpq(iv.first);
    ir.hi = from_gmpq(iv.second);
    ir.multiplicity = static_cast<unsigned>(m);
    // A rational root is reported exactly when the interval's end is it.
    for (const Rational& e : {ir.lo, ir.hi})
      if (eval_power(coeffs, e) == 0) ir.lo = ir.hi = e;
    if (ir.lo < a) ir.lo = a;
    if (b < ir.hi) ir.hi = b;
    out.push_back(ir);
  }
  return out;
}

Rational simplest_rational(const Rational& lo, const Rational& hi) {
  if (hi < lo) throw std::invalid_argument("simplest_rational: empty interval");
  // floor for rationals: numerator / denominator rounded towards -infinity.
  const auto floor_q = [](const Rational& v) {
    Integer q = numerator(v) / denominator(v);  // truncates towards 0
    if (q * denominator(v) > numerator(v)) q -= 1;
    return Rational(q);
  };
  const Rational f = floor_q(lo);
  if (f == lo) return lo;
  if (f + 1 <= hi) return f + 1;
  // lo, hi in (f, f + 1): 1 / (x - f) maps them to an interval in (1, inf), reversed.
  return f + 1 / simplest_rational(1 / (hi - f), 1 / (lo - f));
}

std::vector<ClassifiedRoot> classify_real_roots(const std::vector<Rational>& coeffs, const Rational& a, const Rational& b) {
  // Leading coefficient of the denominator-cleared integer polynomial.
  Integer l = 1;
  for (const auto& c : coeffs) l = boost::multiprecision::lcm(l, denominator(c));
  Integer lead = 0;
  for (const auto& c : coeffs)
    if (c != 0) lead = numerator(Rational(c * Rational(l)));
  if (lead < 0) lead = -lead;
  // Width 2^-bits < 1 / lead^2.
  const int bits = 2 * static_cast<int>(lead == 0 ? 1 : boost::multiprecision::msb(lead) + 1) + 2;
  std::vector<ClassifiedRoot> out;
  for (const auto& r : isolate_real_roots(coeffs, a, b, bits)) {
    ClassifiedRoot c{r, std::nullopt};
    const Rational s = r.lo == r.hi ? r.lo : simplest_rational(r.lo, r.hi);
    if (eval_power(coeffs, s) == 0) c.exact = s;
    out.push_back(c);
  }
  return out;
}

std::vector<EdgeCrossing> trimming_edge_crossings(const TrimmedComposition<Rational>& C, std::size_t pi, int refine_bits) {
  const auto& P = C.patches.at(pi);
  const BSpline<Rational>& S = C.inner_pieces[P.inner_piece].spline;
  const int k = S.dim();
  std::vector<EdgeCrossing> out;
  for (int free = 0; free < k; ++free) {
    // Every edge in direction `free`: the other parameters at the lower or upper end of the box.
    const int others = k - 1;
    for (int mask = 0; mask < (1 << others); ++mask) {
      std::vector<Rational> fixed(k);
      std::vector<int> fixed_idx(k, 0);
      for (int l = 0, bit = 0; l < k; ++l) {
        if (l == free) continue;
        const bool up = (mask >> bit++) & 1;
        fixed[l] = up ? S.domain_hi(l) : S.domain_lo(l);
        fixed_idx[l] = up ? S.degrees[l] : 0;
      }
      // The edge's Bernstein coefficients: the control points along `free` at the fixed corner indices.
      std::vector<std::size_t> stride(k);
      std::size_t st = 1;
      for (int l = 0; l < k; ++l) { stride[l] = st; st *= S.count(l); }
      for (std::size_t ci = 0; ci < P.region.size(); ++ci) {
        const auto& cond = P.region[ci];
        for (bool upper : {false, true}) {
          if ((upper && !cond.check_hi) || (!upper && !cond.check_lo)) continue;
          const Rational bound = upper ? cond.hi : cond.lo;
          std::vector<Rational> bern;
          for (int i = 0; i <= S.degrees[free]; ++i) {
            std::size_t g = 0;
            for (int l = 0; l < k; ++l) g += (l == free ? i : fixed_idx[l]) * stride[l];
            const Rational w = S.is_rational() ? S.weights[g] : Rational(1);
            bern.push_back(S.points[g * S.q + cond.coord] * w - bound * w);  // X_c - bound * W
          }
          bool all_zero = true;
          for (const auto& x : bern) all_zero = all_zero && x == 0;
          if (all_zero) continue;  // the edge lies on the knot line: no isolated crossing
          const Rational lo = S.domain_lo(free), width = S.domain_hi(free) - lo;
          for (auto root : isolate_real_roots(bernstein_to_power(bern), Rational(0), Rational(1), refine_bits)) {
            root.lo = lo + width * root.lo;
            root.hi = lo + width * root.hi;
            out.push_back({static_cast<int>(ci), upper, free, fixed, root});
          }
        }
      }
    }
  }
  return out;
}

}  // namespace splinex
