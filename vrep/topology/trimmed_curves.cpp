// The certified curve graph (vrep/topology/curve_graph.hpp) and the V-curves between two trimming surfaces
// of a trimmed cell (vrep/trimmed/trimmed.hpp: trimmed_curves has the method), instantiated for Rational
// and double.
#include <algorithm>
#include <deque>
#include <map>

#include "base/errors.hpp"
#include "solve/solver.hpp"
#include "spline/bezier.hpp"
#include "vrep/topology/box_components.hpp"
#include "vrep/topology/curve_graph.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"
#include "vrep/topology/trimmed_curves.hpp"

namespace splinex {

namespace vrep_detail {

template <class T>
Bernstein<T> divide_facet(const Bernstein<T>& G, int d, int side) {
  Bernstein<T> H;
  H.deg = G.deg;
  const int p = G.deg[static_cast<std::size_t>(d)];
  H.deg[static_cast<std::size_t>(d)] = p - 1;
  H.c.resize(detail::tensor_size(H.deg));
  const std::size_t n = G.deg.size();
  std::vector<int> idx(n);
  // With G's coefficients c_i along d (degree p): B_i^p = (p / i) t B_{i-1}^{p-1} = (p / (p - i)) (1 - t) B_i^{p-1}.
  for (std::size_t h = 0; h < H.c.size(); ++h) {
    detail::unflatten(h, H.deg, idx);
    const int i = idx[static_cast<std::size_t>(d)];
    idx[static_cast<std::size_t>(d)] = side ? i : i + 1;  // the coefficient of G it comes from
    std::size_t g = 0;
    for (std::size_t l = 0; l < n; ++l) g += static_cast<std::size_t>(idx[l]) * detail::tensor_stride(G.deg, static_cast<int>(l));
    H.c[h] = G.c[g] * T(p) / T(side ? p - i : i + 1);
  }
  return H;
}


template <class T>
CurveProblem<T, 3> cell_problem(const BSpline<T>& V, const Region<T>& trim, const std::vector<const Poly3<T>*>& leaves, const CurveOptions& options,
                                const Limits& limits) {
  CurveProblem<T, 3> problem;
  problem.trim = &trim;
  problem.options = options;
  for (int d = 0; d < 3; ++d) {
    problem.dom_lo[static_cast<std::size_t>(d)] = V.domain_lo(d);
    problem.dom_hi[static_cast<std::size_t>(d)] = V.domain_hi(d);
  }
  for (auto& lp : leaf_pieces(V, leaves, limits)) {
    CurvePiece<T, 3> piece{std::move(lp.G), lp.lo, lp.hi};
    // A leaf vanishing on a face of the domain (a trimming plane on a face of the cell: coplanar
    // contact) has that face's parameter as a factor; the curves of the open domain are those of
    // the quotient, which has the same signs inside.
    for (auto& G : piece.G)
      for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 2; ++s)
          while ((s ? piece.hi[d] == V.domain_hi(d) : piece.lo[d] == V.domain_lo(d)) && G.deg[static_cast<std::size_t>(d)] > 0 && !all_zero(G) &&
                 all_zero(bern_face(G, d, s)))
            G = divide_facet(G, d, s);
    problem.pieces.push_back(std::move(piece));
  }
  // V's own identifications: faces collapsed or equal to another face.
  {
    std::array<std::array<BSpline<T>, 2>, 3> faces;
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) faces[d][s] = face(V, d, s);
    for (std::size_t d = 0; d < 3; ++d)
      for (std::size_t s = 0; s < 2; ++s) {
        problem.identified[d][s] = problem.identified[d][s] || collapsed(faces[d][s], 0) || collapsed(faces[d][s], 1);
        for (std::size_t d2 = d; d2 < 3; ++d2)
          for (std::size_t s2 = 0; s2 < 2; ++s2) {
            if (d2 == d && s2 <= s) continue;
            if (corner_set(faces[d][s]) != corner_set(faces[d2][s2]) || !same_surface(faces[d][s], faces[d2][s2], T(0), limits)) continue;
            problem.identified[d][s] = problem.identified[d2][s2] = true;
          }
      }
  }
  return problem;
}

