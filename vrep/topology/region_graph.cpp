// The connected pieces of a region's part of a face of a trivariate's domain, from a certified
// subdivision (vrep/topology/curve_graph.hpp: count_region states the method), instantiated for Rational
// and double.
//
// Why a resolved box's pieces are what this file says. In a box B (a rectangle) let C_k be the
// zero set of a leaf k whose sign matters there. When one partial derivative of g_k has a strict
// sign on B and g_k has exactly two simple roots on B's boundary (none at a corner), C_k is one
// arc from boundary to boundary: every component of C_k is monotone along that direction, so it
// is an arc with both ends on the boundary (no loop), and there are two ends. By Mayer-Vietoris
// for B = {g_k >= 0} u {g_k <= 0} (H_1(B) = 0, H~_0(B) = 0), H~_0(C_k) = H~_0 of the two sides,
// and H_1 of each side is 0: both sides are connected and acyclic. A second such leaf l with
// det(grad g_k, grad g_l) of strict sign on B is monotone along C_k and g_k along C_l, so C_l meets
// each side of C_k in one arc (or not at all) and the same argument splits each side again: every
// sign pattern of (g_k, g_l) that occurs in B occurs on one connected, acyclic face of the
// arrangement. Every face meets B's boundary in an interval of positive length (a face away from
// the boundary would be enclosed by arcs meeting twice), so the patterns that occur are exactly
// those seen between consecutive roots on the boundary, and two faces share an arc of positive
// length exactly when their patterns differ in one sign (three faces when the arcs do not cross,
// four around the crossing when they do). The region's interior in B is the union of the faces
// whose pattern makes the formula true; its pieces are the components of those faces under that
// adjacency.
#include <algorithm>
#include <deque>
#include <optional>

#include "base/errors.hpp"
#include "vrep/model/brackets.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/topology/box_components.hpp"
#include "vrep/topology/curve_graph.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"

namespace splinex {

namespace {

using namespace vrep_detail;

/// One side of a resolved box: the roots along it of the leaves that matter in the box, in
/// increasing order of the running coordinate, and the piece of the box each gap between them
/// (and the side's ends) belongs to (-1: outside the region).
template <class T>
struct Side {
  std::vector<Root<T>> roots;
  std::vector<int> gap;
};

template <class T>
struct Resolved {
  std::array<T, 2> lo, hi;
  int pieces = 0;
  std::array<Side<T>, 4> sides;  // side index 2 d + s: x_d at its lower (s = 0) or upper end
  std::size_t first = 0;          // its pieces' numbers in the union-find
};

template <class T>
class RegionRun {
 public:
  RegionRun(const CurveProblem<T, 2>& p, const T& frac) : P(p), frac_(frac), nl_(p.pieces.empty() ? 0 : p.pieces.front().G.size()) {}

  bool run(RegionCount& out) {
    using Open = PolynomialBox<T, 2>;
    std::vector<Open> roots;
    for (const auto& pc : P.pieces) roots.push_back({pc.lo, pc.hi, pc.G, 0});
    auto examine_box = [&](Open& B, int) {
      Resolved<T> r;
      r.lo = B.lo;
      r.hi = B.hi;
      if (examine(B.G, r) != 1) return Examined::split;
      if (r.pieces > 0) done_.push_back(std::move(r));
      return Examined::settled;
    };
    auto split = [&](Open&& B, int, auto&& emit) {
      Open c[2];
      split_box(B, widest(B.lo, B.hi), frac_, c);
      emit(std::move(c[0]));
      emit(std::move(c[1]));
    };
    const Subdivision run =
        subdivide(std::move(roots), Walk{Order::breadth_first, 2, true}, attempt_budget(P.options), examine_box, split, [](Open&&, Left) {});
    if (!count_run(run, P.options,
                   "a box at the deepest level is still open (a trimming curve is singular or tangent to a split line there, or more than two curves meet)",
                   out))
      return false;
    return graph(out);
  }

 private:
  const CurveProblem<T, 2>& P;
  T frac_;
  std::size_t nl_;
  std::vector<Resolved<T>> done_;

  Truth truth(const std::vector<Truth>& t) const {
    std::size_t k = 0;
    return combine(*P.trim, t, k);
  }

