// Curve projection onto a surface (solve/curve_projection.hpp).
#include "solve/curve_projection.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <numeric>

#include "base/errors.hpp"
#include "base/verdict.hpp"
#include "solve/strata.hpp"
#include "solve/testing.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

using solve_detail::PairSystem;
using solve_detail::Stratum;
using BernQ = Bernstein<Rational>;
using BernD = Bernstein<double>;

BernD to_double_bern(const BernQ& b) {
  BernD d{b.deg, {}};
  d.c.reserve(b.c.size());
  for (const auto& x : b.c) d.c.push_back(to_double(x));
  return d;
}

bool is_zero(const BernQ& b) {
  for (const auto& x : b.c)
    if (x != 0) return false;
  return true;
}

/// A special point with its node data.
struct Node {
  ProjectionSpecialPoint sp;
  bool terminal = false;  // an end of a segment (the curve's end, the surface's boundary)
  bool joint = false;     // a point where a solution goes on into the neighbouring pair of pieces
  std::size_t pair = 0;
  std::array<double, 3> at{};  // the centre, in double
};

/// A traced arc between two critical values of one pair.
struct Arc {
  ProjectionBranch branch;
  std::size_t pair = 0;
  std::size_t cluster_below = 0, cluster_above = 0;  // indices into the pair's clusters (npos: none)
  std::size_t next[2] = {static_cast<std::size_t>(-1), static_cast<std::size_t>(-1)};  // the arc its lower / upper end goes on into
};

struct UnionFind {
  std::vector<std::size_t> p;
  std::size_t add() {
    p.push_back(p.size());
    return p.size() - 1;
  }
  std::size_t find(std::size_t a) {
    while (p[a] != a) a = p[a] = p[p[a]];
    return a;
  }
  void unite(std::size_t a, std::size_t b) { p[find(a)] = find(b); }
};

