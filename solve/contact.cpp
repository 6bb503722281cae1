// The minimum distance of two surfaces (solve/contact.hpp), for Rational and double.
#include "solve/contact.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <cmath>
#include <numeric>
#include <type_traits>

#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "solve/strata.hpp"
#include "spline/errors.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

using namespace solve_detail;

template <class T>
std::vector<T> concat(const std::vector<T>& a, const std::vector<T>& b) {
  std::vector<T> c = a;
  c.insert(c.end(), b.begin(), b.end());
  return c;
}

/// The parameters (A's, then B's: (u, v, r, t) for two surfaces) of a system point x.
template <class T>
std::vector<T> params(const Stratum<T>& A, const Stratum<T>& B, const std::vector<T>& x) {
  return concat(surface_parameters(A, x, 0), surface_parameters(B, x, static_cast<std::size_t>(A.k)));
}

/// Tries to prove that the strata meet near the box [a, b] of their system: S1 - S2 = 0 (D = 0)
/// with one unknown fixed at the box's centre when there are four, solved on the box widened
/// four times (inside the system's box). Returns the (u, v, r, t) box of a certified common point.
template <class T>
bool certify_common_point(const Stratum<T>& A, const Stratum<T>& B, const PairSystem<T>& sys, const std::vector<T>& a,
                          const std::vector<T>& b, std::vector<T>& lo4, std::vector<T>& hi4) {
  const std::size_t n = sys.n;
  if (n < 3) return false;
  std::vector<T> la(n), lb(n);
  for (std::size_t l = 0; l < n; ++l) {
    const T w = sys.hi[l] - sys.lo[l], c = (a[l] + b[l]) / T(2), r = (b[l] - a[l]) * T(2) + w / T(1 << 20);
    T x0 = c - r, x1 = c + r;
    if (x0 < sys.lo[l]) x0 = sys.lo[l];
    if (sys.hi[l] < x1) x1 = sys.hi[l];
    la[l] = (x0 - sys.lo[l]) / w;
    lb[l] = (x1 - sys.lo[l]) / w;
  }
  for (std::size_t fixed = 0; fixed < (n == 4 ? n : 1); ++fixed) {
    std::vector<detail::Bern<T>> eq(3);
    std::vector<T> lo, hi;
    for (int c = 0; c < 3; ++c) {
      eq[c] = sys.D[c];
      for (std::size_t l = 0; l < n; ++l) eq[c] = detail::bern_restrict(eq[c], static_cast<int>(l), la[l], lb[l]);
    }
    T fixed_value(0);
    if (n == 4) {
      // Fix unknown `fixed` at the centre of the widened box (local 1/2).
      for (auto& g : eq) g = detail::bern_fix(g, static_cast<int>(fixed), T(1) / T(2));
      const T w = sys.hi[fixed] - sys.lo[fixed];
      fixed_value = sys.lo[fixed] + w * (la[fixed] + lb[fixed]) / T(2);
    }
    for (std::size_t l = 0; l < n; ++l) {
      if (n == 4 && l == fixed) continue;
      const T w = sys.hi[l] - sys.lo[l];
      lo.push_back(sys.lo[l] + w * la[l]);
      hi.push_back(sys.lo[l] + w * lb[l]);
    }
    bool zero = false;
    for (const auto& g : eq) {
      bool z = true;
      for (const auto& x : g.c) z = z && x == T(0);
      zero = zero || z;
    }
    if (zero) continue;
    SolveOptions so;
    so.max_depth = 24;
    so.max_boxes = 4000;
    const auto r = solve_system(eq, lo, hi, so);
    for (const auto& root : r.roots) {
      if (!root.unique && !root.exact) continue;
      std::vector<T> xl = root.exact ? root.point : root.lo, xh = root.exact ? root.point : root.hi;
      if (n == 4) {
        xl.insert(xl.begin() + static_cast<long>(fixed), fixed_value);
        xh.insert(xh.begin() + static_cast<long>(fixed), fixed_value);
      }
      lo4 = params(A, B, xl);
      hi4 = params(A, B, xh);
      return true;
    }
  }
  return false;
}

}  // namespace

