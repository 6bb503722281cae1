// The V-model (vrep/model/vmodel.hpp): the templates, instantiated in vrep/instances.cpp.
#pragma once
#include <algorithm>
#include <map>
#include <set>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "float/mpfr.hpp"  // ArithTraits<T>::exact of every arithmetic
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/insert.hpp"
#include "spline/integrate.hpp"
#include "spline/knots.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/model/vmodel.hpp"

namespace splinex {

namespace vrep_detail {

template <class T>
T magnitude(const T& x) {
  return x < T(0) ? T(-x) : x;
}

/// The centre of a spline's parameter domain.
template <class T>
std::vector<T> centre_of(const BSpline<T>& V) {
  std::vector<T> x;
  for (int d = 0; d < V.dim(); ++d) x.push_back((V.domain_lo(d) + V.domain_hi(d)) / T(2));
  return x;
}

template <class T>
bool close(const T& a, const T& b, const T& eps) {
  return eps == T(0) ? a == b : !(eps < magnitude(T(a - b)));
}

/// S with every direction's domain mapped affinely onto [0, 1] (knots only; exact in exact
/// arithmetic; the geometry is unchanged).
template <class T>
BSpline<T> unit_domains(BSpline<T> S) {
  for (int d = 0; d < S.dim(); ++d) {
    const T lo = S.domain_lo(d), hi = S.domain_hi(d);
    if (lo == T(0) && hi == T(1)) continue;
    for (auto& u : S.knots[d]) u = (u - lo) / (hi - lo);
  }
  return S;
}

/// The two directions of a surface swapped.
template <class T>
BSpline<T> swap_directions(const BSpline<T>& S) {
  BSpline<T> R = S;
  std::swap(R.degrees[0], R.degrees[1]);
  std::swap(R.knots[0], R.knots[1]);
  const std::size_t n0 = S.count(0), n1 = S.count(1);
  for (std::size_t j = 0; j < n1; ++j)
    for (std::size_t i = 0; i < n0; ++i) {
      for (int c = 0; c < S.q; ++c) R.points[(j + n1 * i) * S.q + c] = S.points[(i + n0 * j) * S.q + c];
      if (S.is_rational()) R.weights[j + n1 * i] = S.weights[i + n0 * j];
    }
  return R;
}

/// Whether two clamped nets (points of size >= 3) differ at a corner: first three coordinates or
/// weight (1 for a polynomial net) not within eps. A clamped net interpolates its corners, and
/// knot insertion and degree elevation keep the corner points and weights exactly in exact
/// arithmetic, so nets that differ there differ after any common space too. False (not decided)
/// for nets that are not clamped.
template <class T>
bool corners_differ(const BSpline<T>& a, const BSpline<T>& b, const T& eps) {
  const int k = a.dim();
  if (b.dim() != k || a.q < 3 || b.q < 3) return false;
  auto well_formed = [k](const BSpline<T>& s) {  // sizes only: make_compatible validates the rest
    if (s.knots.size() != static_cast<std::size_t>(k)) return false;
    for (int d = 0; d < k; ++d)
      if (s.degrees[d] < 0 || s.knots[d].size() < 2 * static_cast<std::size_t>(s.degrees[d]) + 2) return false;
    return s.points.size() == s.size() * static_cast<std::size_t>(s.q) && (!s.is_rational() || s.weights.size() == s.size());
  };
  if (!well_formed(a) || !well_formed(b)) return false;
  for (int d = 0; d < k; ++d)
    if (!is_clamped(a.knots[d], a.degrees[d], a.count(d)) || !is_clamped(b.knots[d], b.degrees[d], b.count(d))) return false;
  for (unsigned m = 0; m < (1u << k); ++m) {
    std::size_t ia = 0, ib = 0, sa = 1, sb = 1;
    for (int d = 0; d < k; ++d) {
      const bool hi = ((m >> d) & 1u) != 0;
      ia += (hi ? a.count(d) - 1 : 0) * sa;
      ib += (hi ? b.count(d) - 1 : 0) * sb;
      sa *= a.count(d);
      sb *= b.count(d);
    }
    for (int c = 0; c < 3; ++c)
      if (!close(a.points[ia * a.q + c], b.points[ib * b.q + c], eps)) return true;
    if (!close(a.is_rational() ? a.weights[ia] : T(1), b.is_rational() ? b.weights[ib] : T(1), eps)) return true;
  }
  return false;
}

/// Control points (first three coordinates) and weights equal within eps, after a common space.
/// In exact arithmetic nets that differ at a corner are told apart first (corners_differ), without
/// a common space: the same answer, without the refinement and elevation.
template <class T>
bool same_net_within(const BSpline<T>& a0, const BSpline<T>& b0, const T& eps, const Limits& limits) {
  if (a0.dim() != b0.dim()) return false;
  if constexpr (ArithTraits<T>::exact)  // exact: corners are kept exactly (not so in floats)
    if (corners_differ(a0, b0, eps)) return false;
  BSpline<T> a = unit_domains(a0), b = unit_domains(b0);
  if (a.is_rational() != b.is_rational()) {
    if (!a.is_rational()) a.weights.assign(a.size(), T(1));
    if (!b.is_rational()) b.weights.assign(b.size(), T(1));
  }
  // Geometry only: the first three coordinates.
  auto geometry = [](BSpline<T> S) {
    if (S.q == 3) return S;
    std::vector<T> p;
    for (std::size_t i = 0; i < S.size(); ++i)
      for (int c = 0; c < 3; ++c) p.push_back(S.points[i * S.q + c]);
    S.points = std::move(p);
    S.q = 3;
    return S;
  };
  auto [A, B] = make_compatible(geometry(std::move(a)), geometry(std::move(b)), limits);
  if (A.points.size() != B.points.size()) return false;
  for (std::size_t i = 0; i < A.points.size(); ++i)
    if (!close(A.points[i], B.points[i], eps)) return false;
  for (std::size_t i = 0; i < A.weights.size(); ++i)
    if (!close(A.weights[i], B.weights[i], eps)) return false;
  return true;
}

template <class T>
std::vector<T> geometry_of(const BSpline<T>& V, const std::vector<T>& x) {
  auto v = evaluate(V, x);
  v.resize(3);
  return v;
}

}  // namespace vrep_detail

template <class T>
BSpline<T> edge_curve(const BSpline<T>& V, int along, const std::array<int, 3>& sides) {
  const std::size_t n[3] = {V.count(0), V.count(1), V.count(2)};
  BSpline<T> C;
  C.degrees = {V.degrees[along]};
  C.knots = {V.knots[along]};
  C.q = V.q;
  for (std::size_t t = 0; t < n[along]; ++t) {
    std::size_t idx[3];
    for (int d = 0; d < 3; ++d) idx[d] = d == along ? t : (sides[d] == 0 ? 0 : n[d] - 1);
    const std::size_t k = idx[0] + n[0] * (idx[1] + n[1] * idx[2]);
    for (int c = 0; c < V.q; ++c) C.points.push_back(V.points[k * V.q + c]);
    if (V.is_rational()) C.weights.push_back(V.weights[k]);
  }
  return C;
}

template <class T>
bool same_curve(const BSpline<T>& a, const BSpline<T>& b, const T& eps, bool allow_reverse, const Limits& limits) {
  if (vrep_detail::same_net_within(a, b, eps, limits)) return true;
  return allow_reverse && vrep_detail::same_net_within(a, reverse(b, 0), eps, limits);
}

template <class T>
bool same_surface(const BSpline<T>& a, const BSpline<T>& b, const T& eps, const Limits& limits) {
  for (int swap = 0; swap < 2; ++swap)
    for (int rev = 0; rev < 4; ++rev) {
      BSpline<T> c = swap ? vrep_detail::swap_directions(b) : b;
      if (rev & 1) c = reverse(c, 0);
      if (rev & 2) c = reverse(c, 1);
      if (vrep_detail::same_net_within(a, c, eps, limits)) return true;
    }
  return false;
}

template <class T>
VModel<T> glue(const std::vector<BSpline<T>>& trivariates, const T& eps, const std::vector<std::string>& names, const Limits& limits) {
  using M = VModel<T>;
  M model;
  for (std::size_t t = 0; t < trivariates.size(); ++t) {
    const BSpline<T>& V0 = trivariates[t];
    const std::string field = "trivariates[" + std::to_string(t) + "]";
    validate(V0, limits);
    if (V0.dim() != 3 || V0.q < 3)
      throw ValidationError(field, "is not a trivariate with points in R^3", "give B-spline trivariates (q >= 3)");
    model.trivariates.push_back(clamp_all(V0, limits));
  }
  // Indexes, so that gluing H faces costs O(H log H) comparisons of keys instead of O(H^2)
  // surface comparisons: exact points by location (eps = 0; with a tolerance the points are
  // scanned, as closeness is not transitive), V-curves by their two end V-points, half-V-surfaces
  // by the sorted V-curves of their loop (already glued, so exact keys in either mode).
  const bool exact_points = eps == T(0);
  std::map<std::array<T, 3>, std::size_t> point_index;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> curve_index;
  std::map<std::array<std::size_t, 4>, std::vector<std::size_t>> loop_index;
  auto point_id = [&](const std::vector<T>& x) {
    if (exact_points) {
      const std::array<T, 3> key{x[0], x[1], x[2]};
      const auto it = point_index.find(key);
      if (it != point_index.end()) return it->second;
      point_index.emplace(key, model.points.size());
    } else {
      for (std::size_t p = 0; p < model.points.size(); ++p) {
        bool same = true;
        for (int c = 0; c < 3; ++c) same = same && vrep_detail::close(model.points[p].at[c], x[c], eps);
        if (same) return p;
      }
    }
    model.points.push_back({x, {}, {}});
    return model.points.size() - 1;
  };
  for (std::size_t t = 0; t < model.trivariates.size(); ++t) {
    const BSpline<T>& V = model.trivariates[t];
    typename M::Cell cell;
    cell.trivariates = {t};
    cell.name = t < names.size() ? names[t] : "cell " + std::to_string(t);
    const std::size_t cell_id = model.cells.size();
    // Corners -> V-points.
    auto corner = [&](int s0, int s1, int s2) {
      std::vector<T> x{s0 ? V.domain_hi(0) : V.domain_lo(0), s1 ? V.domain_hi(1) : V.domain_lo(1), s2 ? V.domain_hi(2) : V.domain_lo(2)};
      return point_id(vrep_detail::geometry_of(V, x));
    };
    // Edges -> V-curves: edge (along, sides of the other two).
    for (int k = 0; k < 8; ++k) cell.corners[k] = corner(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    // An edge's V-points are two of the corners found above (corner() would give the same ids
    // again, after an evaluation and a search each).
    auto corner_id = [&](const std::array<int, 3>& s) { return cell.corners[s[0] + 2 * s[1] + 4 * s[2]]; };
    auto edge_id = [&](int along, std::array<int, 3> sides) {
      std::array<int, 3> a = sides, b = sides;
      a[along] = 0;
      b[along] = 1;
      const std::size_t p0 = corner_id(a), p1 = corner_id(b);
      const BSpline<T> geom = edge_curve(V, along, sides);
      auto& candidates = curve_index[{std::min(p0, p1), std::max(p0, p1)}];
      for (std::size_t c : candidates)
        if (same_curve(model.curves[c].curve, geom, eps, true, limits)) return c;
      candidates.push_back(model.curves.size());
      model.curves.push_back({geom, {p0, p1}, {}, {}});
      model.points[p0].curves.push_back(model.curves.size() - 1);
      if (p1 != p0) model.points[p1].curves.push_back(model.curves.size() - 1);
      return model.curves.size() - 1;
    };
    // Edge (along, k): k = side of the lower other direction + 2 * side of the higher one.
    auto others = [](int along) { return std::pair<int, int>{along == 0 ? 1 : 0, along == 2 ? 1 : 2}; };
    for (int along = 0; along < 3; ++along)
      for (int k = 0; k < 4; ++k) {
        std::array<int, 3> sides{};
        const auto [lo, hi] = others(along);
        sides[lo] = k & 1;
        sides[hi] = (k >> 1) & 1;
        cell.edges[4 * along + k] = edge_id(along, sides);
      }
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) {
        typename M::HalfSurface h;
        h.cell = cell_id;
        h.trivariate = t;
        h.dir = d;
        h.side = s;
        const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
        // The loop: the four edges of the face, in order (a at b's start, b at a's end, a at b's end, b at a's start).
        for (int k = 0; k < 4; ++k) {
          std::array<int, 3> sides{};
          sides[d] = s;
          const int along = k % 2 == 0 ? a : b, other = k % 2 == 0 ? b : a;
          sides[other] = (k == 1 || k == 2) ? 1 : 0;
          const auto [lo, hi] = others(along);
          h.loop.push_back(cell.edges[4 * along + sides[lo] + 2 * sides[hi]]);  // glued above, once per edge
        }
        const BSpline<T> F = face(V, d, s);
        // A twin: an unpaired half-V-surface with the same edges and the same surface.
        std::array<std::size_t, 4> key{h.loop[0], h.loop[1], h.loop[2], h.loop[3]};
        std::sort(key.begin(), key.end());
        auto& same_loop = loop_index[key];
        for (std::size_t o : same_loop) {
          const auto& other = model.half_surfaces[o];
          // (Planted, tests only: vrep/model/planted.hpp twins faces by their loop alone.)
          if (!vrep_testing::is_planted(vrep_testing::Plant::vmodel_twin_by_loop) &&
              !same_surface(face(model.trivariates[other.trivariate], other.dir, other.side), F, eps, limits))
            continue;
          if (other.twin)
            throw ValidationError("trivariates[" + std::to_string(t) + "].face(" + std::to_string(d) + "," + std::to_string(s) + ")", "matches a V-surface that already has two half-V-surfaces (a non-manifold model)",
                                  "glue cells that meet face to face, at most two at a face");
          h.twin = o;
          h.surface = other.surface;
          break;
        }
        const std::size_t hid = model.half_surfaces.size();
        same_loop.push_back(hid);
        if (h.twin) {
          model.half_surfaces[*h.twin].twin = hid;
          model.surfaces[h.surface].halves.push_back(hid);
        } else {
          h.surface = model.surfaces.size();
          model.surfaces.push_back({{hid}, {}});
          for (std::size_t c : std::set<std::size_t>(h.loop.begin(), h.loop.end())) model.curves[c].surfaces.push_back(h.surface);
        }
        cell.half_surfaces.push_back(hid);
        model.half_surfaces.push_back(std::move(h));
      }
    model.cells.push_back(std::move(cell));
  }
  return model;
}

template <class T>
std::size_t surface_of_face(const VModel<T>& M, std::size_t cell, int dir, int side) {
  if (cell >= M.cells.size()) throw ValidationError("cell", "is not a cell of the model", "give 0.." + std::to_string(M.cells.size() - 1));
  if (dir < 0 || dir > 2 || side < 0 || side > 1) throw ValidationError("face", "is not a face", "give [direction 0..2, side 0|1]");
  for (std::size_t h : M.cells[cell].half_surfaces)
    if (M.half_surfaces[h].dir == dir && M.half_surfaces[h].side == side) return M.half_surfaces[h].surface;
  throw ValidationError("face", "the cell has no such face", "give a face of the cell");
}

template <class T>
std::size_t curve_of_edge(const VModel<T>& M, std::size_t cell, int along, const std::array<int, 3>& sides) {
  if (cell >= M.cells.size()) throw ValidationError("cell", "is not a cell of the model", "give 0.." + std::to_string(M.cells.size() - 1));
  if (along < 0 || along > 2) throw ValidationError("edge", "direction must be 0..2", "give the direction the edge runs along");
  const int lo = along == 0 ? 1 : 0, hi = along == 2 ? 1 : 2;
  if ((sides[lo] | sides[hi]) & ~1) throw ValidationError("edge", "sides must be 0 or 1", "give the sides of the other two directions");
  return M.cells[cell].edges[4 * along + sides[lo] + 2 * sides[hi]];
}

template <class T>
void attach_field(VModel<T>& M, std::size_t cell, const std::string& name, BSpline<T> field, const Limits& limits) {
  if (cell >= M.cells.size()) throw ValidationError("cell", "is not a cell of the model", "give 0.." + std::to_string(M.cells.size() - 1));
  require_field_on(M.trivariates[M.cells[cell].trivariates.front()], field, "attributes." + name, limits);
  M.cells[cell].attributes.fields[name] = std::move(field);
}

template <class T>
void require_field_on(const BSpline<T>& V, const BSpline<T>& F, const std::string& where, const Limits& limits) {
  validate(F, limits);
  if (F.dim() != 3) throw ValidationError(where, "is not a trivariate", "give an attribute trivariate on the cell's domain");
  for (int d = 0; d < 3; ++d)
    if (!(F.domain_lo(d) == V.domain_lo(d)) || !(F.domain_hi(d) == V.domain_hi(d)))
      throw ValidationError(where + ".knots[" + std::to_string(d) + "]", "spans another domain than the cell's trivariate",
                            "give the field on the cell's parameter domain (it shares the cell's parameters)");
}

template <class T>
CellValue<T> evaluate_cell(const VModel<T>& M, std::size_t cell, const std::vector<T>& x) {
  if (cell >= M.cells.size()) throw ValidationError("cell", "is not a cell of the model", "give 0.." + std::to_string(M.cells.size() - 1));
  const auto& c = M.cells[cell];
  CellValue<T> out;
  const auto v = evaluate(M.trivariates[c.trivariates.front()], x);
  out.point.assign(v.begin(), v.begin() + 3);
  out.coordinates.assign(v.begin() + 3, v.end());
  for (const auto& [name, F] : c.attributes.fields) out.fields[name] = evaluate(F, x);
  out.constants = c.attributes.constants;
  return out;
}

template <class T>
VModelCheck check_invariants(const VModel<T>& M, const Limits& limits) {
  VModelCheck r;
  auto fail = [&](const std::string& s) { r.failures.push_back(s); };
  for (std::size_t h = 0; h < M.half_surfaces.size(); ++h) {
    const auto& hs = M.half_surfaces[h];
    const std::string name = "half-V-surface " + std::to_string(h);
    if (hs.cell >= M.cells.size()) fail(name + ": no cell");
    const auto& S = M.surfaces.at(hs.surface);
    if (std::find(S.halves.begin(), S.halves.end(), h) == S.halves.end()) fail(name + ": its V-surface does not list it");
    if (hs.twin) {
      const auto& tw = M.half_surfaces.at(*hs.twin);
      if (!tw.twin || *tw.twin != h) fail(name + ": its twin does not point back");
      if (tw.surface != hs.surface) fail(name + ": its twin is on another V-surface");
      // Opposite orientation: at the common centre, the outward directions of the two cells lie
      // on opposite sides of the tangent plane.
      auto outward = [&](const typename VModel<T>::HalfSurface& x, std::vector<T>& at, std::vector<T>& out, std::vector<T>& normal) {
        const auto& V = M.trivariates[x.trivariate];
        std::vector<T> p = vrep_detail::centre_of(V);
        p[x.dir] = x.side ? V.domain_hi(x.dir) : V.domain_lo(x.dir);
        at = vrep_detail::geometry_of(V, p);
        std::vector<int> ord(3, 0);
        ord[x.dir] = 1;
        out = derivative(V, p, ord);
        out.resize(3);
        if (!x.side)
          for (auto& v : out) v = -v;
        const int a = x.dir == 0 ? 1 : 0, b = x.dir == 2 ? 1 : 2;
        std::vector<int> oa(3, 0), ob(3, 0);
        oa[a] = 1;
        ob[b] = 1;
        auto ta = derivative(V, p, oa), tb = derivative(V, p, ob);
        const Point3<T> n = cross(as_point3(ta), as_point3(tb));
        normal = {n[0], n[1], n[2]};
      };
      std::vector<T> p1, o1, n1, p2, o2, n2;
      outward(hs, p1, o1, n1);
      outward(tw, p2, o2, n2);
      const T d1 = n1[0] * o1[0] + n1[1] * o1[1] + n1[2] * o1[2], d2 = n1[0] * o2[0] + n1[1] * o2[1] + n1[2] * o2[2];
      if (!(d1 * d2 < T(0))) fail(name + ": it and its twin are not oppositely oriented (the cells overlap or one is degenerate there)");
    }
    if (hs.loop.size() != 4) fail(name + ": its loop does not have four V-curves");
    for (std::size_t c : hs.loop) {
      const auto& cv = M.curves.at(c);
      if (std::find(cv.surfaces.begin(), cv.surfaces.end(), hs.surface) == cv.surfaces.end())
        fail(name + ": V-curve " + std::to_string(c) + " of its loop does not list its V-surface");
    }
    // The loop is closed: consecutive V-curves share a V-point.
    for (std::size_t k = 0; k < hs.loop.size(); ++k) {
      const auto& a = M.curves.at(hs.loop[k]).ends;
      const auto& b = M.curves.at(hs.loop[(k + 1) % hs.loop.size()]).ends;
      if (a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1]) fail(name + ": its loop is not closed");
    }
  }
  for (std::size_t s = 0; s < M.surfaces.size(); ++s)
    if (M.surfaces[s].halves.empty() || M.surfaces[s].halves.size() > 2)
      fail("V-surface " + std::to_string(s) + ": has " + std::to_string(M.surfaces[s].halves.size()) + " halves");
  for (std::size_t c = 0; c < M.curves.size(); ++c) {
    const auto& cv = M.curves[c];
    for (std::size_t e : cv.ends) {
      if (e >= M.points.size()) {
        fail("V-curve " + std::to_string(c) + ": an end is not a V-point");
        continue;
      }
      const auto& pc = M.points[e].curves;
      if (std::find(pc.begin(), pc.end(), c) == pc.end()) fail("V-curve " + std::to_string(c) + ": its end V-point does not list it");
    }
    if (cv.surfaces.empty()) fail("V-curve " + std::to_string(c) + ": no V-surface");
  }
  (void)limits;
  r.euler = M.euler_characteristic();
  return r;
}