template CurveProblem<Rational, 3> cell_problem(const BSpline<Rational>&, const Region<Rational>&, const std::vector<const Poly3<Rational>*>&,
                                                const CurveOptions&, const Limits&);
template CurveProblem<double, 3> cell_problem(const BSpline<double>&, const Region<double>&, const std::vector<const Poly3<double>*>&,
                                              const CurveOptions&, const Limits&);

}  // namespace vrep_detail

namespace {

using namespace vrep_detail;

/// a + b or a - b at their common degrees.
template <class T>
Bernstein<T> sum(const Bernstein<T>& a, const Bernstein<T>& b, bool minus) {
  return bern_combine(a, b, minus);
}

template <class T>
Truth strict(const Bernstein<T>& b) {
  const int s = bern_sign(b);
  return s > 0 ? Truth::in : s < 0 ? Truth::out : Truth::mixed;
}

/// The tangent of the curve {f = 0} (N - 1 equations in N unknowns), component by component:
/// N = 3 grad f_0 x grad f_1, N = 2 (d f / d t_1, -d f / d t_0). In the box's unit coordinates each
/// component is a positive multiple of the true one, so its signs are the true ones.
template <class T, std::size_t N>
std::array<Bernstein<T>, N> tangent(const std::vector<Bernstein<T>>& f) {
  std::array<Bernstein<T>, N> X;
  if constexpr (N == 2) {
    X[0] = bern_derivative(f[0], 1);
    X[1] = bern_derivative(f[0], 0);
    for (auto& c : X[1].c) c = -c;
  } else {
    std::array<Bernstein<T>, 3> df, dg;
    for (int d = 0; d < 3; ++d) {
      df[d] = bern_derivative(f[0], d);
      dg[d] = bern_derivative(f[1], d);
    }
    for (int d = 0; d < 3; ++d) {
      const int a = (d + 1) % 3, b = (d + 2) % 3;
      X[d] = sum(bern_product(df[a], dg[b]), bern_product(df[b], dg[a]), true);
    }
  }
  return X;
}

/// The determinant of an n x n matrix, n <= 2 (a facet's Jacobian).
template <class T>
T small_det(const std::vector<std::vector<T>>& J) {
  if (J.size() == 1) return J[0][0];
  return J[0][0] * J[1][1] - J[0][1] * J[1][0];
}

template <class T, std::size_t N>
struct Box {
  std::array<T, N> lo, hi;
  std::size_t piece = 0;
  std::vector<Bernstein<T>> G;    // every leaf
  std::array<Bernstein<T>, N> X;  // the curve's tangent, split with the box from its piece
  int level = 0;
};

/// A simple root of the curve's equations on a facet of a box: the hyperplane x_d = at, the root's
/// box in the other directions (in increasing order).
template <class T, std::size_t N>
struct Crossing {
  int d = 0, side = 0;  // the box's facet: side 0 its lower, 1 its upper one
  T at;
  std::array<T, N - 1> lo, hi;
  bool domain = false;          // on a facet of the domain
  bool identified = false;      // ... one V identifies with another or collapses
  Truth k_sign = Truth::mixed;  // the one undecided further leaf's sign there
};

/// One box's arc: from x[0] to x[1], active along it (or its two halves, cut where g_k = 0).
template <class T, std::size_t N>
struct Arc {
  Crossing<T, N> x[2];
  bool halves = false, vpoint = false;
  bool active[2] = {false, false};
};

enum class ArcStep { none, arc, split, fail };

const char* const kOnDomainFace = "a trimming surface contains a face of the domain";
const char* const kTangent = "the curve is tangent to a split plane or a face of the domain, or lies in one";
const char* const kCoincide = "the trimming surfaces coincide, or the curve is singular all along (its tangent vanishes identically)";
bool permanent(const std::string& reason) { return reason == kOnDomainFace || reason == kCoincide; }

template <class T, std::size_t N>
class CurveRun {
 public:
  CurveRun(const CurveProblem<T, N>& p, const T& frac) : P(p), frac_(frac), nl_(p.pieces.empty() ? 0 : p.pieces.front().G.size()) {
    so_.max_depth = 30;
    so_.max_boxes = 800;
    so_.refine_bits = 60;
    so_.recognize_rationals = true;
  }

