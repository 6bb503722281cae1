#include "untrim/poly.hpp"

#include <algorithm>

#include "exact/root_isolation.hpp"
#include "spline/bernstein.hpp"

namespace splinex::poly {

namespace {
void trim(Poly& p) {
  while (p.size() > 1 && p.back() == 0) p.pop_back();
}
}  // namespace

Poly add(const Poly& p, const Poly& q) {
  Poly r(std::max(p.size(), q.size()), Rational(0));
  for (std::size_t i = 0; i < p.size(); ++i) r[i] += p[i];
  for (std::size_t i = 0; i < q.size(); ++i) r[i] += q[i];
  trim(r);
  return r;
}
Poly sub(const Poly& p, const Poly& q) {
  Poly r(std::max(p.size(), q.size()), Rational(0));
  for (std::size_t i = 0; i < p.size(); ++i) r[i] += p[i];
  for (std::size_t i = 0; i < q.size(); ++i) r[i] -= q[i];
  trim(r);
  return r;
}
Poly mul(const Poly& p, const Poly& q) {
  if (p.empty() || q.empty()) return {Rational(0)};
  Poly r(p.size() + q.size() - 1, Rational(0));
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j) r[i + j] += p[i] * q[j];
  trim(r);
  return r;
}
Poly pow(const Poly& p, int e) {
  Poly r{Rational(1)};
  for (int i = 0; i < e; ++i) r = mul(r, p);
  return r;
}
Poly derivative(const Poly& p) {
  Poly r;
  for (std::size_t i = 1; i < p.size(); ++i) r.push_back(p[i] * Rational(static_cast<long>(i)));
  if (r.empty()) r.push_back(Rational(0));
  return r;
}
Rational eval(const Poly& p, const Rational& x) {
  Rational v = 0;
  for (std::size_t i = p.size(); i-- > 0;) v = v * x + p[i];
  return v;
}
bool is_zero(const Poly& p) {
  for (const auto& c : p)
    if (c != 0) return false;
  return true;
}
Rational integral01(const Poly& p) {
  Rational s = 0;
  for (std::size_t k = 0; k < p.size(); ++k) s += p[k] / Rational(static_cast<long>(k + 1));
  return s;
}
Poly bernstein_monomial(int n, int i, const Rational& lo, const Rational& hi) {
  const Rational w = hi - lo;
  const Poly s{-lo / w, 1 / w}, one_minus_s{1 + lo / w, -1 / w};
  Poly r = mul(pow(s, i), pow(one_minus_s, n - i));
  for (auto& c : r) c *= detail::binomial<Rational>(n, i);
  return r;
}
Poly from_bernstein(const std::vector<Rational>& c, const Rational& lo, const Rational& hi) {
  const int n = static_cast<int>(c.size()) - 1;
  Poly r{Rational(0)};
  for (int i = 0; i <= n; ++i) {
    if (c[i] == 0) continue;
    Poly b = bernstein_monomial(n, i, lo, hi);
    for (auto& v : b) v *= c[i];
    r = add(r, b);
  }
  return r;
}
Rational bernstein_eval(const std::vector<Rational>& c, const Rational& t) {
  std::vector<Rational> a = c;
  for (std::size_t r = 1; r < a.size(); ++r)
    for (std::size_t i = 0; i + r < a.size(); ++i) a[i] = (1 - t) * a[i] + t * a[i + 1];
  return a[0];
}
std::vector<Rational> bernstein_restrict(const std::vector<Rational>& c, const Rational& t0, const Rational& t1) {
  // Left part at t1 (the de Casteljau triangle's first column), then the right part of that at t0 / t1.
  const auto left = [](std::vector<Rational> a, const Rational& t) {
    std::vector<Rational> out{a[0]};
    for (std::size_t r = 1; r < a.size(); ++r) {
      for (std::size_t i = 0; i + r < a.size(); ++i) a[i] = (1 - t) * a[i] + t * a[i + 1];
      out.push_back(a[0]);
    }
    return out;
  };
  const auto right = [](std::vector<Rational> a, const Rational& t) {
    std::vector<Rational> out{a.back()};
    for (std::size_t r = 1; r < a.size(); ++r) {
      for (std::size_t i = 0; i + r < a.size(); ++i) a[i] = (1 - t) * a[i] + t * a[i + 1];
      out.push_back(a[a.size() - 1 - r]);
    }
    std::reverse(out.begin(), out.end());
    return out;
  };
  std::vector<Rational> a = t1 == 1 ? c : left(c, t1);
  if (t0 == 0) return a;
  return right(a, t0 / t1);
}

bool exists_positive(const std::vector<Poly>& gs, const Rational& a, const Rational& b) {
  if (!(a < b)) return false;
  // All of degree <= 1 (straight tiles and edges): {x : g(x) > 0} is an open half-line, the whole
  // line or empty, so the question is whether open intervals intersect, decided exactly without
  // root isolation.
  const auto degree = [](const Poly& g) {
    int d = static_cast<int>(g.size()) - 1;
    while (d >= 0 && g[d] == 0) --d;
    return d;  // -1: the zero polynomial
  };
  bool linear = true;
  for (const auto& g : gs) linear = linear && degree(g) <= 1;
  if (linear) {
    Rational lo = a, hi = b;  // the open interval (lo, hi) where all hold so far
    for (const auto& g : gs) {
      const int d = degree(g);
      if (d < 0) return false;  // the zero polynomial is not positive
      if (d == 0) {
        if (!(g[0] > 0)) return false;
        continue;
      }
      const Rational r = -g[0] / g[1];  // g > 0 right of r when the slope is positive, left of it otherwise
      if (g[1] > 0) lo = std::max(lo, r);
      else hi = std::min(hi, r);
      if (!(lo < hi)) return false;
    }
    return true;
  }
  Poly prod{Rational(1)};
  for (const auto& g : gs) {
    if (is_zero(g)) return false;
    prod = mul(prod, g);
  }
  std::vector<Rational> samples;
  Rational left = a;  // the right end of the previous isolating interval (or a)
  for (const auto& r : isolate_real_roots(prod, a, b, 8)) {
    if (left < r.lo)
      samples.push_back((left + r.lo) / 2);
    else if (a < left && eval(prod, left) != 0)
      samples.push_back(left);  // isolating intervals touching at a non-root
    left = r.hi;
  }
  if (left < b) samples.push_back((left + b) / 2);
  for (const auto& x : samples) {
    bool all = true;
    for (const auto& g : gs) all = all && eval(g, x) > 0;
    if (all) return true;
  }
  return false;
}

}  // namespace splinex::poly
