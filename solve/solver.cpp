// The subdivision solver (solve/solver.hpp), instantiated for Rational (certified) and double.
#include "solve/solver.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "base/errors.hpp"
#include "bernstein/subdivide.hpp"
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "solve/krawczyk.hpp"
#include "solve/testing.hpp"

namespace splinex {

namespace solve_testing {

Plant active_plant = Plant::none;
std::size_t plant_hits = 0;

namespace {
constexpr std::pair<Plant, const char*> plant_names[] = {
    {Plant::none, "none"},
    {Plant::skip_krawczyk_contraction_merged, "skip_krawczyk_contraction_merged"},
    {Plant::skip_krawczyk_contraction_known, "skip_krawczyk_contraction_known"},
    {Plant::closed_interior, "closed_interior"},
    {Plant::krawczyk_wrong_sign, "krawczyk_wrong_sign"},
    {Plant::drop_box, "drop_box"},
    {Plant::closest_ignores_undecided, "closest_ignores_undecided"},
    {Plant::shrink_enclosure, "shrink_enclosure"},
    {Plant::contact_prune_wrong_bound, "contact_prune_wrong_bound"},
    {Plant::curve_counts_unchecked, "curve_counts_unchecked"},
};
}  // namespace

std::string plant_name(Plant p) {
  for (const auto& [q, name] : plant_names)
    if (q == p) return name;
  return "unknown";
}

Plant plant_from_name(const std::string& name) {
  for (const auto& [q, n] : plant_names)
    if (name == n) return q;
  throw std::invalid_argument("no solve plant named '" + name + "'");
}

ScopedPlant::ScopedPlant(Plant p) : previous_(active_plant), previous_hits_(plant_hits) {
  active_plant = p;
  plant_hits = 0;
}
ScopedPlant::~ScopedPlant() {
  active_plant = previous_;
  plant_hits = previous_hits_;
}

}  // namespace solve_testing

namespace {

using solve_testing::Plant;
using solve_detail::dbl;
using solve_detail::exponent_of;
using solve_detail::krawczyk;
using solve_detail::KrawczykResult;
using solve_detail::pow2;
using solve_detail::scale_exponent;
using solve_detail::tmax;
using solve_detail::tmin;

template <class T>
struct Node {
  std::vector<Bernstein<T>> f;  // the equations, then the caller's auxiliary polynomials
  std::vector<T> lo, hi;  // global box
  int depth = 0;
};

/// f restricted to the local box [a, b] (in f's own coordinates), with the global box updated.
template <class T>
Node<T> restrict_node(const Node<T>& N, const std::vector<T>& a, const std::vector<T>& b) {
  Node<T> out = N;
  const std::size_t n = N.lo.size();
  for (std::size_t l = 0; l < n; ++l) {
    for (auto& g : out.f) g = bern_restrict(g, static_cast<int>(l), a[l], b[l]);
    const T w = N.hi[l] - N.lo[l];
    out.lo[l] = N.lo[l] + w * a[l];
    out.hi[l] = N.lo[l] + w * b[l];
  }
  return out;
}

template <class T>
T round_dyadic(const T& x, int bits, bool down) {
  if constexpr (std::is_same_v<T, Rational>)
    return round_to_dyadic(x, bits, down);
  else {
    (void)bits;
    (void)down;
    return x;
  }
}

/// Shrinks the box of a node holding exactly one root (certified) by X <- K(X) with X: every zero
/// in X lies in K(X), so the root stays inside, and no further test is needed.
template <class T>
Node<T> refine(Node<T> N, std::vector<T> klo, std::vector<T> khi, const std::vector<T>& width0, int bits) {
  const std::size_t n = N.lo.size();
  for (int it = 0; it < 12; ++it) {
    // Clip K to [0, 1] and round outward (dyadic, a little finer than the box).
    bool small = true;
    for (std::size_t l = 0; l < n; ++l) {
      klo[l] = tmax(klo[l], T(0));
      khi[l] = tmin(khi[l], T(1));
      const double w = dbl(T(khi[l] - klo[l]));
      const int e = w > 0 ? std::max(8, 8 - static_cast<int>(std::floor(std::log2(w)))) : 8;
      klo[l] = tmax(round_dyadic(klo[l], e, true), T(0));
      khi[l] = tmin(round_dyadic(khi[l], e, false), T(1));
      if (klo[l] == khi[l]) {
        // K pinned this coordinate exactly (a dyadic value, e.g. where an equation is linear in
        // it): one step of 2^-e either side keeps the root strictly inside and the box proper.
        T step(1);
        for (int b = 0; b < e; ++b) step /= T(2);
        klo[l] = tmax(T(klo[l] - step), T(0));
        khi[l] = tmin(T(khi[l] + step), T(1));
      }
      if (!(klo[l] < khi[l])) return N;  // a box of width 0 (double's rounding): keep the last one
    }
    const bool progress = [&] {
      for (std::size_t l = 0; l < n; ++l)
        if (T(0) < klo[l] || khi[l] < T(1)) return true;
      return false;
    }();
    if (!progress) break;
    N = restrict_node(N, klo, khi);
    for (std::size_t l = 0; l < n; ++l)
      small = small && dbl(T(N.hi[l] - N.lo[l])) <= std::ldexp(dbl(width0[l]), -bits);
    if (small) break;
    const auto K = krawczyk(N.f, N.lo.size(), false);
    if (K.outcome == KrawczykResult<T>::unknown) break;
    klo = K.lo;
    khi = K.hi;
  }
  return N;
}

/// Looks for an exact rational root in the node's box: the simplest rational numbers near
/// Newton's estimate (in double) and in the box itself, checked by exact evaluation.
template <class T>
bool recognize(const Node<T>& N, std::vector<T>& point) {
  if constexpr (!std::is_same_v<T, Rational>) {
    (void)N;
    (void)point;
    return false;
  } else {
    const std::size_t n = N.lo.size();
    auto check = [&](const std::vector<Rational>& x) {
      std::vector<Rational> t(n);
      for (std::size_t l = 0; l < n; ++l) {
        if (x[l] < N.lo[l] || N.hi[l] < x[l]) return false;
        const Rational w = N.hi[l] - N.lo[l];
        t[l] = w == 0 ? Rational(0) : Rational((x[l] - N.lo[l]) / w);
      }
      for (std::size_t i = 0; i < n; ++i)
        if (bern_value(N.f[i], t) != 0) return false;
      point = x;
      return true;
    };
    // The simplest point of the box.
    std::vector<Rational> x(n);
    for (std::size_t l = 0; l < n; ++l) x[l] = simplest_rational_between(N.lo[l], N.hi[l]);
    if (check(x)) return true;
    // Newton in double on the local polynomials from the centre.
    std::vector<Bernstein<double>> fd(n);  // each equation scaled by a power of 2 into double's range
    for (std::size_t i = 0; i < n; ++i) {
      fd[i].deg = N.f[i].deg;
      const Rational s = pow2<Rational>(-scale_exponent(N.f[i].c));
      for (const auto& v : N.f[i].c) fd[i].c.push_back(to_double(Rational(v * s)));
    }
    std::vector<std::vector<Bernstein<double>>> dfd(n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) dfd[i].push_back(bern_derivative(fd[i], static_cast<int>(j)));
    std::vector<double> t(n, 0.5);
    for (int it = 0; it < 60; ++it) {
      Eigen::VectorXd F(n);
      Eigen::MatrixXd J(n, n);
      for (std::size_t i = 0; i < n; ++i) {
        F(i) = bern_value(fd[i], t);
        for (std::size_t j = 0; j < n; ++j) J(i, j) = bern_value(dfd[i][j], t);
      }
      if (!F.allFinite() || !J.allFinite()) return false;
      if (F.norm() == 0) break;
      const Eigen::VectorXd d = J.fullPivLu().solve(F);
      if (!d.allFinite()) break;
      for (std::size_t l = 0; l < n; ++l) t[l] = std::clamp(t[l] - d(l), -0.5, 1.5);
      if (d.lpNorm<Eigen::Infinity>() < 1e-17) break;
    }
    for (std::size_t l = 0; l < n; ++l) {
      if (!std::isfinite(t[l])) return false;
      const Rational w = N.hi[l] - N.lo[l];
      const Rational xl = N.lo[l] + w * exact_from_double(t[l], "newton");
      const Rational tol = w * Rational(1, 1 << 30) + Rational(1, 1) / Rational(boost::multiprecision::mpz_int(1) << 200);
      x[l] = simplest_rational_between(xl - tol, xl + tol);
    }
    return check(x);
  }
}

template <class T>
bool boxes_touch(const std::vector<T>& alo, const std::vector<T>& ahi, const std::vector<T>& blo, const std::vector<T>& bhi) {
  for (std::size_t l = 0; l < alo.size(); ++l)
    if (ahi[l] < blo[l] || bhi[l] < alo[l]) return false;
  return true;
}
template <class T>
bool box_inside(const std::vector<T>& alo, const std::vector<T>& ahi, const std::vector<T>& blo, const std::vector<T>& bhi) {
  for (std::size_t l = 0; l < alo.size(); ++l)
    if (alo[l] < blo[l] || bhi[l] < ahi[l]) return false;
  return true;
}

template <class T>
RootBox<T> root_of(const Node<T>& N, bool unique, bool recognise) {
  RootBox<T> r;
  r.lo = N.lo;
  r.hi = N.hi;
  r.unique = unique;
  r.exact = recognise && recognize(N, r.point);
  if (!r.exact) {
    r.point.resize(N.lo.size());
    for (std::size_t l = 0; l < N.lo.size(); ++l) r.point[l] = (N.lo[l] + N.hi[l]) / T(2);
  }
  return r;
}

}  // namespace

Rational round_to_dyadic(const Rational& x, int bits, bool down) {
  using boost::multiprecision::mpz_int;
  const Rational scale = bits >= 0 ? Rational(mpz_int(1) << bits) : Rational(1) / Rational(mpz_int(1) << -bits);
  const Rational scaled = x * scale;
  mpz_int q = boost::multiprecision::numerator(scaled) / boost::multiprecision::denominator(scaled);  // toward zero
  if (down && scaled < Rational(q)) q -= 1;
  if (!down && Rational(q) < scaled) q += 1;
  return Rational(q) / scale;
}

template <class T>
void round_enclosure(T& lo, T& hi) {
  if constexpr (std::is_same_v<T, Rational>) {
    // 72 significant bits, from the exact exponent (values beyond double's range too), and finer
    // where the enclosure is narrower: rounding adds at most a quarter of its width (feet whose
    // d^2 differ by 2e-25 at d^2 = 1/2 stay apart).
    const int narrow = lo < hi ? static_cast<int>(2 - exponent_of(T(hi - lo))) : 0;
    const auto bits = [&](const T& x) { return x == 0 ? std::max(200, narrow) : std::max(static_cast<int>(72 - exponent_of(x)), narrow); };
    const bool nonnegative = !(lo < 0);
    const int blo = bits(lo), bhi = bits(hi);
    lo = round_to_dyadic(lo, blo, true);
    hi = round_to_dyadic(hi, bhi, false);
    if (nonnegative && lo < 0) lo = 0;
    if (solve_testing::planted(solve_testing::Plant::shrink_enclosure) && lo < hi) {
      // Planted: each end moved inward by one unit of its precision (past the unrounded bound).
      using boost::multiprecision::mpz_int;
      const auto unit = [](int b) -> Rational { return b >= 0 ? Rational(1) / Rational(mpz_int(1) << b) : Rational(mpz_int(1) << -b); };
      const T l2 = lo + unit(blo), h2 = hi - unit(bhi);
      if (!(h2 < l2)) {
        lo = l2;
        hi = h2;
        solve_testing::plant_hit();
      }
    }
  } else {
    (void)lo;
    (void)hi;
  }
}
template void round_enclosure(Rational&, Rational&);
template void round_enclosure(double&, double&);
template void round_enclosure(Mpfr&, Mpfr&);

Rational simplest_rational_between(const Rational& a, const Rational& b) {
  if (b < a) return simplest_rational_between(b, a);
  if (!(0 < a) && !(b < 0)) return Rational(0);
  if (b < 0) return Rational(-simplest_rational_between(Rational(-b), Rational(-a)));
  // 0 < a <= b: a continued-fraction step.
  using boost::multiprecision::mpz_int;
  const mpz_int fl = boost::multiprecision::numerator(a) / boost::multiprecision::denominator(a);  // floor (a > 0)
  const Rational n(fl);
  if (n == a) return a;
  if (!(b < n + 1)) return Rational(n + 1);
  return Rational(n + Rational(1) / simplest_rational_between(Rational(1) / (b - n), Rational(1) / (a - n)));
}

template <class T>
bool SolveResult<T>::complete() const {
  if (!undecided.empty() || budget_exhausted) return false;
  for (const auto& r : roots)
    if (!r.unique) return false;
  return true;
}

/// The 2^n halves of a node in every direction, emitted last first (so that a depth-first walk
/// examines them in the order of their flat index).
template <class T, class Emit>
void halve_every_direction(Node<T>&& N, std::size_t n, Emit&& emit) {
  const std::size_t count = std::size_t{1} << n;
  std::vector<std::vector<Bernstein<T>>> parts(count);
  for (const auto& g : N.f) {  // every polynomial in the n unknowns (check_system), halved in all n at once
    if (g.deg.size() != n) throw std::logic_error("halve_every_direction: a polynomial not in the n unknowns");
    auto h = bern_halves(g);
    for (std::size_t K = 0; K < count; ++K) parts[K].push_back(std::move(h[K]));
  }
  // Part K's box: side (K >> (n-1-l)) & 1 of the midpoint in direction l (bern_halves' order).
  const T half = T(1) / T(2);
  std::vector<T> mid(n);
  for (std::size_t l = 0; l < n; ++l) mid[l] = (N.lo[l] + N.hi[l]) * half;
  for (std::size_t K = count; K-- > 0;) {
    std::vector<T> lo = N.lo, hi = N.hi;
    for (std::size_t l = 0; l < n; ++l) ((K >> (n - 1 - l)) & 1 ? lo[l] : hi[l]) = mid[l];
    emit(Node<T>{std::move(parts[K]), std::move(lo), std::move(hi), N.depth + 1});
  }
}

namespace {

/// ValidationError (UsageError for the depth) unless f is n polynomials in n unknowns, none
/// identically zero, on a box with no empty side.
template <class T>
void check_system(const std::vector<Bernstein<T>>& f, const std::vector<T>& lo, const std::vector<T>& hi, const SolveOptions& options) {
  const std::size_t n = f.size();
  if (n == 0) throw ValidationError("system", "has no equations", "give n equations in n unknowns");
  if (lo.size() != n || hi.size() != n)
    throw ValidationError("system", "has " + std::to_string(n) + " equations but a box of " + std::to_string(lo.size()) + " unknowns",
                          "give as many equations as unknowns");
  for (std::size_t i = 0; i < n; ++i) {
    if (f[i].deg.size() != n || f[i].c.size() != detail::tensor_size(f[i].deg))
      throw ValidationError("system[" + std::to_string(i) + "]", "is not a polynomial in the n unknowns",
                            "give Bernstein coefficients for every multi-index");
    bool zero = true;
    for (const auto& x : f[i].c) zero = zero && x == T(0);
    if (zero)
      throw ValidationError("system[" + std::to_string(i) + "]",
                            "is identically zero: the system is degenerate (its zeros are not isolated)",
                            "remove the equation or give a system whose solutions are points");
  }
  for (std::size_t l = 0; l < n; ++l)
    if (!(lo[l] < hi[l])) throw ValidationError("box", "has an empty side", "give lo < hi in every unknown");
  if (options.max_depth < 1 || options.max_depth > 200) throw UsageError("max-depth", "must be in [1, 200]", "use e.g. 30");
}

/// What the steps of one solve share: the system's box, the options, the answer so far, and what
/// the search hands on to the clusters.
template <class T>
struct SolveRun {
  std::size_t n;             // equations and unknowns
  const std::vector<T>& lo;  // the system's box
  const std::vector<T>& hi;
  const SolveOptions& options;
  const Pruning<T>* pruning;
  std::vector<T> width0;  // the box's widths
  SolveResult<T> out;
  std::vector<Bernstein<T>> all;  // the equations and the auxiliary polynomials, split together
  std::vector<Node<T>> leaves;
  std::vector<Node<T>> certified;  // refined boxes with one root each
  std::vector<RootBox<T>> known;   // exact roots certified unique in their boxes during the search
  int recognitions = 0;
};

/// Roots on split lines: an exact rational root in the open box N (recognized), certified as the
/// only root of the box around it (twice N's width) by a contraction there, is listed as known.
template <class T>
void look_for_exact_root(SolveRun<T>& s, const Node<T>& N) {
  const std::size_t n = s.n;
  ++s.recognitions;  // a budget: a curve of solutions would otherwise try every other box
  std::vector<T> r;
  bool fresh = recognize(N, r);
  for (const auto& k : s.known) fresh = fresh && !box_inside(r, r, k.lo, k.hi);
  if (fresh) {
    std::vector<T> a(n), b(n), c(n);
    for (std::size_t l = 0; l < n; ++l) {
      const T w = N.hi[l] - N.lo[l];
      const T x0 = tmax(T(r[l] - w), s.lo[l]), x1 = tmin(T(r[l] + w), s.hi[l]);
      a[l] = (x0 - s.lo[l]) / s.width0[l];
      b[l] = (x1 - s.lo[l]) / s.width0[l];
      c[l] = (r[l] - x0) / (x1 - x0);
    }
    const Node<T> X = restrict_node(Node<T>{s.all, s.lo, s.hi, 0}, a, b);
    bool contraction = krawczyk(X.f, n, false, c).contraction;
    if (!contraction && solve_testing::planted(Plant::skip_krawczyk_contraction_known)) {
      contraction = true;  // planted: the exact root taken as the box's only root without the test
      solve_testing::plant_hit();
    }
    if (contraction) {
      RootBox<T> rb;
      rb.lo = X.lo;
      rb.hi = X.hi;
      rb.unique = rb.exact = true;
      rb.point = r;
      s.known.push_back(rb);
      s.out.roots.push_back(rb);
    }
  }
}

/// One box of the search: 1. sign, the caller's pruning and the boxes of known exact roots;
/// 2. Krawczyk; 3. otherwise split.
template <class T>
Examined examine_box(SolveRun<T>& s, Node<T>& N) {
  const std::size_t n = s.n;
  bool discarded = false;
  for (std::size_t i = 0; i < n; ++i)
    if (bern_sign(N.f[i]) != 0) discarded = true;
  if (discarded) {
    ++s.out.discarded_by_sign;
    return Examined::settled;
  }
  if (s.pruning && s.pruning->discard(N.f.data() + n, s.pruning->aux.size(), N.lo, N.hi)) {
    ++s.out.discarded_by_caller;
    return Examined::settled;
  }
  // Inside the box of a known exact root, which is that box's only root: nothing more here.
  bool in_known = false;
  for (const auto& k : s.known) in_known = in_known || box_inside(N.lo, N.hi, k.lo, k.hi);
  if (in_known) {
    ++s.out.discarded_by_krawczyk;
    return Examined::settled;
  }
  const auto K = krawczyk(N.f, n, true);
  if (K.outcome == KrawczykResult<T>::excluded) {
    ++s.out.discarded_by_krawczyk;
    return Examined::settled;
  }
  if (K.outcome == KrawczykResult<T>::unique) {
    bool seen = false;  // its one root is a known exact root it contains
    for (const auto& k : s.known) seen = seen || box_inside(k.point, k.point, N.lo, N.hi);
    if (!seen) s.certified.push_back(refine(N, K.lo, K.hi, s.width0, s.options.refine_bits));
    return Examined::settled;
  }
  // A root where boxes are split (on the line between them) keeps every box around it open down
  // to the depth limit. Look for an exact rational root now and then: a contraction on the box
  // around it (twice this box's width) makes it that box's only root, and the search then skips
  // what lies inside.
  if (s.options.recognize_rationals && N.depth >= 2 && N.depth % 2 == 0 && s.recognitions < 256) look_for_exact_root(s, N);
  return Examined::split;
}

/// The subdivision of the system's box: certified roots into the answer, the boxes left open
/// (at the depth limit, or when the budget is spent) into `leaves`.
template <class T>
void search_roots(SolveRun<T>& s) {
  const std::size_t n = s.n;
  auto examine = [&](Node<T>& N, int) { return examine_box(s, N); };
  auto split = [&](Node<T>&& N, int, auto&& emit) { halve_every_direction(std::move(N), n, emit); };
  // A box left (the depth reached, or the budget spent) is enough as it is: clusters restrict anew.
  bool dropped = false;
  auto leave = [&](Node<T>&& N, Left why) {
    if (why == Left::boxes && solve_testing::planted(Plant::drop_box)) {  // planted: the unfinished queue forgotten
      if (!dropped) solve_testing::plant_hit();
      dropped = true;
      return;
    }
    s.leaves.push_back(Node<T>{{}, std::move(N.lo), std::move(N.hi), N.depth});
  };
  Budget budget;
  budget.max_boxes = s.options.max_boxes;
  budget.max_depth = s.options.max_depth;
  std::vector<Node<T>> roots{Node<T>{s.all, s.lo, s.hi, 0}};
  const Subdivision run =
      subdivide(std::move(roots), Walk{Order::depth_first, n < 64 ? std::size_t(1) << n : std::numeric_limits<std::size_t>::max(), false},
                budget, examine, split, leave);
  s.out.boxes = run.examined;
  s.out.budget_exhausted = run.stop == Subdivision::Stop::boxes;
  for (const auto& N : s.certified) {
    // Found before a known exact root whose box holds it: the same root.
    bool seen = false;
    for (const auto& k : s.known) seen = seen || (box_inside(k.point, k.point, N.lo, N.hi) || box_inside(N.lo, N.hi, k.lo, k.hi));
    if (!seen) s.out.roots.push_back(root_of(N, true, s.options.recognize_rationals));
  }
}

/// Clusters of touching leaves (a sweep along direction 0), as indices into `leaves`.
template <class T>
std::vector<std::vector<std::size_t>> cluster_leaves(const std::vector<Node<T>>& leaves) {
  std::vector<std::size_t> order(leaves.size()), parent(leaves.size());
  std::iota(order.begin(), order.end(), 0);
  std::iota(parent.begin(), parent.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return leaves[a].lo[0] < leaves[b].lo[0]; });
  const auto find = [&](std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (std::size_t i = 0; i < order.size() && leaves.size() <= 2000; ++i)
    for (std::size_t j = i + 1; j < order.size() && !(leaves[order[i]].hi[0] < leaves[order[j]].lo[0]); ++j)
      if (boxes_touch(leaves[order[i]].lo, leaves[order[i]].hi, leaves[order[j]].lo, leaves[order[j]].hi))
        parent[find(order[i])] = find(order[j]);
  std::vector<std::vector<std::size_t>> clusters;
  if (leaves.size() > 2000) {
    // Too many to join pairwise: one undecided hull around all of them.
    clusters.emplace_back(leaves.size());
    std::iota(clusters[0].begin(), clusters[0].end(), 0);
  } else {
    std::vector<long> index(leaves.size(), -1);
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      const std::size_t r = find(i);
      if (index[r] < 0) {
        index[r] = static_cast<long>(clusters.size());
        clusters.emplace_back();
      }
      clusters[index[r]].push_back(i);
    }
  }
  return clusters;
}

/// Planted (solve/testing.hpp): K(X) in the closed hull taken as one root without the contraction.
template <class T>
void skip_contraction(KrawczykResult<T>& k) {
  if (solve_testing::planted(Plant::skip_krawczyk_contraction_merged) && k.outcome == KrawczykResult<T>::unknown && k.inside_closed) {
    k.outcome = KrawczykResult<T>::unique;
    solve_testing::plant_hit();
  }
}

/// The closed test on a cluster's hull H (local box [a, b] of the system's root node), and on the
/// hull inflated when it fails. True when that settles the hull: no root, or its one root listed
/// (now, or before); false when the hull is left to `exact_root_in_hull`.
template <class T>
bool closed_test(SolveRun<T>& s, const Node<T>& root, const Node<T>& H, const std::vector<T>& a, const std::vector<T>& b) {
  const std::size_t n = s.n;
  auto K = s.out.budget_exhausted ? KrawczykResult<T>{} : krawczyk(H.f, n, false);
  skip_contraction(K);
  if (K.outcome == KrawczykResult<T>::excluded) return true;
  Node<T> G = H;  // the box the test speaks of
  if (K.outcome == KrawczykResult<T>::unknown && !s.out.budget_exhausted) {
    // Epsilon-inflation (Rump): a root 1e-25 from a face of the hull (just beside a split line)
    // is never inside K(X) of so small a hull; the hull widened by its width on each side
    // (within the system's box) can hold it well inside.
    std::vector<T> a2(n), b2(n);
    for (std::size_t l = 0; l < n; ++l) {
      const T w = b[l] - a[l];
      a2[l] = tmax(T(a[l] - w), T(0));
      b2[l] = tmin(T(b[l] + w), T(1));
    }
    Node<T> H2 = restrict_node(root, a2, b2);
    auto K2 = krawczyk(H2.f, n, false);
    skip_contraction(K2);
    if (K2.outcome == KrawczykResult<T>::excluded) return true;
    if (K2.outcome == KrawczykResult<T>::unique) {
      K = K2;
      G = std::move(H2);
    }
  }
  if (K.outcome == KrawczykResult<T>::unique) {
    const Node<T> R = refine(G, K.lo, K.hi, s.width0, s.options.refine_bits);
    // A certified root already found in the hull is this one; one that may straddle it is
    // left undecided.
    bool same = false, unclear = false;
    for (const auto& r : s.out.roots) {
      if (r.exact) {  // a known exact root: the hull's one root if the hull holds it
        same = same || box_inside(r.point, r.point, G.lo, G.hi);
        continue;
      }
      if (!boxes_touch(r.lo, r.hi, G.lo, G.hi)) continue;
      if (box_inside(r.lo, r.hi, G.lo, G.hi))
        same = true;
      else
        unclear = true;
    }
    if (same && !unclear) return true;
    if (!unclear) {
      s.out.roots.push_back(root_of(R, true, s.options.recognize_rationals));
      return true;
    }
  }
  return false;
}

/// A hull the closed test left open: undecided, and an exact root in it listed (certified simple
/// when Krawczyk about it contracts the hull).
template <class T>
void exact_root_in_hull(SolveRun<T>& s, const Node<T>& H) {
  const std::size_t n = s.n;
  RootBox<T> u = root_of(H, false, s.options.recognize_rationals);
  if (u.exact) {
    // Krawczyk about the exact root r (F(r) = 0): a contraction on the hull means r is its only
    // root, and a simple one.
    std::vector<T> c(n);
    for (std::size_t l = 0; l < n; ++l) c[l] = (u.point[l] - H.lo[l]) / (H.hi[l] - H.lo[l]);
    const auto Kr = krawczyk(H.f, n, false, c);
    u.unique = Kr.contraction;
    if (!u.unique && solve_testing::planted(Plant::skip_krawczyk_contraction_merged)) {
      u.unique = true;  // planted: the hull's exact root taken as its only, simple root without the test
      solve_testing::plant_hit();
    }
  }
  // An exact root that is not certified simple is a root of unknown multiplicity, and its hull
  // stays undecided (it may hold more). One found before is not listed twice.
  bool listed = false;
  for (const auto& r : s.out.roots) listed = listed || (u.exact && r.exact && r.point == u.point);
  if (u.exact && !listed) s.out.roots.push_back(u);
  if (!u.unique) s.out.undecided.push_back(std::move(u));
}

/// Undecided leaves: clusters of touching boxes, then the closed test on each cluster's hull.
template <class T>
void decide_clusters(SolveRun<T>& s) {
  const std::size_t n = s.n;
  const std::vector<std::vector<std::size_t>> clusters = cluster_leaves(s.leaves);
  const Node<T> root{s.all, s.lo, s.hi, 0};
  for (const auto& members : clusters) {
    std::vector<T> clo = s.leaves[members[0]].lo, chi = s.leaves[members[0]].hi;
    for (std::size_t m : members)
      for (std::size_t l = 0; l < n; ++l) {
        clo[l] = tmin(clo[l], s.leaves[m].lo[l]);
        chi[l] = tmax(chi[l], s.leaves[m].hi[l]);
      }
    std::vector<T> a(n), b(n);
    for (std::size_t l = 0; l < n; ++l) {
      a[l] = (clo[l] - s.lo[l]) / s.width0[l];
      b[l] = (chi[l] - s.lo[l]) / s.width0[l];
    }
    const Node<T> H = restrict_node(root, a, b);
    if (!closed_test(s, root, H, a, b)) exact_root_in_hull(s, H);
  }
}

}  // namespace