  /// 1: resolved (r filled), 0: split it.
  int examine(const std::vector<Bernstein<T>>& G, Resolved<T>& r) {
    std::vector<Truth> t(nl_);
    std::vector<std::size_t> mixed;
    for (std::size_t l = 0; l < nl_; ++l) {
      const int s = bern_sign(G[l]);
      t[l] = s > 0 ? Truth::in : s < 0 ? Truth::out : Truth::mixed;
      if (s == 0) mixed.push_back(l);
    }
    for (;;) {
      if (mixed.size() > 6) return 0;
      // The leaves that matter: flipping one changes the formula for some pattern of the others.
      std::vector<Truth> value(std::size_t(1) << mixed.size()), tt = t;
      for (std::size_t p = 0; p < value.size(); ++p) {
        for (std::size_t q = 0; q < mixed.size(); ++q) tt[mixed[q]] = (p >> q) & 1 ? Truth::in : Truth::out;
        value[p] = truth(tt);
      }
      std::vector<std::size_t> matter;
      for (std::size_t q = 0; q < mixed.size(); ++q) {
        bool m = false;
        for (std::size_t p = 0; p < value.size(); ++p) m = m || value[p] != value[p ^ (std::size_t(1) << q)];
        if (m) matter.push_back(mixed[q]);
      }
      if (matter.empty()) {
        if (value[0] == Truth::in) {  // the whole box
          r.pieces = 1;
          for (auto& s : r.sides) s.gap = {0};
        }
        return 1;
      }
      if (matter.size() > 2) return 0;
      // Each leaf that matters: one arc through the box, or none (then it has one sign here).
      std::vector<std::size_t> keep;
      bool fixed = false;
      for (std::size_t l : matter) {
        int corner = 0;
        const std::size_t n0 = static_cast<std::size_t>(G[l].deg[0]), n1 = static_cast<std::size_t>(G[l].deg[1]);
        for (std::size_t s0 = 0; s0 < 2; ++s0)
          for (std::size_t s1 = 0; s1 < 2; ++s1) {
            const T& v = G[l].c[s0 * n0 + s1 * n1 * (n0 + 1)];
            if (v == T(0)) return 0;
            corner = sign_of(v);
          }
        if (bern_sign(bern_derivative(G[l], 0)) == 0 && bern_sign(bern_derivative(G[l], 1)) == 0) return 0;
        std::size_t n = 0;
        for (int d = 0; d < 2; ++d)
          for (int s = 0; s < 2; ++s) {
            std::vector<std::pair<T, T>> roots;
            if (!isolate(bern_face(G[l], d, s), T(0), T(1), 48, roots)) return 0;
            n += roots.size();
          }
        if (n == 0) {  // monotone and no crossing: no zero in the box
          t[l] = corner > 0 ? Truth::in : Truth::out;
          fixed = true;
          continue;
        }
        // (Planted, tests only: vrep/model/planted.hpp takes any number of boundary roots for one arc.)
        if (n != 2 && !vrep_testing::is_planted(vrep_testing::Plant::region_arc_unchecked)) return 0;
        keep.push_back(l);
      }
      if (fixed) {
        std::vector<std::size_t> next;
        for (std::size_t l : mixed)
          if (t[l] == Truth::mixed) next.push_back(l);
        mixed = std::move(next);
        continue;
      }
      return arrange(G, t, mixed, keep, r);
    }
  }

