// The minimum distance of two surfaces (solve/contact.hpp), for Rational and double.
#include "solve/contact.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <cmath>
#include <numeric>
#include <type_traits>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "solve/strata.hpp"
#include "solve/testing.hpp"
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
    std::vector<Bernstein<T>> eq(3);
    std::vector<T> lo, hi;
    for (int c = 0; c < 3; ++c) {
      eq[c] = sys.D[c];
      for (std::size_t l = 0; l < n; ++l) eq[c] = bern_restrict(eq[c], static_cast<int>(l), la[l], lb[l]);
    }
    T fixed_value(0);
    if (n == 4) {
      // Fix unknown `fixed` at the centre of the widened box (local 1/2).
      for (auto& g : eq) g = bern_fix(g, static_cast<int>(fixed), T(1) / T(2));
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

/// The largest squared extent of the strata's control-point boxes along an axis (1 when that is 0).
template <class T>
T model_size2(const std::vector<Stratum<T>>& A, const std::vector<Stratum<T>>& B) {
  T size2(0);
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
  return size2;
}

/// A pair of strata to search, and the squared distance of their control points' boxes.
template <class T>
struct Job {
  std::size_t a, b;
  T lower;
};

/// A stationary pair found.
template <class T>
struct Found {
  ContactPoint<T> p;
  long a = -1, b = -1;  // the strata it came from (-1: corner-corner, or a reduced pair)
};

/// What the steps of one search over the pairs of strata share: the strata, what is searched, the
/// thresholds, the bounds so far and what was found.
template <class T>
struct PairSearch {
  const std::vector<Stratum<T>>& A;
  const std::vector<Stratum<T>>& B;
  const SolveOptions& options;
  Search search;
  bool minimum;           // search == Search::minimum
  bool ignore_undecided;  // planted: undecided boxes take no part in the closest verdict
  bool prune_plant;       // planted: a box pruned by its upper bound
  T tau;                  // 2^-32 of the squared size
  T tau_away;             // 2^-16 of it: a distance of 2^-8 of the size
  ContactResult<T> out{};
  // U: the smallest squared distance found so far (branch and bound). In a float arithmetic the
  // search's U comes from round-to-nearest values; `Uout`, the one reported, only from outward
  // enclosures (the same in exact arithmetic). Every box lowers them: its points are real pairs.
  T U = T(0), Uout = T(0);
  bool haveU = false, haveUout = false;
  std::vector<Found<T>> found{};
  std::vector<ContactPoint<T>> undecided{};

  void offer(const T& bound, const T& reported) {
    if (!haveU || bound < U) U = bound, haveU = true;
    if (!haveUout || reported < Uout) Uout = reported, haveUout = true;
  }
};

/// Two strata without free parameters (points): p's parameters, points and exact distance (a float
/// arithmetic: its enclosure), offered to the bounds.
template <class T>
void point_pair(PairSearch<T>& ps, const Stratum<T>& a, const Stratum<T>& b, ContactPoint<T>& p) {
  p.lo = p.hi = params(a, b, {});
  p.exact = true;
  p.p1 = stratum_point(a, {}, 0);
  p.p2 = stratum_point(b, {}, 0);
  if constexpr (ArithTraits<T>::exact) {
    T d2(0);
    for (int c = 0; c < 3; ++c) d2 += (p.p1[c] - p.p2[c]) * (p.p1[c] - p.p2[c]);
    p.d2_lo = p.d2_hi = d2;
  } else {
    std::tie(p.d2_lo, p.d2_hi) = distance2_enclosure(a, b, pair_system(a, b), {}, {});
  }
  ps.offer(p.d2_hi, p.d2_hi);
}

/// The pairs of strata to search, nearest first (by their boxes); pairs of two points are
/// evaluated at once.
template <class T>
std::vector<Job<T>> pairs_to_search(PairSearch<T>& ps) {
  const auto& A = ps.A;
  const auto& B = ps.B;
  std::vector<Job<T>> jobs;
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < B.size(); ++j) {
      if (A[i].k + B[j].k == 0) {  // two points (corners, or a corner and the point)
        ContactPoint<T> p;
        p.where = A[i].where + "-" + B[j].where;
        p.strata = A[i].label + " / " + B[j].label;
        point_pair(ps, A[i], B[j], p);
        p.unique = true;
        ps.found.push_back({std::move(p), -1, -1});
      } else {
        jobs.push_back({i, j, hull_distance2(A[i], B[j])});
      }
    }
  std::stable_sort(jobs.begin(), jobs.end(), [](const Job<T>& x, const Job<T>& y) { return x.lower < y.lower; });
  return jobs;
}

