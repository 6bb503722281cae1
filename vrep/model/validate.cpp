// Validation of V-models before use (vrep/model/validate.hpp): exact, Rational only.
#include "vrep/model/validate.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <optional>
#include <set>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "bernstein/subdivide.hpp"
#include "spline/evaluate.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/model/regularity_impl.hpp"  // vrep_detail::jacobian_numerator, split_half, sign_of
#include "vrep/model/vmodel_impl.hpp"      // vrep_detail::same_net_within, geometry_of

namespace splinex {

namespace {

using R = Rational;
using P3 = Point3<R>;

std::string cell_text(const std::string& where, std::size_t c, const std::vector<std::string>& names) {
  std::string s = where + ".cells[" + std::to_string(c) + "]";
  if (c < names.size() && !names[c].empty()) s += " (" + names[c] + ")";
  return s;
}

std::string point_text(const std::vector<R>& x) {
  std::string s = "(";
  for (std::size_t k = 0; k < x.size(); ++k) s += (k ? ", " : "") + to_fraction_string(x[k]);
  return s + ")";
}
std::string point_text(const P3& x) { return point_text(std::vector<R>(x.begin(), x.end())); }

bool is_zero(const P3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

/// A cell's geometry for the pairwise tests: the control-point box, the exact corners and, for a
/// convex cell with planar faces, its six inner half-spaces.
struct CellGeometry {
  P3 lo, hi;
  std::array<P3, 8> corners;  // corner s0 + 2 s1 + 4 s2
  std::optional<std::vector<HalfSpace<R>>> planes;
  std::vector<std::optional<HalfSpace<R>>> face_planes;  // (dir, side) -> 2 dir + side, where planar
  std::vector<std::vector<std::vector<R>>> quads;         // face_corners, same order
  bool axis_edges = true;                                 // every edge parallel to a coordinate axis
};

std::vector<std::pair<int, int>> cell_edges();

CellGeometry geometry_of_cell(const BSpline<R>& V) {
  CellGeometry g;
  for (std::size_t i = 0; i < V.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const R& x = V.points[i * V.q + c];
      if (i == 0 || x < g.lo[c]) g.lo[c] = x;
      if (i == 0 || g.hi[c] < x) g.hi[c] = x;
    }
  for (int k = 0; k < 8; ++k) {
    std::vector<R> u(3);
    for (int d = 0; d < 3; ++d) u[d] = (k >> d) & 1 ? V.domain_hi(d) : V.domain_lo(d);
    const auto p = evaluate(V, u);
    g.corners[k] = {p[0], p[1], p[2]};
  }
  for (const auto& [i, j] : cell_edges()) {
    int nonzero = 0;
    for (int c = 0; c < 3; ++c) nonzero += !(g.corners[i][c] == g.corners[j][c]);
    g.axis_edges = g.axis_edges && nonzero <= 1;
  }
  g.planes = convex_planes(V, R(0));
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) {
      g.face_planes.push_back(face_plane(V, d, s, R(0)));
      g.quads.push_back(face_corners(V, d, s));
    }
  return g;
}

/// Interiors of the boxes overlap (closed boxes meeting in a face or less do not).
bool boxes_overlap(const CellGeometry& a, const CellGeometry& b) {
  for (int c = 0; c < 3; ++c)
    if (!(a.lo[c] < b.hi[c]) || !(b.lo[c] < a.hi[c])) return false;
  return true;
}
/// The closed boxes meet.
bool boxes_meet(const CellGeometry& a, const CellGeometry& b) {
  for (int c = 0; c < 3; ++c)
    if (b.hi[c] < a.lo[c] || a.hi[c] < b.lo[c]) return false;
  return true;
}

/// The 12 edges of a cell as corner pairs (along d: corner k with bit d clear and k | 1 << d).
std::vector<std::pair<int, int>> cell_edges() {
  std::vector<std::pair<int, int>> e;
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 8; ++k)
      if (!((k >> d) & 1)) e.push_back({k, k | (1 << d)});
  return e;
}

/// Separating-axis test for two convex polytopes given by their vertices (the exact corners), with
/// the face normals of both and the cross products of their edges as axes: true when the interiors
/// overlap (no axis separates them, touching counts as separated).
bool convex_interiors_overlap(const CellGeometry& a, const CellGeometry& b) {
  std::vector<P3> axes;
  for (const auto* g : {&a, &b})
    for (const auto& H : *g->planes) axes.push_back(H.n);
  std::vector<P3> ea, eb;
  for (const auto& [i, j] : cell_edges()) {
    const P3 x = sub(a.corners[j], a.corners[i]), y = sub(b.corners[j], b.corners[i]);
    if (!is_zero(x)) ea.push_back(x);
    if (!is_zero(y)) eb.push_back(y);
  }
  for (const auto& x : ea)
    for (const auto& y : eb) axes.push_back(cross(x, y));
  for (const auto& n : axes) {
    if (is_zero(n)) continue;
    R amin = dot(n, a.corners[0]), amax = amin, bmin = dot(n, b.corners[0]), bmax = bmin;
    for (int k = 1; k < 8; ++k) {
      const R x = dot(n, a.corners[k]), y = dot(n, b.corners[k]);
      amin = std::min(amin, x);
      amax = std::max(amax, x);
      bmin = std::min(bmin, y);
      bmax = std::max(bmax, y);
    }
    if (!(bmin < amax) || !(amin < bmax)) return false;
  }
  return true;
}

/// A plane (a planar face of either cell) with every control point of one cell on its inner side
/// and every one of the other on its outer side: the cells' interiors are disjoint (convex hulls).
bool separated_by_face_plane(const BSpline<R>& A, const CellGeometry& ga, const BSpline<R>& B, const CellGeometry& gb) {
  auto sides = [](const BSpline<R>& V, const HalfSpace<R>& H, bool& all_in, bool& all_out) {
    all_in = all_out = true;
    for (std::size_t i = 0; i < V.size() && (all_in || all_out); ++i) {
      const R* x = &V.points[i * V.q];
      const R v = H.n[0] * x[0] + H.n[1] * x[1] + H.n[2] * x[2] + H.d;
      all_in = all_in && !(v < 0);
      all_out = all_out && !(0 < v);
    }
  };
  for (int pass = 0; pass < 2; ++pass) {
    const auto& g = pass ? gb : ga;
    for (const auto& H : g.face_planes) {
      if (!H) continue;
      bool ai, ao, bi, bo;
      sides(A, *H, ai, ao);
      sides(B, *H, bi, bo);
      if ((ai && bo) || (ao && bi)) return true;
    }
  }
  return false;
}

/// p strictly inside the segment q0 q1 (q0 != q1).
bool inside_segment(const P3& p, const P3& q0, const P3& q1) {
  const P3 e = sub(q1, q0), v = sub(p, q0);
  if (is_zero(e) || !is_zero(cross(e, v))) return false;
  const R t = dot(v, e);
  return 0 < t && t < dot(e, e);
}

/// p strictly inside the convex planar quadrilateral Q (in order) with inner normal n of the cell
/// (zero-length sides skipped; p must lie on the plane).
bool inside_quad(const P3& p, const std::vector<std::vector<R>>& Q, const HalfSpace<R>& H) {
  const P3 n{H.n[0], H.n[1], H.n[2]};
  if (!(dot(n, p) + H.d == 0)) return false;
  int sign = 0, sides = 0;
  for (int k = 0; k < 4; ++k) {
    const P3 a{Q[k][0], Q[k][1], Q[k][2]}, b{Q[(k + 1) % 4][0], Q[(k + 1) % 4][1], Q[(k + 1) % 4][2]};
    const P3 e = sub(b, a);
    if (is_zero(e)) continue;
    ++sides;
    const R s = dot(cross(e, sub(p, a)), n);
    const int sg = s < 0 ? -1 : 0 < s ? 1 : 0;
    if (sg == 0 || (sign != 0 && sg != sign)) return false;
    sign = sg;
  }
  return sides >= 3;
}

/// Two segments crossing at one point strictly inside both (not parallel, in one plane), exactly.
bool segments_cross(const P3& p0, const P3& p1, const P3& q0, const P3& q1) {
  const P3 e = sub(p1, p0), f = sub(q1, q0), w = sub(q0, p0), n = cross(e, f);
  if (is_zero(n) || !(dot(w, n) == 0)) return false;
  const R nn = dot(n, n), s = dot(cross(w, f), n), t = dot(cross(w, e), n);  // s / nn, t / nn: the parameters
  return 0 < s && s < nn && 0 < t && t < nn;
}

/// A corner of cell i lying inside an edge or a face of cell j, or an edge of i crossing an edge of
/// j inside both (cells not both axis-aligned; for boxes a point contact is always at corners):
/// the contact is not conforming (both convex planar). Returns the description, or empty.
std::string nonconforming_corner(const CellGeometry& gi, const CellGeometry& gj) {
  for (const auto& p : gi.corners) {
    if (std::find(gj.corners.begin(), gj.corners.end(), p) != gj.corners.end()) continue;
    for (const auto& [a, b] : cell_edges())
      if (inside_segment(p, gj.corners[a], gj.corners[b]) && !vrep_testing::is_planted(vrep_testing::Plant::validate_corner_in_edge))  // (planted: tests only)
        return "its corner " + point_text(p) + " lies inside an edge of";
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) {
        const auto& H = gj.face_planes[2 * d + s];
        if (H && inside_quad(p, gj.quads[2 * d + s], *H)) return "its corner " + point_text(p) + " lies inside a face of";
      }
  }
  if (!gi.axis_edges || !gj.axis_edges)
    for (const auto& [a, b] : cell_edges())
      for (const auto& [c, d] : cell_edges())
        if (segments_cross(gi.corners[a], gi.corners[b], gj.corners[c], gj.corners[d]))
          return "its edge " + point_text(gi.corners[a]) + " - " + point_text(gi.corners[b]) + " crosses an edge of";
  return {};
}

