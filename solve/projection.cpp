// Point projection onto a surface (solve/projection.hpp), instantiated for Rational and double.
#include "solve/projection.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "float/arith_spec.hpp"
#include "spline/bezier.hpp"
#include "spline/errors.hpp"
#include "spline/knots.hpp"

namespace splinex {

namespace {

using detail::Bern;

template <class T>
std::string text(const T& x) {
  return ArithTraits<T>::to_string(x);
}

/// One Bezier piece of the surface with its homogeneous coordinates and the equations.
template <class T>
struct Piece {
  std::vector<T> lo, hi;  // parameter box
  std::size_t s0 = 0, s1 = 0;
  Bern<T> X[3], W;        // W = 1 for a polynomial surface
  Bern<T> D, W2;          // |X - P W|^2 and W^2: the squared distance is D / W^2
  std::vector<Bern<T>> grad;  // the two equations
};

template <class T>
Piece<T> make_piece(const BezierPiece<T>& bp, std::size_t s0, std::size_t s1, const std::vector<T>& P) {
  Piece<T> pc;
  pc.s0 = s0;
  pc.s1 = s1;
  for (int d = 0; d < 2; ++d) {
    pc.lo.push_back(bp.box[d].first);
    pc.hi.push_back(bp.box[d].second);
  }
  const BSpline<T>& S = bp.spline;
  const bool rational = S.is_rational();
  pc.W = detail::bern_coordinate(S, S.q);
  for (int c = 0; c < 3; ++c) pc.X[c] = detail::bern_coordinate(S, c);
  Bern<T> A[3];  // X_c - P_c W
  for (int c = 0; c < 3; ++c) {
    A[c] = pc.X[c];
    for (std::size_t i = 0; i < A[c].c.size(); ++i) A[c].c[i] -= P[c] * pc.W.c[i];
  }
  pc.D = detail::bern_product(A[0], A[0]);
  for (int c = 1; c < 3; ++c) pc.D = detail::bern_add(pc.D, detail::bern_product(A[c], A[c]));
  pc.W2 = detail::bern_product(pc.W, pc.W);
  for (int d = 0; d < 2; ++d) {
    Bern<T> sum;
    for (int c = 0; c < 3; ++c) {
      const Bern<T> b = rational ? detail::bern_sub(detail::bern_product(detail::bern_derivative(pc.X[c], d), pc.W),
                                                    detail::bern_product(pc.X[c], detail::bern_derivative(pc.W, d)))
                                 : detail::bern_derivative(pc.X[c], d);
      const Bern<T> term = detail::bern_product(A[c], b);
      sum = c == 0 ? term : detail::bern_add(sum, term);
    }
    pc.grad.push_back(std::move(sum));
  }
  return pc;
}

/// Local coordinate of the global parameter x in direction d of the piece.
template <class T>
T local(const Piece<T>& pc, int d, const T& x) {
  return (x - pc.lo[d]) / (pc.hi[d] - pc.lo[d]);
}

/// S at the global parameter (u, v) of the piece, exactly (first three coordinates), and the
/// squared distance.
template <class T>
std::vector<T> point_at(const Piece<T>& pc, const std::vector<T>& uv, T& d2) {
  const std::vector<T> t{local(pc, 0, uv[0]), local(pc, 1, uv[1])};
  const T w = detail::bern_value(pc.W, t);
  std::vector<T> x(3);
  for (int c = 0; c < 3; ++c) x[c] = detail::bern_value(pc.X[c], t) / w;
  d2 = detail::bern_value(pc.D, t) / (w * w);
  return x;
}

/// Where a candidate came from: the piece and the stratum (fix < 0: interior; else the edge
/// t_fix = side), to test exactly whether another candidate's exact point is a root of its system.
struct Origin {
  std::size_t piece = 0;
  int fix = -1, side = 0;
};

template <class T>
bool root_of_stratum(const Piece<T>& pc, const Origin& o, const std::vector<T>& uv) {
  for (int d = 0; d < 2; ++d)
    if (uv[d] < pc.lo[d] || pc.hi[d] < uv[d]) return false;
  const std::vector<T> t{local(pc, 0, uv[0]), local(pc, 1, uv[1])};
  if (o.fix < 0) return detail::bern_value(pc.grad[0], t) == T(0) && detail::bern_value(pc.grad[1], t) == T(0);
  if (!(t[o.fix] == T(o.side))) return false;
  return detail::bern_value(pc.grad[1 - o.fix], t) == T(0);
}

template <class T>
struct Candidate {
  CriticalPoint<T> cp;
  Origin origin;
};

/// The candidate of a root box (global (u, v) box) of the piece: distance enclosure and point.
template <class T>
CriticalPoint<T> make_point(const Piece<T>& pc, std::vector<T> lo, std::vector<T> hi, bool exact, bool unique) {
  CriticalPoint<T> cp;
  cp.exact = exact;
  cp.unique = unique;
  cp.lo = lo;
  cp.hi = hi;
  std::vector<T> mid{(lo[0] + hi[0]) / T(2), (lo[1] + hi[1]) / T(2)};
  if (exact) mid = lo;
  T d2;
  cp.point = point_at(pc, mid, d2);
  if (exact) {
    cp.d2_lo = cp.d2_hi = d2;
    return cp;
  }
  Bern<T> D = pc.D, W2 = pc.W2;
  for (int d = 0; d < 2; ++d) {
    const T a = local(pc, d, lo[d]), b = local(pc, d, hi[d]);
    if (a < b) {
      D = detail::bern_restrict(D, d, a, b);
      W2 = detail::bern_restrict(W2, d, a, b);
    }
  }
  for (int d = 1; d >= 0; --d) {  // sides of width 0 (an edge's fixed parameter), last direction first
    const T a = local(pc, d, lo[d]);
    if (a < local(pc, d, hi[d])) continue;
    const auto face = [&](const Bern<T>& g) {
      if (T(0) < a && a < T(1)) return detail::bern_face(detail::bern_split(g, d, a).second, d, 0);
      return detail::bern_face(g, d, a == T(0) ? 0 : 1);
    };
    D = face(D);
    W2 = face(W2);
  }
  const auto [dlo, dhi] = detail::bern_range(D);
  const auto [wlo, whi] = detail::bern_range(W2);
  cp.d2_lo = dlo < T(0) ? T(0) : T(dlo / whi);
  cp.d2_hi = dhi / wlo;
  round_enclosure(cp.d2_lo, cp.d2_hi);
  return cp;
}

}  // namespace

template <class T>
ProjectionResult<T> project_point(const BSpline<T>& S, const std::vector<T>& P, const SolveOptions& options, const Limits& limits) {
  validate(S, limits);
  if (S.dim() != 2 || S.q < 3)
    throw ValidationError("surface", "is not a surface in R^3", "give a spline with two parametric directions and points x,y,z");
  if (P.size() != 3) throw ValidationError("point", "has " + std::to_string(P.size()) + " coordinates", "give x,y,z");
  for (int d = 0; d < 2; ++d) {
    if (S.degrees[d] == 0)
      throw ValidationError("degrees[" + std::to_string(d) + "]", "is 0: the surface has no tangent plane, the projection equations are degenerate",
                            "elevate the surface to degree >= 1");
    // The equations' degrees: 2p - 1 (polynomial) or 3p - 1 (rational) in the derivative's direction.
    limits.check_degree(static_cast<long>(S.is_rational() ? 3 : 2) * S.degrees[d], "degrees[" + std::to_string(d) + "]");
  }
  const BezierForm<T> F = bezier_form(S, limits);
  const std::size_t seg0 = F.breaks[0].size() - 1;
  std::vector<Piece<T>> pieces;
  for (std::size_t k = 0; k < F.size(); ++k) pieces.push_back(make_piece(F.piece(k), k % seg0, k / seg0, P));

  // Knot lines where S is not C^1: multiplicity >= degree.
  const auto crease = [&](int d, const T& x) {
    if (x == S.domain_lo(d) || x == S.domain_hi(d)) return 2;  // the domain's boundary
    int m = 0;
    for (const auto& k : S.knots[d]) m += k == x ? 1 : 0;
    return m > S.degrees[d] ? 3 : m >= S.degrees[d] ? 1 : 0;  // 3: a jump (C^-1), 1: C^0
  };

  ProjectionResult<T> out;
  std::vector<Candidate<T>> cands;
  std::vector<CriticalPoint<T>> undecided;
  auto add_result = [&](const SolveResult<T>& r, const Piece<T>& pc, const Origin& o, const std::string& where, const std::string& stratum,
                        const T& fixed) {
    out.boxes += r.boxes;
    auto to2 = [&](const std::vector<T>& x) {
      if (o.fix < 0) return x;
      std::vector<T> y(2);
      y[o.fix] = fixed;
      y[1 - o.fix] = x[0];
      return y;
    };
    for (const auto& root : r.roots) {
      Candidate<T> c;
      c.cp = make_point(pc, to2(root.exact ? root.point : root.lo), to2(root.exact ? root.point : root.hi), root.exact, root.unique);
      c.cp.where = where;
      c.cp.stratum = stratum;
      c.origin = o;
      cands.push_back(std::move(c));
    }
    for (const auto& box : r.undecided) {
      auto u = make_point(pc, to2(box.lo), to2(box.hi), false, false);
      u.where = where;
      u.stratum = stratum;
      undecided.push_back(std::move(u));
    }
  };

  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Piece<T>& pc = pieces[k];
    const std::string name = "piece [" + text(pc.lo[0]) + ", " + text(pc.hi[0]) + "] x [" + text(pc.lo[1]) + ", " + text(pc.hi[1]) + "]";
    // Interior: the two equations on the closed piece.
    bool degenerate = false;
    for (const auto& g : pc.grad) {
      bool zero = true;
      for (const auto& x : g.c) zero = zero && x == T(0);
      degenerate = degenerate || zero;
    }
    if (degenerate) {
      // Every point of the piece is critical in some direction (a flat piece seen along its normal
      // is not this: that is one equation vanishing identically, e.g. a line-like piece).
      auto u = make_point(pc, pc.lo, pc.hi, false, false);
      u.where = "interior";
      u.stratum = name + ": an equation vanishes identically (a degenerate piece)";
      undecided.push_back(std::move(u));
    } else {
      add_result(solve_system(pc.grad, pc.lo, pc.hi, options), pc, Origin{k, -1, 0}, "interior", name, T(0));
    }
    // Edges on the boundary and on creases; a C^0 crease once (from the piece below it).
    for (int fix = 0; fix < 2; ++fix)
      for (int side = 0; side < 2; ++side) {
        const T x = side ? pc.hi[fix] : pc.lo[fix];
        const int kind = crease(fix, x);
        if (kind == 0) continue;
        if (kind == 1 && side == 0) continue;
        const int e = 1 - fix;
        const Bern<T> g = detail::bern_face(pc.grad[e], fix, side);
        const std::string ename = std::string(fix == 0 ? "u" : "v") + " = " + text(x) + ", " + (e == 0 ? "u" : "v") + " in [" +
                                  text(pc.lo[e]) + ", " + text(pc.hi[e]) + "]" + (kind == 2 ? " (boundary)" : " (knot line, not C^1)");
        bool zero = true;
        for (const auto& c : g.c) zero = zero && c == T(0);
        if (zero) {
          auto u = make_point(pc, fix == 0 ? std::vector<T>{x, pc.lo[1]} : std::vector<T>{pc.lo[0], x},
                              fix == 0 ? std::vector<T>{x, pc.hi[1]} : std::vector<T>{pc.hi[0], x}, false, false);
          u.where = "edge";
          u.stratum = ename + ": the distance is constant along it";
          undecided.push_back(std::move(u));
        } else {
          add_result(solve_system(std::vector<Bern<T>>{g}, std::vector<T>{pc.lo[e]}, std::vector<T>{pc.hi[e]}, options), pc,
                     Origin{k, fix, side}, "edge", ename, x);
        }
        // The edge's ends are corners.
        for (int end = 0; end < 2; ++end) {
          std::vector<T> uv(2);
          uv[fix] = x;
          uv[e] = end ? pc.hi[e] : pc.lo[e];
          Candidate<T> c;
          c.cp = make_point(pc, uv, uv, true, true);
          c.cp.where = "corner";
          c.cp.stratum = "corner (" + text(uv[0]) + ", " + text(uv[1]) + ")";
          c.origin = Origin{k, fix, side};
          cands.push_back(std::move(c));
        }
      }
  }