double dist2(const std::array<double, 3>& a, const std::array<double, 3>& b, bool with_t) {
  double s = 0;
  for (int i = 0; i < (with_t ? 3 : 2); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return s;
}

bool boxes_meet(const std::vector<Rational>& alo, const std::vector<Rational>& ahi, const std::vector<Rational>& blo, const std::vector<Rational>& bhi) {
  for (std::size_t l = 0; l < alo.size(); ++l)
    if (ahi[l] < blo[l] || bhi[l] < alo[l]) return false;
  return true;
}

/// Critical values of t: a cluster of the special points' t ranges.
struct Cluster {
  Rational lo, hi;
  std::vector<std::size_t> members;
};

/// What the steps of one curve projection share: the curve, the surface and the options, the
/// domain in (u, v, t), the special points and arcs found so far, and what the verdict needs.
struct CurveProjection {
  const BSpline<Rational>& C;
  const BSpline<Rational>& S;
  const CurveProjectionOptions& options;
  std::array<Rational, 3> dlo, dhi;
  CurveProjectionResult out{};
  std::vector<Node> nodes{};
  std::vector<Arc> arcs{};
  bool consistent = true, counts = true;
  // Arc ends joined to nodes, and arc ends joined to arc ends, recorded for the union below.
  std::vector<std::pair<std::size_t, std::size_t>> arc_node{}, arc_arc{};
};

/// One pair (surface piece A, curve piece B): its system, the surface's two equations F, its special
/// points (the nodes from first_node on), its critical values of t and its arcs.
struct PiecePair {
  const Stratum<Rational>& A;
  const Stratum<Rational>& B;
  std::size_t pair;
  const PairSystem<Rational>& sys;
  const std::vector<BernQ>& F;
  std::size_t first_node;
  std::vector<Cluster> clusters{};
  std::vector<std::size_t> pair_arcs{};
};

/// A special point of the pair as a node (unless the pair has it already).
void add_node(CurveProjection& cp, const PiecePair& pp, Node n) {
  std::vector<Node>& nodes = cp.nodes;
  // The same point found on two faces of the box (an edge or corner of it) is one node.
  for (std::size_t i = pp.first_node; i < nodes.size(); ++i)
    if ((n.sp.exact && nodes[i].sp.exact && n.sp.lo == nodes[i].sp.lo) ||
        (!(n.sp.exact && nodes[i].sp.exact) && boxes_meet(n.sp.lo, n.sp.hi, nodes[i].sp.lo, nodes[i].sp.hi))) {
      if (n.terminal) nodes[i].terminal = true, nodes[i].sp.kind = n.sp.kind, nodes[i].sp.where = n.sp.where;
      if (n.joint && !nodes[i].terminal) nodes[i].joint = true, nodes[i].sp.kind = n.sp.kind, nodes[i].sp.where = n.sp.where;
      return;
    }
  n.pair = pp.pair;
  for (int l = 0; l < 3; ++l) n.at[l] = to_double((n.sp.lo[l] + n.sp.hi[l]) / 2);
  nodes.push_back(std::move(n));
}

/// A box the solver left open (its (u, v, t) box by to3): the counts are not certified.
void add_undecided(CurveProjection& cp, const RootBox<Rational>& box, const std::string& what,
                   const std::function<std::vector<Rational>(const std::vector<Rational>&)>& to3) {
  ProjectionSpecialPoint u;
  u.kind = status_name(Status::undecided);  // a box whose kind is not decided
  u.where = what;
  u.lo = to3(box.lo);
  u.hi = to3(box.hi);
  cp.out.undecided.push_back(u);
  cp.counts = false;
}

/// End points on the six faces of the box.
void end_points(CurveProjection& cp, const PiecePair& pp) {
  const PairSystem<Rational>& sys = pp.sys;
  const std::vector<BernQ>& F = pp.F;
  const char* name[3] = {"u", "v", "t"};
  for (int l = 0; l < 3; ++l)
    for (int side = 0; side < 2; ++side) {
      const Rational x = side ? sys.hi[l] : sys.lo[l];
      const std::vector<BernQ> G{bern_fix(F[0], l, Rational(side)), bern_fix(F[1], l, Rational(side))};
      std::vector<Rational> glo, ghi;
      for (int m = 0; m < 3; ++m)
        if (m != l) {
          glo.push_back(sys.lo[m]);
          ghi.push_back(sys.hi[m]);
        }
      const auto to3 = [&](const std::vector<Rational>& y) {
        std::vector<Rational> z(y);
        z.insert(z.begin() + l, x);
        return z;
      };
      const bool terminal = x == cp.dlo[l] || x == cp.dhi[l];
      const std::string kind = terminal ? (l == 2 ? "curve end" : "surface boundary") : "joint";
      const std::string where = std::string(name[l]) + " = " + to_fraction_string(x) +
                                (terminal ? ""
                                 : l == 2 ? " (a knot of the curve)"
                                          : " (a knot line of the surface)");
      if (is_zero(G[0]) || is_zero(G[1])) {
        RootBox<Rational> b;
        b.lo = glo;
        b.hi = ghi;
        add_undecided(cp, b, where + ": the equations vanish on the whole face", to3);
        continue;
      }
      const auto r = solve_system(G, glo, ghi, cp.options.solve);
      cp.out.boxes += r.boxes;
      for (const auto& root : r.roots) {
        Node n;
        n.sp.kind = kind;
        n.sp.where = where;
        n.sp.exact = root.exact;
        n.sp.unique = root.unique;
        n.sp.lo = to3(root.exact ? root.point : root.lo);
        n.sp.hi = to3(root.exact ? root.point : root.hi);
        n.terminal = terminal;
        n.joint = !terminal;
        if (!root.unique) cp.counts = false;
        add_node(cp, pp, std::move(n));
      }
      for (const auto& box : r.undecided) add_undecided(cp, box, where, to3);
    }
}

/// Turning points: F = 0 and det dF/d(u, v) = 0.
void turning_points(CurveProjection& cp, const PiecePair& pp) {
  const PairSystem<Rational>& sys = pp.sys;
  const std::vector<BernQ>& F = pp.F;
  const BernQ J = bern_sub(bern_product(bern_derivative(F[0], 0), bern_derivative(F[1], 1)),
                           bern_product(bern_derivative(F[0], 1), bern_derivative(F[1], 0)));
  const auto id = [](const std::vector<Rational>& y) { return y; };
  if (is_zero(J)) {
    RootBox<Rational> b;
    b.lo = sys.lo;
    b.hi = sys.hi;
    add_undecided(cp, b, pp.A.label + " / " + pp.B.label + ": det dF/d(u, v) vanishes identically", id);
  } else {
    const auto r = solve_system({F[0], F[1], J}, sys.lo, sys.hi, cp.options.solve);
    cp.out.boxes += r.boxes;
    for (const auto& root : r.roots) {
      Node n;
      n.sp.kind = "turning point";
      n.sp.where = pp.A.label + " / " + pp.B.label;
      n.sp.exact = root.exact;
      n.sp.unique = root.unique;
      n.sp.lo = root.exact ? root.point : root.lo;
      n.sp.hi = root.exact ? root.point : root.hi;
      if (!root.unique) cp.counts = false;
      add_node(cp, pp, std::move(n));
    }
    for (const auto& box : r.undecided) add_undecided(cp, box, "turning points of " + pp.A.label + " / " + pp.B.label, id);
  }
}

/// Critical values of t: clusters of the special points' t ranges.
void critical_values(const CurveProjection& cp, PiecePair& pp) {
  const std::vector<Node>& nodes = cp.nodes;
  std::vector<Cluster>& clusters = pp.clusters;
  std::vector<std::size_t> order(nodes.size() - pp.first_node);
  std::iota(order.begin(), order.end(), pp.first_node);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nodes[a].sp.lo[2] < nodes[b].sp.lo[2]; });
  for (std::size_t i : order) {
    if (!clusters.empty() && !(clusters.back().hi < nodes[i].sp.lo[2])) {
      if (clusters.back().hi < nodes[i].sp.hi[2]) clusters.back().hi = nodes[i].sp.hi[2];
      clusters.back().members.push_back(i);
    } else {
      clusters.push_back({nodes[i].sp.lo[2], nodes[i].sp.hi[2], {i}});
    }
  }
}