namespace solve_detail {

template <class T>
ContactResult<T> stationary_pairs(const std::vector<Stratum<T>>& A, const std::vector<Stratum<T>>& B, const SolveOptions& options,
                                  Search search) {
  const bool minimum = search == Search::minimum;
  ContactResult<T> out;
  out.strata_pairs = A.size() * B.size();
  // The model's size, for the threshold below which an intersection is sought.
  T size2(0);
  {
    std::array<T, 6> box = A[0].hull;
    for (const auto* L : {&A, &B})
      for (const auto& s : *L)
        for (int c = 0; c < 3; ++c) {
          if (s.hull[c] < box[c]) box[c] = s.hull[c];
          if (box[c + 3] < s.hull[c + 3]) box[c + 3] = s.hull[c + 3];
        }
    for (int c = 0; c < 3; ++c) {
      const T e = box[c + 3] - box[c];
      if (size2 < e * e) size2 = e * e;
    }
    if (size2 == T(0)) size2 = T(1);
  }
  const T tau = size2 / T(static_cast<long>(1) << 32);       // 2^-32 of the squared size
  const T tau_away = size2 / T(static_cast<long>(1) << 16);  // 2^-16 of it: a distance of 2^-8 of the size

  // U: the corners' closest pair, exactly.
  struct Job {
    std::size_t a, b;
    T lower;
  };
  std::vector<Job> jobs;
  T U(-1);
  struct Found {
    ContactPoint<T> p;
    long a = -1, b = -1;  // the strata it came from (-1: corner-corner)
  };
  std::vector<Found> found;
  std::vector<ContactPoint<T>> undecided;
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < B.size(); ++j) {
      if (A[i].k + B[j].k == 0) {  // two points (corners, or a corner and the point)
        ContactPoint<T> p;
        p.where = A[i].where + "-" + B[j].where;
        p.strata = A[i].label + " / " + B[j].label;
        p.lo = p.hi = params(A[i], B[j], {});
        p.exact = p.unique = true;
        p.p1 = stratum_point(A[i], {}, 0);
        p.p2 = stratum_point(B[j], {}, 0);
        T d2(0);
        for (int c = 0; c < 3; ++c) d2 += (p.p1[c] - p.p2[c]) * (p.p1[c] - p.p2[c]);
        p.d2_lo = p.d2_hi = d2;
        if (U < T(0) || d2 < U) U = d2;
        found.push_back({std::move(p), -1, -1});
      } else {
        jobs.push_back({i, j, hull_distance2(A[i], B[j])});
      }
    }
  std::stable_sort(jobs.begin(), jobs.end(), [](const Job& x, const Job& y) { return x.lower < y.lower; });