/// One pair of strata as searched: the strata reduced where an equation vanishes identically
/// (along_a, along_b: the parameters fixed at their lower ends), their system, their names, and
/// the first box of the search within tau of contact.
template <class T>
struct StrataPair {
  const Job<T>& job;
  Stratum<T> a, b;
  PairSystem<T> sys{};
  std::vector<int> along_a{}, along_b{};
  bool degenerate = false;  // every equation of a piece vanishes
  bool reduced = false;
  std::string where{}, label{};
  bool stop_near = false;  // the search stops at the first box within tau
  std::vector<T> near_lo{}, near_hi{};
};

/// The pair of strata of `job`, reduced.
template <class T>
StrataPair<T> reduced_pair(const PairSearch<T>& ps, const Job<T>& job) {
  StrataPair<T> pair{job, ps.A[job.a], ps.B[job.b]};
  Stratum<T>& a = pair.a;
  Stratum<T>& b = pair.b;
  PairSystem<T>& sys = pair.sys;
  std::vector<int>& along_a = pair.along_a;
  std::vector<int>& along_b = pair.along_b;
  sys = pair_system(a, b);
  // An equation that vanishes identically is a distance constant along its unknown on the whole
  // pair of strata (it is W^3 / 2 times the derivative): the minimum and the critical points
  // are those of the face at the unknown's lower end, times its range (a pole, a collapsed edge,
  // a point on an axis of revolution). Only where every equation of a piece vanishes (the point
  // at a centre of the surface) is the pair degenerate.
  for (bool first = true; a.k + b.k > 0; first = false) {
    std::size_t zeros = 0, last_zero = 0;
    for (std::size_t i = 0; i < sys.equations.size(); ++i) {
      bool z = true;
      for (const auto& x : sys.equations[i].c) z = z && x == T(0);
      if (z) ++zeros, last_zero = i;
    }
    if (zeros == 0) break;
    if (first && zeros == sys.n && a.where == "interior" && (b.k == 0 || b.where == "interior")) {
      pair.degenerate = true;
      break;
    }
    const bool in_a = last_zero < static_cast<std::size_t>(a.k);
    Stratum<T>& s = in_a ? a : b;
    const int v = static_cast<int>(in_a ? last_zero : last_zero - a.k);
    int d = 0;
    while (s.var[d] != v) ++d;
    (in_a ? along_a : along_b).push_back(d);
    const std::string where = s.where, label = s.label;
    s = stratum_face(s, d, 0);
    s.where = where;
    s.label = label;
    sys = pair_system(a, b);
  }
  pair.reduced = !along_a.empty() || !along_b.empty();
  pair.where = a.where + "-" + b.where;
  pair.label = a.label + " / " + b.label +
               (pair.reduced ? ": the distance is constant along " + std::to_string(along_a.size() + along_b.size()) +
                                   " of the parameters (an equation vanishes identically), its critical points form segments"
                             : "");
  return pair;
}

