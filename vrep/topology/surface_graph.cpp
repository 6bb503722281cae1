// The connected pieces of a trimming surface's part of a trimmed cell's boundary, from a certified
// subdivision (vrep/topology/curve_graph.hpp: count_surface states the method), instantiated for Rational
// and double.
//
// Why a resolved box's pieces are what this file says. In a box B let P = {g = 0} (g the leaf whose
// surface is counted), S = {g <= 0} and U = {g >= 0}. B = S u U, S n U = P, and H_1(B) = H_2(B) =
// H~_0(B) = 0, so Mayer-Vietoris gives H~_0(P) = H~_0(S) + H~_0(U) and H_1(P) = H_1(S) + H_1(U):
// P is connected and acyclic when S and U are contractible. A set X = {s g >= 0} n B with
// s dg/dx_d >= 0 on B deformation-retracts onto its face at the end of x_d where s g is larger
// (push along x_d: s g does not decrease), so X ~ X n F, one dimension down; on a segment X is
// contractible when it is one interval; on a rectangle also when {s h = 0} is one closed loop with
// X its inside (X one piece off the rectangle's boundary, its complement one piece: a disk). For a
// further leaf l whose curve C = {g = g_l = 0} n B is one arc or empty (a component of
// grad g x grad g_l of one strict sign: monotone, no loop; exactly two or no crossings with B's
// boundary), Mayer-Vietoris on P = (P n {g_l >= 0}) u (P n {g_l <= 0}) (H_1(P) = 0) makes both
// parts connected and acyclic; a second leaf m with det(grad g, grad g_l, grad g_m) of one strict
// sign crosses each part's arc at most once, so the four sign patterns' parts are connected too.
// Every such part meets B's boundary (P is a disk cut by proper arcs that cross at most once), so
// the patterns that occur on P are those seen on the traces of {g = 0} on B's six faces; parts
// whose patterns differ in one sign share an arc of C. The traces are resolved on each face by a
// 2D subdivision into rectangles where {g = 0} is one arc (a partial of one strict sign, two simple
// roots on the rectangle's boundary) crossed at most once by the one further leaf that changes
// sign there (2D determinant of one strict sign): the patterns at the arc's two ends are read off
// exactly (brackets refined until the leaf has one strict sign on them) and a crossing counted
// when they differ. Two boxes sharing a face part E of positive area join the parts whose
// patterns occur on the trace in E's interior.
#include <algorithm>
#include <deque>
#include <map>

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

/// +1 / -1: every coefficient >= 0 / <= 0 (weakly monotone), 0: neither.
template <class T>
int weak_sign(const Bernstein<T>& b) {
  bool pos = true, neg = true;
  for (const auto& x : b.c) {
    pos = pos && !(x < T(0));
    neg = neg && !(T(0) < x);
  }
  return pos ? 1 : neg ? -1 : 0;
}

enum class Shape { empty, contractible, unknown };

/// {s f >= 0} on [0, 1] (f univariate).
template <class T>
Shape shape1(const Bernstein<T>& f, int s) {
  const int st = bern_sign(f) * s;
  if (st > 0) return Shape::contractible;
  if (st < 0) return Shape::empty;
  if (f.c.front() == T(0) || f.c.back() == T(0)) return Shape::unknown;
  std::vector<std::pair<T, T>> roots;
  if (!isolate(f, T(0), T(1), 48, roots)) return Shape::unknown;
  // Simple roots alternate the sign: the intervals where s f > 0.
  int sign = sign_of(f.c.front()) * s, intervals = sign > 0 ? 1 : 0;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    sign = -sign;
    if (sign > 0) ++intervals;
  }
  return intervals == 0 ? Shape::empty : intervals == 1 ? Shape::contractible : Shape::unknown;
}

/// The region {g >= 0} of one leaf (its polynomial unused: count_region reads the formula only).
template <class T>
Region<T> one_leaf() {
  Poly3<T> g;
  g.terms[{0, 0, 0}] = T(1);
  return region_leaf(g, "");
}