  const auto started = std::chrono::steady_clock::now();
  auto last = started;
  std::size_t done = 0;
  for (const auto& job : jobs) {
    ++done;
    if (options.progress && std::chrono::steady_clock::now() - last > std::chrono::seconds(2)) {
      last = std::chrono::steady_clock::now();
      std::ostringstream line;
      line << std::fixed << std::setprecision(1) << std::chrono::duration<double>(last - started).count() << " s: pairs of strata " << done << "/"
           << jobs.size() << " (" << out.pairs_solved << " solved, " << out.pairs_skipped << " skipped), " << out.boxes << " boxes";
      if (minimum && !(U < T(0))) line << ", smallest d^2 so far <= " << std::setprecision(6) << to_double(ArithTraits<T>::to_rational(U));
      options.progress(line.str());
    }
    if (out.intersecting) break;
    if (minimum && (U < job.lower || (!(tau < U) && A[job.a].k + B[job.b].k < 3))) {
      ++out.pairs_skipped;  // farther than the minimum, or too few unknowns to certify a common point
      continue;
    }
    const Stratum<T>& a = A[job.a];
    const Stratum<T>& b = B[job.b];
    const PairSystem<T> sys = pair_system(a, b);
    bool degenerate = false;
    for (const auto& g : sys.equations) {
      bool z = true;
      for (const auto& x : g.c) z = z && x == T(0);
      degenerate = degenerate || z;
    }
    const std::string where = a.where + "-" + b.where, label = a.label + " / " + b.label;
    // The whole search's budget: max_boxes for ten systems; past it the pairs are left undecided whole.
    const bool over_budget = out.boxes >= options.max_boxes * 10;
    if (degenerate || over_budget) {
      ContactPoint<T> u;
      u.where = where;
      u.strata = label + (degenerate ? ": an equation vanishes identically" : ": not searched (the search's budget of boxes is spent)");
      u.degenerate = degenerate;
      u.lo = params(a, b, sys.lo);
      u.hi = params(a, b, sys.hi);
      std::tie(u.d2_lo, u.d2_hi) = distance2_range(sys, sys.lo, sys.hi);
      round_enclosure(u.d2_lo, u.d2_hi);
      u.p1 = stratum_point(a, sys.lo, 0);
      u.p2 = stratum_point(b, sys.lo, static_cast<std::size_t>(a.k));
      if (U < T(0) || u.d2_hi < U) U = u.d2_hi;
      undecided.push_back(std::move(u));
      continue;
    }
    // Branch and bound: boxes whose distance is surely above U are not searched; every box lowers U.
    std::vector<T> near_lo, near_hi;
    Pruning<T> pr;
    pr.aux = {sys.W, sys.D[0], sys.D[1], sys.D[2]};
    pr.discard = [&](const detail::Bern<T>* aux, std::size_t, const std::vector<T>& lo, const std::vector<T>& hi) {
      auto [low, high] = distance2_bounds(aux + 1, aux[0]);
      // The box's corners are points of the strata: their exact distances bound the minimum
      // (much tighter than the bound for any point of the box).
      const std::size_t nv = aux[0].deg.size();
      const auto corner = [&](const detail::Bern<T>& g, std::size_t m) {
        std::size_t i = 0;
        for (std::size_t l = 0; l < nv; ++l)
          if (m >> l & 1) i += g.deg[l] * detail::tensor_stride(g.deg, static_cast<int>(l));
        return g.c[i];
      };
      for (std::size_t m = 0; m < (std::size_t(1) << nv); ++m) {
        T d2(0);
        for (int c = 1; c <= 3; ++c) {
          const T x = corner(aux[c], m);
          d2 += x * x;
        }
        const T w = corner(aux[0], m);
        d2 = d2 / (w * w);
        if (d2 < high) high = d2;
      }
      if (high < U) U = high;
      // Within tau of each other the surfaces probably meet along a curve, where Eq. 4 has no
      // isolated solutions and the search would not end: the first such box is kept for the
      // common-point certificate below, and this pair's search stops.
      if (!(tau < high) && near_lo.empty()) {
        near_lo = lo;
        near_hi = hi;
      }
      return U < low || !near_lo.empty();
    };
    // Away from contact: boxes whose points are surely within 2^-8 of the model's size of each
    // other are skipped (shallower penetrations are not searched).
    Pruning<T> away;
    away.aux = pr.aux;
    away.discard = [&](const detail::Bern<T>* aux, std::size_t, const std::vector<T>&, const std::vector<T>&) {
      return !(tau_away < distance2_bounds(aux + 1, aux[0]).second);
    };
    const auto r = solve_system(sys.equations, sys.lo, sys.hi, options, minimum ? &pr : search == Search::away_from_contact ? &away : nullptr);
    ++out.pairs_solved;
    out.boxes += r.boxes;
    const auto add = [&](const RootBox<T>& root, bool as_root) {
      ContactPoint<T> p;
      p.where = where;
      p.strata = label;
      p.exact = as_root && root.exact;
      p.unique = as_root && root.unique;
      const std::vector<T>& xl = p.exact ? root.point : root.lo;
      const std::vector<T>& xh = p.exact ? root.point : root.hi;
      p.lo = params(a, b, xl);
      p.hi = params(a, b, xh);
      if (p.exact) {
        p.d2_lo = p.d2_hi = distance2_at(sys, root.point);
      } else {
        std::tie(p.d2_lo, p.d2_hi) = distance2_range(sys, xl, xh);
        round_enclosure(p.d2_lo, p.d2_hi);
      }
      std::vector<T> at = xl;
      for (std::size_t l = 0; l < xl.size(); ++l) at[l] = (xl[l] + xh[l]) / T(2);
      p.p1 = stratum_point(a, at, 0);
      p.p2 = stratum_point(b, at, static_cast<std::size_t>(a.k));
      if (as_root && (U < T(0) || p.d2_hi < U)) U = p.d2_hi;
      if (as_root)
        found.push_back({std::move(p), static_cast<long>(job.a), static_cast<long>(job.b)});
      else
        undecided.push_back(std::move(p));
    };
    for (const auto& root : r.roots) add(root, true);
    for (const auto& box : r.undecided) add(box, false);
    if (!near_lo.empty()) {
      std::vector<T> lo4, hi4;
      if (certify_common_point(a, b, sys, near_lo, near_hi, lo4, hi4)) {
        out.intersecting = true;
        out.common_lo = lo4;
        out.common_hi = hi4;
      }
    }
  }