/// What tracing in double needs of a pair: its two equations and their derivatives in (u, v), its
/// box, and the steps per gap.
struct Tracer {
  BernD Fd[2];
  BernD dF[2][2];
  double t0, t1, u0, u1, v0, v1;
  int steps;
};

/// One branch traced from `start` (local (u, v) at the local t = ts) toward the local t = target,
/// its points (global (u, v, t)) appended to pts; false when Newton lost it (or it left the box).
bool trace_branch(const Tracer& tr, const std::array<double, 2>& start, double ts, double target, std::vector<std::array<double, 3>>& pts) {
  const double t0 = tr.t0, t1 = tr.t1, u0 = tr.u0, u1 = tr.u1, v0 = tr.v0, v1 = tr.v1;
  std::array<double, 2> p = start, prev = start;
  // Steps shrink toward the target (t_k = target - (target - ts)(1 - k/steps)^2): a
  // branch ending in a fold behaves like sqrt(t* - t), and uniform steps jumped over
  // its last part. The predictor is the secant scaled to the step.
  double t_prev = ts, dt_prev = 0;
  for (int k = 1; k <= tr.steps; ++k) {
    const double r = 1.0 - static_cast<double>(k) / tr.steps;
    const double t = target - (target - ts) * r * r, dt = t - t_prev;
    std::array<double, 2> guess = p;
    if (k > 1 && dt_prev != 0)
      for (int i = 0; i < 2; ++i) guess[i] = p[i] + (p[i] - prev[i]) * (dt / dt_prev);
    bool ok = false;
    double last_step = INFINITY;
    for (int it = 0; it < 40; ++it) {
      const std::vector<double> at{guess[0], guess[1], t};
      Eigen::Vector2d f(bern_value(tr.Fd[0], at), bern_value(tr.Fd[1], at));
      Eigen::Matrix2d J;
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) J(i, j) = bern_value(tr.dF[i][j], at);
      const Eigen::Vector2d d = J.fullPivLu().solve(f);
      if (!d.allFinite()) break;
      guess[0] -= d(0);
      guess[1] -= d(1);
      const double step = d.lpNorm<Eigen::Infinity>();
      // Converged: a step at double's resolution, or (near a fold, where J is nearly
      // singular and rounding noise keeps the steps above it) steps that stopped
      // shrinking at a small size.
      if (step < 1e-15 || (step < 1e-9 && step >= last_step / 2)) {
        ok = true;
        break;
      }
      last_step = step;
    }
    t_prev = t;
    dt_prev = dt;
    if (!ok || guess[0] < -1e-9 || guess[0] > 1 + 1e-9 || guess[1] < -1e-9 || guess[1] > 1 + 1e-9) return false;
    prev = p;
    p = guess;
    pts.push_back({u0 + (u1 - u0) * p[0], v0 + (v1 - v0) * p[1], t0 + (t1 - t0) * t});
  }
  return true;
}

