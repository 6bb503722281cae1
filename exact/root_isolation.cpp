#include "exact/root_isolation.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <stdexcept>

#include "base/errors.hpp"
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

}  // namespace splinex
