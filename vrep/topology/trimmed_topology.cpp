// The boundary structure of a trimmed cell (vrep/trimmed/trimmed.hpp: trimmed_topology), instantiated for
// Rational and double.
#include <algorithm>
#include <deque>
#include <functional>
#include <type_traits>

#include "base/errors.hpp"
#include "solve/solver.hpp"
#include "spline/bezier.hpp"
#include "vrep/topology/box_components.hpp"
#include "vrep/topology/curve_graph.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_topology.hpp"

namespace splinex {

namespace vrep_detail {

template <class T>
std::vector<Bernstein<T>> leaves_on_face(const BSpline<T>& V, const LeafPiece<T>& p, int d, int s, const std::vector<char>* outside,
                                    std::vector<int>* multiplicity) {
  const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
  const std::array<T, 2> face_lo{V.domain_lo(a), V.domain_lo(b)}, face_hi{V.domain_hi(a), V.domain_hi(b)};
  const std::array<T, 2> plo{p.lo[a], p.lo[b]}, phi{p.hi[a], p.hi[b]};
  std::vector<Bernstein<T>> out;
  if (multiplicity) multiplicity->assign(p.G.size(), 0);
  for (std::size_t l = 0; l < p.G.size(); ++l) {
    Bernstein<T> G = p.G[l];
    int m = 0;
    while (G.deg[static_cast<std::size_t>(d)] > 0 && !all_zero(G) && all_zero(bern_face(G, d, s))) {
      G = divide_facet(G, d, s);
      ++m;
    }
    if (multiplicity) (*multiplicity)[l] = m;
    Bernstein<T> H = bern_face(G, d, s);
    for (int fd = 0; fd < 2; ++fd)
      for (int fs = 0; fs < 2; ++fs)
        while ((fs ? phi[static_cast<std::size_t>(fd)] == face_hi[static_cast<std::size_t>(fd)] : plo[static_cast<std::size_t>(fd)] == face_lo[static_cast<std::size_t>(fd)]) &&
               H.deg[static_cast<std::size_t>(fd)] > 0 && !all_zero(H) && all_zero(bern_face(H, fd, fs)))
          H = divide_facet(H, fd, fs);
    // Just outside the face the quotient's sign is multiplied by (-1)^m (m: the leaf's order of
    // vanishing on the face).
    if (outside && (*outside)[l] && m % 2 == 1)
      for (auto& c : H.c) c = -c;
    out.push_back(std::move(H));
  }
  return out;
}

template <class T>
FaceEdges face_edges(const BSpline<T>& V, int d, int s, const Limits& limits) {
  const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
  FaceEdges out;
  std::vector<BSpline<T>> curves;
  for (int fd = 0; fd < 2; ++fd)
    for (int fs = 0; fs < 2; ++fs) {
      std::array<int, 3> sides{};
      sides[static_cast<std::size_t>(d)] = s;
      const int other = fd == 0 ? b : a;  // the edge fixes face direction fd, runs along the other
      sides[static_cast<std::size_t>(fd == 0 ? a : b)] = fs;
      curves.push_back(edge_curve(V, other, sides));
      out.ids.push_back({fd, fs});
    }
  out.point.assign(curves.size(), 0);
  for (std::size_t i = 0; i < curves.size(); ++i) {
    out.point[i] = curve_collapsed(curves[i]);
    for (std::size_t j = i + 1; j < curves.size(); ++j)
      if (same_curve(curves[i], curves[j], T(0), true, limits)) out.same.push_back({i, j});
  }
  return out;
}

template <class T>
CurveProblem<T, 2> face_curve_problem(const BSpline<T>& V, const std::vector<LeafPiece<T>>& pieces, int d, int s, const FaceEdges& edges,
                                      const std::vector<char>* outside) {
  const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
  CurveProblem<T, 2> problem;
  problem.dom_lo = {V.domain_lo(a), V.domain_lo(b)};
  problem.dom_hi = {V.domain_hi(a), V.domain_hi(b)};
  for (std::size_t e = 0; e < edges.ids.size(); ++e) {
    bool id = edges.point[e] != 0;
    for (const auto& [i, j] : edges.same) id = id || i == e || j == e;
    problem.identified[static_cast<std::size_t>(edges.ids[e].first)][static_cast<std::size_t>(edges.ids[e].second)] = id;
  }
  const T at = s ? V.domain_hi(d) : V.domain_lo(d);
  for (const auto& p : pieces) {
    if (!((s ? p.hi[d] : p.lo[d]) == at)) continue;
    CurvePiece<T, 2> fp;
    fp.lo = {p.lo[a], p.lo[b]};
    fp.hi = {p.hi[a], p.hi[b]};
    fp.G = leaves_on_face(V, p, d, s, outside, nullptr);
    problem.pieces.push_back(std::move(fp));
  }
  return problem;
}

#define SPLINEX_FACE_HELPERS(T)                                                                                                        \
  template std::vector<Bernstein<T>> leaves_on_face(const BSpline<T>&, const LeafPiece<T>&, int, int, const std::vector<char>*, std::vector<int>*); \
  template FaceEdges face_edges(const BSpline<T>&, int, int, const Limits&);                                                           \
  template CurveProblem<T, 2> face_curve_problem(const BSpline<T>&, const std::vector<LeafPiece<T>>&, int, int, const FaceEdges&,      \
                                                 const std::vector<char>*);
SPLINEX_FACE_HELPERS(Rational)
SPLINEX_FACE_HELPERS(double)
#undef SPLINEX_FACE_HELPERS

}  // namespace vrep_detail

namespace {

using namespace vrep_detail;

/// Strict truth of G >= 0 on a box: every coefficient > 0 (in), every one < 0 (out), else mixed.
template <class T>
Truth strict_truth(const Bernstein<T>& G) {
  bool pos = true, neg = true;
  for (const auto& x : G.c) {
    pos = pos && T(0) < x;
    neg = neg && x < T(0);
  }
  return pos ? Truth::in : neg ? Truth::out : Truth::mixed;
}

/// The formula's truth with leaf k forced to `forced`.
template <class T>
Truth forced_truth(const Region<T>& R, std::vector<Truth> leaf, std::size_t k, Truth forced) {
  leaf[k] = forced;
  std::size_t i = 0;
  return combine(R, leaf, i);
}

const char* kDirName[3] = {"u", "v", "w"};

/// The halves of a subdivision box (its leaves' polynomials and its parameter range) across its
/// widest parameter direction.
template <class Box>
void halve(const Box& x, Box (&c)[2]) {
  int dir = 0;
  for (int d = 1; d < static_cast<int>(x.lo.size()); ++d)
    if ((x.hi[dir] - x.lo[dir]) < (x.hi[d] - x.lo[d])) dir = d;
  for (auto& h : c) {
    h.lo = x.lo;
    h.hi = x.hi;
    h.G.resize(x.G.size());
  }
  for (std::size_t l = 0; l < x.G.size(); ++l) std::tie(c[0].G[l], c[1].G[l]) = vrep_detail::split_half(x.G[l], dir);
  const auto mid = (x.lo[dir] + x.hi[dir]) / 2;
  c[0].hi[dir] = mid;
  c[1].lo[dir] = mid;
}

/// The values at the corners of a tensor Bernstein polynomial's box (its corner coefficients).
template <class T>
std::vector<T> corner_values(const Bernstein<T>& b) {
  const std::size_t n = b.deg.size();
  std::vector<T> out;
  for (std::size_t c = 0; c < (std::size_t(1) << n); ++c) {
    std::size_t i = 0;
    for (std::size_t l = 0; l < n; ++l)
      if ((c >> l) & 1) i += static_cast<std::size_t>(b.deg[l]) * detail::tensor_stride(b.deg, static_cast<int>(l));
    out.push_back(b.c[i]);
  }
  return out;
}

/// Leaf k may bound the cell in a box: it may vanish there (its coefficients are not all of one
/// strict sign: a zero set on the box's boundary counts, e.g. on a split plane) and the formula, with
/// the other leaves' coefficient truths, does not come out the same decided value with k in and out.
template <class T>
bool may_bound(const Region<T>& R, const std::vector<Bernstein<T>>& G, const std::vector<Truth>& leaf, std::size_t k) {
  if (strict_truth(G[k]) != Truth::mixed) return false;
  const Truth i = forced_truth(R, leaf, k, Truth::in), o = forced_truth(R, leaf, k, Truth::out);
  return !(i == o && i != Truth::mixed);
}

/// Every other leaf strictly signed on the box, and the formula in with leaf k on one side and out
/// with it on the other.
template <class T>
bool others_decide(const Region<T>& R, const std::vector<Bernstein<T>>& G, std::size_t k) {
  std::vector<Truth> strict;
  for (std::size_t l = 0; l < G.size(); ++l) {
    strict.push_back(l == k ? Truth::mixed : strict_truth(G[l]));
    if (l != k && strict.back() == Truth::mixed) return false;
  }
  const Truth i = forced_truth(R, strict, k, Truth::in), o = forced_truth(R, strict, k, Truth::out);
  return i != Truth::mixed && o != Truth::mixed && i != o;
}

/// The sign pattern of leaf k's corner values: bit 0 some > 0, bit 1 some < 0.
template <class T>
int corner_signs(const Bernstein<T>& g) {
  int m = 0;
  for (const auto& v : corner_values(g)) m |= (T(0) < v ? 1 : 0) | (v < T(0) ? 2 : 0);
  return m;
}

/// Marks the cover boxes that certainly hold a point of leaf k's bounding piece. On a path from a
/// corner where the leaf is > 0 to one where it is < 0 it changes sign at some point; inside one box,
/// or through the common point of two touching boxes, where every other leaf is strictly signed (the
/// same sign on both: they touch) and the formula changes with the leaf, that point bounds the cell.
/// It lies in the box (or one of the two) that is in the cover, and two touching cover boxes are in
/// one component.
template <class T, std::size_t N>
std::vector<char> certified_points(const Region<T>& R, const std::vector<std::vector<Bernstein<T>>>& G, const std::vector<std::array<T, N>>& lo,
                                   const std::vector<std::array<T, N>>& hi, const std::vector<char>& in_cover, std::size_t k) {
  const std::size_t n = G.size();
  std::vector<char> mark(n, 0);
  std::vector<std::size_t> decided;
  std::vector<int> signs(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!others_decide(R, G[i], k)) continue;
    decided.push_back(i);
    signs[i] = corner_signs(G[i][k]);
    if (signs[i] == 3 && in_cover[i]) mark[i] = 1;
  }
  for (const auto& [a, b] : vrep_detail::touching_pairs(lo, hi, decided))
    if (((signs[a] & 1) && (signs[b] & 2)) || ((signs[a] & 2) && (signs[b] & 1))) {
      if (in_cover[a]) mark[a] = 1;
      if (in_cover[b]) mark[b] = 1;
    }
  return mark;
}

/// A part's exact count into its Surface entry; in exact arithmetic a count below the certified
/// lower bound is an internal error (both are certified), never a result.
template <class T>
void take_count(typename TrimmedTopology<T>::Surface& sf, const RegionCount& rc) {
  sf.decided = rc.decided;
  sf.pieces = rc.pieces;
  sf.on_identified_edges = rc.on_identified;
  sf.undecided_reason = rc.undecided_reason;
  if (!std::is_floating_point_v<T> && sf.decided && sf.pieces < sf.at_least)
    throw std::logic_error("trimmed_topology: exact pieces of " + sf.what + " (" + std::to_string(sf.pieces) + ") below the certified lower bound (" +
                           std::to_string(sf.at_least) + ")");
}

/// Components of `cover` (after `join`) and how many of them hold a box marked in `certified`.
inline std::pair<std::size_t, std::size_t> count_components(const std::vector<std::size_t>& cover, const std::vector<char>& certified,
                                                            vrep_detail::UnionFind& uf) {
  std::vector<long> comp(certified.size(), -1);
  std::vector<char> has;
  for (std::size_t i : cover) {
    const std::size_t r = uf.find(i);
    if (comp[r] < 0) {
      comp[r] = static_cast<long>(has.size());
      has.push_back(0);
    }
    if (certified[i]) has[static_cast<std::size_t>(comp[r])] = 1;
  }
  return {has.size(), static_cast<std::size_t>(std::count(has.begin(), has.end(), 1))};
}

}  // namespace