/// The gap g between critical values (and the box's ends): its certified slice, and an arc traced
/// from each of the slice's roots.
void trace_gap(CurveProjection& cp, PiecePair& pp, const Tracer& tr, std::size_t g) {
  const PairSystem<Rational>& sys = pp.sys;
  const std::vector<BernQ>& F = pp.F;
  const std::vector<Cluster>& clusters = pp.clusters;
  const double t0 = tr.t0, t1 = tr.t1, u0 = tr.u0, u1 = tr.u1, v0 = tr.v0, v1 = tr.v1;
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  const Rational glo = g == 0 ? sys.lo[2] : clusters[g - 1].hi, ghi = g == clusters.size() ? sys.hi[2] : clusters[g].lo;
  if (!(glo < ghi)) return;
  const Rational q = (ghi - glo) / 4;
  ProjectionSlice sl;
  sl.t = simplest_rational_between(glo + q, ghi - q);
  const Rational tl = (sl.t - sys.lo[2]) / (sys.hi[2] - sys.lo[2]);
  const std::vector<BernQ> G{bern_fix(F[0], 2, tl), bern_fix(F[1], 2, tl)};
  if (is_zero(G[0]) || is_zero(G[1])) {
    cp.counts = false;
    return;
  }
  const auto r = solve_system(G, {sys.lo[0], sys.lo[1]}, {sys.hi[0], sys.hi[1]}, cp.options.solve);
  cp.out.boxes += r.boxes;
  sl.roots = r.roots.size();
  sl.certified = r.complete();
  if (!sl.certified && solve_testing::planted(solve_testing::Plant::curve_counts_unchecked)) {
    sl.certified = true;  // planted (solve/testing.hpp): the slice's count taken without completeness
    solve_testing::plant_hit();
  }
  cp.counts = cp.counts && sl.certified;
  cp.out.slices.push_back(sl);
  // Trace each root up to ghi and down to glo in double (local coordinates of the box).
  // A special point's box may be refined to 2^-60: Newton in double cannot follow a branch
  // into a fold that close (its Jacobian is singular there), so the tracing stops 2^-24 of
  // the box short of a cluster; the joins below take the nearest point anyway.
  const double margin = std::ldexp(1.0, -24), ts = to_double(tl);
  const double tlo = std::min(ts, (to_double(glo) - t0) / (t1 - t0) + (g == 0 ? 0.0 : margin)),
               thi = std::max(ts, (to_double(ghi) - t0) / (t1 - t0) - (g == clusters.size() ? 0.0 : margin));
  for (const auto& root : r.roots) {
    const std::vector<Rational>& x = root.exact ? root.point : root.lo;
    const std::vector<Rational>& y = root.exact ? root.point : root.hi;
    std::array<double, 2> start = {(to_double((x[0] + y[0]) / 2) - u0) / (u1 - u0), (to_double((x[1] + y[1]) / 2) - v0) / (v1 - v0)};
    std::vector<std::array<double, 3>> down, up;
    bool lost = false;
    for (int dir = -1; dir <= 1; dir += 2)
      if (!trace_branch(tr, start, ts, dir < 0 ? tlo : thi, dir < 0 ? down : up)) lost = true;
    if (lost) cp.consistent = false;
    Arc a;
    a.pair = pp.pair;
    std::reverse(down.begin(), down.end());
    a.branch.points = down;
    a.branch.points.push_back({u0 + (u1 - u0) * start[0], v0 + (v1 - v0) * start[1], t0 + (t1 - t0) * ts});
    a.branch.points.insert(a.branch.points.end(), up.begin(), up.end());
    a.cluster_below = g == 0 ? none : g - 1;
    a.cluster_above = g == clusters.size() ? none : g;
    pp.pair_arcs.push_back(cp.arcs.size());
    cp.arcs.push_back(std::move(a));
  }
}