/// {s h >= 0} on [0, 1]^2.
template <class T>
Shape shape2(const Bernstein<T>& h, int s, std::size_t budget) {
  const int st = bern_sign(h) * s;
  if (st > 0) return Shape::contractible;
  if (st < 0) return Shape::empty;
  for (int d = 0; d < 2; ++d) {
    const int w = weak_sign(bern_derivative(h, d)) * s;
    if (w != 0) return shape1(bern_face(h, d, w > 0 ? 1 : 0), s);
  }
  // One closed loop with the set inside: s h < 0 on the whole boundary, {s h > 0} and {s h < 0}
  // one piece each (count_region).
  for (int d = 0; d < 2; ++d)
    for (int side = 0; side < 2; ++side) {
      const Bernstein<T> e = bern_face(h, d, side);
      if (s * bern_sign(e) < 0) continue;
      if (e.c.front() == T(0) || e.c.back() == T(0) || sign_of(e.c.front()) * s > 0) return Shape::unknown;
      std::vector<std::pair<T, T>> roots;
      if (!isolate(e, T(0), T(1), 48, roots) || !roots.empty()) return Shape::unknown;
    }
  const Region<T> R = one_leaf<T>();
  CurveProblem<T, 2> p;
  p.trim = &R;
  p.options.max_boxes = budget;
  p.options.max_total_boxes = 3 * budget;
  p.dom_lo = {T(0), T(0)};
  p.dom_hi = {T(1), T(1)};
  Bernstein<T> in = h;
  if (s < 0)
    for (auto& c : in.c) c = -c;
  p.pieces.push_back({{in}, p.dom_lo, p.dom_hi});
  const RegionCount a = count_region(p);
  if (!a.decided || a.pieces != 1) return Shape::unknown;
  for (auto& c : p.pieces.front().G.front().c) c = -c;
  const RegionCount b = count_region(p);
  if (!b.decided || b.pieces != 1) return Shape::unknown;
  return Shape::contractible;
}

/// {s g >= 0} on the box [0, 1]^3.
template <class T>
Shape shape3(const Bernstein<T>& g, int s, std::size_t budget) {
  const int st = bern_sign(g) * s;
  if (st > 0) return Shape::contractible;
  if (st < 0) return Shape::empty;
  for (int d = 0; d < 3; ++d) {
    const int w = weak_sign(bern_derivative(g, d)) * s;
    if (w != 0) return shape2(bern_face(g, d, w > 0 ? 1 : 0), s, budget);
  }
  return Shape::unknown;
}

/// The patterns of the tracked leaves (bit q: leaf q > 0) on the trace {h = 0} in the open
/// rectangle [0, 1]^2 (h and the tracked leaves restricted to it), and the crossings of each
/// tracked leaf's zero set with the trace. False when a rectangle stays open.
struct Trace {
  unsigned patterns = 0;  // bit p: pattern p occurs
  std::vector<std::size_t> crossings;
  std::string why;
};