/// The reduced pair's parameters widened back to the segments along which the distance is
/// constant, and whether each segment is one point in space.
template <class T>
void widen(const PairSearch<T>& ps, const StrataPair<T>& pair, ContactPoint<T>& p) {
  const Job<T>& job = pair.job;
  const Stratum<T>& a = pair.a;
  p.along.clear();
  for (int d : pair.along_a) {
    p.along.push_back(d);
    p.lo[d] = ps.A[job.a].lo[d];
    p.hi[d] = ps.A[job.a].hi[d];
  }
  for (int d : pair.along_b) {
    p.along.push_back(a.dims + d);
    p.lo[a.dims + d] = ps.B[job.b].lo[d];
    p.hi[a.dims + d] = ps.B[job.b].hi[d];
  }
  if (p.exact && !p.along.empty()) {
    std::vector<T> ua(p.lo.begin(), p.lo.begin() + a.dims), ub(p.lo.begin() + a.dims, p.lo.end());
    p.collapsed = constant_along(ps.A[job.a], pair.along_a, ua) && constant_along(ps.B[job.b], pair.along_b, ub);
  }
}

/// A pair left undecided whole: degenerate, or past the search's budget.
template <class T>
void leave_undecided(PairSearch<T>& ps, const StrataPair<T>& pair) {
  const Stratum<T>& a = pair.a;
  const Stratum<T>& b = pair.b;
  const PairSystem<T>& sys = pair.sys;
  ContactPoint<T> u;
  u.where = pair.where;
  u.strata =
      pair.label + (pair.degenerate ? ": an equation vanishes identically" : ": not searched (the search's budget of boxes is spent)");
  u.degenerate = pair.degenerate;
  u.lo = params(a, b, sys.lo);
  u.hi = params(a, b, sys.hi);
  std::tie(u.d2_lo, u.d2_hi) = distance2_enclosure(a, b, sys, sys.lo, sys.hi);
  u.p1 = stratum_point(a, sys.lo, 0);
  u.p2 = stratum_point(b, sys.lo, static_cast<std::size_t>(a.k));
  widen(ps, pair, u);
  if (!ps.ignore_undecided)
    ps.offer(u.d2_hi, u.d2_hi);
  else
    solve_testing::plant_hit();
  ps.undecided.push_back(std::move(u));
}

/// The coefficient of g (nv unknowns) at the corner m of its box (bit l of m: the upper end in l).
template <class T>
T corner(const Bernstein<T>& g, std::size_t m, std::size_t nv) {
  std::size_t i = 0;
  for (std::size_t l = 0; l < nv; ++l)
    if (m >> l & 1) i += g.deg[l] * detail::tensor_stride(g.deg, static_cast<int>(l));
  return g.c[i];
}

/// Branch and bound on one box [lo, hi] of the pair's system (aux: W, D_0, D_1, D_2 on it): the box
/// lowers U; true when it is discarded.
template <class T>
bool bound_box(PairSearch<T>& ps, StrataPair<T>& pair, const Bernstein<T>* aux, const std::vector<T>& lo, const std::vector<T>& hi) {
  auto [low, high] = distance2_bounds(aux + 1, aux[0]);
  // The box's corners are points of the strata: their exact distances bound the minimum
  // (much tighter than the bound for any point of the box).
  const std::size_t nv = aux[0].deg.size();
  std::size_t best = 0;
  for (std::size_t m = 0; m < (std::size_t(1) << nv); ++m) {
    T d2(0);
    for (int c = 1; c <= 3; ++c) {
      const T x = corner(aux[c], m, nv);
      d2 += x * x;
    }
    const T w = corner(aux[0], m, nv);
    d2 = d2 / (w * w);
    if (d2 < high) high = d2, best = m;
  }
  if (!ps.haveU || high < ps.U) {
    T reported = high;
    if constexpr (!ArithTraits<T>::exact) {
      // Round to nearest: the reported bound is the corner's distance enclosed exactly.
      std::vector<T> x(nv);
      for (std::size_t l = 0; l < nv; ++l) x[l] = best >> l & 1 ? hi[l] : lo[l];
      reported = distance2_enclosure(pair.a, pair.b, pair.sys, x, x).second;
    }
    ps.offer(high, reported);
  }
  // Within tau of each other the surfaces probably meet along a curve, where Eq. 4 has no
  // isolated solutions and the search would not end: the first such box is kept for the
  // common-point certificate below, and this pair's search stops (it is searched again in
  // full when no common point is certified: surfaces that nearly touch).
  if (pair.stop_near && !(ps.tau < high) && pair.near_lo.empty()) {
    pair.near_lo = lo;
    pair.near_hi = hi;
  }
  if (ps.prune_plant && ps.U < high && !(ps.U < low)) {
    // Planted (solve/testing.hpp): pruned by its upper bound, although it may hold the minimum.
    solve_testing::plant_hit();
    return true;
  }
  return ps.U < low || (pair.stop_near && !pair.near_lo.empty());
}