  // Merge: exact pairs by equality, boxes that overlap into one entry.
  // A box that holds one root of its strata's system is an exact pair of another stratum when that
  // pair solves the same system (and gives the same points: not across a jump).
  const auto same_root = [&](const Found& f, const ContactPoint<T>& k) {
    if (f.a < 0 || !f.p.unique) return false;
    const Stratum<T>& a = A[f.a];
    const Stratum<T>& b = B[f.b];
    std::vector<T> x(static_cast<std::size_t>(a.k + b.k));
    for (int s = 0; s < 2; ++s) {
      const Stratum<T>& st = s == 0 ? a : b;
      const std::size_t off = s == 0 ? 0 : static_cast<std::size_t>(a.k);
      for (int d = 0; d < st.dims; ++d) {
        const T& v = k.lo[(s == 0 ? 0 : a.dims) + d];
        if (v < st.lo[d] || st.hi[d] < v) return false;
        if (st.var[d] < 0) {
          if (!(v == st.lo[d])) return false;
        } else {
          x[off + st.var[d]] = v;
        }
      }
    }
    const PairSystem<T> sys = pair_system(a, b);
    std::vector<T> t(sys.n);
    for (std::size_t l = 0; l < sys.n; ++l) t[l] = (x[l] - sys.lo[l]) / (sys.hi[l] - sys.lo[l]);
    for (const auto& g : sys.equations)
      if (!(detail::bern_value(g, t) == T(0))) return false;
    return stratum_point(a, x, 0) == k.p1 && stratum_point(b, x, static_cast<std::size_t>(a.k)) == k.p2;
  };
  std::vector<ContactPoint<T>> kept;
  std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.p.exact && !y.p.exact; });
  for (auto& f : found) {
    auto& p = f.p;
    bool dup = false;
    for (auto& k : kept) {
      bool touch = true;
      for (std::size_t l = 0; l < p.lo.size(); ++l) touch = touch && !(p.hi[l] < k.lo[l]) && !(k.hi[l] < p.lo[l]);
      if (!touch) continue;
      if (p.exact && k.exact) {
        dup = p.lo == k.lo && p.p1 == k.p1 && p.p2 == k.p2;
      } else if (!p.exact && k.exact) {
        dup = same_root(f, k);
      } else {
        for (std::size_t l = 0; l < p.lo.size(); ++l) {
          if (p.lo[l] < k.lo[l]) k.lo[l] = p.lo[l];
          if (k.hi[l] < p.hi[l]) k.hi[l] = p.hi[l];
        }
        if (p.d2_lo < k.d2_lo) k.d2_lo = p.d2_lo;
        if (k.d2_hi < p.d2_hi) k.d2_hi = p.d2_hi;
        k.merged = true;
        k.unique = false;
        dup = true;
      }
      if (dup) break;
    }
    if (!dup) kept.push_back(std::move(p));
  }
  // Only what can matter to the minimum (everything when all stationary pairs are asked for).
  for (auto& p : kept)
    if (!minimum || !(U < p.d2_lo)) out.points.push_back(std::move(p));
  for (auto& u : undecided)
    if (!minimum || !(U < u.d2_lo)) out.undecided.push_back(std::move(u));
  std::stable_sort(out.points.begin(), out.points.end(), [](const auto& x, const auto& y) { return x.d2_lo < y.d2_lo; });

  for (const auto& p : out.points)
    if (minimum && !out.intersecting && p.exact && p.d2_hi == T(0)) {  // an exact common point
      out.intersecting = true;
      out.common_lo = p.lo;
      out.common_hi = p.hi;
    }
  if (minimum && out.intersecting) {
    out.distance2_lo = out.distance2_hi = T(0);
    ContactPoint<T> c;
    c.where = "intersection";
    c.strata = "a common point of the surfaces (S1 - S2 = 0 certified)";
    c.lo = out.common_lo;
    c.hi = out.common_hi;
    c.exact = out.common_lo == out.common_hi;
    c.unique = true;
    c.d2_lo = c.d2_hi = T(0);
    out.points.insert(out.points.begin(), c);
    out.closest = {0};
    out.closest_certified = ArithTraits<T>::exact;
    return out;
  }
  out.distance2_hi = U;
  out.distance2_lo = U;
  for (const auto& p : out.points)
    if (p.d2_lo < out.distance2_lo) out.distance2_lo = p.d2_lo;
  bool undecided_below = false;
  for (const auto& u : out.undecided) {
    if (u.d2_lo < out.distance2_lo) out.distance2_lo = u.d2_lo;
    undecided_below = undecided_below || !(U < u.d2_lo);
  }
  for (std::size_t i = 0; i < out.points.size(); ++i)
    if (!(out.distance2_hi < out.points[i].d2_lo)) out.closest.push_back(i);
  const bool within_tau = minimum && !(tau < U);
  // One closest pair: one candidate, or several exact ones that are the same points in space (a
  // seam or a collapsed edge maps several parameters to one point).
  bool one = out.closest.size() == 1 && (out.points[out.closest[0]].unique || out.points[out.closest[0]].exact);
  if (out.closest.size() > 1) {
    const auto& f = out.points[out.closest[0]];
    one = true;
    for (std::size_t i : out.closest) {
      const auto& p = out.points[i];
      one = one && p.exact && f.exact && p.d2_lo == f.d2_lo && p.p1 == f.p1 && p.p2 == f.p2;
    }
  }
  out.closest_certified = ArithTraits<T>::exact && one && !undecided_below && !within_tau;
  return out;
}