template <class T>
bool trace(const Bernstein<T>& h0, const std::vector<Bernstein<T>>& tracked0, int max_depth, std::size_t& budget, Trace& out) {
  static const char* const unresolved =
      "the trace of a trimming surface on a face of a box stays unresolved (tangent to the face, singular, or crossed by two surfaces at one point)";
  const std::size_t nt = tracked0.size();
  out.crossings.assign(nt, 0);
  // Depth first on the engine, halving across u and v in turn; `budget` (shared by the caller's
  // traces) counts the halvings. A rectangle that stays open at max_depth or with the budget spent
  // ends the trace (false).
  struct Q {
    Bernstein<T> h;
    std::vector<Bernstein<T>> o;
  };
  const T half = T(1) / T(2);
  auto examine = [&](const Q& q, int) {
    if (bern_sign(q.h) != 0) return Examined::settled;
    if (all_zero(q.h)) {
      out.why = "a trimming surface contains a split plane or a face of the domain";
      return Examined::left;
    }
    const auto open = [&]() {
      if (budget == 0) out.why = unresolved;
      return budget == 0 ? Examined::left : Examined::split;
    };
    // The tracked leaves' signs here; at most one changes.
    std::vector<int> sign(nt);
    std::size_t mixed = nt;
    int nmixed = 0;
    for (std::size_t l = 0; l < nt; ++l) {
      sign[l] = bern_sign(q.o[l]);
      if (sign[l] == 0) mixed = l, ++nmixed;
    }
    bool ok = nmixed <= 1;
    const std::size_t n0 = static_cast<std::size_t>(q.h.deg[0]), n1 = static_cast<std::size_t>(q.h.deg[1]);
    for (std::size_t c0 = 0; c0 < 2 && ok; ++c0)
      for (std::size_t c1 = 0; c1 < 2 && ok; ++c1) ok = !(q.h.c[c0 * n0 + c1 * n1 * (n0 + 1)] == T(0));
    ok = ok && (bern_sign(bern_derivative(q.h, 0)) != 0 || bern_sign(bern_derivative(q.h, 1)) != 0);
    // The trace's ends on the rectangle's boundary: exactly two (one arc), or none (no trace).
    struct End {
      Root<T> r;
      int d, side;
    };
    std::vector<End> ends;
    for (int d = 0; d < 2 && ok; ++d)
      for (int side = 0; side < 2 && ok; ++side) {
        const Bernstein<T> e = bern_face(q.h, d, side);
        std::vector<std::pair<T, T>> iso;
        ok = isolate(e, T(0), T(1), 48, iso);
        for (const auto& [a, b] : iso) ends.push_back({Root<T>{0, e, T(0), T(1), a, b}, d, side});
      }
    ok = ok && (ends.size() == 2 || ends.empty());
    if (ok && nmixed == 1) {
      const Bernstein<T>& o = q.o[mixed];
      const Bernstein<T> det = bern_sub(bern_product(bern_derivative(q.h, 0), bern_derivative(o, 1)),
                                           bern_product(bern_derivative(q.h, 1), bern_derivative(o, 0)));
      ok = bern_sign(det) != 0;
    }
    if (!ok) return open();
    if (ends.empty()) return Examined::settled;
    // The pattern at each end: the changing leaf's sign on a refined bracket.
    unsigned pat[2] = {0, 0};
    for (std::size_t k = 0; k < 2 && ok; ++k) {
      unsigned p = 0;
      for (std::size_t l = 0; l < nt; ++l) {
        int sg = sign[l];
        if (l == mixed) {
          const Bernstein<T> oe = bern_face(q.o[l], ends[k].d, ends[k].side);
          Root<T>& r = ends[k].r;
          for (int it = 0; it < 64 && sg == 0; ++it) {
            if (r.exact()) {
              sg = sign_of(bern_value(oe, {r.lo}));
              break;
            }
            sg = bern_sign(bern_restrict(oe, 0, r.lo, r.hi));
            if (sg == 0) r.cut((r.lo + r.hi) / 2);
          }
          if (sg == 0) ok = false;
        }
        if (sg > 0) p |= 1u << l;
      }
      pat[k] = p;
    }
    if (!ok) return open();
    out.patterns |= (1u << pat[0]) | (1u << pat[1]);
    if (pat[0] != pat[1]) ++out.crossings[mixed];
    return Examined::settled;
  };
  auto split = [&](Q&& q, int depth, auto&& emit) {
    --budget;
    const int dir = depth % 2;
    Q c[2];
    std::tie(c[0].h, c[1].h) = bern_split(q.h, dir, half);
    for (auto& x : c) x.o.resize(nt);
    for (std::size_t l = 0; l < nt; ++l) std::tie(c[0].o[l], c[1].o[l]) = bern_split(q.o[l], dir, half);
    emit(std::move(c[0]));  // depth first: the second half is examined first
    emit(std::move(c[1]));
  };
  auto leave = [&](Q&&, Left why) {
    if (why == Left::depth) out.why = unresolved;
  };
  Budget depth_only;
  depth_only.max_depth = max_depth;
  return subdivide(std::vector<Q>{Q{h0, tracked0}}, Walk{Order::depth_first, 2, true}, depth_only, examine, split, leave).stop ==
         Subdivision::Stop::complete;
}