template <class T>
std::size_t VModel<T>::boundary_surfaces() const {
  std::size_t n = 0;
  for (const auto& s : surfaces) n += s.halves.size() == 1;
  return n;
}

template <class T>
std::size_t VModel<T>::internal_surfaces() const {
  return surfaces.size() - boundary_surfaces();
}

template <class T>
std::vector<std::size_t> VModel<T>::cells_of_curve(std::size_t curve) const {
  std::set<std::size_t> out;
  for (std::size_t s : curves.at(curve).surfaces)
    for (std::size_t h : surfaces.at(s).halves) out.insert(half_surfaces[h].cell);
  // Cells that meet the curve only along an edge of theirs without a V-surface on it still list it in a loop.
  for (const auto& h : half_surfaces)
    if (std::find(h.loop.begin(), h.loop.end(), curve) != h.loop.end()) out.insert(h.cell);
  return {out.begin(), out.end()};
}

template <class T>
std::vector<std::size_t> VModel<T>::neighbours_of_cell(std::size_t cell) const {
  std::set<std::size_t> out;
  for (std::size_t h : cells.at(cell).half_surfaces)
    if (half_surfaces[h].twin) {
      const std::size_t other = half_surfaces[*half_surfaces[h].twin].cell;
      if (other != cell) out.insert(other);
    }
  return {out.begin(), out.end()};
}

template <class T>
std::string VModel<T>::shared(std::size_t a, std::size_t b) const {
  for (std::size_t h : cells.at(a).half_surfaces)
    if (half_surfaces[h].twin && half_surfaces[*half_surfaces[h].twin].cell == b) return "surface";
  std::set<std::size_t> ca, cb;
  for (std::size_t h : cells.at(a).half_surfaces) ca.insert(half_surfaces[h].loop.begin(), half_surfaces[h].loop.end());
  for (std::size_t h : cells.at(b).half_surfaces) cb.insert(half_surfaces[h].loop.begin(), half_surfaces[h].loop.end());
  for (std::size_t c : ca)
    if (cb.count(c)) return "curve";
  std::set<std::size_t> pa, pb;
  for (std::size_t c : ca) pa.insert(curves[c].ends.begin(), curves[c].ends.end());
  for (std::size_t c : cb) pb.insert(curves[c].ends.begin(), curves[c].ends.end());
  for (std::size_t p : pa)
    if (pb.count(p)) return "point";
  return "none";
}

}  // namespace splinex