template <class T>
TrimmedTopology<T> trimmed_topology(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes, const Limits& limits) {
  const std::vector<const Poly3<T>*> leaves = checked_trim_leaves(V, trim, max_boxes, limits);
  const std::size_t nl = leaves.size();
  const auto pieces = leaf_pieces(V, leaves, limits);
  auto domain_at = [&](int d, int s) { return s ? V.domain_hi(d) : V.domain_lo(d); };
  auto truth_of = [&](const std::vector<Truth>& t) {
    std::size_t i = 0;
    return combine(trim, t, i);
  };
  TrimmedTopology<T> out;

  // Corners: exact values of every leaf there.
  for (int c = 0; c < 8; ++c) {
    for (const auto& p : pieces) {
      bool here = true;
      for (int d = 0; d < 3; ++d) here = here && (((c >> d) & 1) ? p.hi[d] == V.domain_hi(d) : p.lo[d] == V.domain_lo(d));
      if (!here) continue;
      std::vector<Truth> t;
      for (const auto& G : p.G) t.push_back(value_truth(corner(G, c & 1, (c >> 1) & 1, c >> 2), T(0)));
      const Truth r = truth_of(t);
      if (r == Truth::in) ++out.corners;
      else if (r == Truth::mixed) ++out.corners_on_trimming;
      break;
    }
  }

  // Edges: exact cuts at the leaves' roots along each.
  SolveOptions so;
  so.recognize_rationals = true;
  for (int along = 0; along < 3; ++along)
    for (int s1 = 0; s1 < 2; ++s1)
      for (int s2 = 0; s2 < 2; ++s2) {
        typename TrimmedTopology<T>::Edge e;
        e.along = along;
        const int a = along == 0 ? 1 : 0, b = along == 2 ? 1 : 2;  // the fixed directions, a < b
        e.sides[a] = s1;
        e.sides[b] = s2;
        const BSpline<T> C = edge_curve(V, along, e.sides);
        if (vrep_detail::curve_collapsed(C)) {
          e.status = TrimmedTopology<T>::Edge::collapsed;
          out.edges.push_back(e);
          continue;
        }
        // Per piece on the edge: the leaves as univariate polynomials along it.
        struct Segment {
          T lo, hi;
          std::vector<Bernstein<T>> g;
        };
        std::vector<Segment> segs;
        struct Event {
          T lo, hi;
        };
        std::vector<Event> events;
        for (const auto& p : pieces) {
          if (!((s1 ? p.hi[a] : p.lo[a]) == domain_at(a, s1)) || !((s2 ? p.hi[b] : p.lo[b]) == domain_at(b, s2))) continue;
          Segment sg{p.lo[along], p.hi[along], {}};
          for (const auto& G : p.G) sg.g.push_back(bern_face(bern_face(G, b, s2), a, s1));  // b > a: remove b first
          for (const auto& g : sg.g) {
            if (all_zero(g)) {
              e.status = TrimmedTopology<T>::Edge::on_trimming_surface;
              continue;
            }
            const SolveResult<T> r = solve_system(std::vector<Bernstein<T>>{g}, {sg.lo}, {sg.hi}, so);
            if (!r.undecided.empty()) e.status = Uncertain<typename TrimmedTopology<T>::Edge::Status>::undecided("a solver box left (tangency)");
            for (const auto& root : r.roots) events.push_back(root.exact ? Event{root.point[0], root.point[0]} : Event{root.lo[0], root.hi[0]});
          }
          segs.push_back(std::move(sg));
        }
        if (e.status != TrimmedTopology<T>::Edge::curve) {
          out.edges.push_back(e);
          continue;
        }
        // The truth between consecutive events, at an exact point there.
        auto truth_at = [&](const T& t) {
          for (const auto& sg : segs) {
            if (t < sg.lo || sg.hi < t) continue;
            const std::vector<T> x{(t - sg.lo) / (sg.hi - sg.lo)};
            std::vector<Truth> tr;
            for (const auto& g : sg.g) tr.push_back(value_truth(bern_value(g, x), T(0)));
            return static_cast<int>(truth_of(tr));
          }
          return static_cast<int>(Truth::mixed);
        };
        std::vector<std::pair<T, T>> ev;
        for (const auto& x : events) ev.push_back({x.lo, x.hi});
        const auto runs = edge_runs(ev, V.domain_lo(along), V.domain_hi(along), truth_at);
        if (!runs.decided) e.status = Uncertain<typename TrimmedTopology<T>::Edge::Status>::undecided("the truth between the events is not decided");
        e.pieces = runs.pieces;
        e.points = runs.points;
        e.cuts = runs.cuts;
        out.edges.push_back(e);
      }

  // V-points off the edges: where two leaves meet on a face of the domain (2x2 systems on the
  // face) or three inside it (3x3 systems), certified simple roots strictly inside the piece, with
  // every other leaf of one strict sign on the root's box. Near such a root the leaves' zero sets
  // are transversal (Krawczyk: the Jacobian is regular on the box), so the sign patterns of the
  // meeting leaves are the local sectors; the root is a corner of the cell's boundary when the
  // formula depends on every one of those signs there (else one zero set passes by smoothly, or
  // the point is not on the cell at all).
  {
    SolveOptions vo;
    vo.max_depth = 24;
    vo.max_boxes = 4000;
    vo.refine_bits = 40;
    const std::size_t nl = leaves.size();
    auto corner_of = [&](const std::vector<Truth>& fixed, const std::vector<std::size_t>& which) { return depends_on_each(trim, fixed, which); };
    // The roots of the leaves `which` (Bernstein over the unit box standing for [lo, hi]) and the
    // decision at each; `all` every leaf on the same box; (dir, side) the face of V's domain, or
    // dir = -1 inside.
    auto meet = [&](const std::vector<Bernstein<T>>& sys, const std::vector<std::size_t>& which, const std::vector<Bernstein<T>>& all, const std::vector<T>& lo,
                    const std::vector<T>& hi, int dir, int side) {
      std::size_t& found = dir < 0 ? out.interior_points : out.face_points;
      std::size_t& undecided = out.points_undecided;
      const SolveResult<T> r = solve_system(sys, lo, hi, vo);
      undecided += r.undecided.size();
      const std::size_t n = lo.size();
      // With every other leaf decided near the root (clear): a V-point when the formula depends
      // on each meeting sign; otherwise undecided.
      auto conclude = [&](bool clear, const std::vector<Truth>& fixed, const std::vector<T>& at_lo, const std::vector<T>& at_hi) {
        if (!clear) ++undecided;
        else if (corner_of(fixed, which)) {
          ++found;
          out.inner_points.push_back({dir, side, which, at_lo, at_hi});
        }
      };
      for (const auto& root : r.roots) {
        std::vector<Truth> fixed(nl, Truth::mixed);
        if (root.exact) {
          // An exact rational root: simple and transversal when the Jacobian is regular there
          // (exact determinant); the other leaves' exact values decide them nearby.
          bool inside = true;
          std::vector<T> u(n);
          for (std::size_t d = 0; d < n; ++d) {
            inside = inside && lo[d] < root.point[d] && root.point[d] < hi[d];
            u[d] = (root.point[d] - lo[d]) / (hi[d] - lo[d]);
          }
          std::vector<std::vector<T>> J(n, std::vector<T>(n));
          for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = 0; b < n; ++b) J[a][b] = bern_value(bern_derivative(sys[a], static_cast<int>(b)), u);
          T det;
          if (n == 2) det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
          else
            det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                  J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
          bool clear = inside && !(det == T(0));
          for (std::size_t l = 0; l < nl && clear; ++l) {
            if (std::find(which.begin(), which.end(), l) != which.end()) continue;
            fixed[l] = value_truth(bern_value(all[l], u), T(0));
            clear = fixed[l] != Truth::mixed;
          }
          conclude(clear, fixed, root.point, root.point);
          continue;
        }
        if (!root.unique) {
          ++undecided;
          continue;
        }
        bool inside = true;
        for (std::size_t d = 0; d < n; ++d) inside = inside && lo[d] < root.lo[d] && root.hi[d] < hi[d];
        if (!inside) {  // on the piece's boundary: an edge's V-point, or across pieces
          ++undecided;
          continue;
        }
        bool clear = true;
        for (std::size_t l = 0; l < nl && clear; ++l) {
          if (std::find(which.begin(), which.end(), l) != which.end()) continue;
          Bernstein<T> b = all[l];
          for (std::size_t d = 0; d < n; ++d)
          {
            const T a = (root.lo[d] - lo[d]) / (hi[d] - lo[d]), c = (root.hi[d] - lo[d]) / (hi[d] - lo[d]);
            b = bern_restrict(b, static_cast<int>(d), a, c);
          }
          fixed[l] = strict_truth(b);
          clear = fixed[l] != Truth::mixed;
        }
        conclude(clear, fixed, root.lo, root.hi);
      }
    };
    for (const auto& p : pieces) {
      // On the faces of the domain that this piece touches.
      for (int d = 0; d < 3; ++d)
        for (int sd = 0; sd < 2; ++sd) {
          if (!((sd ? p.hi[d] : p.lo[d]) == domain_at(d, sd))) continue;
          std::vector<Bernstein<T>> H;
          for (const auto& G : p.G) H.push_back(bern_face(G, d, sd));
          std::vector<T> lo, hi;
          for (int e = 0; e < 3; ++e)
            if (e != d) {
              lo.push_back(p.lo[e]);
              hi.push_back(p.hi[e]);
            }
          for (std::size_t i = 0; i < nl; ++i)
            for (std::size_t j = i + 1; j < nl; ++j) {
              if (all_zero(H[i]) || all_zero(H[j]) || strict_truth(H[i]) != Truth::mixed || strict_truth(H[j]) != Truth::mixed) continue;
              meet({H[i], H[j]}, {i, j}, H, lo, hi, d, sd);
            }
        }
      // Inside: three leaves.
      std::vector<T> lo(p.lo.begin(), p.lo.end()), hi(p.hi.begin(), p.hi.end());
      for (std::size_t i = 0; i < nl; ++i)
        for (std::size_t j = i + 1; j < nl; ++j)
          for (std::size_t k = j + 1; k < nl; ++k) {
            if (strict_truth(p.G[i]) != Truth::mixed || strict_truth(p.G[j]) != Truth::mixed || strict_truth(p.G[k]) != Truth::mixed) continue;
            meet({p.G[i], p.G[j], p.G[k]}, {i, j, k}, p.G, lo, hi, -1, -1);
          }
    }
  }

  // Faces: 2D subdivision with the faces' coefficients.
  const std::size_t face_budget = std::max<std::size_t>(8, max_boxes / 8);
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) {
      typename TrimmedTopology<T>::Surface sf;
      sf.what = std::string("face ") + kDirName[d] + " = " + (s ? "end" : "start");
      sf.dir = d;
      sf.side = s;
      const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
      const BSpline<T> Fc = face(V, d, s);
      if (collapsed(Fc, 0) || collapsed(Fc, 1)) {
        sf.collapsed = true;
        out.surfaces.push_back(sf);
        continue;
      }
      struct Box2 {
        std::vector<Bernstein<T>> G;
        std::array<T, 2> lo, hi;
        Truth truth;
      };
      auto eval2 = [&](Box2& x) {
        std::vector<Truth> t;
        for (const auto& G : x.G) t.push_back(coefficient_truth(G, T(0)));
        x.truth = truth_of(t);
      };
      // The leaves on the face, read from inside: a leaf containing the face (coplanar contact) is
      // divided by the face's parameter (its sign just inside the face), and a leaf vanishing
      // along an edge of the domain on this face by that edge's parameter (the same signs inside
      // the face). Without this the face's part would count where a coplanar leaf's zero set
      // lies on it, not where the cell is.
      auto face_leaves = [&](const LeafPiece<T>& p) { return leaves_on_face(V, p, d, s, nullptr, nullptr); };
      std::deque<Box2> todo;
      std::vector<Box2> done;
      for (const auto& p : pieces) {
        if (!((s ? p.hi[d] : p.lo[d]) == domain_at(d, s))) continue;
        Box2 x;
        x.G = face_leaves(p);
        x.lo = {p.lo[a], p.lo[b]};
        x.hi = {p.hi[a], p.hi[b]};
        eval2(x);
        if (x.truth == Truth::mixed) todo.push_back(std::move(x));
        else done.push_back(std::move(x));
      }
      while (!todo.empty() && todo.size() + done.size() < face_budget) {
        Box2 x = std::move(todo.front());
        todo.pop_front();
        Box2 c[2];
        halve(x, c);
        for (auto& h : c) {
          eval2(h);
          if (h.truth == Truth::mixed) todo.push_back(std::move(h));
          else done.push_back(std::move(h));
        }
      }
      for (auto& x : todo) done.push_back(std::move(x));
      std::vector<std::array<T, 2>> lo, hi;
      std::vector<std::size_t> cover;
      for (std::size_t i = 0; i < done.size(); ++i) {
        lo.push_back(done[i].lo);
        hi.push_back(done[i].hi);
        if (done[i].truth != Truth::out) cover.push_back(i);
      }
      // The face's own identifications: an edge collapsed to a point or equal to another edge of
      // the face joins every box of a cover meeting it (conservative).
      const FaceEdges edges_ids = face_edges(V, d, s, limits);
      const auto& edge_ids = edges_ids.ids;
      const auto& point = edges_ids.point;
      const auto& same = edges_ids.same;
      auto components = [&](const std::vector<std::size_t>& cov, const std::vector<char>& certified) {
        UnionFind uf(done.size());
        join_touching(lo, hi, cov, uf);
        auto touching = [&](std::size_t e) {
          std::vector<std::size_t> t;
          const int fd = edge_ids[e].first, fs = edge_ids[e].second;
          const T at = domain_at(fd == 0 ? a : b, fs);
          for (std::size_t i : cov)
            if ((fs ? hi[i][fd] : lo[i][fd]) == at) t.push_back(i);
          return t;
        };
        auto join_all = [&](const std::vector<std::size_t>& t) {
          for (std::size_t i = 1; i < t.size(); ++i) uf.join(t[0], t[i]);
        };
        for (std::size_t e = 0; e < point.size(); ++e)
          if (point[e]) join_all(touching(e));
        for (const auto& [i, j] : same) {
          auto t = touching(i);
          const auto t2 = touching(j);
          t.insert(t.end(), t2.begin(), t2.end());
          join_all(t);
        }
        return count_components(cov, certified, uf);
      };
      std::vector<char> in_box(done.size(), 0);
      for (std::size_t i = 0; i < done.size(); ++i) in_box[i] = done[i].truth == Truth::in;
      const auto [fc, fl] = components(cover, in_box);
      sf.boxes = done.size();
      sf.cover_boxes = cover.size();
      sf.cover = fc;
      sf.at_least = fl;
      sf.absent = cover.empty();
      const std::size_t face_index = out.surfaces.size();
      out.surfaces.push_back(sf);
      // The trimming surfaces' boundary curves on this face: per leaf, where it bounds the face's part.
      std::vector<std::vector<Bernstein<T>>> Gs;
      std::vector<std::vector<Truth>> truths;
      for (const auto& x : done) {
        Gs.push_back(x.G);
        truths.emplace_back();
        for (const auto& G : x.G) truths.back().push_back(coefficient_truth(G, T(0)));
      }
      // The exact count of each leaf's curve on this face (vrep/topology/curve_graph.hpp, in 2D).
      CurveProblem<T, 2> face_problem = face_curve_problem(V, pieces, d, s, edges_ids, nullptr);
      face_problem.trim = &trim;
      face_problem.options.max_boxes = std::max<std::size_t>(512, max_boxes / 2);  // per leaf and attempt
      {
        // The exact pieces of the face's part (its leaves read from inside, as for the curves).
        take_count<T>(out.surfaces[face_index], count_region(face_problem));
      }
      for (std::size_t k = 0; k < nl; ++k) {
        typename TrimmedTopology<T>::FaceCurve fcv;
        fcv.dir = d;
        fcv.side = s;
        fcv.leaf = static_cast<int>(k);
        std::vector<std::size_t> cov;
        std::vector<char> in_cov(done.size(), 0);
        for (std::size_t i = 0; i < done.size(); ++i) {
          if (!may_bound(trim, Gs[i], truths[i], k)) continue;
          cov.push_back(i);
          in_cov[i] = 1;
        }
        const auto cert = certified_points(trim, Gs, lo, hi, in_cov, k);
        const auto [cc, cl] = components(cov, cert);
        fcv.cover = cc;
        fcv.at_least = cl;
        fcv.absent = cov.empty();
        if (fcv.absent) fcv.decided = true;
        else {
          bool on_face = false;
          for (const auto& fp : face_problem.pieces) on_face = on_face || all_zero(fp.G[k]);
          if (on_face) fcv.undecided_reason = "the trimming surface's composition vanishes identically";
          else {
            face_problem.curve = {k};
            const CurveCount c = count_curve(face_problem);
            fcv.decided = c.decided;
            fcv.arcs = c.arcs;
            fcv.loops = c.loops;
            fcv.ends_on_edges = c.ends_on_facets;
            fcv.ends_at_points = c.ends_at_points;
            fcv.undecided_reason = c.undecided_reason;
          }
        }
        out.face_curves.push_back(fcv);
      }
    }

  // Trimming surfaces: 3D subdivision of the boxes where some leaf may bound the cell.
  struct Box3 {
    std::vector<Bernstein<T>> G;
    std::array<T, 3> lo, hi;
    std::vector<Truth> leaf;  // coefficient truths
  };
  auto bounds_here = [&](const Box3& x, std::size_t k) { return may_bound(trim, x.G, x.leaf, k); };
  auto eval3 = [&](Box3& x) {
    x.leaf.clear();
    for (const auto& G : x.G) x.leaf.push_back(coefficient_truth(G, T(0)));
    for (std::size_t k = 0; k < nl; ++k)
      if (bounds_here(x, k)) return true;
    return false;
  };
  std::deque<Box3> todo3;
  std::vector<Box3> done3;
  if (nl > 0)
    for (const auto& p : pieces) {
      Box3 x{p.G, p.lo, p.hi, {}};
      if (eval3(x)) todo3.push_back(std::move(x));
      else done3.push_back(std::move(x));
    }
  while (!todo3.empty() && todo3.size() + done3.size() < max_boxes) {
    Box3 x = std::move(todo3.front());
    todo3.pop_front();
    Box3 c[2];
    halve(x, c);
    for (auto& h : c) {
      if (eval3(h)) todo3.push_back(std::move(h));
      else done3.push_back(std::move(h));
    }
  }
  for (auto& x : todo3) done3.push_back(std::move(x));
  out.boxes = done3.size();
  std::vector<std::array<T, 3>> lo3, hi3;
  std::vector<std::vector<Bernstein<T>>> G3;
  for (const auto& x : done3) {
    lo3.push_back(x.lo);
    hi3.push_back(x.hi);
    G3.push_back(x.G);
  }
  // The exact pieces of each trimming surface's part (vrep/topology/curve_graph.hpp: count_surface).
  CurveOptions surface_options;
  surface_options.max_boxes = std::min<std::size_t>(8192, std::max<std::size_t>(512, max_boxes));
  surface_options.max_total_boxes = 3 * surface_options.max_boxes;
  const CurveProblem<T, 3> surface_problem = cell_problem(V, trim, leaves, surface_options, limits);
  for (std::size_t k = 0; k < nl; ++k) {
    typename TrimmedTopology<T>::Surface sf;
    sf.leaf = static_cast<int>(k);
    std::size_t j = 0;
    std::string label;
    // The leaf's label: the region's leaves carry theirs.
    std::function<void(const Region<T>&)> find_label = [&](const Region<T>& R) {
      if (R.kind == Region<T>::leaf) {
        if (j++ == k) label = R.label;
        return;
      }
      for (const auto& p : R.parts) find_label(p);
    };
    find_label(trim);
    sf.what = "leaf " + std::to_string(k) + (label.empty() ? "" : " (" + label + ")");
    std::vector<std::size_t> cover;
    std::vector<char> in_cov(done3.size(), 0);
    for (std::size_t i = 0; i < done3.size(); ++i)
      if (bounds_here(done3[i], k)) {
        cover.push_back(i);
        in_cov[i] = 1;
      }
    const auto witness = certified_points(trim, G3, lo3, hi3, in_cov, k);
    UnionFind uf(done3.size());
    join_touching(lo3, hi3, cover, uf);
    join_identified(V, lo3, hi3, cover, uf, limits);
    const auto [cc, cl] = count_components(cover, witness, uf);
    sf.boxes = done3.size();
    sf.cover_boxes = cover.size();
    sf.cover = cc;
    sf.at_least = cl;
    sf.absent = cover.empty();
    if (sf.absent) sf.decided = true;
    else {
      take_count<T>(sf, count_surface(surface_problem, k));
    }
    out.surfaces.push_back(sf);
  }
  return out;
}

template TrimmedTopology<Rational> trimmed_topology(const BSpline<Rational>&, const Region<Rational>&, std::size_t, const Limits&);
template TrimmedTopology<double> trimmed_topology(const BSpline<double>&, const Region<double>&, std::size_t, const Limits&);

}  // namespace splinex
