// The boundary structure of a trimmed cell (vrep/trimmed/trimmed.hpp: trimmed_topology), instantiated for
// Rational and double.
#include <algorithm>
#include <functional>
#include <type_traits>

#include "base/errors.hpp"
#include "bernstein/subdivide.hpp"
#include "solve/solver.hpp"
#include "spline/bezier.hpp"
#include "vrep/topology/box_components.hpp"
#include "vrep/topology/curve_graph.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_edges.hpp"
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

/// A cover by a breadth-first refinement (bernstein/subdivide.hpp): the boxes roots(emit) makes,
/// halved while open(box) says the box is undecided and the cover has fewer than `budget` boxes;
/// the cover's boxes, the decided ones in the order they were made, then the undecided ones.
template <class Box, class Roots, class Open>
std::vector<Box> refine_cover(Roots&& roots, std::size_t budget, Open&& open) {
  std::vector<Box> cover;
  Budget b;
  b.max_boxes = budget;
  refine_from<Box>(
      roots, Order::breadth_first, b, [&](Box& x) { return open(x) ? Examined::split : Examined::settled; },
      [](Box&& x, int, auto&& emit) {
        Box c[2];
        vrep_detail::halve_widest(std::move(x), c);
        emit(std::move(c[0]));
        emit(std::move(c[1]));
      },
      []() { return false; }, [&](Box&& x, bool) { cover.push_back(std::move(x)); });
  return cover;
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

/// A subdivision box of a face of the domain: the leaves on the face, its parameter range, the
/// formula's truth there.
template <class T>
struct FaceBox {
  std::vector<Bernstein<T>> G;
  std::array<T, 2> lo, hi;
  Truth truth = Truth::mixed;
};

/// A subdivision box of the domain where some leaf may bound the cell.
template <class T>
struct CellBox {
  std::vector<Bernstein<T>> G;
  std::array<T, 3> lo, hi;
  std::vector<Truth> leaf;  // coefficient truths
};

/// The boxes of face (dir, side) and what the counts on the face read of them: the boxes' ranges,
/// the cover of the face's part, the leaves and their coefficient truths per box, the face's edges.
template <class T>
struct FaceCover {
  int dir = 0, side = 0;
  std::vector<FaceBox<T>> done;
  std::vector<std::array<T, 2>> lo, hi;
  std::vector<std::size_t> cover;
  FaceEdges edges;
  std::vector<std::vector<Bernstein<T>>> G;
  std::vector<std::vector<Truth>> truths;
};

/// The boxes of the trimming surfaces' cover and their ranges and leaves.
template <class T>
struct CellCover {
  std::vector<CellBox<T>> done;
  std::vector<std::array<T, 3>> lo, hi;
  std::vector<std::vector<Bernstein<T>>> G;
};

/// The steps of trimmed_topology (docs/vrep/topology.md) on one trivariate and region: its leaves,
/// their Bezier pieces and the budget, shared by the steps, and the result they fill in.
template <class T>
class TopologyRun {
 public:
  TopologyRun(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes, const Limits& limits)
      : V_(V),
        trim_(trim),
        max_boxes_(max_boxes),
        limits_(limits),
        leaves_(checked_trim_leaves(V, trim, max_boxes, limits)),
        nl_(leaves_.size()),
        pieces_(leaf_pieces(V, leaves_, limits)) {}

  /// Corners: exact values of every leaf there.
  void corners() {
    for (int c = 0; c < 8; ++c) {
      for (const auto& p : pieces_) {
        bool here = true;
        for (int d = 0; d < 3; ++d) here = here && (((c >> d) & 1) ? p.hi[d] == V_.domain_hi(d) : p.lo[d] == V_.domain_lo(d));
        if (!here) continue;
        std::vector<Truth> t;
        for (const auto& G : p.G) t.push_back(value_truth(corner(G, c & 1, (c >> 1) & 1, c >> 2), T(0)));
        const Truth r = truth_of(t);
        if (r == Truth::in) ++out_.corners;
        else if (r == Truth::mixed) ++out_.corners_on_trimming;
        break;
      }
    }
  }

  /// Edges: exact cuts at the leaves' roots along each.
  void edges() { cut_edges(V_, trim_, pieces_, out_.edges); }

  /// V-points off the edges: where two leaves meet on a face of the domain (2x2 systems on the
  /// face) or three inside it (3x3 systems), certified simple roots strictly inside the piece, with
  /// every other leaf of one strict sign on the root's box. Near such a root the leaves' zero sets
  /// are transversal (Krawczyk: the Jacobian is regular on the box), so the sign patterns of the
  /// meeting leaves are the local sectors; the root is a corner of the cell's boundary when the
  /// formula depends on every one of those signs there (else one zero set passes by smoothly, or
  /// the point is not on the cell at all).
  void v_points() {
    for (const auto& p : pieces_) {
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
          for (std::size_t i = 0; i < nl_; ++i)
            for (std::size_t j = i + 1; j < nl_; ++j) {
              if (all_zero(H[i]) || all_zero(H[j]) || strict_truth(H[i]) != Truth::mixed || strict_truth(H[j]) != Truth::mixed) continue;
              meet({H[i], H[j]}, {i, j}, H, lo, hi, d, sd);
            }
        }
      // Inside: three leaves.
      std::vector<T> lo(p.lo.begin(), p.lo.end()), hi(p.hi.begin(), p.hi.end());
      for (std::size_t i = 0; i < nl_; ++i)
        for (std::size_t j = i + 1; j < nl_; ++j)
          for (std::size_t k = j + 1; k < nl_; ++k) {
            if (strict_truth(p.G[i]) != Truth::mixed || strict_truth(p.G[j]) != Truth::mixed || strict_truth(p.G[k]) != Truth::mixed) continue;
            meet({p.G[i], p.G[j], p.G[k]}, {i, j, k}, p.G, lo, hi, -1, -1);
          }
    }
  }

  /// Faces: 2D subdivision with the faces' coefficients.
  void faces() {
    const std::size_t face_budget = std::max<std::size_t>(8, max_boxes_ / 8);
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) face_part(d, s, face_budget);
  }

  /// Trimming surfaces: 3D subdivision of the boxes where some leaf may bound the cell.
  void trimming_surfaces() {
    const CellCover<T> cover = surface_cover();
    // The exact pieces of each trimming surface's part (vrep/topology/curve_graph.hpp: count_surface).
    CurveOptions surface_options;
    surface_options.max_boxes = std::min<std::size_t>(8192, std::max<std::size_t>(512, max_boxes_));
    surface_options.max_total_boxes = 3 * surface_options.max_boxes;
    const CurveProblem<T, 3> surface_problem = cell_problem(V_, trim_, leaves_, surface_options, limits_);
    for (std::size_t k = 0; k < nl_; ++k) trimming_surface(k, cover, surface_problem);
  }

  TrimmedTopology<T> result() { return std::move(out_); }

 private:
  T domain_at(int d, int s) const { return s ? V_.domain_hi(d) : V_.domain_lo(d); }

  Truth truth_of(const std::vector<Truth>& t) const {
    std::size_t i = 0;
    return combine(trim_, t, i);
  }

  /// The solver's options for the V-points.
  static SolveOptions v_point_options() {
    SolveOptions vo;
    vo.max_depth = 24;
    vo.max_boxes = 4000;
    vo.refine_bits = 40;
    return vo;
  }

  /// With every other leaf decided near the root (clear): a V-point when the formula depends
  /// on each meeting sign; otherwise undecided.
  void conclude(bool clear, const std::vector<Truth>& fixed, const std::vector<std::size_t>& which, int dir, int side,
                const std::vector<T>& at_lo, const std::vector<T>& at_hi) {
    std::size_t& found = dir < 0 ? out_.interior_points : out_.face_points;
    std::size_t& undecided = out_.points_undecided;
    if (!clear) ++undecided;
    else if (depends_on_each(trim_, fixed, which)) {
      ++found;
      out_.inner_points.push_back({dir, side, which, at_lo, at_hi});
    }
  }

  /// The roots of the leaves `which` (Bernstein over the unit box standing for [lo, hi]) and the
  /// decision at each; `all` every leaf on the same box; (dir, side) the face of V's domain, or
  /// dir = -1 inside.
  void meet(const std::vector<Bernstein<T>>& sys, const std::vector<std::size_t>& which, const std::vector<Bernstein<T>>& all,
            const std::vector<T>& lo, const std::vector<T>& hi, int dir, int side) {
    std::size_t& undecided = out_.points_undecided;
    const SolveResult<T> r = solve_system(sys, lo, hi, vo_);
    undecided += r.undecided.size();
    const std::size_t n = lo.size();
    for (const auto& root : r.roots) {
      std::vector<Truth> fixed(nl_, Truth::mixed);
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
        for (std::size_t l = 0; l < nl_ && clear; ++l) {
          if (std::find(which.begin(), which.end(), l) != which.end()) continue;
          fixed[l] = value_truth(bern_value(all[l], u), T(0));
          clear = fixed[l] != Truth::mixed;
        }
        conclude(clear, fixed, which, dir, side, root.point, root.point);
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
      for (std::size_t l = 0; l < nl_ && clear; ++l) {
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
      conclude(clear, fixed, which, dir, side, root.lo, root.hi);
    }
  }

  /// Face (d, s): its part's cover, components and exact pieces, then the trimming surfaces'
  /// boundary curves on it.
  void face_part(int d, int s, std::size_t face_budget) {
    typename TrimmedTopology<T>::Surface sf;
    sf.what = std::string("face ") + kDirName[d] + " = " + (s ? "end" : "start");
    sf.dir = d;
    sf.side = s;
    const BSpline<T> Fc = face(V_, d, s);
    if (collapsed(Fc, 0) || collapsed(Fc, 1)) {
      sf.collapsed = true;
      out_.surfaces.push_back(sf);
      return;
    }
    FaceCover<T> f = face_cover(d, s, face_budget);
    std::vector<char> in_box(f.done.size(), 0);
    for (std::size_t i = 0; i < f.done.size(); ++i) in_box[i] = f.done[i].truth == Truth::in;
    const auto [fc, fl] = face_components(f, f.cover, in_box);
    sf.boxes = f.done.size();
    sf.cover_boxes = f.cover.size();
    sf.cover = fc;
    sf.at_least = fl;
    sf.absent = f.cover.empty();
    const std::size_t face_index = out_.surfaces.size();
    out_.surfaces.push_back(sf);
    // The trimming surfaces' boundary curves on this face: per leaf, where it bounds the face's part.
    for (const auto& x : f.done) {
      f.G.push_back(x.G);
      f.truths.emplace_back();
      for (const auto& G : x.G) f.truths.back().push_back(coefficient_truth(G, T(0)));
    }
    // The exact count of each leaf's curve on this face (vrep/topology/curve_graph.hpp, in 2D).
    CurveProblem<T, 2> face_problem = face_curve_problem(V_, pieces_, d, s, f.edges, nullptr);
    face_problem.trim = &trim_;
    face_problem.options.max_boxes = std::max<std::size_t>(512, max_boxes_ / 2);  // per leaf and attempt
    {
      // The exact pieces of the face's part (its leaves read from inside, as for the curves).
      take_count<T>(out_.surfaces[face_index], count_region(face_problem));
    }
    for (std::size_t k = 0; k < nl_; ++k) face_curve(f, k, face_problem);
  }

  /// The cover of face (d, s) by a 2D subdivision (the boxes where the formula is not out), and the
  /// face's edges.
  FaceCover<T> face_cover(int d, int s, std::size_t face_budget) const {
    const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
    auto eval2 = [&](FaceBox<T>& x) {
      std::vector<Truth> t;
      for (const auto& G : x.G) t.push_back(coefficient_truth(G, T(0)));
      x.truth = truth_of(t);
    };
    // The leaves on the face, read from inside: a leaf containing the face (coplanar contact) is
    // divided by the face's parameter (its sign just inside the face), and a leaf vanishing
    // along an edge of the domain on this face by that edge's parameter (the same signs inside
    // the face). Without this the face's part would count where a coplanar leaf's zero set
    // lies on it, not where the cell is.
    auto face_leaves = [&](const LeafPiece<T>& p) { return leaves_on_face(V_, p, d, s, nullptr, nullptr); };
    auto face_roots = [&](auto&& emit) {
      for (const auto& p : pieces_) {
        if (!((s ? p.hi[d] : p.lo[d]) == domain_at(d, s))) continue;
        FaceBox<T> x;
        x.G = face_leaves(p);
        x.lo = {p.lo[a], p.lo[b]};
        x.hi = {p.hi[a], p.hi[b]};
        emit(std::move(x));
      }
    };
    FaceCover<T> f;
    f.dir = d;
    f.side = s;
    f.done = refine_cover<FaceBox<T>>(face_roots, face_budget, [&](FaceBox<T>& x) {
      eval2(x);
      return x.truth == Truth::mixed;
    });
    for (std::size_t i = 0; i < f.done.size(); ++i) {
      f.lo.push_back(f.done[i].lo);
      f.hi.push_back(f.done[i].hi);
      if (f.done[i].truth != Truth::out) f.cover.push_back(i);
    }
    // The face's own identifications: an edge collapsed to a point or equal to another edge of
    // the face joins every box of a cover meeting it (conservative).
    f.edges = face_edges(V_, d, s, limits_);
    return f;
  }

  /// Components of the face's boxes `cov` (touching, and joined by the face's identifications) and
  /// how many of them hold a box marked in `certified`.
  std::pair<std::size_t, std::size_t> face_components(const FaceCover<T>& f, const std::vector<std::size_t>& cov,
                                                      const std::vector<char>& certified) const {
    const int a = f.dir == 0 ? 1 : 0, b = f.dir == 2 ? 1 : 2;
    const auto& edge_ids = f.edges.ids;
    const auto& point = f.edges.point;
    const auto& same = f.edges.same;
    const auto& lo = f.lo;
    const auto& hi = f.hi;
    UnionFind uf(f.done.size());
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
  }

  /// Leaf k's boundary curve on the face: its cover, components and exact count.
  void face_curve(const FaceCover<T>& f, std::size_t k, CurveProblem<T, 2>& face_problem) {
    typename TrimmedTopology<T>::FaceCurve fcv;
    fcv.dir = f.dir;
    fcv.side = f.side;
    fcv.leaf = static_cast<int>(k);
    std::vector<std::size_t> cov;
    std::vector<char> in_cov(f.done.size(), 0);
    for (std::size_t i = 0; i < f.done.size(); ++i) {
      if (!may_bound(trim_, f.G[i], f.truths[i], k)) continue;
      cov.push_back(i);
      in_cov[i] = 1;
    }
    const auto cert = certified_points(trim_, f.G, f.lo, f.hi, in_cov, k);
    const auto [cc, cl] = face_components(f, cov, cert);
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
    out_.face_curves.push_back(fcv);
  }

  bool bounds_here(const CellBox<T>& x, std::size_t k) const { return may_bound(trim_, x.G, x.leaf, k); }

  /// The 3D subdivision's boxes (the budget's), their ranges and leaves.
  CellCover<T> surface_cover() {
    auto eval3 = [&](CellBox<T>& x) {
      x.leaf.clear();
      for (const auto& G : x.G) x.leaf.push_back(coefficient_truth(G, T(0)));
      for (std::size_t k = 0; k < nl_; ++k)
        if (bounds_here(x, k)) return true;
      return false;
    };
    auto roots3 = [&](auto&& emit) {
      if (nl_ > 0)
        for (const auto& p : pieces_) emit(CellBox<T>{p.G, p.lo, p.hi, {}});
    };
    CellCover<T> cover;
    cover.done = refine_cover<CellBox<T>>(roots3, max_boxes_, eval3);
    out_.boxes = cover.done.size();
    for (const auto& x : cover.done) {
      cover.lo.push_back(x.lo);
      cover.hi.push_back(x.hi);
      cover.G.push_back(x.G);
    }
    return cover;
  }

  /// Leaf k's trimming surface: its cover, components and exact pieces.
  void trimming_surface(std::size_t k, const CellCover<T>& c, const CurveProblem<T, 3>& surface_problem) {
    const auto& done3 = c.done;
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
    find_label(trim_);
    sf.what = "leaf " + std::to_string(k) + (label.empty() ? "" : " (" + label + ")");
    std::vector<std::size_t> cover;
    std::vector<char> in_cov(done3.size(), 0);
    for (std::size_t i = 0; i < done3.size(); ++i)
      if (bounds_here(done3[i], k)) {
        cover.push_back(i);
        in_cov[i] = 1;
      }
    const auto witness = certified_points(trim_, c.G, c.lo, c.hi, in_cov, k);
    UnionFind uf(done3.size());
    join_touching(c.lo, c.hi, cover, uf);
    join_identified(V_, c.lo, c.hi, cover, uf, limits_);
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
    out_.surfaces.push_back(sf);
  }

  const BSpline<T>& V_;
  const Region<T>& trim_;
  std::size_t max_boxes_;
  const Limits& limits_;
  std::vector<const Poly3<T>*> leaves_;
  std::size_t nl_;
  std::vector<LeafPiece<T>> pieces_;
  SolveOptions vo_ = v_point_options();
  TrimmedTopology<T> out_;
};

}  // namespace

template <class T>
TrimmedTopology<T> trimmed_topology(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes, const Limits& limits) {
  TopologyRun<T> run(V, trim, max_boxes, limits);
  run.corners();
  run.edges();
  run.v_points();
  run.faces();
  run.trimming_surfaces();
  return run.result();
}

template TrimmedTopology<Rational> trimmed_topology(const BSpline<Rational>&, const Region<Rational>&, std::size_t, const Limits&);
template TrimmedTopology<double> trimmed_topology(const BSpline<double>&, const Region<double>&, std::size_t, const Limits&);

}  // namespace splinex