template <class T>
struct Piece3 {
  std::array<T, 3> lo, hi;
  std::vector<std::size_t> rel;          // the further leaves that matter here (at most two)
  std::vector<int> sign;                 // every leaf's strict sign here (0: mixed)
  std::array<int, 4> piece_of{-1, -1, -1, -1};  // per pattern of `rel`
  int pieces = 0;
  std::size_t first = 0;
  std::vector<Bernstein<T>> G;
};

template <class T>
class SurfaceRun {
 public:
  SurfaceRun(const CurveProblem<T, 3>& p, std::size_t leaf, const T& frac) : P(p), k_(leaf), frac_(frac), nl_(p.pieces.empty() ? 0 : p.pieces.front().G.size()) {}

  bool run(RegionCount& out) {
    using Open = PolynomialBox<T, 3>;
    std::vector<Open> roots;
    for (const auto& pc : P.pieces)
      if (bern_sign(pc.G[k_]) == 0) roots.push_back({pc.lo, pc.hi, pc.G, 0});
    budget_ = 40 * P.options.max_boxes;
    std::string hard;
    auto examine_box = [&](Open& B, int) {
      Piece3<T> r;
      r.lo = B.lo;
      r.hi = B.hi;
      r.G = B.G;
      hard.clear();
      const int v = examine(r, hard);
      if (v < 0) return Examined::left;
      if (v == 0) return Examined::split;
      if (r.pieces > 0) done_.push_back(std::move(r));
      return Examined::settled;
    };
    auto split = [&](Open&& B, int, auto&& emit) {
      Open c[2];
      split_box(B, widest(B.lo, B.hi), frac_, c);
      for (auto& h : c)
        if (bern_sign(h.G[k_]) == 0) emit(std::move(h));
    };
    const Subdivision run =
        subdivide(std::move(roots), Walk{Order::breadth_first, 2, true}, attempt_budget(P.options), examine_box, split, [](Open&&, Left) {});
    const std::string deepest = hard.empty() ? "a box at the deepest level is still open (the surface is singular, or tangent to a split plane, or more than three surfaces meet)" : hard;
    if (!count_run(run, P.options, deepest, out)) return false;
    return graph(out);
  }

 private:
  const CurveProblem<T, 3>& P;
  std::size_t k_;
  T frac_;
  std::size_t nl_;
  std::size_t budget_ = 0;
  std::vector<Piece3<T>> done_;

  Truth truth(const std::vector<Truth>& t) const {
    std::size_t i = 0;
    return combine(*P.trim, t, i);
  }

  /// Whether the formula depends on leaf k with the other leaves at `t` (mixed ones undecided).
  int active(std::vector<Truth> t) const {
    t[k_] = Truth::in;
    const Truth a = truth(t);
    t[k_] = Truth::out;
    const Truth b = truth(t);
    if (a == Truth::mixed || b == Truth::mixed) return -1;
    return a != b ? 1 : 0;
  }

  /// Leaf l's truth from a pattern bit or its strict sign.
  static Truth of_sign(int s) { return s > 0 ? Truth::in : s < 0 ? Truth::out : Truth::mixed; }