  /// One attempt; false (reason set) when it does not decide.
  bool run(CurveCount& out) {
    std::vector<Box<T, N>> todo;
    for (std::size_t p = 0; p < P.pieces.size(); ++p) {
      bool meet = true;
      for (std::size_t c : P.curve) meet = meet && bern_sign(P.pieces[p].G[c]) == 0;
      if (!meet) continue;
      Box<T, N> b;
      b.lo = P.pieces[p].lo;
      b.hi = P.pieces[p].hi;
      b.piece = p;
      b.G = P.pieces[p].G;
      std::vector<Bernstein<T>> f;
      for (std::size_t c : P.curve) f.push_back(b.G[c]);
      b.X = tangent<T, N>(f);
      todo.push_back(std::move(b));
    }
    std::vector<Arc<T, N>> arcs;
    std::string hard;
    auto examine_box = [&](Box<T, N>& B, int) {
      Arc<T, N> arc;
      hard.clear();
      const ArcStep v = examine(B, arc, hard);
      if (v == ArcStep::arc) arcs.push_back(std::move(arc));
      return v == ArcStep::fail ? Examined::left : v == ArcStep::split ? Examined::split : Examined::settled;
    };
    auto split = [&](Box<T, N>&& B, int, auto&& emit) {
      const int dir = widest(B.lo, B.hi);
      Box<T, N> c[2];
      split_box(B, dir, frac_, c);
      for (auto& h : c) h.piece = B.piece;
      for (std::size_t d = 0; d < N; ++d) std::tie(c[0].X[d], c[1].X[d]) = bern_split(B.X[d], dir, frac_);
      emit(std::move(c[0]));
      emit(std::move(c[1]));
    };
    Left why = Left::examined;
    auto leave = [&](Box<T, N>&&, Left w) { why = w; };
    const Subdivision run = subdivide(std::move(todo), Walk{Order::breadth_first, 2, true}, attempt_budget(P.options), examine_box, split, leave);
    if (!count_run(run, P.options, why == Left::depth ? "a box at the deepest level is still open (a singular or tangential point of the curve)" : hard, out))
      return false;
    return graph(arcs, out);
  }

 private:
  const CurveProblem<T, N>& P;
  T frac_;
  std::size_t nl_;
  SolveOptions so_;

  bool on_curve(std::size_t l) const { return std::find(P.curve.begin(), P.curve.end(), l) != P.curve.end(); }

  std::vector<std::size_t> with(std::size_t k) const {
    auto w = P.curve;
    w.push_back(k);
    return w;
  }