/// A root (as_root) or an undecided box of the pair's system, kept with its distance enclosure.
template <class T>
void add_box(PairSearch<T>& ps, const StrataPair<T>& pair, const RootBox<T>& root, bool as_root) {
  const Stratum<T>& a = pair.a;
  const Stratum<T>& b = pair.b;
  ContactPoint<T> p;
  p.where = pair.where;
  p.strata = pair.label;
  p.exact = as_root && root.exact;
  p.unique = as_root && root.unique && !pair.reduced;
  const std::vector<T>& xl = p.exact ? root.point : root.lo;
  const std::vector<T>& xh = p.exact ? root.point : root.hi;
  p.lo = params(a, b, xl);
  p.hi = params(a, b, xh);
  if (p.exact)
    p.d2_lo = p.d2_hi = distance2_at(pair.sys, root.point);
  else
    std::tie(p.d2_lo, p.d2_hi) = distance2_enclosure(a, b, pair.sys, xl, xh);
  std::vector<T> at = xl;
  for (std::size_t l = 0; l < xl.size(); ++l) at[l] = (xl[l] + xh[l]) / T(2);
  p.p1 = stratum_point(a, at, 0);
  p.p2 = stratum_point(b, at, static_cast<std::size_t>(a.k));
  widen(ps, pair, p);
  // Undecided boxes too: every point of a box is a pair of points of the strata, so the
  // box's upper bound bounds the minimum (a candidate above it cannot be the closest).
  if (as_root || !ps.ignore_undecided)
    ps.offer(p.d2_hi, p.d2_hi);
  else
    solve_testing::plant_hit();
  if (as_root)
    ps.found.push_back(
        {std::move(p), pair.reduced ? -1L : static_cast<long>(pair.job.a), pair.reduced ? -1L : static_cast<long>(pair.job.b)});
  else
    ps.undecided.push_back(std::move(p));
}

/// The pair's system solved (branch and bound when the minimum is searched, or away from contact)
/// and its roots and undecided boxes kept; true when it came within tau of contact with no common
/// point certified (then nothing of it is kept).
template <class T>
bool solve_pair(PairSearch<T>& ps, StrataPair<T>& pair, bool full) {
  auto& out = ps.out;
  const PairSystem<T>& sys = pair.sys;
  // Branch and bound: boxes whose distance is surely above U are not searched; every box lowers U.
  pair.stop_near = !full;
  Pruning<T> pr;
  pr.aux = {sys.W, sys.D[0], sys.D[1], sys.D[2]};
  pr.discard = [&](const Bernstein<T>* aux, std::size_t, const std::vector<T>& lo, const std::vector<T>& hi) {
    return bound_box(ps, pair, aux, lo, hi);
  };
  // Away from contact: boxes whose points are surely within 2^-8 of the model's size of each
  // other are skipped (shallower penetrations are not searched).
  Pruning<T> away;
  away.aux = pr.aux;
  away.discard = [&](const Bernstein<T>* aux, std::size_t, const std::vector<T>&, const std::vector<T>&) {
    return !(ps.tau_away < distance2_bounds(aux + 1, aux[0]).second);
  };
  const Pruning<T>* pruning = ps.minimum ? &pr : ps.search == Search::away_from_contact ? &away : nullptr;
  const auto r = solve_system(sys.equations, sys.lo, sys.hi, ps.options, pruning);
  out.boxes += r.boxes;
  if (!pair.near_lo.empty()) {
    std::vector<T> lo4, hi4;
    if (!certify_common_point(pair.a, pair.b, sys, pair.near_lo, pair.near_hi, lo4, hi4))
      return true;  // they may only come close (2^-20 apart)
    out.intersecting = true;
    out.common_lo = lo4;
    out.common_hi = hi4;
  }
  ++out.pairs_solved;
  for (const auto& root : r.roots) add_box(ps, pair, root, true);
  for (const auto& box : r.undecided) add_box(ps, pair, box, false);
  return false;
}