template <class T>
SolveResult<T> solve_system(const std::vector<Bernstein<T>>& f, const std::vector<T>& lo, const std::vector<T>& hi,
                            const SolveOptions& options, const Pruning<T>* pruning) {
  check_system(f, lo, hi, options);
  const std::size_t n = f.size();
  SolveRun<T> s{n, lo, hi, options, pruning, std::vector<T>(n), {}, f, {}, {}, {}, 0};
  for (std::size_t l = 0; l < n; ++l) s.width0[l] = hi[l] - lo[l];
  if (pruning) {
    for (const auto& g : pruning->aux)
      if (g.deg.size() != n || g.c.size() != detail::tensor_size(g.deg))
        throw ValidationError("pruning", "an auxiliary polynomial is not in the n unknowns", "give it on the system's box");
    s.all.insert(s.all.end(), pruning->aux.begin(), pruning->aux.end());
  }
  search_roots(s);
  // Undecided leaves: clusters of touching boxes (a sweep along direction 0), then the closed test
  // on each cluster's hull.
  decide_clusters(s);
  return std::move(s.out);
}

template struct SolveResult<Rational>;
template struct SolveResult<double>;
template struct SolveResult<Mpfr>;
template SolveResult<Rational> solve_system(const std::vector<Bernstein<Rational>>&, const std::vector<Rational>&, const std::vector<Rational>&,
                                            const SolveOptions&, const Pruning<Rational>*);
template SolveResult<double> solve_system(const std::vector<Bernstein<double>>&, const std::vector<double>&, const std::vector<double>&,
                                          const SolveOptions&, const Pruning<double>*);
template SolveResult<Mpfr> solve_system(const std::vector<Bernstein<Mpfr>>&, const std::vector<Mpfr>&, const std::vector<Mpfr>&, const SolveOptions&,
                                        const Pruning<Mpfr>*);

}  // namespace splinex