  // Merge: exact points by equality of parameters and point (corners first, then edges, then
  // interiors: the lowest stratum names it); a box that contains another candidate's exact point
  // which is a root of the box's own system is that point (the box holds one root); boxes that
  // overlap across a knot line become one entry.
  const auto rank = [](const std::string& w) { return w == "corner" ? 0 : w == "edge" ? 1 : 2; };
  std::stable_sort(cands.begin(), cands.end(), [&](const Candidate<T>& a, const Candidate<T>& b) {
    if (a.cp.exact != b.cp.exact) return a.cp.exact;
    return rank(a.cp.where) < rank(b.cp.where);
  });
  std::vector<Candidate<T>> kept;
  for (auto& c : cands) {
    bool dup = false;
    for (auto& k : kept) {
      if (c.cp.exact && k.cp.exact) {
        if (c.cp.lo == k.cp.lo && c.cp.point == k.cp.point) dup = true;
      } else if (!c.cp.exact && k.cp.exact) {
        if (c.cp.unique && root_of_stratum(pieces[c.origin.piece], c.origin, k.cp.lo)) {
          T d2;
          dup = point_at(pieces[c.origin.piece], k.cp.lo, d2) == k.cp.point;  // not across a jump
        }
      } else if (!c.cp.exact && !k.cp.exact) {
        bool touch = true;
        for (int d = 0; d < 2; ++d) touch = touch && !(c.cp.hi[d] < k.cp.lo[d]) && !(k.cp.hi[d] < c.cp.lo[d]);
        if (touch) {
          for (int d = 0; d < 2; ++d) {
            if (c.cp.lo[d] < k.cp.lo[d]) k.cp.lo[d] = c.cp.lo[d];
            if (k.cp.hi[d] < c.cp.hi[d]) k.cp.hi[d] = c.cp.hi[d];
          }
          if (c.cp.d2_lo < k.cp.d2_lo) k.cp.d2_lo = c.cp.d2_lo;
          if (k.cp.d2_hi < c.cp.d2_hi) k.cp.d2_hi = c.cp.d2_hi;
          k.cp.merged = true;
          k.cp.unique = false;
          dup = true;
        }
      }
      if (dup) break;
    }
    if (!dup) kept.push_back(std::move(c));
  }
  for (auto& c : kept) out.critical.push_back(std::move(c.cp));
  std::stable_sort(out.critical.begin(), out.critical.end(), [](const auto& a, const auto& b) { return a.d2_lo < b.d2_lo; });
  out.undecided = std::move(undecided);