/// Two faces of convex planar cells, in one plane with opposite inner sides, overlap with positive
/// area (projected along the normal's largest coordinate, no edge of either separates them).
bool faces_overlap(const HalfSpace<R>& F, const std::vector<std::vector<R>>& fc, const HalfSpace<R>& G, const std::vector<std::vector<R>>& gc) {
  if (!(F.n[0] * G.n[0] + F.n[1] * G.n[1] + F.n[2] * G.n[2] < 0)) return false;
  for (const auto& c : fc)
    if (!(G.n[0] * c[0] + G.n[1] * c[1] + G.n[2] * c[2] + G.d == 0)) return false;
  int drop = 0;
  for (int d = 1; d < 3; ++d)
    if (abs(F.n[drop]) < abs(F.n[d])) drop = d;
  const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
  auto separates = [&](const std::vector<std::vector<R>>& P, const std::vector<std::vector<R>>& Q) {
    R cu(0), cv(0);
    for (const auto& p : P) {
      cu += p[u];
      cv += p[v];
    }
    cu /= R(4);
    cv /= R(4);
    for (int k = 0; k < 4; ++k) {
      const auto &A = P[k], &B = P[(k + 1) % 4];
      const R eu = B[u] - A[u], ev = B[v] - A[v];
      if (eu == 0 && ev == 0) continue;
      auto side = [&](const R& x, const R& y) { return eu * (y - A[v]) - ev * (x - A[u]); };
      const R inner = side(cu, cv);
      bool all_out = true;
      for (const auto& q : Q) all_out = all_out && !(0 < (inner < 0 ? R(-side(q[u], q[v])) : side(q[u], q[v])));
      if (all_out) return true;
    }
    return false;
  };
  return !separates(fc, gc) && !separates(gc, fc);
}

