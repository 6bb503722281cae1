// Univariate polynomials with rational coefficients in the power basis (c[0] + c[1] x + ...),
// the small algebra the curved untrimming and Green's theorem need, and exact sign questions on an
// interval answered with exact root isolation (exact/root_isolation).
#pragma once
#include <vector>

#include "exact/rational.hpp"

namespace splinex::poly {

using Poly = std::vector<Rational>;

Poly add(const Poly& p, const Poly& q);
Poly sub(const Poly& p, const Poly& q);
Poly mul(const Poly& p, const Poly& q);
Poly pow(const Poly& p, int e);
Poly derivative(const Poly& p);
Rational eval(const Poly& p, const Rational& x);
bool is_zero(const Poly& p);
/// int_0^1 p(t) dt.
Rational integral01(const Poly& p);
/// B_i^n((x - lo) / (hi - lo)) in powers of x.
Poly bernstein_monomial(int n, int i, const Rational& lo, const Rational& hi);
/// sum_i c_i B_i^n((x - lo) / (hi - lo)) in powers of x.
Poly from_bernstein(const std::vector<Rational>& c, const Rational& lo, const Rational& hi);
/// The Bernstein polynomial at t, by de Casteljau.
Rational bernstein_eval(const std::vector<Rational>& c, const Rational& t);
/// The ordinates of the Bernstein polynomial restricted to [t0, t1] (subdivision, exact).
std::vector<Rational> bernstein_restrict(const std::vector<Rational>& c, const Rational& t0, const Rational& t1);

/// Is there an x in the open interval (a, b) where every g_j(x) > 0? Exact: the product's real
/// roots are isolated, and each g_j has constant sign between consecutive roots, so one rational
/// sample strictly between consecutive isolating intervals (and the ends) decides each piece.
/// The zero polynomial counts as not positive.
bool exists_positive(const std::vector<Poly>& gs, const Rational& a, const Rational& b);

}  // namespace splinex::poly