  /// The crossings of the curve with facet (d, s) of box B; false when they are not all certified
  /// simple roots strictly inside the facet (`hard`: splitting cannot help).
  bool facet_crossings(const Box<T, N>& B, long k, int d, int s, std::vector<Crossing<T, N>>& found, std::string& hard) {
    std::vector<Bernstein<T>> H;
    for (std::size_t c : P.curve) {
      H.push_back(bern_face(B.G[c], d, s));
      if (bern_sign(H.back()) != 0) return true;
    }
    const bool on_domain = s ? B.hi[d] == P.dom_hi[d] : B.lo[d] == P.dom_lo[d];
    for (const auto& h : H)
      if (all_zero(h)) {
        hard = on_domain ? kOnDomainFace : "a trimming surface contains a split plane";
        return false;
      }
    std::vector<T> lo, hi;
    for (std::size_t e = 0; e < N; ++e)
      if (static_cast<int>(e) != d) {
        lo.push_back(B.lo[e]);
        hi.push_back(B.hi[e]);
      }
    const SolveResult<T> r = solve_system(H, lo, hi, so_);
    // Undecided roots on a facet (the curve tangent to it or lying in it) stay on it however the
    // box is split: another split fraction must move the facet.
    if (!r.undecided.empty() || r.budget_exhausted) {
      hard = kTangent;
      return false;
    }
    constexpr std::size_t M = N - 1;
    for (const auto& root : r.roots) {
      Crossing<T, N> c;
      c.d = d;
      c.side = s;
      c.at = s ? B.hi[d] : B.lo[d];
      std::vector<T> u(M);
      if (root.exact) {
        for (std::size_t q = 0; q < M; ++q) {
          c.lo[q] = c.hi[q] = root.point[q];
          u[q] = (root.point[q] - lo[q]) / (hi[q] - lo[q]);
        }
        // A simple root: the Jacobian is regular at it (exact determinant).
        std::vector<std::vector<T>> J(M, std::vector<T>(M));
        for (std::size_t a = 0; a < M; ++a)
          for (std::size_t b = 0; b < M; ++b) J[a][b] = bern_value(bern_derivative(H[a], static_cast<int>(b)), u);
        if (small_det(J) == T(0)) {
          hard = kTangent;
          return false;
        }
      } else {
        if (!root.unique) {
          hard = kTangent;
          return false;
        }
        for (std::size_t q = 0; q < M; ++q) {
          c.lo[q] = root.lo[q];
          c.hi[q] = root.hi[q];
        }
      }
      for (std::size_t q = 0; q < M; ++q)
        if (!(lo[q] < c.lo[q] && c.hi[q] < hi[q])) {
          hard = N == 3 ? "a V-curve meets an edge of a subdivision box" : "a curve on a face meets a corner of a subdivision box";
          return false;
        }
      c.domain = on_domain;
      c.identified = on_domain && P.identified[static_cast<std::size_t>(d)][static_cast<std::size_t>(s)];
      if (k >= 0) {
        Bernstein<T> h = bern_face(B.G[static_cast<std::size_t>(k)], d, s);
        if (root.exact) c.k_sign = value_truth(bern_value(h, u), T(0));
        else {
          for (std::size_t q = 0; q < M; ++q) {
            const T from = (c.lo[q] - lo[q]) / (hi[q] - lo[q]), to = (c.hi[q] - lo[q]) / (hi[q] - lo[q]);
            h = bern_restrict(h, static_cast<int>(q), from, to);
          }
          c.k_sign = strict(h);
        }
        if (c.k_sign == Truth::mixed) {  // a further surface through the crossing: a V-point on a split plane
          hard = "a V-point lies on a split plane";
          return false;
        }
      }
      found.push_back(std::move(c));
    }
    return true;
  }