struct Checked {
  std::vector<CellGeometry> geometry;
};

/// Shapes and pairwise overlap of the cells (the first two rules of vrep/model/validate.hpp).
Checked check_cells(const std::vector<BSpline<R>>& cells, const std::vector<std::string>& names, const std::string& where,
                    const ValidityOptions& options, const Limits& limits, ValidityReport& rep) {
  Checked out;
  rep.cells = cells.size();
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const CellShape shape = certify_cell_shape(cells[c], cell_text(where, c, names), options.levels, limits);
    rep.regularity.push_back(shape.regularity);
    if (shape.degenerate) rep.degenerate.push_back(cell_text(where, c, names) + ": " + rep.regularity.back().verdict.reason());
    if (shape.valid.is_undecided())
      rep.undecided.push_back(cell_text(where, c, names) + ": the sign of det J: " + rep.regularity.back().verdict.reason());
    out.geometry.push_back(geometry_of_cell(cells[c]));
  }
  // Pairs in order of the boxes' low x: a sweep, so that far-apart cells cost nothing.
  std::vector<std::size_t> order(cells.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  const auto& g = out.geometry;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return g[a].lo[0] < g[b].lo[0]; });
  std::size_t curved_pairs = 0;
  std::string first_curved;
  for (std::size_t x = 0; x < order.size(); ++x)
    for (std::size_t y = x + 1; y < order.size(); ++y) {
      std::size_t i = order[x], j = order[y];
      // (Planted, tests only: vrep/model/planted.hpp compares with the wrong end of the box.)
      if (!(g[j].lo[0] < (vrep_testing::is_planted(vrep_testing::Plant::validate_sweep_bound) ? g[i].lo[0] : g[i].hi[0]))) break;
      if (!boxes_overlap(g[i], g[j])) continue;
      if (j < i) std::swap(i, j);
      ++rep.pairs_tested;
      const std::string pair = cell_text(where, i, names) + " and " + cell_text(where, j, names);
      const std::string fix = "give cells whose interiors are disjoint, meeting face to face (vrep boolean union merges overlapping models)";
      if (vrep_detail::same_net_within(cells[i], cells[j], R(0), limits))
        throw ValidationError(cell_text(where, j, names), "is the same cell as " + cell_text(where, i, names) + " (a duplicated cell)",
                              "remove the duplicate");
      if (g[i].planes && g[j].planes) {
        if (!convex_interiors_overlap(g[i], g[j])) continue;
        auto inside = [&](const CellGeometry& in, const CellGeometry& of) {
          for (const auto& p : in.corners)
            for (const auto& H : *of.planes)
              if (H.n[0] * p[0] + H.n[1] * p[1] + H.n[2] * p[2] + H.d < 0) return false;
          return true;
        };
        if (inside(g[j], g[i])) throw ValidationError(cell_text(where, j, names), "lies inside " + cell_text(where, i, names) + " (their interiors overlap)", fix);
        if (inside(g[i], g[j])) throw ValidationError(cell_text(where, i, names), "lies inside " + cell_text(where, j, names) + " (their interiors overlap)", fix);
        throw ValidationError(cell_text(where, i, names), "overlaps " + cell_text(where, j, names) + " (their interiors meet: no separating plane, exact)", fix);
      }
      if (separated_by_face_plane(cells[i], g[i], cells[j], g[j])) continue;
      if (++curved_pairs == 1) first_curved = pair;
    }
  if (curved_pairs)
    rep.undecided.push_back("overlap of " + first_curved + (curved_pairs > 1 ? " (and " + std::to_string(curved_pairs - 1) + " more pairs)" : "") +
                            ": curved cells whose control-point boxes overlap and that no planar face separates; "
                            "the interiors may or may not meet (not decided)");
  return out;
}

