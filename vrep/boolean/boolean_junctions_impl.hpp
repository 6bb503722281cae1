// Partial edge and vertex contacts in a Boolean's pieces (vrep/boolean/boolean.hpp, issue 47 vrep 1): the
// part of the conformity pass that looks at corners (boolean_impl.hpp looks at faces).
#pragma once
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/point.hpp"
#include "spline/evaluate.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/model/vmodel_impl.hpp"  // vrep_detail::magnitude, close

namespace splinex {

namespace vrep_detail {

/// Partial edge and vertex contacts between pieces of different source cells (issue 47, vrep 1): a
/// corner of a convex planar piece strictly inside an edge or a face of another. Gluing shares only
/// equal V-points, V-curves and faces, so such a contact would be left unglued and the Euler
/// characteristic wrong; it is a junction like two faces overlapping in part, resolved the same
/// way (the two source cells take each other's planes). Within eps in float arithmetic.
template <class T>
void find_corner_junctions(const VModel<T>& M, const std::vector<std::pair<int, std::size_t>>& origin, const std::vector<std::string>& names,
                           const T& eps, std::set<std::pair<std::pair<int, std::size_t>, std::pair<int, std::size_t>>>& junctions,
                           std::string& first_junction) {
  using P = Point3<T>;
  struct Geometry {
    bool planar = false;
    std::array<P, 8> c;
    P lo, hi;
    std::vector<std::optional<HalfSpace<T>>> faces;
    std::vector<std::vector<std::vector<T>>> quads;  // face_corners per face
    bool axis_edges = true;                          // every edge parallel to a coordinate axis
  };
  auto norm1 = [](const P& a) { return magnitude(a[0]) + magnitude(a[1]) + magnitude(a[2]); };
  std::vector<Geometry> g(M.cells.size());
  for (std::size_t k = 0; k < M.cells.size(); ++k) {
    const auto& V = M.trivariates[M.cells[k].trivariates.front()];
    if (!convex_planes(V, eps)) continue;
    g[k].planar = true;
    for (int i = 0; i < 8; ++i) {
      std::vector<T> u(3);
      for (int d = 0; d < 3; ++d) u[d] = (i >> d) & 1 ? V.domain_hi(d) : V.domain_lo(d);
      const auto x = evaluate(V, u);
      g[k].c[i] = {x[0], x[1], x[2]};
      for (int d = 0; d < 3; ++d) {
        if (i == 0 || x[d] < g[k].lo[d]) g[k].lo[d] = x[d];
        if (i == 0 || g[k].hi[d] < x[d]) g[k].hi[d] = x[d];
      }
    }
    for (int d = 0; d < 3; ++d)
      for (int i = 0; i < 8; ++i) {
        if ((i >> d) & 1) continue;
        int nonzero = 0;
        for (int c = 0; c < 3; ++c) nonzero += !(g[k].c[i][c] == g[k].c[i | (1 << d)][c]);
        g[k].axis_edges = g[k].axis_edges && nonzero <= 1;
      }
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) {
        g[k].faces.push_back(face_plane(V, d, s, eps));
        g[k].quads.push_back(face_corners(V, d, s));
      }
  }
  auto same_point = [&](const P& a, const P& b) { return close(a[0], b[0], eps) && close(a[1], b[1], eps) && close(a[2], b[2], eps); };
  auto inside_edge = [&](const P& p, const P& q0, const P& q1) {
    const P e = sub(q1, q0), v = sub(p, q0);
    const T tol = eps * norm1(e);
    if (!(tol < norm1(e)) || tol < norm1(cross(e, v))) return false;
    const T t = dot(v, e);
    return tol < t && t + tol < dot(e, e);
  };
  auto inside_face = [&](const P& p, const std::vector<std::vector<T>>& Q, const HalfSpace<T>& H) {
    const T ptol = eps * (magnitude(H.n[0]) + magnitude(H.n[1]) + magnitude(H.n[2]));
    if (ptol < magnitude(T(H.n[0] * p[0] + H.n[1] * p[1] + H.n[2] * p[2] + H.d))) return false;
    const P n{H.n[0], H.n[1], H.n[2]};
    int sign = 0, sides = 0;
    for (int k = 0; k < 4; ++k) {
      const P a{Q[k][0], Q[k][1], Q[k][2]}, b{Q[(k + 1) % 4][0], Q[(k + 1) % 4][1], Q[(k + 1) % 4][2]};
      const P e = sub(b, a);
      if (!(eps * norm1(e) < norm1(e))) continue;
      ++sides;
      const T s = dot(cross(e, sub(p, a)), n), tol = eps * norm1(e) * norm1(n);
      const int sg = s < -tol ? -1 : tol < s ? 1 : 0;
      if (sg == 0 || (sign != 0 && sg != sign)) return false;
      sign = sg;
    }
    return sides >= 3;
  };
  for (std::size_t i = 0; i < M.cells.size(); ++i)
    for (std::size_t j = 0; j < M.cells.size(); ++j) {
      if (i == j || !g[i].planar || !g[j].planar || origin[i] == origin[j]) continue;
      bool meet = true;
      for (int d = 0; d < 3; ++d) meet = meet && !(g[j].hi[d] + eps < g[i].lo[d]) && !(g[i].hi[d] + eps < g[j].lo[d]);
      if (!meet) continue;
      for (const auto& p : g[i].c) {
        bool corner = false;
        for (const auto& q : g[j].c) corner = corner || same_point(p, q);
        if (corner) continue;
        std::string where;
        for (int d = 0; d < 3 && where.empty(); ++d)
          for (int k = 0; k < 8 && where.empty(); ++k)
            if (!((k >> d) & 1) && inside_edge(p, g[j].c[k], g[j].c[k | (1 << d)])) where = "an edge";
        for (int f = 0; f < 6 && where.empty(); ++f)
          if (g[j].faces[f] && inside_face(p, g[j].quads[f], *g[j].faces[f])) where = "a face";
        if (where.empty()) continue;
        junctions.insert({origin[i], origin[j]});
        if (first_junction.empty())
          first_junction = "a corner of piece " + names[i] + " lies inside " + where + " of piece " + names[j] + " (a partial edge or vertex contact)";
        break;
      }
      // Exact arithmetic: an edge of i crossing an edge of j at one point inside both (a vertex
      // contact without a corner there; boxes never touch so).
      if (!(eps == T(0)) || (g[i].axis_edges && g[j].axis_edges) || junctions.count({origin[i], origin[j]})) continue;
      for (int d = 0; d < 3; ++d)
        for (int k = 0; k < 8; ++k) {
          if ((k >> d) & 1) continue;
          const P& p0 = g[i].c[k];
          const P e = sub(g[i].c[k | (1 << d)], p0);
          for (int d2 = 0; d2 < 3; ++d2)
            for (int k2 = 0; k2 < 8; ++k2) {
              if ((k2 >> d2) & 1) continue;
              const P f = sub(g[j].c[k2 | (1 << d2)], g[j].c[k2]), w = sub(g[j].c[k2], p0), n = cross(e, f);
              if (norm1(n) == T(0) || !(dot(w, n) == T(0))) continue;
              const T nn = dot(n, n), s = dot(cross(w, f), n), t = dot(cross(w, e), n);
              if (!(T(0) < s && s < nn && T(0) < t && t < nn)) continue;
              junctions.insert({origin[i], origin[j]});
              if (first_junction.empty()) first_junction = "an edge of piece " + names[i] + " crosses an edge of piece " + names[j] + " (a vertex contact)";
            }
        }
    }
}

}  // namespace vrep_detail

}  // namespace splinex
