// The certified graph of a curve given by N - 1 polynomial equations in N unknowns (N = 2: a
// trimming surface's trace on a face of a trivariate's domain; N = 3: two trimming surfaces
// meeting inside it), restricted to where a region's formula depends on all of them: its arcs and
// closed loops, cut at the points where a further leaf crosses (vrep/trimmed/trimmed.hpp: trimmed_curves
// describes the method; vrep/topology/trimmed_curves.cpp implements it). Internal to vrep.
#pragma once
#include <array>
#include <string>
#include <tuple>
#include <vector>

#include "bernstein/subdivide.hpp"
#include "bernstein/tensor.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_curves.hpp"

namespace splinex::vrep_detail {

/// The leaves of a region in Bernstein form on one box of the domain (a Bezier piece of V, or its
/// face), with the box.
template <class T, std::size_t N>
struct CurvePiece {
  std::vector<Bernstein<T>> G;  // per leaf (collect order)
  std::array<T, N> lo, hi;
};

template <class T, std::size_t N>
struct CurveProblem {
  const Region<T>* trim = nullptr;
  std::vector<CurvePiece<T, N>> pieces;        // together they tile the domain [dom_lo, dom_hi]
  std::array<T, N> dom_lo, dom_hi;
  std::array<std::array<bool, 2>, N> identified{};  // facets of the domain V identifies with others or collapses
  std::vector<std::size_t> curve;              // the N - 1 leaves whose common zero set is the curve
  CurveOptions options;
};

/// The counts, or the reason they are undecided.
struct CurveCount {
  bool decided = false;
  std::size_t arcs = 0, loops = 0;
  std::size_t ends_on_facets = 0, ends_at_points = 0, ends_on_identified = 0;
  std::size_t boxes = 0, crossings = 0;  // of the deciding attempt
  std::size_t spent = 0;                  // boxes over all attempts
  int split_fraction = 0;                 // index for split_fraction<T>() below
  std::string undecided_reason;
};

/// The widest direction of the box [lo, hi] (the first of equal ones): the one a subdivision splits.
template <class T, std::size_t N>
int widest(const std::array<T, N>& lo, const std::array<T, N>& hi) {
  int dir = 0;
  for (std::size_t d = 1; d < N; ++d)
    if ((hi[static_cast<std::size_t>(dir)] - lo[static_cast<std::size_t>(dir)]) < (hi[d] - lo[d])) dir = static_cast<int>(d);
  return dir;
}

/// A box of an N-dimensional parameter domain with the attempt's polynomials on it, in Bernstein
/// form over the box, and its subdivision level: what the region and surface attempts subdivide.
template <class T, std::size_t N>
struct PolynomialBox {
  std::array<T, N> lo, hi;
  std::vector<Bernstein<T>> G;
  int level = 0;
};

/// The two parts c[0], c[1] of a subdivision box (members lo, hi, level, G: its leaves on it) at
/// the fraction `frac` of direction `dir`: ranges, polynomials and level; other members are left
/// to the caller.
template <class Box, class T>
void split_box(const Box& box, int dir, const T& frac, Box (&c)[2]) {
  const std::size_t D = static_cast<std::size_t>(dir), n = box.G.size();
  for (auto& h : c) {
    h.lo = box.lo;
    h.hi = box.hi;
    h.level = box.level + 1;
    h.G.resize(n);
  }
  for (std::size_t l = 0; l < n; ++l) std::tie(c[0].G[l], c[1].G[l]) = bern_split(box.G[l], dir, frac);
  const T mid = box.lo[D] + frac * (box.hi[D] - box.lo[D]);
  c[0].hi[D] = mid;
  c[1].lo[D] = mid;
}

/// The subdivision budget of one attempt: CurveOptions' boxes and levels.
inline Budget attempt_budget(const CurveOptions& o) {
  Budget b;
  b.max_boxes = o.max_boxes;
  b.max_depth = o.max_level;
  return b;
}

/// An attempt's run in its count (CurveCount or RegionCount): the boxes spent (those examined,
/// and the one refused when the box budget ran out, so a spent budget reads max_boxes + 1, as it
/// always has) and, when it did not decide, why (`deepest`: the reason of a box left undecided).
template <class Count>
bool count_run(const Subdivision& run, const CurveOptions& o, const std::string& deepest, Count& out) {
  out.boxes = run.examined + (run.stop == Subdivision::Stop::boxes ? 1 : 0);
  if (run.stop == Subdivision::Stop::boxes) out.undecided_reason = "the box budget (" + std::to_string(o.max_boxes) + ") is spent";
  if (run.stop == Subdivision::Stop::left) out.undecided_reason = deepest;
  return run.stop == Subdivision::Stop::complete;  // (no attempt refutes: its examine settles, splits or fails)
}

/// The split fractions tried in turn: 1/2, 7/16, 13/32 (index 0, 1, 2).
template <class T>
T split_fraction(int index) {
  return index == 0 ? T(1) / T(2) : index == 1 ? T(7) / T(16) : T(13) / T(32);
}

/// Runs the subdivision at the split fractions 1/2, 7/16, 13/32 until one decides.
template <class T, std::size_t N>
CurveCount count_curve(const CurveProblem<T, N>& problem);

/// The connected pieces of the interior of {formula true} on a rectangle (the face of a
/// trivariate's domain; `curve` unused), in its parameters, from a certified subdivision
/// (vrep/topology/region_graph.cpp proves the box rule): a box is resolved when the formula is decided on
/// it, or at most two leaves matter there and each is one arc through the box (a partial
/// derivative of one strict sign, exactly two simple roots on the box's boundary, none at a
/// corner) and, for two, det(grad g_k, grad g_l) has one strict sign (they cross at most once).
/// The sign patterns between consecutive roots along the boundary are the faces of the box's
/// arrangement; true faces whose patterns differ in one sign form one piece. Pieces of boxes that
/// share a side join where their true gaps overlap on the common segment (roots compared exactly:
/// brackets refined, equal roots of one leaf certified by Descartes' rule). Regions that touch at
/// a single point are separate pieces. Split at the fraction 6/13 of a box, retried at 7/17 and 1/2
/// when a curve is tangent to a split line or crosses another on it (`split_fraction`: 0, 1, 2 for
/// 6/13, 7/17, 1/2): rational data on dyadic grids put tangencies on dyadic split lines, which
/// the odd denominators miss.
struct RegionCount {
  bool decided = false;
  std::size_t pieces = 0;
  std::size_t on_identified = 0;  // pieces reaching an edge V identifies with another or collapses
  std::size_t boxes = 0, spent = 0;
  int split_fraction = 0;
  std::string undecided_reason;
};

template <class T>
RegionCount count_region(const CurveProblem<T, 2>& problem);

/// The attempts of count_region and count_surface: `attempt(fraction, out)` at the split
/// fractions 6/13, 7/17, 1/2 until one decides or `max_total` boxes are spent. Data on dyadic
/// grids put tangencies on dyadic split lines (a circle of radius 5/8 about (1/2, 1) touches
/// y = 13/8); odd denominators miss them (starting at 1/2 spent the budget on every such case).
template <class T, class Attempt>
RegionCount retry_fractions(std::size_t max_total, Attempt&& attempt) {
  RegionCount out;
  const T fractions[3] = {T(6) / T(13), T(7) / T(17), T(1) / T(2)};
  for (int f = 0; f < 3; ++f) {
    RegionCount a;
    const bool ok = attempt(fractions[f], a);
    out.spent += a.boxes;
    if (ok) {
      a.spent = out.spent;
      a.split_fraction = f;
      return a;
    }
    out.undecided_reason = a.undecided_reason;
    out.boxes = a.boxes;
    if (out.spent >= max_total) break;
  }
  return out;
}

/// The connected pieces of the part of leaf `leaf`'s zero set where the formula depends on its
/// sign (a trimming surface's part of the cell's boundary), in the trivariate's parameters, from a
/// certified subdivision (vrep/topology/surface_graph.cpp proves the box rule): a box is resolved when the
/// surface misses it or does not bound there, or when {g <= 0} and {g >= 0} are contractible in it
/// (retractions along weakly monotone directions, down to a segment or a rectangle with one closed
/// loop), so the surface piece is a disk, at most two further leaves change whether it bounds, each
/// cutting it in one arc (a strict component of the curve's tangent, two or no crossings with the
/// box's faces) and two crossing at most once (a strict triple product). The sign patterns on the
/// surface's traces on the box's faces are its parts; parts whose patterns differ in one sign are
/// joined (undecided if that leaf bounds there too: more than two sheets); parts of boxes sharing
/// a face join where their patterns occur on the trace there. Split fractions as for count_region.
template <class T>
RegionCount count_surface(const CurveProblem<T, 3>& problem, std::size_t leaf);

/// The leaves of a trimmed cell on V's Bezier pieces, leaves vanishing on a face of the domain
/// divided by that face's parameter, and V's identified or collapsed faces: the problem
/// count_curve (N = 3) and count_surface work on (`curve` left empty).
template <class T>
CurveProblem<T, 3> cell_problem(const BSpline<T>& V, const Region<T>& trim, const std::vector<const Poly3<T>*>& leaves, const CurveOptions& options,
                                const Limits& limits);

template <class T>
struct LeafPiece;

/// A face (d, s) of V's domain: its four edges (face direction, side), those collapsed to a point,
/// and pairs of equal edges (V's identifications on the face).
struct FaceEdges {
  std::vector<std::pair<int, int>> ids;
  std::vector<char> point;
  std::vector<std::pair<std::size_t, std::size_t>> same;
};
template <class T>
FaceEdges face_edges(const BSpline<T>& V, int d, int s, const Limits& limits);

/// The leaves of one piece on face (d, s) of V's domain, read from inside: a leaf containing the
/// face (coplanar contact) divided by the face's parameter as often as it vanishes there (its
/// order m, returned in `multiplicity`), a leaf vanishing along an edge of the face by that edge's
/// parameter. Where `outside` marks a leaf, it is read from the other side of the face: the
/// quotient times (-1)^m.
template <class T>
std::vector<Bernstein<T>> leaves_on_face(const BSpline<T>& V, const LeafPiece<T>& p, int d, int s, const std::vector<char>* outside,
                                            std::vector<int>* multiplicity);

/// The 2D problem of face (d, s): the pieces touching it with leaves_on_face, the face's
/// identified edges (`trim` and `options` left to the caller).
template <class T>
CurveProblem<T, 2> face_curve_problem(const BSpline<T>& V, const std::vector<LeafPiece<T>>& pieces, int d, int s, const FaceEdges& edges,
                                      const std::vector<char>* outside);

/// G / t_d (side 0) or G / (1 - t_d) (side 1), for G vanishing identically on that facet: the
/// same signs inside the box.
template <class T>
Bernstein<T> divide_facet(const Bernstein<T>& G, int d, int side);

}  // namespace splinex::vrep_detail
