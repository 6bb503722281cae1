#include "proofs/identity.hpp"

#include <algorithm>
#include <sstream>

#include "spline/evaluate.hpp"
#include "spline/knots.hpp"

namespace splinex {

std::vector<std::pair<Rational, Rational>> domain_box(const BSpline<Rational>& S) {
  std::vector<std::pair<Rational, Rational>> box;
  for (int d = 0; d < S.dim(); ++d) box.emplace_back(S.domain_lo(d), S.domain_hi(d));
  return box;
}

namespace {

std::string show(const std::vector<Rational>& v) {
  std::ostringstream o;
  o << "(";
  for (std::size_t i = 0; i < v.size(); ++i) o << (i ? ", " : "") << to_fraction_string(v[i]);
  o << ")";
  return o.str();
}

}  // namespace

IdentityCheck prove_equal_on_box(const BSpline<Rational>& A, const BSpline<Rational>& B,
                                 const std::vector<std::pair<Rational, Rational>>& box,
                                 const std::vector<AffineMap1>& phi_in, const std::string& identity) {
  IdentityCheck r;
  r.identity = identity;
  const int k = A.dim();
  std::vector<AffineMap1> phi = phi_in.empty() ? std::vector<AffineMap1>(k) : phi_in;
  if (B.dim() != k || A.q != B.q || static_cast<int>(box.size()) != k) {
    r.holds = false;
    r.counterexample = "the two maps have different dimensions";
    return r;
  }
  const bool rational = A.is_rational() || B.is_rational();
  // Cells per direction: breakpoints of A and pulled-back breakpoints of B, clipped to the box.
  std::vector<std::vector<Rational>> cuts(k);
  for (int d = 0; d < k; ++d) {
    std::vector<Rational> c{box[d].first, box[d].second};
    for (const auto& u : breakpoints(A.knots[d], A.degrees[d], A.count(d))) c.push_back(u);
    for (const auto& u : breakpoints(B.knots[d], B.degrees[d], B.count(d))) c.push_back(phi[d].inverse(u));
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    c.erase(std::remove_if(c.begin(), c.end(), [&](const Rational& x) { return x < box[d].first || box[d].second < x; }),
            c.end());
    cuts[d] = std::move(c);
    r.degree_bound.push_back(rational ? A.degrees[d] + B.degrees[d] : std::max(A.degrees[d], B.degrees[d]));
  }
  const auto mismatch = [&](const std::vector<Rational>& x) -> std::string {
    std::vector<Rational> y(k);
    for (int d = 0; d < k; ++d) y[d] = phi[d](x[d]);
    const std::vector<Rational> a = evaluate_homogeneous(A, x), b = evaluate_homogeneous(B, y);
    bool same = true;
    if (!rational) {
      same = (a == b);
    } else {
      const Rational wa = A.is_rational() ? a[A.q] : Rational(1), wb = B.is_rational() ? b[B.q] : Rational(1);
      for (int c = 0; c < A.q && same; ++c) same = (a[c] * wb == b[c] * wa);
    }
    return same ? std::string() : "left " + show(a) + ", right " + show(b) + " (homogeneous)";
  };
  IdentityCheck res = prove_by_samples(cuts, r.degree_bound, mismatch, identity);
  return res;
}

IdentityCheck prove_by_samples(const std::vector<std::vector<Rational>>& cuts, const std::vector<int>& degree_bound,
                               const std::function<std::string(const std::vector<Rational>&)>& mismatch,
                               const std::string& identity) {
  IdentityCheck r;
  r.identity = identity;
  r.degree_bound = degree_bound;
  const int k = static_cast<int>(cuts.size());
  std::vector<std::vector<std::vector<Rational>>> samples(k);
  std::size_t ncells = 1;
  for (int d = 0; d < k; ++d) {
    const int deg = degree_bound[d];
    for (std::size_t c = 0; c + 1 < cuts[d].size(); ++c) {
      std::vector<Rational> s;
      const Rational lo = cuts[d][c], w = cuts[d][c + 1] - lo;
      for (int i = 0; i <= deg; ++i) s.push_back(lo + w * Rational(i + 1, deg + 2));
      samples[d].push_back(std::move(s));
    }
    ncells *= samples[d].size();
  }
  r.cells = ncells;
  if (ncells == 0) return r;
  std::vector<std::size_t> per(k), idx(k, 0);
  for (int d = 0; d < k; ++d) per[d] = samples[d].size() * (degree_bound[d] + 1);
  std::vector<Rational> x(k);
  while (true) {
    for (int d = 0; d < k; ++d) {
      const std::size_t deg1 = degree_bound[d] + 1;
      x[d] = samples[d][idx[d] / deg1][idx[d] % deg1];
    }
    ++r.points;
    const std::string why = mismatch(x);
    if (!why.empty()) {
      r.holds = false;
      r.counterexample = "at x = " + show(x) + ": " + why;
      return r;
    }
    int d = 0;
    while (d < k && ++idx[d] == per[d]) { idx[d] = 0; ++d; }
    if (d == k) break;
  }
  return r;
}

IdentityCheck prove_same_function(const BSpline<Rational>& A, const BSpline<Rational>& B, const std::string& identity) {
  const auto box = domain_box(A);
  if (B.dim() != A.dim() || domain_box(B) != box) {
    IdentityCheck r;
    r.identity = identity;
    r.holds = false;
    r.counterexample = "the domains differ";
    return r;
  }
  return prove_equal_on_box(A, B, box, {}, identity);
}

}  // namespace splinex
