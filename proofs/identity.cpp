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

PiecewiseShape shape_of(const BSpline<Rational>& S) {
  PiecewiseShape s;
  for (int d = 0; d < S.dim(); ++d) {
    s.breaks.push_back(breakpoints(S.knots[d], S.degrees[d], S.count(d)));
    s.numerator.push_back(S.degrees[d]);
    s.denominator.push_back(S.is_rational() ? S.degrees[d] : 0);
  }
  return s;
}

std::vector<std::vector<Rational>> union_cuts(const PiecewiseShape& A, const PiecewiseShape& B,
                                              const std::vector<std::pair<Rational, Rational>>& box) {
  std::vector<std::vector<Rational>> cuts;
  for (std::size_t d = 0; d < box.size(); ++d) {
    const auto& [lo, hi] = box[d];
    std::vector<Rational> c;
    if (lo < hi) {
      c = {lo, hi};
      for (const auto* S : {&A, &B})
        if (d < S->breaks.size())
          for (const auto& u : S->breaks[d])
            if (lo < u && u < hi) c.push_back(u);
      std::sort(c.begin(), c.end());
      c.erase(std::unique(c.begin(), c.end()), c.end());
    }
    cuts.push_back(std::move(c));
  }
  return cuts;
}

std::vector<int> identity_bound(const PiecewiseShape& A, const PiecewiseShape& B) {
  std::vector<int> b;
  for (std::size_t d = 0; d < A.numerator.size() && d < B.numerator.size(); ++d)
    b.push_back(std::max(A.numerator[d] + B.denominator[d], B.numerator[d] + A.denominator[d]));
  return b;
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
                                 const std::vector<AffineMap1>& phi_in, const std::string& identity,
                                 bool open_cells_only) {
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
  // Cells per direction: breakpoints of A and pulled-back breakpoints of B, clipped to the box (an
  // empty or inverted box gives none: no verdict); the bound from both shapes.
  PiecewiseShape a = shape_of(A), b = shape_of(B);
  for (int d = 0; d < k; ++d)
    for (auto& u : b.breaks[d]) u = phi[d].inverse(u);
  const auto cuts = union_cuts(a, b, box);
  r.degree_bound = identity_bound(a, b);
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
  SampleEnds ends;
  bool reversing = false;
  for (const auto& m : phi) reversing = reversing || m.scale < 0;
  if (!open_cells_only && !reversing) {
    ends.lower = true;
    ends.upper = true;
    for (int d = 0; d < k; ++d) ends.upper = ends.upper && box[d].second == A.domain_hi(d);
  }
  IdentityCheck res = prove_by_samples(cuts, r.degree_bound, mismatch, identity, ends);
  return res;
}

IdentityCheck prove_by_samples(const std::vector<std::vector<Rational>>& cuts, const std::vector<int>& degree_bound,
                               const std::function<std::string(const std::vector<Rational>&)>& mismatch,
                               const std::string& identity, SampleEnds ends) {
  IdentityCheck r;
  r.identity = identity;
  r.degree_bound = degree_bound;
  const int k = static_cast<int>(cuts.size());
  // Per direction the flat list of sample values: per cell (its lower end), d+1 interior points;
  // then (the upper end).
  std::vector<std::vector<Rational>> samples(k);
  std::size_t ncells = 1;
  for (int d = 0; d < k; ++d) {
    if (degree_bound[d] < 0) {  // nothing to sample is no proof
      ncells = 0;
      break;
    }
    const int deg = degree_bound[d];
    std::size_t cells = 0;
    for (std::size_t c = 0; c + 1 < cuts[d].size(); ++c, ++cells) {
      const Rational lo = cuts[d][c], w = cuts[d][c + 1] - lo;
      if (ends.lower) samples[d].push_back(lo);
      for (int i = 0; i <= deg; ++i) samples[d].push_back(lo + w * Rational(i + 1, deg + 2));
    }
    if (ends.upper && cells > 0) samples[d].push_back(cuts[d].back());
    ncells *= cells;
  }
  r.cells = ncells;
  if (ncells == 0) return r;
  std::vector<std::size_t> per(k), idx(k, 0);
  for (int d = 0; d < k; ++d) per[d] = samples[d].size();
  std::vector<Rational> x(k);
  while (true) {
    for (int d = 0; d < k; ++d) x[d] = samples[d][idx[d]];
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