  /// 1: resolved, 0: split, -1: give up (hard: the reason).
  int examine(Piece3<T>& r, std::string& hard) {
    const auto& G = r.G;
    r.sign.assign(nl_, 0);
    std::vector<std::size_t> mixed;
    for (std::size_t l = 0; l < nl_; ++l) {
      r.sign[l] = bern_sign(G[l]);
      if (l != k_ && r.sign[l] == 0) mixed.push_back(l);
    }
    if (mixed.size() > 6) return 0;
    // Activity of leaf k per pattern of the mixed others; the ones that change it matter.
    std::vector<Truth> t(nl_);
    for (std::size_t l = 0; l < nl_; ++l) t[l] = of_sign(r.sign[l]);
    std::vector<int> act(std::size_t(1) << mixed.size());
    for (std::size_t p = 0; p < act.size(); ++p) {
      for (std::size_t q = 0; q < mixed.size(); ++q) t[mixed[q]] = (p >> q) & 1 ? Truth::in : Truth::out;
      act[p] = active(t);
      if (act[p] < 0) return 0;
    }
    if (std::all_of(act.begin(), act.end(), [](int a) { return a == 0; })) return 1;  // bounds nowhere here
    for (std::size_t q = 0; q < mixed.size(); ++q) {
      bool m = false;
      for (std::size_t p = 0; p < act.size(); ++p) m = m || act[p] != act[p ^ (std::size_t(1) << q)];
      if (m) r.rel.push_back(mixed[q]);
    }
    if (r.rel.size() > 2) return 0;
    // P = {g_k = 0} in the box: connected and acyclic, or empty.
    const std::size_t sb = std::max<std::size_t>(64, P.options.max_boxes / 8);
    const Shape a = shape3(G[k_], 1, sb), b = shape3(G[k_], -1, sb);
    if (a == Shape::empty || b == Shape::empty) return 1;
    // (Planted, tests only: vrep/model/planted.hpp takes the sides for contractible unchecked.)
    if ((a != Shape::contractible || b != Shape::contractible) && !vrep_testing::is_planted(vrep_testing::Plant::surface_shape_unchecked)) return 0;
    // The curves C_l: monotone (a strict component of grad g_k x grad g_l); two leaves: a strict
    // triple product.
    std::array<Bernstein<T>, 3> dk;
    for (int d = 0; d < 3; ++d) dk[static_cast<std::size_t>(d)] = bern_derivative(G[k_], d);
    std::vector<std::array<Bernstein<T>, 3>> dl;
    for (std::size_t l : r.rel) {
      std::array<Bernstein<T>, 3> x;
      for (int d = 0; d < 3; ++d) x[static_cast<std::size_t>(d)] = bern_derivative(G[l], d);
      dl.push_back(x);
      bool mono = false;
      for (int d = 0; d < 3 && !mono; ++d) {
        const std::size_t a1 = static_cast<std::size_t>((d + 1) % 3), a2 = static_cast<std::size_t>((d + 2) % 3);
        mono = bern_sign(sum(bern_product(dk[a1], x[a2]), bern_product(dk[a2], x[a1]), true)) != 0;
      }
      if (!mono) return 0;
    }
    if (r.rel.size() == 2) {
      Bernstein<T> det;
      bool first = true;
      for (int d = 0; d < 3; ++d) {
        const std::size_t a1 = static_cast<std::size_t>((d + 1) % 3), a2 = static_cast<std::size_t>((d + 2) % 3);
        const Bernstein<T> cross = sum(bern_product(dk[a1], dl[0][a2]), bern_product(dk[a2], dl[0][a1]), true);
        const Bernstein<T> term = bern_product(cross, dl[1][static_cast<std::size_t>(d)]);
        det = first ? term : sum(det, term, false);
        first = false;
      }
      if (bern_sign(det) == 0) return 0;
    }
    // The traces on the six faces: patterns present and crossings of each C_l.
    unsigned present = 0;
    std::vector<std::size_t> cross(r.rel.size(), 0);
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) {
        std::vector<Bernstein<T>> o;
        for (std::size_t l : r.rel) o.push_back(bern_face(G[l], d, s));
        Trace tr;
        if (!trace(bern_face(G[k_], d, s), o, 24, budget_, tr)) {
          if (budget_ == 0) {
            hard = "the budget of face subdivisions is spent";
            return -1;
          }
          return 0;
        }
        present |= tr.patterns;
        for (std::size_t q = 0; q < r.rel.size(); ++q) cross[q] += tr.crossings[q];
      }
    for (std::size_t c : cross)
      if (c != 0 && c != 2) return 0;
    // Pieces: active patterns present, joined across one sign where that leaf does not bound
    // there itself (else a V-curve with more than two sheets: undecided).
    for (std::size_t l = 0; l < nl_; ++l) t[l] = of_sign(r.sign[l]);
    for (std::size_t l : mixed) t[l] = Truth::out;  // they do not change the activity
    auto at = [&](unsigned p) {
      auto u = t;
      for (std::size_t q = 0; q < r.rel.size(); ++q) u[r.rel[q]] = (p >> q) & 1 ? Truth::in : Truth::out;
      return u;
    };
    UnionFind uf(4);
    for (unsigned p = 0; p < 4; ++p)
      for (unsigned q2 = 0; q2 < r.rel.size(); ++q2) {
        const unsigned p2 = p ^ (1u << q2);
        if (p2 < p || !((present >> p) & 1) || !((present >> p2) & 1)) continue;
        if (active(at(p)) != 1 || active(at(p2)) != 1) continue;
        // Does leaf rel[q2] bound there too (with k on either side, the leaves that do not
        // matter for k at any value)?
        bool sheets = false;
        std::vector<std::size_t> free;
        for (std::size_t l : mixed)
          if (std::find(r.rel.begin(), r.rel.end(), l) == r.rel.end()) free.push_back(l);
        auto u = at(p);
        for (std::size_t f = 0; f < (std::size_t(1) << free.size()) && !sheets; ++f)
          for (Truth kt : {Truth::in, Truth::out}) {
            for (std::size_t i = 0; i < free.size(); ++i) u[free[i]] = (f >> i) & 1 ? Truth::in : Truth::out;
            u[k_] = kt;
            u[r.rel[q2]] = Truth::in;
            const Truth x1 = truth(u);
            u[r.rel[q2]] = Truth::out;
            sheets = sheets || x1 != truth(u);
          }
        if (sheets) {
          hard = "more than two sheets of the boundary meet along a curve";
          return -1;
        }
        uf.join(p, p2);
      }
    int n = 0;
    for (unsigned p = 0; p < 4; ++p) {
      if (!((present >> p) & 1) || active(at(p)) != 1) continue;
      const std::size_t root = uf.find(p);
      if (r.piece_of[root] < 0) r.piece_of[root] = n++;
      r.piece_of[p] = r.piece_of[root];
    }
    r.pieces = n;
    return 1;
  }

  static Bernstein<T> sum(const Bernstein<T>& a, const Bernstein<T>& b, bool minus) { return bern_combine(a, b, minus); }

  bool graph(RegionCount& out) {
    std::vector<std::array<T, 3>> lo, hi;
    std::vector<std::size_t> ids;
    const std::size_t total = number_pieces(done_, lo, hi, ids);
    UnionFind uf(total);
    for (const auto& [ia, ib] : touching_pairs(lo, hi, ids))
      for (int d = 0; d < 3; ++d) {
        std::size_t a = ia, b = ib;
        const std::size_t D = static_cast<std::size_t>(d);
        if (done_[b].hi[D] == done_[a].lo[D]) std::swap(a, b);
        if (!(done_[a].hi[D] == done_[b].lo[D])) continue;
        // The common face part E (positive area) in the other two directions.
        std::array<T, 2> e0, e1;
        bool area = true;
        int j = 0;
        for (int e = 0; e < 3; ++e) {
          if (e == d) continue;
          const std::size_t E = static_cast<std::size_t>(e);
          e0[static_cast<std::size_t>(j)] = std::max(done_[a].lo[E], done_[b].lo[E]);
          e1[static_cast<std::size_t>(j)] = std::min(done_[a].hi[E], done_[b].hi[E]);
          area = area && e0[static_cast<std::size_t>(j)] < e1[static_cast<std::size_t>(j)];
          ++j;
        }
        if (!area) continue;
        if (!join(done_[a], done_[b], d, e0, e1, uf, out)) return false;
      }
    std::vector<char> is_root(total, 0), on_id(total, 0);
    for (std::size_t i = 0; i < total; ++i) is_root[uf.find(i)] = 1;
    // Pieces reaching a face of the domain that V identifies or collapses: their trace there.
    for (const auto& r : done_)
      for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 2; ++s) {
          const std::size_t D = static_cast<std::size_t>(d);
          if (!P.identified[D][static_cast<std::size_t>(s)] || !(s ? r.hi[D] == P.dom_hi[D] : r.lo[D] == P.dom_lo[D])) continue;
          std::vector<Bernstein<T>> o;
          for (std::size_t l : r.rel) o.push_back(bern_face(r.G[l], d, s));
          Trace tr;
          std::size_t budget = 4096;
          if (!trace(bern_face(r.G[k_], d, s), o, 24, budget, tr)) {
            for (int p = 0; p < r.pieces; ++p) on_id[uf.find(r.first + static_cast<std::size_t>(p))] = 1;  // conservative
            continue;
          }
          for (unsigned p = 0; p < 4; ++p)
            if (((tr.patterns >> p) & 1) && r.piece_of[p] >= 0) on_id[uf.find(r.first + static_cast<std::size_t>(r.piece_of[p]))] = 1;
        }
    out.pieces = static_cast<std::size_t>(std::count(is_root.begin(), is_root.end(), 1));
    out.on_identified = static_cast<std::size_t>(std::count(on_id.begin(), on_id.end(), 1));
    out.decided = true;
    return true;
  }

  /// Boxes a (below) and b (above in direction d) with the common face part [e0, e1] (in the other
  /// two directions, increasing): the patterns on the trace there join their pieces.
  bool join(const Piece3<T>& a, const Piece3<T>& b, int d, const std::array<T, 2>& e0, const std::array<T, 2>& e1, UnionFind& uf, RegionCount& out) {
    // The leaves tracked: those that matter in either box.
    std::vector<std::size_t> tracked = a.rel;
    for (std::size_t l : b.rel)
      if (std::find(tracked.begin(), tracked.end(), l) == tracked.end()) tracked.push_back(l);
    auto on_E = [&](const Bernstein<T>& G3) {
      Bernstein<T> f = bern_face(G3, d, 1);  // a's upper face
      int j = 0;
      for (int e = 0; e < 3; ++e) {
        if (e == d) continue;
        const std::size_t E = static_cast<std::size_t>(e), J = static_cast<std::size_t>(j);
        const T w = a.hi[E] - a.lo[E];
        f = bern_restrict(f, j, T((e0[J] - a.lo[E]) / w), T((e1[J] - a.lo[E]) / w));
        ++j;
      }
      return f;
    };
    std::vector<Bernstein<T>> o;
    for (std::size_t l : tracked) o.push_back(on_E(a.G[l]));
    Trace tr;
    if (!trace(on_E(a.G[k_]), o, 24, budget_, tr)) {
      out.undecided_reason = tr.why.empty() ? "the budget of face subdivisions is spent" : tr.why;
      return false;
    }
    auto local = [&](const Piece3<T>& x, unsigned pattern) {
      unsigned p = 0;
      for (std::size_t q = 0; q < x.rel.size(); ++q) {
        const std::size_t i = static_cast<std::size_t>(std::find(tracked.begin(), tracked.end(), x.rel[q]) - tracked.begin());
        if ((pattern >> i) & 1) p |= 1u << q;
      }
      return x.piece_of[p];
    };
    for (unsigned p = 0; p < (1u << tracked.size()); ++p) {
      if (!((tr.patterns >> p) & 1)) continue;
      const int pa = local(a, p), pb = local(b, p);
      if ((pa < 0) != (pb < 0)) {
        out.undecided_reason = "inconsistent: a trimming surface bounds the cell on one side of a split plane only (rounding?)";
        return false;
      }
      if (pa >= 0) uf.join(a.first + static_cast<std::size_t>(pa), b.first + static_cast<std::size_t>(pb));
    }
    return true;
  }
};

}  // namespace

namespace vrep_detail {

template <class T>
RegionCount count_surface(const CurveProblem<T, 3>& problem, std::size_t leaf) {
  RegionCount out;
  for (const auto& p : problem.pieces)
    if (all_zero(p.G[leaf])) {
      out.undecided_reason = "the trimming surface's composition vanishes identically on a piece";
      return out;
    }
  return retry_fractions<T>(problem.options.max_total_boxes, [&](const T& fraction, RegionCount& attempt) {
    SurfaceRun<T> run(problem, leaf, fraction);
    return run.run(attempt);
  });
}

template RegionCount count_surface(const CurveProblem<Rational, 3>&, std::size_t);
template RegionCount count_surface(const CurveProblem<double, 3>&, std::size_t);

}  // namespace vrep_detail

}  // namespace splinex