template ContactResult<Rational> stationary_pairs(const std::vector<Stratum<Rational>>&, const std::vector<Stratum<Rational>>&, const SolveOptions&,
                                                  Search);
template ContactResult<double> stationary_pairs(const std::vector<Stratum<double>>&, const std::vector<Stratum<double>>&, const SolveOptions&,
                                                Search);
template ContactResult<Mpfr> stationary_pairs(const std::vector<Stratum<Mpfr>>&, const std::vector<Stratum<Mpfr>>&, const SolveOptions&, Search);

}  // namespace solve_detail

template <class T>
ContactResult<T> surface_distance(const BSpline<T>& S1, const BSpline<T>& S2, const SolveOptions& options, const Limits& limits, bool penetration) {
  // Eq. 4's equations: degree 2 p in each surface's own directions (3 p rational), times 2 for the pair.
  require_surface(S1, "first", limits, 4);
  require_surface(S2, "second", limits, 4);
  const auto A = surface_strata(S1, limits), B = surface_strata(S2, limits);
  auto out = solve_detail::stationary_pairs(A, B, options, solve_detail::Search::minimum);
  for (const auto& u : out.undecided)
    if (u.degenerate && u.where == "interior-interior")
      throw ValidationError("surfaces", "the distance equations vanish identically on " + u.strata.substr(0, u.strata.rfind(':')) +
                                            ": the stationary pairs are not isolated (equidistant surfaces, or a degenerate piece)",
                            "give surfaces whose distance is not constant along a piece");
  if (!out.intersecting || !penetration) return out;
  // Intersecting: the stationary pairs away from the intersection, and on which side of each
  // surface the other's point lies (the normals S_u x S_v, S_r x S_t at the pair's point).
  auto away = solve_detail::stationary_pairs(A, B, options, solve_detail::Search::away_from_contact);
  out.boxes += away.boxes;
  out.extremes_complete = away.undecided.empty();
  const auto side = [](const BSpline<T>& S, const std::vector<T>& uv, const std::vector<T>& from, const std::vector<T>& to) {
    const auto su = derivative(S, uv, {1, 0}), sv = derivative(S, uv, {0, 1});
    const T n[3] = {su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2], su[0] * sv[1] - su[1] * sv[0]};
    T s(0);
    for (int c = 0; c < 3; ++c) s += (to[c] - from[c]) * n[c];
    return T(0) < s ? 1 : s < T(0) ? -1 : 0;
  };
  for (auto& p : away.points) {
    std::vector<T> x(4);
    for (int l = 0; l < 4; ++l) x[l] = (p.lo[l] + p.hi[l]) / T(2);
    p.side1 = side(S1, {x[0], x[1]}, p.p1, p.p2);
    p.side2 = side(S2, {x[2], x[3]}, p.p2, p.p1);
    if (!(p.unique || p.exact) || !(out.distance2_hi < p.d2_lo)) continue;
    if (p.side2 < 0 && (out.deepest_1_in_2 < 0 || away.points[out.deepest_1_in_2].d2_hi < p.d2_hi))
      out.deepest_1_in_2 = &p - away.points.data();
    if (p.side1 < 0 && (out.deepest_2_in_1 < 0 || away.points[out.deepest_2_in_1].d2_hi < p.d2_hi))
      out.deepest_2_in_1 = &p - away.points.data();
  }
  out.extremes = std::move(away.points);
  return out;
}

template ContactResult<Rational> surface_distance(const BSpline<Rational>&, const BSpline<Rational>&, const SolveOptions&, const Limits&, bool);
template ContactResult<double> surface_distance(const BSpline<double>&, const BSpline<double>&, const SolveOptions&, const Limits&, bool);
template ContactResult<Mpfr> surface_distance(const BSpline<Mpfr>&, const BSpline<Mpfr>&, const SolveOptions&, const Limits&, bool);

}  // namespace splinex