  /// One box: no curve that matters, one arc, split it, or give up.
  ArcStep examine(const Box<T, N>& B, Arc<T, N>& arc, std::string& hard) {
    for (std::size_t c : P.curve)
      if (bern_sign(B.G[c]) != 0) return ArcStep::none;
    std::vector<Truth> fixed(nl_, Truth::mixed);
    std::vector<std::size_t> open;  // other leaves without one strict sign
    for (std::size_t l = 0; l < nl_; ++l) {
      if (on_curve(l)) continue;
      fixed[l] = strict(B.G[l]);
      if (fixed[l] == Truth::mixed) open.push_back(l);
    }
    // Whether the curve may matter here: the formula depends on each of its leaves for some signs
    // of the undecided ones (a box where it cannot is skipped: along the curve the activity is
    // continuous wherever the other leaves are strictly signed, so no arc of a box that matters
    // ends there; one that does anyway is reported as an inconsistency).
    bool matters = open.size() > 6;
    for (std::size_t pattern = 0; !matters && pattern < (std::size_t(1) << open.size()); ++pattern) {
      auto f = fixed;
      for (std::size_t q = 0; q < open.size(); ++q) f[open[q]] = (pattern >> q) & 1 ? Truth::in : Truth::out;
      matters = depends_on_each(*P.trim, f, P.curve);
    }
    if (!matters) return ArcStep::none;
    bool monotone = false, flat = true;
    for (std::size_t d = 0; d < N; ++d) {
      monotone = monotone || bern_sign(B.X[d]) != 0;
      flat = flat && all_zero(B.X[d]);
    }
    if (flat && B.level >= 6) {
      hard = kCoincide;
      return ArcStep::fail;
    }
    if (!monotone || open.size() >= 2) return ArcStep::split;
    const long k = open.empty() ? -1 : static_cast<long>(open.front());
    if (k >= 0) {
      // det(grad f..., grad g_k) on the box: the derivatives of g_k in the box's unit coordinates,
      // the tangent in its piece's; each term scaled to one positive multiple of the determinant.
      const auto& piece = P.pieces[B.piece];
      std::array<T, N> r;
      for (std::size_t d = 0; d < N; ++d) r[d] = (B.hi[d] - B.lo[d]) / (piece.hi[d] - piece.lo[d]);
      Bernstein<T> D;
      for (std::size_t d = 0; d < N; ++d) {
        Bernstein<T> t = bern_product(bern_derivative(B.G[static_cast<std::size_t>(k)], static_cast<int>(d)), B.X[d]);
        T scale(1);
        for (std::size_t e = 0; e < N; ++e)
          if (e != d) scale *= r[e];
        for (auto& x : t.c) x *= scale;
        D = d == 0 ? t : sum(D, t, false);
      }
      if (bern_sign(D) == 0) return ArcStep::split;
    }
    std::vector<Crossing<T, N>> found;
    for (int d = 0; d < static_cast<int>(N); ++d)
      for (int s = 0; s < 2; ++s)
        if (!facet_crossings(B, k, d, s, found, hard)) return hard.empty() ? ArcStep::split : ArcStep::fail;
    if (found.empty()) return ArcStep::none;
    if (found.size() != 2) return ArcStep::split;
    arc = Arc<T, N>{};
    arc.x[0] = found[0];
    arc.x[1] = found[1];
    if (k < 0) {
      arc.active[0] = depends_on_each(*P.trim, fixed, P.curve);
      return ArcStep::arc;
    }
    auto f0 = fixed, f1 = fixed;
    f0[static_cast<std::size_t>(k)] = found[0].k_sign;
    f1[static_cast<std::size_t>(k)] = found[1].k_sign;
    arc.active[0] = depends_on_each(*P.trim, f0, P.curve);
    if (found[0].k_sign != found[1].k_sign) {
      arc.halves = true;
      arc.active[1] = depends_on_each(*P.trim, f1, P.curve);
      arc.vpoint = depends_on_each(*P.trim, fixed, with(static_cast<std::size_t>(k)));
    }
    return ArcStep::arc;
  }