/// One pair of strata; `full`: without the stop near contact. Returns true when the pair came
/// within tau without a certified common point: it is then searched in full after the others
/// (nothing of it is kept now), unless a common point is certified elsewhere first.
template <class T>
bool search_pair(PairSearch<T>& ps, const Job<T>& job, bool full) {
  StrataPair<T> pair = reduced_pair(ps, job);
  if (pair.a.k + pair.b.k == 0) {  // reduced to a pair of points
    ContactPoint<T> p;
    p.where = pair.where;
    p.strata = pair.label;
    point_pair(ps, pair.a, pair.b, p);
    widen(ps, pair, p);
    ps.found.push_back({std::move(p), -1, -1});
    return false;
  }
  // The whole search's budget: max_boxes for ten systems; past it the pairs are left undecided whole.
  const bool over_budget = ps.out.boxes >= ps.options.max_boxes * 10;
  if (pair.degenerate || over_budget) {
    leave_undecided(ps, pair);
    return false;
  }
  return solve_pair(ps, pair, full);
}

/// Every pair of strata in turn, nearest first, with a line of progress about every two seconds;
/// then the pairs deferred.
template <class T>
void search_pairs(PairSearch<T>& ps, const std::vector<Job<T>>& jobs) {
  auto& out = ps.out;
  const auto started = std::chrono::steady_clock::now();
  auto last = started;
  std::size_t done = 0;
  std::vector<const Job<T>*> deferred;
  for (const auto& job : jobs) {
    ++done;
    if (ps.options.progress && std::chrono::steady_clock::now() - last > std::chrono::seconds(2)) {
      last = std::chrono::steady_clock::now();
      std::ostringstream line;
      line << std::fixed << std::setprecision(1) << std::chrono::duration<double>(last - started).count() << " s: pairs of strata " << done
           << "/" << jobs.size() << " (" << out.pairs_solved << " solved, " << out.pairs_skipped << " skipped), " << out.boxes << " boxes";
      if (ps.minimum && ps.haveU)
        line << ", smallest d^2 so far <= " << std::setprecision(6) << to_double(ArithTraits<T>::to_rational(ps.U));
      ps.options.progress(line.str());
    }
    if (out.intersecting) break;
    if (ps.minimum && ps.haveU && ps.U < job.lower) {
      ++out.pairs_skipped;  // farther than the minimum
      continue;
    }
    if (search_pair(ps, job, false)) deferred.push_back(&job);
  }
  // Pairs that came within tau of each other with no common point certified: searched in full
  // (surfaces that nearly touch); where they do meet along a curve, the budget leaves boxes
  // undecided. Not needed once a common point is certified (the minimum is then 0).
  for (const Job<T>* job : deferred) {
    if (out.intersecting) break;
    if (ps.minimum && ps.haveU && ps.U < job->lower) {
      ++out.pairs_skipped;
      continue;
    }
    search_pair(ps, *job, true);
  }
}

/// A box that holds one root of its strata's system is an exact pair of another stratum when that
/// pair solves the same system (and gives the same points: not across a jump).
template <class T>
bool same_root(const PairSearch<T>& ps, const Found<T>& f, const ContactPoint<T>& k) {
  if (f.a < 0 || !f.p.unique) return false;
  const Stratum<T>& a = ps.A[f.a];
  const Stratum<T>& b = ps.B[f.b];
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
    if (!(bern_value(g, t) == T(0))) return false;
  return stratum_point(a, x, 0) == k.p1 && stratum_point(b, x, static_cast<std::size_t>(a.k)) == k.p2;
}