/// Corners of convex planar cells inside an edge or a face of another (the third rule).
void check_conformity(const std::vector<BSpline<R>>& cells, const std::vector<std::string>& names, const std::string& where,
                      const std::vector<CellGeometry>& g, ValidityReport& rep) {
  bool curved = false;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    curved = curved || !g[i].planes;
    if (!g[i].planes) continue;
    for (std::size_t j = 0; j < cells.size(); ++j) {
      if (i == j || !g[j].planes || !boxes_meet(g[i], g[j])) continue;
      const std::string how = nonconforming_corner(g[i], g[j]);
      if (!how.empty())
        throw ValidationError(cell_text(where, i, names), how + " " + cell_text(where, j, names) +
                                                              ": the cells touch along part of an edge or face, which gluing cannot share (the topology would be wrong)",
                              "split the cells there so that they meet in whole faces, edges or corners (vrep boolean union does)");
    }
  }
  if (curved && cells.size() > 1) rep.not_checked.push_back("partial edge and vertex contacts between curved cells");
}

bool same_region(const Region<R>& a, const Region<R>& b) {
  if (a.kind != b.kind || a.g.terms != b.g.terms || a.parts.size() != b.parts.size() || a.alias != b.alias || a.flip != b.flip) return false;
  for (std::size_t k = 0; k < a.parts.size(); ++k)
    if (!same_region(a.parts[k], b.parts[k])) return false;
  return true;
}

}  // namespace