  /// The graph: crossings are nodes (matched across the facets boxes share), arcs are edges; its
  /// components over the active edges are the curves.
  bool graph(const std::vector<Arc<T, N>>& arcs, CurveCount& out) {
    const std::size_t nx = 2 * arcs.size();
    out.crossings = nx;
    UnionFind nodes(nx + arcs.size());  // crossings, then one middle node per arc
    std::map<std::pair<int, T>, std::vector<std::size_t>> planes;
    for (std::size_t a = 0; a < arcs.size(); ++a)
      for (int e = 0; e < 2; ++e)
        if (!arcs[a].x[e].domain) planes[{arcs[a].x[e].d, arcs[a].x[e].at}].push_back(2 * a + static_cast<std::size_t>(e));
    auto crossing = [&](std::size_t r) -> const Crossing<T, N>& { return arcs[r / 2].x[r % 2]; };
    for (const auto& [plane, recs] : planes) {
      std::vector<std::size_t> partners(recs.size(), 0), partner(recs.size(), 0);
      for (std::size_t p = 0; p < recs.size(); ++p)
        for (std::size_t q = p + 1; q < recs.size(); ++q) {
          const auto &x = crossing(recs[p]), &y = crossing(recs[q]);
          if (x.side == y.side) continue;  // the same side of the plane: different boxes' facets there do not overlap
          bool meet = true;
          for (std::size_t t = 0; t + 1 < N && meet; ++t) meet = !(x.hi[t] < y.lo[t] || y.hi[t] < x.lo[t]);
          if (!meet) continue;
          ++partners[p];
          ++partners[q];
          partner[p] = q;
          partner[q] = p;
        }
      for (std::size_t p = 0; p < recs.size(); ++p) {
        if (partners[p] > 1) {
          out.undecided_reason = "two crossings of the curve with a split plane cannot be told apart";
          return false;
        }
        if (partners[p] == 1) nodes.join(recs[p], recs[partner[p]]);
      }
    }
    // Node kinds: 1 an end on the domain's facets, 2 a V-point; 0 an inner node.
    std::vector<int> kind(nx + arcs.size(), 0);
    std::vector<char> seam(nx + arcs.size(), 0);
    for (std::size_t r = 0; r < nx; ++r)
      if (crossing(r).domain) {
        kind[nodes.find(r)] = 1;
        seam[nodes.find(r)] = crossing(r).identified;
      }
    struct Edge {
      std::size_t a, b;
    };
    std::vector<Edge> edges;  // the active ones
    for (std::size_t a = 0; a < arcs.size(); ++a) {
      const std::size_t n0 = nodes.find(2 * a), n1 = nodes.find(2 * a + 1), m = nx + a;
      if (!arcs[a].halves) {
        if (arcs[a].active[0]) edges.push_back({n0, n1});
        continue;
      }
      if (arcs[a].vpoint) kind[m] = 2;
      if (arcs[a].active[0]) edges.push_back({n0, m});
      if (arcs[a].active[1]) edges.push_back({m, n1});
    }
    std::vector<std::size_t> degree(kind.size(), 0);
    std::vector<std::vector<std::size_t>> at(kind.size());
    for (std::size_t e = 0; e < edges.size(); ++e)
      for (std::size_t n : {edges[e].a, edges[e].b}) {
        ++degree[n];
        at[n].push_back(e);
      }
    UnionFind comp(edges.size());
    for (std::size_t n = 0; n < kind.size(); ++n) {
      if (kind[n] != 0 || degree[n] == 0) continue;
      if (degree[n] != 2) {
        out.undecided_reason = "an arc of the curve ends inside the domain without a V-point (inconsistent subdivision)";
        return false;
      }
      comp.join(at[n][0], at[n][1]);
    }
    std::map<std::size_t, std::size_t> ends;  // component -> its ends
    for (std::size_t e = 0; e < edges.size(); ++e) {
      std::size_t& c = ends[comp.find(e)];
      for (std::size_t n : {edges[e].a, edges[e].b})
        if (kind[n] != 0) {
          ++c;
          if (kind[n] == 1) {
            ++out.ends_on_facets;
            out.ends_on_identified += static_cast<std::size_t>(seam[n]);
          } else
            ++out.ends_at_points;
        }
    }
    for (const auto& [c, e] : ends) {
      if (e == 0) ++out.loops;
      else if (e == 2) ++out.arcs;
      else {
        out.undecided_reason = "a curve with " + std::to_string(e) + " ends (inconsistent subdivision)";
        return false;
      }
    }
    return true;
  }
};

}  // namespace