/// Gaps between the critical values (and the box's ends), each with a certified slice and traced arcs.
void trace_gaps(CurveProjection& cp, PiecePair& pp) {
  const PairSystem<Rational>& sys = pp.sys;
  const std::vector<BernQ>& F = pp.F;
  Tracer tr{{to_double_bern(F[0]), to_double_bern(F[1])},
            {},
            to_double(sys.lo[2]),
            to_double(sys.hi[2]),
            to_double(sys.lo[0]),
            to_double(sys.hi[0]),
            to_double(sys.lo[1]),
            to_double(sys.hi[1]),
            cp.options.steps};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) tr.dF[i][j] = bern_derivative(tr.Fd[i], j);
  for (std::size_t g = 0; g <= pp.clusters.size(); ++g) trace_gap(cp, pp, tr, g);
}

/// Joins at each cluster: every arc end goes to the nearest special point of the cluster or
/// the nearest arc end on its other side, in (u, v, t).
void join_at_clusters(CurveProjection& cp, const PiecePair& pp) {
  std::vector<Arc>& arcs = cp.arcs;
  std::vector<Node>& nodes = cp.nodes;
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  for (std::size_t c = 0; c < pp.clusters.size(); ++c) {
    for (std::size_t ai : pp.pair_arcs) {
      for (int side = 0; side < 2; ++side) {
        const bool below = side == 0;  // the arc's lower end at cluster c (the arc lies above it)
        if ((below ? arcs[ai].cluster_below : arcs[ai].cluster_above) != c) continue;
        const auto& end = below ? arcs[ai].branch.points.front() : arcs[ai].branch.points.back();
        double best = INFINITY;
        std::size_t best_node = none, best_arc = none;
        for (std::size_t m : pp.clusters[c].members) {
          const double d = dist2(end, nodes[m].at, true);
          if (d < best) best = d, best_node = m, best_arc = none;
        }
        for (std::size_t bj : pp.pair_arcs) {  // an arc on the other side going on through
          if (bj == ai) continue;
          if ((below ? arcs[bj].cluster_above : arcs[bj].cluster_below) != c) continue;
          const auto& other = below ? arcs[bj].branch.points.back() : arcs[bj].branch.points.front();
          const double d = dist2(end, other, true);
          if (d < best) best = d, best_node = none, best_arc = bj;
        }
        if (best_node != none) {
          cp.arc_node.emplace_back(ai, best_node);
          ++nodes[best_node].sp.branches;
        } else if (best_arc != none) {
          cp.arc_arc.emplace_back(ai, best_arc);
          arcs[ai].next[side] = best_arc;
        } else {
          cp.consistent = false;  // nothing to join to
        }
      }
    }
  }
}

/// One pair of pieces: its special points certified, its gaps sliced and traced, the joins made.
void project_pair(CurveProjection& cp, const Stratum<Rational>& A, const Stratum<Rational>& B, std::size_t pair) {
  const PairSystem<Rational> sys = solve_detail::pair_system(A, B);
  const std::vector<BernQ> F{sys.equations[0], sys.equations[1]};            // the surface's two: Eq. 3
  if (bern_sign(F[0]) != 0 || bern_sign(F[1]) != 0) return;                  // no solution in this box
  const bool over_budget = cp.out.boxes >= cp.options.solve.max_boxes * 10;  // the whole search's budget
  if (is_zero(F[0]) || is_zero(F[1]) || over_budget) {
    ProjectionSpecialPoint u;
    u.kind = over_budget ? "not searched" : "degenerate";
    u.where = A.label + " / " + B.label + (over_budget ? ": the search's budget of boxes is spent" : ": an equation vanishes identically");
    u.lo = sys.lo;
    u.hi = sys.hi;
    cp.out.undecided.push_back(u);
    cp.counts = false;
    return;
  }
  PiecePair pp{A, B, pair, sys, F, cp.nodes.size()};
  end_points(cp, pp);
  turning_points(cp, pp);
  critical_values(cp, pp);
  trace_gaps(cp, pp);
  join_at_clusters(cp, pp);
}