std::string ValidityReport::verdict() const {
  if (!undecided.empty())
    return "undecided: " + undecided.front() + (undecided.size() > 1 ? " (and " + std::to_string(undecided.size() - 1) + " more)" : "");
  if (!not_checked.empty()) {
    std::string s = "valid in what was checked; not checked: ";
    for (std::size_t k = 0; k < not_checked.size(); ++k) s += (k ? "; " : "") + not_checked[k];
    return s;
  }
  return "valid";
}

CellShape certify_cell_shape(const BSpline<Rational>& V, const std::string& field, int levels, const Limits& limits) {
  const std::string fix = "give cells with det J of one sign (vrep certify shows it): reorder or move the control points";
  auto rep = certify_regularity(V, levels, limits);
  if (rep.verdict.is_proved()) return {rep, Verdict::proved(rep.verdict.reason()), false};
  if (rep.verdict.is_refuted() && !rep.other.empty())
    throw ValidationError(field, "folds: det J changes sign (" + to_fraction_string(rep.value) + " at " + point_text(rep.point) + ", " +
                                     to_fraction_string(rep.other_value) + " at " + point_text(rep.other) + ")",
                          fix);
  for (int d = 0; d < 3; ++d)
    if (V.degrees[d] == 0)  // the message of vrep/model/regularity.hpp's require_jacobian_input, with the cell
      throw ValidationError("degrees", "has degree 0 in a direction: det J is 0 (" + field + " is flat in direction " + std::to_string(d) + ")",
                            "elevate it and give it volume");
  // det J = 0 at a point inside the parameter domain: the cell is not regular there (pinched or
  // folded); on the domain's boundary (a collapsed edge or face) it is degenerate but valid.
  auto interior = [&](const std::vector<R>& x) {
    if (vrep_testing::is_planted(vrep_testing::Plant::validate_interior_zero)) return false;  // (planted: tests only)
    for (int d = 0; d < 3; ++d)
      if (!(V.domain_lo(d) < x[d] && x[d] < V.domain_hi(d))) return false;
    return true;
  };
  auto refuse_interior_zero = [&](const std::vector<R>& x) {
    throw ValidationError(field, "is not regular inside: det J = 0 at the interior parameter point " + point_text(x) + " (the cell is pinched or folded there)", fix);
  };
  if (rep.verdict.is_refuted() && interior(rep.point)) refuse_interior_zero(rep.point);
  // det J = 0 somewhere, or undecided: is det J of one sign (>= 0 or <= 0) and nowhere 0 on a
  // box? Boxes whose coefficients have one weak sign are decided; a box with all coefficients 0
  // is a flat part; strict signs of both kinds (corners or decided boxes) are a fold.
  using Box = vrep_detail::JacobianBox<R>;
  const std::size_t per_piece = vrep_detail::check_jacobian_size(V, limits);
  Budget budget;
  budget.max_depth = levels;
  budget.max_alive = std::max<std::size_t>(64, limits.max_control_points / per_piece);
  std::string pos_at, neg_at, undecided_at;
  auto box_text = [](const Box& b) {
    return "[" + to_fraction_string(b.lo[0]) + ", " + to_fraction_string(b.hi[0]) + "] x [" + to_fraction_string(b.lo[1]) + ", " +
           to_fraction_string(b.hi[1]) + "] x [" + to_fraction_string(b.lo[2]) + ", " + to_fraction_string(b.hi[2]) + "]";
  };
  auto examine = [&](const Box& b, int) {
    int lo = 2, hi = -2;
    for (const auto& c : b.N.c) {
      const int s = vrep_detail::sign_of(c);
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
    if (lo == 0 && hi == 0) {
      if (vrep_testing::is_planted(vrep_testing::Plant::validate_flat_skipped)) return Examined::settled;  // (planted: tests only)
      throw ValidationError(field, "is flat: det J = 0 on the parameter box " + box_text(b), fix);
    }
    b.for_each_corner([&](std::size_t i, const std::vector<R>& x) {
      if (vrep_detail::sign_of(b.N.c[i]) == 0 && interior(x)) refuse_interior_zero(x);
      return true;
    });
    if (lo >= 0 && pos_at.empty()) pos_at = box_text(b);
    if (hi <= 0 && neg_at.empty()) neg_at = box_text(b);
    if (lo < 0 && hi > 0) {
      // Strict corner values of both signs: a fold, exactly.
      b.for_each_corner([&](std::size_t i, const std::vector<R>& x) {
        if (const int s = vrep_detail::sign_of(b.N.c[i]); s != 0) (s > 0 ? pos_at : neg_at) = "the point " + point_text(x);
        return true;
      });
    }
    if (!pos_at.empty() && !neg_at.empty())
      throw ValidationError(field, "folds: det J changes sign (> 0 on " + pos_at + ", < 0 on " + neg_at + ")", fix);
    return lo >= 0 || hi <= 0 ? Examined::settled : Examined::split;
  };
  auto split = [](Box&& b, int, auto&& emit) { vrep_detail::split_octants(std::move(b), emit); };
  auto leave = [&](Box&& b, Left) {
    if (undecided_at.empty()) undecided_at = box_text(b);
  };
  const bool undecided =
      subdivide(vrep_detail::jacobian_boxes(V, limits), Walk{Order::breadth_first, 8, false}, budget, examine, split, leave).left > 0;
  if (undecided) {
    rep.verdict = Verdict::undecided("det J has Bernstein coefficients of both signs on " + undecided_at + " after " + std::to_string(levels) +
                                     " subdivision levels (a fold is not excluded)");
    return {rep, rep.verdict, false};
  }
  // One weak sign everywhere, nowhere identically 0: valid, degenerate where det J = 0.
  rep.verdict.add_to_reason(rep.verdict.is_refuted() ? "; elsewhere det J has that sign (certified): degenerate, not folded"
                                                      : "; det J >= 0 or <= 0 everywhere (certified), > 0 not decided: not folded");
  return {rep, Verdict::proved(rep.verdict.reason()), true};
}

ValidityReport validate_cells(const std::vector<BSpline<Rational>>& cells, const std::vector<std::string>& names, const std::string& where,
                              const ValidityOptions& options, const Limits& limits) {
  ValidityReport rep;
  const auto checked = check_cells(cells, names, where, options, limits, rep);
  check_conformity(cells, names, where, checked.geometry, rep);
  return rep;
}

ValidityReport validate_vmodel(const VModel<Rational>& M, const std::string& where, const ValidityOptions& options, const Limits& limits) {
  ValidityReport rep;
  std::vector<BSpline<R>> cells;
  std::vector<std::string> names;
  for (const auto& c : M.cells) {
    cells.push_back(M.trivariates[c.trivariates.front()]);
    names.push_back(c.name);
  }
  const auto checked = check_cells(cells, names, where, options, limits, rep);
  if (!options.topology) {
    check_conformity(cells, names, where, checked.geometry, rep);
    return rep;
  }
  const auto& g = checked.geometry;
  // Unglued boundary faces of convex planar cells overlapping in a plane: a T-junction.
  for (std::size_t h = 0; h < M.half_surfaces.size(); ++h) {
    const auto& a = M.half_surfaces[h];
    if (a.twin || !g[a.cell].planes) continue;
    const auto& Fa = g[a.cell].face_planes[2 * a.dir + a.side];
    if (!Fa) continue;
    for (std::size_t k = h + 1; k < M.half_surfaces.size(); ++k) {
      const auto& b = M.half_surfaces[k];
      if (b.twin || b.cell == a.cell || !g[b.cell].planes || !boxes_meet(g[a.cell], g[b.cell])) continue;
      const auto& Fb = g[b.cell].face_planes[2 * b.dir + b.side];
      if (!Fb || !faces_overlap(*Fa, g[a.cell].quads[2 * a.dir + a.side], *Fb, g[b.cell].quads[2 * b.dir + b.side])) continue;
      auto face_text = [&](const VModel<R>::HalfSurface& x) {
        return "face (" + std::to_string(x.dir) + ", " + std::to_string(x.side) + ") of " + cell_text(where, x.cell, names);
      };
      throw ValidationError(cell_text(where, a.cell, names),
                            face_text(a) + " overlaps " + face_text(b) + " without being glued to it (a T-junction: the face is listed as boundary although the solid continues)",
                            "split the cells so that they meet in whole faces (vrep boolean union does)");
    }
  }
  check_conformity(cells, names, where, g, rep);
  const auto inv = check_invariants(M, limits);
  if (!inv.ok()) {
    std::string what = inv.failures.front();
    const std::string prefix = "half-V-surface ";
    if (what.rfind(prefix, 0) == 0) {
      const std::size_t h = std::stoul(what.substr(prefix.size()));
      if (h < M.half_surfaces.size()) what += " (face of " + cell_text(where, M.half_surfaces[h].cell, names) + ")";
    }
    throw ValidationError(where, "is not a valid V-model: " + what, "give regular cells glued face to face");
  }
  return rep;
}

ValidityReport validate_trimmed(const TrimmedModel<Rational>& M, const std::string& where, const ValidityOptions& options, const Limits& limits) {
  ValidityReport rep;
  rep.cells = M.cells.size();
  std::vector<std::string> names;
  for (const auto& c : M.cells) names.push_back(c.name);
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto& x = M.cells[c];
    if (x.category != "" && x.category != "A" && x.category != "both" && x.category != "B")
      throw ValidationError(cell_text(where, c, names) + ".category", "is \"" + x.category + "\"",
                            "give \"A\", \"both\", \"B\" (after a Boolean) or \"\" (an input cell)");
    if (x.trivariate >= M.trivariates.size())
      throw ValidationError(cell_text(where, c, names) + ".trivariate", "is not an index of the model's trivariates",
                            "give 0.." + std::to_string(M.trivariates.size()) + " exclusive");
    for (std::size_t t : x.inherited)
      if (t >= M.trivariates.size())
        throw ValidationError(cell_text(where, c, names) + ".inherited", "holds " + std::to_string(t) + ", not an index of the model's trivariates",
                              "give indices into trivariates");
  }
  // The trivariates the cells are on: det J of one sign.
  std::vector<char> done(M.trivariates.size(), 0);
  std::vector<CellGeometry> g(M.trivariates.size());
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const std::size_t t = M.cells[c].trivariate;
    if (done[t]) continue;
    done[t] = 1;
    const CellShape shape = certify_cell_shape(M.trivariates[t], where + ".trivariates[" + std::to_string(t) + "]", options.levels, limits);
    rep.regularity.push_back(shape.regularity);
    if (shape.degenerate) rep.degenerate.push_back(where + ".trivariates[" + std::to_string(t) + "]: " + rep.regularity.back().verdict.reason());
    if (shape.valid.is_undecided())
      rep.undecided.push_back(where + ".trivariates[" + std::to_string(t) + "]: the sign of det J: " + rep.regularity.back().verdict.reason());
    g[t] = geometry_of_cell(M.trivariates[t]);
  }
  std::size_t open = 0;
  for (std::size_t i = 0; i < M.cells.size(); ++i)
    for (std::size_t j = i + 1; j < M.cells.size(); ++j) {
      const auto &a = M.cells[i], &b = M.cells[j];
      if (a.trivariate == b.trivariate && same_region(a.trim, b.trim))
        throw ValidationError(cell_text(where, j, names), "is the same cell as " + cell_text(where, i, names) + " (same trivariate and trim: a duplicated cell)",
                              "remove the duplicate");
      if (a.trivariate == b.trivariate || boxes_overlap(g[a.trivariate], g[b.trivariate])) ++open;
    }
  if (open) rep.not_checked.push_back("overlap of trimmed cells (" + std::to_string(open) + " pairs on one trivariate or with overlapping control-point boxes)");
  return rep;
}

}  // namespace splinex