  /// The arrangement of the one or two arcs `keep` (the other mixed leaves do not matter): the
  /// sign patterns on the boundary, the faces and pieces.
  int arrange(const std::vector<Bernstein<T>>& G, std::vector<Truth> t, const std::vector<std::size_t>& mixed, const std::vector<std::size_t>& keep,
              Resolved<T>& r) {
    if (keep.size() == 2) {
      const Bernstein<T> det = bern_sub(bern_product(bern_derivative(G[keep[0]], 0), bern_derivative(G[keep[1]], 1)),
                                     bern_product(bern_derivative(G[keep[0]], 1), bern_derivative(G[keep[1]], 0)));
      if (bern_sign(det) == 0) return 0;
    }
    // The patterns of the kept leaves (bit q: leaf keep[q] > 0) that make the formula true; the
    // leaves that do not matter at any value.
    for (std::size_t l : mixed) t[l] = Truth::out;
    auto true_for = [&](unsigned pattern) {
      for (std::size_t q = 0; q < keep.size(); ++q) t[keep[q]] = (pattern >> q) & 1 ? Truth::in : Truth::out;
      return truth(t) == Truth::in;
    };
    unsigned present = 0;
    for (int d = 0; d < 2; ++d)
      for (int s = 0; s < 2; ++s) {
        const int idx = 2 * d + s, e = 1 - d;
        Side<T>& side = r.sides[static_cast<std::size_t>(idx)];
        std::vector<Bernstein<T>> f;
        for (std::size_t l : keep) f.push_back(bern_face(G[l], d, s));
        const T L = r.lo[static_cast<std::size_t>(e)], H = r.hi[static_cast<std::size_t>(e)];
        for (std::size_t q = 0; q < keep.size(); ++q) {
          std::vector<std::pair<T, T>> iso;
          isolate(f[q], T(0), T(1), 48, iso);
          for (const auto& [a, b] : iso) side.roots.push_back({keep[q], f[q], L, H, L + a * (H - L), L + b * (H - L)});
        }
        // In increasing order, brackets disjoint (a root of both leaves on a side: split).
        for (std::size_t i = 0; i < side.roots.size(); ++i)
          for (std::size_t j = i + 1; j < side.roots.size(); ++j) {
            const auto c = compare(side.roots[i], side.roots[j], true);
            if (!c || *c == 0) return 0;
            if (*c > 0) std::swap(side.roots[i], side.roots[j]);
          }
        auto apart = [](const Root<T>& a, const Root<T>& b) { return a.hi < b.lo || (a.hi == b.lo && !a.exact() && !b.exact()); };
        for (std::size_t i = 0; i + 1 < side.roots.size(); ++i) {
          for (int k = 0; k < kRefine && !apart(side.roots[i], side.roots[i + 1]); ++k) {
            const T m = (side.roots[i + 1].lo + side.roots[i].hi) / 2;
            side.roots[i].cut(m);
            side.roots[i + 1].cut(m);
            if (side.roots[i].exact() && side.roots[i + 1].exact() && side.roots[i].lo == side.roots[i + 1].lo) return 0;
          }
          if (!apart(side.roots[i], side.roots[i + 1])) return 0;
        }
        // The pattern of each gap at an exact point of it (a side's ends are corners: no root).
        for (std::size_t g = 0; g <= side.roots.size(); ++g) {
          const T at = g == 0 ? L : g == side.roots.size() ? H : (side.roots[g - 1].hi + side.roots[g].lo) / 2;
          unsigned pattern = 0;
          for (std::size_t q = 0; q < keep.size(); ++q) {
            const int sg = sign_of(bern_value(f[q], {(at - L) / (H - L)}));
            if (sg == 0) return 0;
            if (sg > 0) pattern |= 1u << q;
          }
          side.gap.push_back(static_cast<int>(pattern));
          present |= 1u << pattern;
        }
      }
    // Faces: the patterns present; pieces: true faces joined when their patterns differ in one sign.
    std::array<int, 4> piece_of{-1, -1, -1, -1};
    UnionFind uf(4);
    for (unsigned a = 0; a < 4; ++a)
      for (unsigned b = a + 1; b < 4; ++b) {
        const unsigned x = a ^ b;
        if (((present >> a) & 1) && ((present >> b) & 1) && (x == 1 || x == 2) && true_for(a) && true_for(b)) uf.join(a, b);
      }
    int n = 0;
    for (unsigned a = 0; a < 4; ++a) {
      if (!((present >> a) & 1) || !true_for(a)) continue;
      const std::size_t root = uf.find(a);
      if (piece_of[root] < 0) piece_of[root] = n++;
      piece_of[a] = piece_of[root];
    }
    r.pieces = n;
    for (auto& side : r.sides)
      for (auto& g : side.gap) g = piece_of[static_cast<std::size_t>(g)];
    return 1;
  }