/// The joins checked, and the components counted: segments (with ends) and loops.
void join_components(CurveProjection& cp) {
  std::vector<Arc>& arcs = cp.arcs;
  std::vector<Node>& nodes = cp.nodes;
  CurveProjectionResult& out = cp.out;
  bool& consistent = cp.consistent;
  // An arc that goes on into another must be that arc's choice too; an arc end at the box's side
  // with no special point there is a point the solver did not find.
  for (std::size_t a = 0; a < arcs.size(); ++a) {
    if (arcs[a].cluster_below == static_cast<std::size_t>(-1) || arcs[a].cluster_above == static_cast<std::size_t>(-1)) consistent = false;
    for (int side = 0; side < 2; ++side)
      if (arcs[a].next[side] != static_cast<std::size_t>(-1) && arcs[arcs[a].next[side]].next[1 - side] != a) consistent = false;
  }
  // Components: nodes and arcs; joints of neighbouring pairs that are the same point are one.
  UnionFind uf;
  for (std::size_t i = 0; i < nodes.size() + arcs.size(); ++i) uf.add();
  const std::size_t base = nodes.size();
  for (const auto& [a, n] : cp.arc_node) uf.unite(base + a, n);
  for (const auto& [a, b] : cp.arc_arc) uf.unite(base + a, base + b);
  std::vector<int> joint_branches(nodes.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i) joint_branches[i] = nodes[i].sp.branches;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = i + 1; j < nodes.size(); ++j)
      if (nodes[i].joint && nodes[j].joint && nodes[i].pair != nodes[j].pair &&
          ((nodes[i].sp.exact && nodes[j].sp.exact) ? nodes[i].sp.lo == nodes[j].sp.lo
                                                    : boxes_meet(nodes[i].sp.lo, nodes[i].sp.hi, nodes[j].sp.lo, nodes[j].sp.hi))) {
        uf.unite(i, j);
        joint_branches[i] += nodes[j].sp.branches;
        joint_branches[j] += nodes[i].sp.branches;
      }
  // What each special point needs: an end one branch, a turning point two, a joint one from each side.
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto& n = nodes[i];
    const int need = n.terminal ? 1 : 2;  // a joint: one from each side, counted over the joined nodes
    const int have = n.joint && !n.terminal ? joint_branches[i] : n.sp.branches;
    if (have != need) consistent = false;
  }
  std::vector<long> comp(uf.p.size(), -1);
  std::vector<bool> has_end;
  std::vector<bool> has_arc;
  for (std::size_t i = 0; i < uf.p.size(); ++i) {
    const std::size_t r = uf.find(i);
    if (comp[r] < 0) {
      comp[r] = static_cast<long>(has_end.size());
      has_end.push_back(false);
      has_arc.push_back(false);
    }
    if (i < base && nodes[i].terminal) has_end[comp[r]] = true;
    if (i >= base) has_arc[comp[r]] = true;
  }
  for (std::size_t c = 0; c < has_end.size(); ++c) {
    if (!has_arc[c]) continue;
    (has_end[c] ? out.segments : out.loops) += 1;
  }
  for (std::size_t a = 0; a < arcs.size(); ++a) {
    arcs[a].branch.component = static_cast<int>(comp[uf.find(base + a)]);
    out.branches.push_back(std::move(arcs[a].branch));
  }
  for (auto& n : nodes) out.special.push_back(std::move(n.sp));
}

