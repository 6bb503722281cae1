#include "vrep/boolean/nef_check.hpp"

#include <CGAL/Cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/convex_decomposition_3.h>
#include <CGAL/convex_hull_3.h>

#include <map>
#include <functional>
#include <numeric>
#include <set>

#include "base/errors.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

using K = CGAL::Cartesian<CGAL::Gmpq>;
using Nef = CGAL::Nef_polyhedron_3<K>;
using Poly = CGAL::Polyhedron_3<K>;

CGAL::Gmpq gq(const Rational& x) { return CGAL::Gmpq(x.backend().data()); }
Rational rq(const CGAL::Gmpq& x) { return Rational(x.mpq()); }

Nef model_nef(const VModel<Rational>& M, const std::string& name) {
  Nef out(Nef::EMPTY);
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto& V = M.trivariates[M.cells[c].trivariates.front()];
    if (!convex_planes(V))
      throw DomainError(name + ".cells[" + std::to_string(c) + "]", "is not convex with planar faces", "give boxes or planar hexahedra");
    std::vector<K::Point_3> pts;
    for (int k = 0; k < 8; ++k) {
      std::vector<Rational> x;
      for (int d = 0; d < 3; ++d) x.push_back((k >> d) & 1 ? V.domain_hi(d) : V.domain_lo(d));
      const auto p = evaluate(V, x);
      pts.emplace_back(gq(p[0]), gq(p[1]), gq(p[2]));
    }
    Poly P;
    CGAL::convex_hull_3(pts.begin(), pts.end(), P);
    out += Nef(P);
  }
  return out;
}

}  // namespace

PolyhedronCounts nef_boolean(const VModel<Rational>& A, const VModel<Rational>& B, BooleanOp op) {
  const Nef a = model_nef(A, "A"), b = model_nef(B, "B");
  Nef r = op == BooleanOp::intersect ? a * b : op == BooleanOp::subtract ? a - b : a + b;
  r = r.regularization();
  PolyhedronCounts out;
  out.vertices = r.number_of_vertices();
  out.edges = r.number_of_edges();
  out.facets = r.number_of_facets();
  out.manifold = r.is_simple();
  if (r.is_empty()) return out;
  // The volume from a convex decomposition (robust where the boundary is not a 2-manifold): every
  // marked convex volume as a polyhedron, its faces fanned into triangles over the origin.
  Nef parts = r;
  CGAL::convex_decomposition_3(parts);
  CGAL::Gmpq six_v(0);
  for (auto ci = ++parts.volumes_begin(); ci != parts.volumes_end(); ++ci) {
    if (!ci->mark()) continue;
    Poly P;
    parts.convert_inner_shell_to_polyhedron(ci->shells_begin(), P);
    CGAL::Gmpq part(0);
    for (auto f = P.facets_begin(); f != P.facets_end(); ++f) {
      std::vector<K::Point_3> v;
      auto h = f->facet_begin();
      do {
        v.push_back(h->vertex()->point());
      } while (++h != f->facet_begin());
      for (std::size_t i = 1; i + 1 < v.size(); ++i) {
        const K::Point_3 &p = v[0], &q = v[i], &s = v[i + 1];
        part += p.x() * (q.y() * s.z() - q.z() * s.y()) - p.y() * (q.x() * s.z() - q.z() * s.x()) +
                p.z() * (q.x() * s.y() - q.y() * s.x());
      }
    }
    six_v += part < 0 ? -part : part;
  }
  out.volume = rq(six_v) / Rational(6);
  if (out.volume < 0) out.volume = -out.volume;
  return out;
}

PolyhedronCounts boundary_counts(const VModel<Rational>& M) {
  PolyhedronCounts out;
  for (std::size_t c = 0; c < M.cells.size(); ++c) out.volume += cell_volume(M, c);
  // Boundary V-surfaces, their planes (outward, normalized to a unit first non-zero component).
  std::vector<std::size_t> bnd;
  std::map<std::size_t, std::size_t> index;  // surface -> position in bnd
  std::vector<std::array<Rational, 4>> plane;
  for (std::size_t s = 0; s < M.surfaces.size(); ++s) {
    if (M.surfaces[s].halves.size() != 1) continue;
    const auto& h = M.half_surfaces[M.surfaces[s].halves[0]];
    const auto H = face_plane(M.trivariates[h.trivariate], h.dir, h.side);
    if (!H) throw DomainError("cells[" + std::to_string(h.cell) + "]", "has a boundary face that is not planar", "give boxes or planar hexahedra");
    std::array<Rational, 4> e{H->n[0], H->n[1], H->n[2], H->d};
    Rational lead(0);
    for (const auto& x : e)
      if (lead == 0 && x != 0) lead = abs(x);
    for (auto& x : e) x /= lead;
    index[s] = bnd.size();
    bnd.push_back(s);
    plane.push_back(e);
  }
  // Union-find of coplanar neighbours.
  std::vector<std::size_t> parent(bnd.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  for (const auto& curve : M.curves) {
    std::vector<std::size_t> on;
    for (std::size_t s : curve.surfaces)
      if (index.count(s)) on.push_back(index[s]);
    for (std::size_t i = 0; i < on.size(); ++i)
      for (std::size_t j = i + 1; j < on.size(); ++j)
        if (plane[on[i]] == plane[on[j]]) parent[find(on[i])] = find(on[j]);
  }
  std::set<std::size_t> groups;
  for (std::size_t i = 0; i < bnd.size(); ++i) groups.insert(find(i));
  out.facets = groups.size();
  // Creases: boundary V-curves between two different facets.
  std::vector<std::set<std::size_t>> point_groups(M.points.size());
  std::vector<std::size_t> crease_degree(M.points.size(), 0);
  std::size_t creases = 0;
  for (const auto& curve : M.curves) {
    std::set<std::size_t> g;
    for (std::size_t s : curve.surfaces)
      if (index.count(s)) g.insert(find(index[s]));
    for (std::size_t p : curve.ends) point_groups[p].insert(g.begin(), g.end());
    if (g.size() >= 2) {
      ++creases;
      if (g.size() != 2) out.manifold = false;
      for (std::size_t p : curve.ends) ++crease_degree[p];
    }
  }
  std::size_t interior = 0;
  for (std::size_t p = 0; p < M.points.size(); ++p) {
    if (point_groups[p].size() >= 3) ++out.vertices;
    else if (point_groups[p].size() == 2 && crease_degree[p] == 2) ++interior;
  }
  out.edges = creases - interior;
  return out;
}

}  // namespace splinex