  /// Joins the pieces of boxes that share a side segment of positive length across the gaps that
  /// overlap there; counts the components.
  bool graph(RegionCount& out) {
    std::vector<std::array<T, 2>> lo, hi;
    std::vector<std::size_t> ids;
    const std::size_t total = number_pieces(done_, lo, hi, ids);
    UnionFind uf(total);
    for (const auto& [ia, ib] : touching_pairs(lo, hi, ids)) {
      for (int d = 0; d < 2; ++d) {
        const int e = 1 - d;
        std::size_t a = ia, b = ib;
        if (done_[b].hi[static_cast<std::size_t>(d)] == done_[a].lo[static_cast<std::size_t>(d)]) std::swap(a, b);
        if (!(done_[a].hi[static_cast<std::size_t>(d)] == done_[b].lo[static_cast<std::size_t>(d)])) continue;
        const T e0 = std::max(done_[a].lo[static_cast<std::size_t>(e)], done_[b].lo[static_cast<std::size_t>(e)]);
        const T e1 = std::min(done_[a].hi[static_cast<std::size_t>(e)], done_[b].hi[static_cast<std::size_t>(e)]);
        if (!(e0 < e1)) continue;
        Side<T>& sa = done_[a].sides[static_cast<std::size_t>(2 * d + 1)];
        Side<T>& sb = done_[b].sides[static_cast<std::size_t>(2 * d + 0)];
        for (std::size_t ga = 0; ga < sa.gap.size(); ++ga)
          for (std::size_t gb = 0; gb < sb.gap.size(); ++gb) {
            // The gaps' ends and the common segment's: they overlap when every lower end is below
            // every upper end.
            Bound<T> lower[3] = {ga == 0 ? Bound<T>{nullptr, done_[a].lo[static_cast<std::size_t>(e)]} : Bound<T>{&sa.roots[ga - 1], T(0)},
                                 gb == 0 ? Bound<T>{nullptr, done_[b].lo[static_cast<std::size_t>(e)]} : Bound<T>{&sb.roots[gb - 1], T(0)},
                                 Bound<T>{nullptr, e0}};
            Bound<T> upper[3] = {ga == sa.roots.size() ? Bound<T>{nullptr, done_[a].hi[static_cast<std::size_t>(e)]} : Bound<T>{&sa.roots[ga], T(0)},
                                 gb == sb.roots.size() ? Bound<T>{nullptr, done_[b].hi[static_cast<std::size_t>(e)]} : Bound<T>{&sb.roots[gb], T(0)},
                                 Bound<T>{nullptr, e1}};
            bool overlap = true;
            for (auto& x : lower)
              for (auto& y : upper) {
                if (!overlap) break;
                const auto c = compare(x, y, true);
                if (!c) {
                  out.undecided_reason = "two trimming curves cross a split line at nearly the same point";
                  return false;
                }
                overlap = *c < 0;
              }
            if (!overlap) continue;
            const int pa = sa.gap[ga], pb = sb.gap[gb];
            if ((pa < 0) != (pb < 0)) {
              out.undecided_reason = "inconsistent: the region differs on the two sides of a split line (rounding?)";
              return false;
            }
            if (pa >= 0) uf.join(done_[a].first + static_cast<std::size_t>(pa), done_[b].first + static_cast<std::size_t>(pb));
          }
      }
    }
    std::vector<char> is_root(total, 0), on_id(total, 0);
    for (std::size_t i = 0; i < total; ++i) is_root[uf.find(i)] = 1;
    for (const auto& r : done_)
      for (int d = 0; d < 2; ++d)
        for (int s = 0; s < 2; ++s) {
          if (!P.identified[static_cast<std::size_t>(d)][static_cast<std::size_t>(s)]) continue;
          if (!(s ? r.hi[static_cast<std::size_t>(d)] == P.dom_hi[static_cast<std::size_t>(d)] : r.lo[static_cast<std::size_t>(d)] == P.dom_lo[static_cast<std::size_t>(d)]))
            continue;
          for (int g : r.sides[static_cast<std::size_t>(2 * d + s)].gap)
            if (g >= 0) on_id[uf.find(r.first + static_cast<std::size_t>(g))] = 1;
        }
    out.pieces = static_cast<std::size_t>(std::count(is_root.begin(), is_root.end(), 1));
    out.on_identified = static_cast<std::size_t>(std::count(on_id.begin(), on_id.end(), 1));
    out.decided = true;
    return true;
  }
};

}  // namespace

namespace vrep_detail {

template <class T>
RegionCount count_region(const CurveProblem<T, 2>& problem) {
  RegionCount out;
  for (const auto& p : problem.pieces)
    for (const auto& g : p.G)
      if (all_zero(g)) {
        out.undecided_reason = "a trimming surface's composition vanishes identically on the face";
        return out;
      }
  return retry_fractions<T>(problem.options.max_total_boxes, [&](const T& fraction, RegionCount& attempt) {
    RegionRun<T> run(problem, fraction);
    return run.run(attempt);
  });
}

template RegionCount count_region(const CurveProblem<Rational, 2>&);
template RegionCount count_region(const CurveProblem<double, 2>&);

}  // namespace vrep_detail

}  // namespace splinex