/// Every traced point measured exactly: cos^2 of the angles between C - S and S_u, S_v.
void measure_traced_points(CurveProjection& cp) {
  const BSpline<Rational>& S = cp.S;
  const BSpline<Rational>& C = cp.C;
  CurveProjectionResult& out = cp.out;
  Rational worst(0);
  std::size_t total = 0;
  for (const auto& b : out.branches) total += b.points.size();
  const std::size_t stride = std::max<std::size_t>(1, total / 4000);
  std::size_t k = 0;
  for (const auto& b : out.branches)
    for (const auto& p : b.points) {
      ++out.traced_points;
      if (k++ % stride != 0) continue;
      std::vector<Rational> uv(2), t(1);
      for (int i = 0; i < 2; ++i) uv[i] = std::clamp(exact_from_double(p[i], "u"), Rational(cp.dlo[i]), Rational(cp.dhi[i]));
      t[0] = std::clamp(exact_from_double(p[2], "t"), Rational(cp.dlo[2]), Rational(cp.dhi[2]));
      const auto s = evaluate(S, uv), c = evaluate(C, t);
      Rational dd(0);
      std::vector<Rational> d(3);
      for (int i = 0; i < 3; ++i) {
        d[i] = c[i] - s[i];
        dd += d[i] * d[i];
      }
      if (dd == 0) continue;  // the curve meets the surface: every direction is orthogonal
      for (int dir = 0; dir < 2; ++dir) {
        const auto su = derivative(S, uv, {dir == 0 ? 1 : 0, dir == 1 ? 1 : 0});
        Rational dot(0), ss(0);
        for (int i = 0; i < 3; ++i) {
          dot += d[i] * su[i];
          ss += su[i] * su[i];
        }
        if (ss == 0) continue;
        const Rational cos2 = dot * dot / (dd * ss);
        if (worst < cos2) worst = cos2;
      }
    }
  out.max_cosine = std::sqrt(to_double(worst));
}

}  // namespace

CurveProjectionResult project_curve(const BSpline<Rational>& C, const BSpline<Rational>& S, const CurveProjectionOptions& options,
                                    const Limits& limits) {
  validate(C, limits);
  if (C.dim() != 1 || C.q < 3)
    throw ValidationError("curve", "is not a curve in R^3", "give a spline with one parametric direction and points x,y,z");
  if (C.degrees[0] == 0) throw ValidationError("curve.degrees[0]", "is 0", "elevate the curve to degree >= 1");
  solve_detail::require_surface(S, "surface", limits, 2);
  if (options.steps < 2 || options.steps > 100000) throw UsageError("steps", "must be in [2, 100000]", "use e.g. 48");
  const auto faces = [&] {
    std::vector<Stratum<Rational>> out;
    for (auto& s : solve_detail::surface_strata(S, limits))
      if (s.where == "interior") out.push_back(std::move(s));
    return out;
  }();
  const auto curves = solve_detail::curve_strata(C, limits);
  CurveProjection cp{C, S, options, {S.domain_lo(0), S.domain_lo(1), C.domain_lo(0)}, {S.domain_hi(0), S.domain_hi(1), C.domain_hi(0)}};
  std::size_t pair_index = 0;

  const auto started = std::chrono::steady_clock::now();
  auto last = started;
  for (const auto& A : faces)
    for (const auto& B : curves) {
      const std::size_t pair = pair_index++;
      if (options.solve.progress && std::chrono::steady_clock::now() - last > std::chrono::seconds(2)) {
        last = std::chrono::steady_clock::now();
        options.solve.progress(std::to_string(static_cast<long>(std::chrono::duration<double>(last - started).count())) +
                               " s: pairs of pieces " + std::to_string(pair) + "/" + std::to_string(faces.size() * curves.size()) + ", " +
                               std::to_string(cp.out.boxes) + " boxes");
      }
      project_pair(cp, A, B, pair);
    }

  join_components(cp);
  cp.out.certified_counts = cp.counts;
  if (!cp.counts && solve_testing::planted(solve_testing::Plant::curve_counts_unchecked)) {
    cp.out.certified_counts = true;  // planted: the counts certified without the solver's completeness
    solve_testing::plant_hit();
  }
  cp.out.consistent = cp.consistent;

  measure_traced_points(cp);
  return std::move(cp.out);
}

}  // namespace splinex