namespace vrep_detail {

template <class T, std::size_t N>
CurveCount count_curve(const CurveProblem<T, N>& problem) {
  static_assert(N == 2 || N == 3, "curves in 2 or 3 unknowns");
  if (problem.curve.size() != N - 1) throw ValidationError("curve", "needs N - 1 equations", "pass one leaf on a face, two inside");
  CurveCount out;
  std::string reason;
  std::size_t spent = 0;
  for (int f = 0; f < 3; ++f) {
    out = CurveCount{};
    CurveRun<T, N> run(problem, split_fraction<T>(f));
    const bool decided = run.run(out);
    spent += out.boxes;
    if (decided) {
      out.decided = true;
      out.split_fraction = f;
      out.spent = spent;
      return out;
    }
    reason = out.undecided_reason;
    if (permanent(reason)) break;  // another split fraction cannot help
  }
  out = CurveCount{};
  out.undecided_reason = reason;
  out.spent = spent;
  return out;
}

template Bernstein<Rational> divide_facet(const Bernstein<Rational>&, int, int);
template Bernstein<double> divide_facet(const Bernstein<double>&, int, int);
template CurveCount count_curve(const CurveProblem<Rational, 2>&);
template CurveCount count_curve(const CurveProblem<Rational, 3>&);
template CurveCount count_curve(const CurveProblem<double, 2>&);
template CurveCount count_curve(const CurveProblem<double, 3>&);

}  // namespace vrep_detail

template <class T>
TrimmedCurves<T> trimmed_curves(const BSpline<T>& V, const Region<T>& trim, const CurveOptions& options, const Limits& limits) {
  if (options.max_level < 1 || options.max_level > 200) throw ValidationError("max_level", "must be in [1, 200]", "give a level between 1 and 200");
  const std::vector<const Poly3<T>*> leaves = checked_trim_leaves(V, trim, options.max_boxes, limits);
  const std::size_t nl = leaves.size();
  TrimmedCurves<T> out;
  if (nl < 2) return out;
  CurveProblem<T, 3> problem = cell_problem(V, trim, leaves, options, limits);
  std::size_t spent = 0;  // boxes over all pairs and attempts
  for (std::size_t i = 0; i < nl; ++i)
    for (std::size_t j = i + 1; j < nl; ++j) {
      bool meet = false;
      for (const auto& p : problem.pieces) meet = meet || (bern_sign(p.G[i]) == 0 && bern_sign(p.G[j]) == 0);
      if (!meet) continue;
      problem.curve = {i, j};
      CurveCount c;
      if (spent >= options.max_total_boxes)
        c.undecided_reason = "the cell's total box budget (" + std::to_string(options.max_total_boxes) + ") is spent";
      else {
        problem.options.max_boxes = std::min(options.max_boxes, options.max_total_boxes - spent);
        c = count_curve(problem);
        spent += c.spent;
      }
      typename TrimmedCurves<T>::Pair pr;
      pr.i = i;
      pr.j = j;
      pr.decided = c.decided;
      pr.arcs = c.arcs;
      pr.loops = c.loops;
      pr.ends_on_faces = c.ends_on_facets;
      pr.ends_at_points = c.ends_at_points;
      pr.ends_on_identified_faces = c.ends_on_identified;
      pr.boxes = c.boxes;
      pr.crossings = c.crossings;
      pr.split = split_fraction<T>(c.split_fraction);
      pr.undecided_reason = c.undecided_reason;
      if (!pr.decided) out.decided = false;
      else {
        out.arcs += pr.arcs;
        out.loops += pr.loops;
      }
      out.pairs.push_back(std::move(pr));
    }
  return out;
}

template TrimmedCurves<Rational> trimmed_curves(const BSpline<Rational>&, const Region<Rational>&, const CurveOptions&, const Limits&);
template TrimmedCurves<double> trimmed_curves(const BSpline<double>&, const Region<double>&, const CurveOptions&, const Limits&);

}  // namespace splinex