  // The smallest distance: below the smallest upper bound, above the smallest lower bound.
  out.complete = out.undecided.empty();
  for (const auto& c : out.critical) out.complete = out.complete && (c.unique || c.exact) && !c.merged;
  out.distance2_hi = out.critical.front().d2_hi;  // corners always exist
  out.distance2_lo = out.critical.front().d2_lo;
  for (const auto& c : out.critical) {
    if (c.d2_hi < out.distance2_hi) out.distance2_hi = c.d2_hi;
    if (c.d2_lo < out.distance2_lo) out.distance2_lo = c.d2_lo;
  }
  bool undecided_below = false;
  for (const auto& u : out.undecided) {
    if (u.d2_lo < out.distance2_lo) out.distance2_lo = u.d2_lo;
    undecided_below = undecided_below || !(out.distance2_hi < u.d2_lo);
  }
  for (std::size_t i = 0; i < out.critical.size(); ++i)
    if (!(out.distance2_hi < out.critical[i].d2_lo)) out.closest.push_back(i);
  out.closest_certified = ArithTraits<T>::exact && out.closest.size() == 1 && !undecided_below;
  return out;
}

template ProjectionResult<Rational> project_point(const BSpline<Rational>&, const std::vector<Rational>&, const SolveOptions&, const Limits&);
template ProjectionResult<double> project_point(const BSpline<double>&, const std::vector<double>&, const SolveOptions&, const Limits&);

}  // namespace splinex