/// Merge: exact pairs by equality, boxes that overlap into one entry.
template <class T>
std::vector<ContactPoint<T>> merge_found(PairSearch<T>& ps) {
  std::vector<ContactPoint<T>> kept;
  std::stable_sort(ps.found.begin(), ps.found.end(), [](const auto& x, const auto& y) { return x.p.exact && !y.p.exact; });
  for (auto& f : ps.found) {
    auto& p = f.p;
    bool dup = false;
    for (auto& k : kept) {
      bool touch = true;
      for (std::size_t l = 0; l < p.lo.size(); ++l) touch = touch && !(p.hi[l] < k.lo[l]) && !(k.hi[l] < p.lo[l]);
      if (!touch) continue;
      if (p.exact && k.exact) {
        dup = p.lo == k.lo && p.p1 == k.p1 && p.p2 == k.p2;
      } else if (!p.exact && k.exact) {
        dup = same_root(ps, f, k);
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
  return kept;
}

/// The minimum search only: whether a common point is known (an exact pair at distance 0, or a box
/// whose enclosure reaches no higher than 0); then the minimum is 0 and the common point comes first.
template <class T>
bool common_point(PairSearch<T>& ps) {
  auto& out = ps.out;
  const bool minimum = ps.minimum;
  for (const auto& p : out.points)
    if (minimum && !out.intersecting && p.exact && p.d2_hi == T(0)) {  // an exact common point
      out.intersecting = true;
      out.common_lo = p.lo;
      out.common_hi = p.hi;
    }
  // A box whose (outward) enclosure has upper bound 0: every point of it is a common point.
  if (minimum && !out.intersecting && ps.haveUout && !(T(0) < ps.Uout))
    for (const auto* L : {&out.points, &out.undecided})
      for (const auto& p : *L)
        if (!out.intersecting && !(T(0) < p.d2_hi)) {
          out.intersecting = true;
          out.common_lo = p.lo;
          out.common_hi = p.hi;
        }
  if (minimum && out.intersecting) {
    out.distance2_lo = out.distance2_hi = T(0);
    ContactPoint<T> c;
    c.where = "intersection";
    c.strata = ArithTraits<T>::exact
                   ? "a common point of the surfaces (S1 - S2 = 0 certified)"
                   : "a common point of the surfaces (S1 - S2 = 0 found in " + ArithTraits<T>::name() + ", not certified)";
    c.lo = out.common_lo;
    c.hi = out.common_hi;
    c.exact = out.common_lo == out.common_hi;
    c.unique = true;
    c.d2_lo = c.d2_hi = T(0);
    out.points.insert(out.points.begin(), c);
    out.closest = {0};
    out.closest_certified = ArithTraits<T>::exact;
    if (!out.closest_certified) out.reason = "the subdivision ran in " + ArithTraits<T>::name();
    return true;
  }
  return false;
}

/// The minimum enclosed, the candidates and undecided boxes that may be the closest, and the
/// verdict, with the reason when it is not certified.
template <class T>
void closest_verdict(PairSearch<T>& ps) {
  auto& out = ps.out;
  const bool ignore_undecided = ps.ignore_undecided;
  out.distance2_hi = ps.Uout;
  out.distance2_lo = ps.Uout;
  for (const auto& p : out.points)
    if (p.d2_lo < out.distance2_lo) out.distance2_lo = p.d2_lo;
  for (const auto& u : out.undecided)
    if (u.d2_lo < out.distance2_lo) out.distance2_lo = u.d2_lo;
  // A candidate whose lower bound is above the smallest upper bound (of any candidate or box) is
  // not the closest; an undecided box below it may hold the closest pair.
  for (std::size_t i = 0; i < out.points.size(); ++i)
    if (!(out.distance2_hi < out.points[i].d2_lo)) out.closest.push_back(i);
  for (std::size_t i = 0; i < out.undecided.size(); ++i)
    if (!(out.distance2_hi < out.undecided[i].d2_lo)) out.undecided_closest.push_back(i);
  // One closest pair: one candidate, or several exact ones that are the same points in space (a
  // seam or a collapsed edge maps several parameters to one point); a segment of equidistant
  // critical points is one pair only when it is one point in space.
  const auto single = [](const ContactPoint<T>& p) { return p.along.empty() || p.collapsed; };
  bool one = out.closest.size() == 1 && (out.points[out.closest[0]].unique || out.points[out.closest[0]].exact) &&
             single(out.points[out.closest[0]]);
  if (out.closest.size() > 1) {
    const auto& f = out.points[out.closest[0]];
    one = true;
    for (std::size_t i : out.closest) {
      const auto& p = out.points[i];
      one = one && p.exact && f.exact && single(p) && p.d2_lo == f.d2_lo && p.p1 == f.p1 && p.p2 == f.p2;
    }
  }
  out.closest_certified = ArithTraits<T>::exact && one && (out.undecided_closest.empty() || ignore_undecided);
  if (ignore_undecided && !out.undecided_closest.empty()) solve_testing::plant_hit();
  if (ps.minimum && !(T(0) < out.distance2_lo)) out.intersection_undecided = true;
  // Why not certified, in words.
  if (!ArithTraits<T>::exact) {
    out.reason = "the subdivision ran in " + ArithTraits<T>::name();
  } else if (!out.undecided_closest.empty()) {
    out.reason = std::to_string(out.undecided_closest.size()) + " undecided box(es) may hold the closest " +
                 (ps.B[0].dims == 0 ? "point" : "pair") +
                 (out.closest.empty() ? std::string(", closer than every certified candidate") : std::string(""));
  } else if (out.closest.empty()) {
    out.reason = "no candidate below the smallest upper bound was found (the search was cut short)";
  } else if (!one) {
    bool segment = false;
    for (std::size_t i : out.closest) segment = segment || !single(out.points[i]);
    out.reason =
        segment
            ? "the distance is constant along a segment of critical points that is not one point in space: the closest pair is not unique"
        : out.closest.size() > 1
            ? std::to_string(out.closest.size()) + " candidates' distance enclosures overlap: the closest is not decided (or not unique)"
            : "the closest candidate's box is not certified to hold one simple stationary pair";
  }
}

}  // namespace

namespace solve_detail {

template <class T>
ContactResult<T> stationary_pairs(const std::vector<Stratum<T>>& A, const std::vector<Stratum<T>>& B, const SolveOptions& options,
                                  Search search) {
  const bool minimum = search == Search::minimum;
  // Planted (solve/testing.hpp): undecided boxes take no part in the closest verdict.
  const bool ignore_undecided = solve_testing::planted(solve_testing::Plant::closest_ignores_undecided);
  // Planted: branch and bound prunes a box whose upper bound (not its lower bound) is above U.
  const bool prune_plant = solve_testing::planted(solve_testing::Plant::contact_prune_wrong_bound);
  // The model's size, for the threshold below which an intersection is sought.
  const T size2 = model_size2(A, B);
  const T tau = size2 / T(static_cast<long>(1) << 32);       // 2^-32 of the squared size
  const T tau_away = size2 / T(static_cast<long>(1) << 16);  // 2^-16 of it: a distance of 2^-8 of the size
  PairSearch<T> ps{A, B, options, search, minimum, ignore_undecided, prune_plant, tau, tau_away};
  ps.out.strata_pairs = A.size() * B.size();
  const std::vector<Job<T>> jobs = pairs_to_search(ps);
  search_pairs(ps, jobs);

  std::vector<ContactPoint<T>> kept = merge_found(ps);
  auto& out = ps.out;
  // Only what can matter to the minimum (everything when all stationary pairs are asked for).
  for (auto& p : kept)
    if (!minimum || !(ps.Uout < p.d2_lo)) out.points.push_back(std::move(p));
  for (auto& u : ps.undecided)
    if (!minimum || !(ps.Uout < u.d2_lo)) out.undecided.push_back(std::move(u));
  std::stable_sort(out.points.begin(), out.points.end(), [](const auto& x, const auto& y) { return x.d2_lo < y.d2_lo; });

  if (!common_point(ps)) closest_verdict(ps);
  return std::move(ps.out);
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
    const Point3<T> n = cross(as_point3(su), as_point3(sv));
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
