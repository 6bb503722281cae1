// V-curves between two trimming surfaces of a trimmed cell (vrep/trimmed.hpp: trimmed_curves has
// the method), instantiated for Rational and double.
#include <algorithm>
#include <deque>
#include <map>

#include "solve/solver.hpp"
#include "spline/bezier.hpp"
#include "spline/errors.hpp"
#include "vrep/box_components.hpp"
#include "vrep/trimmed.hpp"
#include "vrep/trimmed_impl.hpp"

namespace splinex {

namespace {

using detail::Bern;
using namespace vrep_detail;

/// a raised to the degrees `deg` (each >= a's): a times the polynomial 1 of the difference.
template <class T>
Bern<T> elevate_to(const Bern<T>& a, const std::vector<int>& deg) {
  Bern<T> one;
  one.deg.resize(deg.size());
  bool same = true;
  for (std::size_t l = 0; l < deg.size(); ++l) {
    one.deg[l] = deg[l] - a.deg[l];
    same = same && one.deg[l] == 0;
  }
  if (same) return a;
  one.c.assign(detail::tensor_size(one.deg), T(1));
  return detail::bern_product(a, one);
}

/// a + b or a - b at their common degrees.
template <class T>
Bern<T> sum(const Bern<T>& a, const Bern<T>& b, bool minus) {
  std::vector<int> deg(a.deg.size());
  for (std::size_t l = 0; l < deg.size(); ++l) deg[l] = std::max(a.deg[l], b.deg[l]);
  const Bern<T> x = elevate_to(a, deg), y = elevate_to(b, deg);
  return minus ? detail::bern_sub(x, y) : detail::bern_add(x, y);
}

/// G / t_d (side 0) or G / (1 - t_d) (side 1) for G vanishing on that face: with G's coefficients
/// c_i along d (degree p), B_i^p = (p / i) t B_{i-1}^{p-1} = (p / (p - i)) (1 - t) B_i^{p-1}.
template <class T>
Bern<T> divide_face(const Bern<T>& G, int d, int side) {
  Bern<T> H;
  H.deg = G.deg;
  const int p = G.deg[static_cast<std::size_t>(d)];
  H.deg[static_cast<std::size_t>(d)] = p - 1;
  H.c.resize(detail::tensor_size(H.deg));
  const std::size_t n = G.deg.size();
  std::vector<int> idx(n);
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
Truth strict(const Bern<T>& b) {
  const int s = detail::bern_sign(b);
  return s > 0 ? Truth::in : s < 0 ? Truth::out : Truth::mixed;
}

/// The components of grad f x grad g (in the box's unit coordinates: each a positive multiple of
/// the true one, so its signs are the true ones).
template <class T>
std::array<Bern<T>, 3> cross(const Bern<T>& f, const Bern<T>& g) {
  std::array<Bern<T>, 3> df, dg, X;
  for (int d = 0; d < 3; ++d) {
    df[d] = detail::bern_derivative(f, d);
    dg[d] = detail::bern_derivative(g, d);
  }
  for (int d = 0; d < 3; ++d) {
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    X[d] = sum(detail::bern_product(df[a], dg[b]), detail::bern_product(df[b], dg[a]), true);
  }
  return X;
}

template <class T>
struct CBox {
  std::array<T, 3> lo, hi;
  std::size_t piece = 0;
  std::vector<Bern<T>> G;    // every leaf
  std::array<Bern<T>, 3> X;  // grad g_i x grad g_j, split with the box from its piece
  int level = 0;
};

/// A root of g_i = g_j = 0 on a face of a box: the plane x_d = at, the root's box in the other two
/// directions (in increasing order).
template <class T>
struct Crossing {
  int d = 0, side = 0;  // the box's face: side 0 its lower, 1 its upper one
  T at;
  std::array<T, 2> lo, hi;
  bool domain = false;          // on a face of V's domain
  bool identified = false;      // ... one V identifies with another or collapses
  Truth k_sign = Truth::mixed;  // the one undecided other leaf's sign there
};

/// One box's arc: from x[0] to x[1], active along it (or its two halves, cut where g_k = 0).
template <class T>
struct Arc {
  Crossing<T> x[2];
  bool halves = false, vpoint = false;
  bool active[2] = {false, false};
};

enum class Verdict { none, arc, split, fail };

const char* const kOnDomainFace = "a trimming surface contains a face of the domain";
const char* const kTangent = "the curve is tangent to a split plane or a face of the domain, or lies in one";
const char* const kCoincide = "the two trimming surfaces coincide (grad g_i x grad g_j vanishes identically)";
bool permanent(const std::string& reason) { return reason == kOnDomainFace || reason == kCoincide; }

}  // namespace

template <class T>
TrimmedCurves<T> trimmed_curves(const BSpline<T>& V, const Region<T>& trim, const CurveOptions& options, const Limits& limits) {
  require_jacobian_input(V, limits);
  if (options.max_boxes < 8) throw ValidationError("boxes", "must be at least 8", "give a larger box budget");
  if (options.max_level < 1 || options.max_level > 200) throw ValidationError("max_level", "must be in [1, 200]", "give a level between 1 and 200");
  require_clamped(V);
  require_positive_weights(V);
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(trim, leaves);
  const std::size_t nl = leaves.size();
  const std::size_t per_piece = composed_leaves_size(V, leaves, limits);
  checked_product(per_piece + 1, options.max_boxes, limits, "region composed on the subdivision boxes");
  TrimmedCurves<T> out;
  if (nl < 2) return out;
  auto pieces = leaf_pieces(V, leaves, limits);
  using Piece = LeafPiece<T>;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    // A leaf vanishing on a face of the domain (a trimming plane on a face of the cell: coplanar
    // contact) has that face's parameter as a factor; the curves of the open domain are those of
    // the quotient, which has the same signs inside.
    for (auto& G : pieces[k].G)
      for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 2; ++s)
          while ((s ? pieces[k].hi[d] == V.domain_hi(d) : pieces[k].lo[d] == V.domain_lo(d)) && G.deg[static_cast<std::size_t>(d)] > 0 &&
                 !all_zero(G) && all_zero(detail::bern_face(G, d, s)))
            G = divide_face(G, d, s);
  }
  // V's own identifications: faces collapsed or equal to another face.
  bool identified[3][2] = {};
  {
    std::array<std::array<BSpline<T>, 2>, 3> faces;
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) faces[d][s] = face(V, d, s);
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) {
        identified[d][s] = identified[d][s] || collapsed(faces[d][s], 0) || collapsed(faces[d][s], 1);
        for (int d2 = d; d2 < 3; ++d2)
          for (int s2 = 0; s2 < 2; ++s2) {
            if (d2 == d && s2 <= s) continue;
            if (corner_set(faces[d][s]) != corner_set(faces[d2][s2]) || !same_surface(faces[d][s], faces[d2][s2], T(0), limits)) continue;
            identified[d][s] = identified[d2][s2] = true;
          }
      }
  }
  SolveOptions so;
  so.max_depth = 30;
  so.max_boxes = 800;
  so.refine_bits = 60;
  so.recognize_rationals = true;

  // The crossings of {g_i = g_j = 0} with face (d, s) of box B; false when they are not all
  // certified simple roots strictly inside the face (`hard`: splitting cannot help).
  auto face_crossings = [&](const CBox<T>& B, std::size_t i, std::size_t j, long k, int d, int s, std::vector<Crossing<T>>& found, std::string& hard) {
    const Bern<T> Hi = detail::bern_face(B.G[i], d, s), Hj = detail::bern_face(B.G[j], d, s);
    if (detail::bern_sign(Hi) != 0 || detail::bern_sign(Hj) != 0) return true;
    if (all_zero(Hi) || all_zero(Hj)) {
      const bool on_domain = s ? B.hi[d] == V.domain_hi(d) : B.lo[d] == V.domain_lo(d);
      hard = on_domain ? kOnDomainFace : "a trimming surface contains a split plane";
      return false;
    }
    const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
    const std::vector<T> lo{B.lo[a], B.lo[b]}, hi{B.hi[a], B.hi[b]};
    const SolveResult<T> r = solve_system(std::vector<Bern<T>>{Hi, Hj}, lo, hi, so);
    // Undecided roots on a face (the curve tangent to it or lying in it) stay on it however the box
    // is split: another split fraction must move the face.
    if (!r.undecided.empty() || r.budget_exhausted) {
      hard = kTangent;
      return false;
    }
    for (const auto& root : r.roots) {
      Crossing<T> c;
      c.d = d;
      c.side = s;
      c.at = s ? B.hi[d] : B.lo[d];
      std::vector<T> u(2);
      if (root.exact) {
        for (int q = 0; q < 2; ++q) {
          c.lo[q] = c.hi[q] = root.point[q];
          u[q] = (root.point[q] - lo[q]) / (hi[q] - lo[q]);
        }
        // A simple root: the Jacobian is regular at it (exact determinant).
        const T det = detail::bern_value(detail::bern_derivative(Hi, 0), u) * detail::bern_value(detail::bern_derivative(Hj, 1), u) -
                      detail::bern_value(detail::bern_derivative(Hi, 1), u) * detail::bern_value(detail::bern_derivative(Hj, 0), u);
        if (det == T(0)) {
          hard = kTangent;
          return false;
        }
      } else {
        if (!root.unique) {
          hard = kTangent;
          return false;
        }
        for (int q = 0; q < 2; ++q) {
          c.lo[q] = root.lo[q];
          c.hi[q] = root.hi[q];
        }
      }
      for (int q = 0; q < 2; ++q)
        if (!(lo[q] < c.lo[q] && c.hi[q] < hi[q])) {
          hard = "a V-curve meets an edge of a subdivision box";
          return false;
        }
      c.domain = (s ? c.at == V.domain_hi(d) : c.at == V.domain_lo(d));
      c.identified = c.domain && identified[d][s];
      if (k >= 0) {
        const Bern<T> Hk = detail::bern_face(B.G[static_cast<std::size_t>(k)], d, s);
        if (root.exact) c.k_sign = value_truth(detail::bern_value(Hk, u), T(0));
        else {
          Bern<T> h = Hk;
          for (int q = 0; q < 2; ++q) {
            const T from = (c.lo[q] - lo[q]) / (hi[q] - lo[q]), to = (c.hi[q] - lo[q]) / (hi[q] - lo[q]);
            h = detail::bern_restrict(h, q, from, to);
          }
          c.k_sign = strict(h);
        }
        if (c.k_sign == Truth::mixed) {  // a third surface through the crossing: a V-point on a split plane
          hard = "a V-point lies on a split plane";
          return false;
        }
      }
      found.push_back(std::move(c));
    }
    return true;
  };

  // One box: no curve that matters, one arc, split it, or give up.
  auto examine = [&](const CBox<T>& B, std::size_t i, std::size_t j, Arc<T>& arc, std::string& hard) {
    if (detail::bern_sign(B.G[i]) != 0 || detail::bern_sign(B.G[j]) != 0) return Verdict::none;
    std::vector<Truth> fixed(nl, Truth::mixed);
    std::vector<std::size_t> open;  // other leaves without one strict sign
    for (std::size_t l = 0; l < nl; ++l) {
      if (l == i || l == j) continue;
      fixed[l] = strict(B.G[l]);
      if (fixed[l] == Truth::mixed) open.push_back(l);
    }
    // Whether the edge may matter here: the formula depends on both signs for some signs of the
    // undecided leaves (a box where it cannot is skipped: along a curve the activity is continuous
    // wherever the other leaves are strictly signed, so no arc of a box that matters ends there).
    bool matters = open.size() > 6;
    for (std::size_t pattern = 0; !matters && pattern < (std::size_t(1) << open.size()); ++pattern) {
      auto f = fixed;
      for (std::size_t q = 0; q < open.size(); ++q) f[open[q]] = (pattern >> q) & 1 ? Truth::in : Truth::out;
      matters = depends_on_each(trim, f, {i, j});
    }
    if (!matters) return Verdict::none;
    bool monotone = false, flat = true;
    for (int d = 0; d < 3; ++d) {
      monotone = monotone || detail::bern_sign(B.X[d]) != 0;
      flat = flat && all_zero(B.X[d]);
    }
    if (flat && B.level >= 6) {
      hard = kCoincide;
      return Verdict::fail;
    }
    if (!monotone || open.size() >= 2) return Verdict::split;
    const long k = open.empty() ? -1 : static_cast<long>(open.front());
    if (k >= 0) {
      // det(grad g_i, grad g_j, grad g_k) on the box: the derivatives of g_k in the box's unit
      // coordinates, X in its piece's; scaled to one positive multiple of the true determinant.
      const Piece& P = pieces[B.piece];
      std::array<T, 3> r;
      for (int d = 0; d < 3; ++d) r[d] = (B.hi[d] - B.lo[d]) / (P.hi[d] - P.lo[d]);
      Bern<T> D;
      for (int d = 0; d < 3; ++d) {
        Bern<T> t = detail::bern_product(detail::bern_derivative(B.G[static_cast<std::size_t>(k)], d), B.X[d]);
        const T scale = r[(d + 1) % 3] * r[(d + 2) % 3];
        for (auto& x : t.c) x *= scale;
        D = d == 0 ? t : sum(D, t, false);
      }
      if (detail::bern_sign(D) == 0) return Verdict::split;
    }
    std::vector<Crossing<T>> found;
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s)
        if (!face_crossings(B, i, j, k, d, s, found, hard)) return hard.empty() ? Verdict::split : Verdict::fail;
    if (found.empty()) return Verdict::none;
    if (found.size() != 2) return Verdict::split;
    arc = Arc<T>{};
    arc.x[0] = found[0];
    arc.x[1] = found[1];
    if (k < 0) {
      arc.active[0] = depends_on_each(trim, fixed, {i, j});
      return Verdict::arc;
    }
    auto f0 = fixed, f1 = fixed;
    f0[static_cast<std::size_t>(k)] = found[0].k_sign;
    f1[static_cast<std::size_t>(k)] = found[1].k_sign;
    arc.active[0] = depends_on_each(trim, f0, {i, j});
    if (found[0].k_sign != found[1].k_sign) {
      arc.halves = true;
      arc.active[1] = depends_on_each(trim, f1, {i, j});
      arc.vpoint = depends_on_each(trim, fixed, {i, j, static_cast<std::size_t>(k)});
    }
    return Verdict::arc;
  };

  // One attempt at one split fraction; false (reason set) when it does not decide.
  auto attempt = [&](std::size_t i, std::size_t j, const T& frac, typename TrimmedCurves<T>::Pair& pr) {
    pr.arcs = pr.loops = pr.ends_on_faces = pr.ends_at_points = pr.ends_on_identified_faces = pr.crossings = 0;
    std::deque<CBox<T>> todo;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      if (detail::bern_sign(pieces[p].G[i]) != 0 || detail::bern_sign(pieces[p].G[j]) != 0) continue;
      CBox<T> b;
      b.lo = pieces[p].lo;
      b.hi = pieces[p].hi;
      b.piece = p;
      b.G = pieces[p].G;
      b.X = cross(b.G[i], b.G[j]);
      todo.push_back(std::move(b));
    }
    std::vector<Arc<T>> arcs;
    std::size_t boxes = 0;
    while (!todo.empty()) {
      if (++boxes > options.max_boxes) {
        pr.boxes = boxes;
        pr.undecided_reason = "the box budget (" + std::to_string(options.max_boxes) + ") is spent";
        return false;
      }
      CBox<T> B = std::move(todo.front());
      todo.pop_front();
      Arc<T> arc;
      std::string hard;
      const Verdict v = examine(B, i, j, arc, hard);
      if (v == Verdict::fail) {
        pr.undecided_reason = hard;
        return false;
      }
      if (v == Verdict::arc) arcs.push_back(std::move(arc));
      if (v != Verdict::split) continue;
      if (B.level >= options.max_level) {
        pr.undecided_reason = "a box at the deepest level is still open (a singular or tangential point of the curve)";
        return false;
      }
      int dir = 0;
      for (int d = 1; d < 3; ++d)
        if ((B.hi[dir] - B.lo[dir]) < (B.hi[d] - B.lo[d])) dir = d;
      CBox<T> c[2];
      for (auto& h : c) {
        h.lo = B.lo;
        h.hi = B.hi;
        h.piece = B.piece;
        h.level = B.level + 1;
        h.G.resize(nl);
      }
      for (std::size_t l = 0; l < nl; ++l) std::tie(c[0].G[l], c[1].G[l]) = detail::bern_split(B.G[l], dir, frac);
      for (int d = 0; d < 3; ++d) std::tie(c[0].X[d], c[1].X[d]) = detail::bern_split(B.X[d], dir, frac);
      const T mid = B.lo[dir] + frac * (B.hi[dir] - B.lo[dir]);
      c[0].hi[dir] = mid;
      c[1].lo[dir] = mid;
      todo.push_back(std::move(c[0]));
      todo.push_back(std::move(c[1]));
    }
    pr.boxes = boxes;
    // The graph: crossings are nodes (matched across the faces boxes share), arcs are edges.
    const std::size_t nx = 2 * arcs.size();
    pr.crossings = nx;
    UnionFind nodes(nx + arcs.size());  // crossings, then one middle node per arc
    std::map<std::pair<int, T>, std::vector<std::size_t>> planes;
    for (std::size_t a = 0; a < arcs.size(); ++a)
      for (int e = 0; e < 2; ++e)
        if (!arcs[a].x[e].domain) planes[{arcs[a].x[e].d, arcs[a].x[e].at}].push_back(2 * a + static_cast<std::size_t>(e));
    auto crossing = [&](std::size_t r) -> const Crossing<T>& { return arcs[r / 2].x[r % 2]; };
    for (const auto& [plane, recs] : planes) {
      std::vector<std::size_t> partners(recs.size(), 0), partner(recs.size(), 0);
      for (std::size_t p = 0; p < recs.size(); ++p)
        for (std::size_t q = p + 1; q < recs.size(); ++q) {
          const auto &x = crossing(recs[p]), &y = crossing(recs[q]);
          if (x.side == y.side) continue;  // the same side of the plane: different boxes' faces there do not overlap
          bool meet = true;
          for (int t = 0; t < 2 && meet; ++t) meet = !(x.hi[t] < y.lo[t] || y.hi[t] < x.lo[t]);
          if (!meet) continue;
          ++partners[p];
          ++partners[q];
          partner[p] = q;
          partner[q] = p;
        }
      for (std::size_t p = 0; p < recs.size(); ++p) {
        if (partners[p] > 1) {
          pr.undecided_reason = "two crossings of the curve with a split plane cannot be told apart";
          return false;
        }
        if (partners[p] == 1) nodes.join(recs[p], recs[partner[p]]);
      }
    }
    // Node kinds: 1 an end on the domain's faces, 2 a V-point; 0 an inner node.
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
        pr.undecided_reason = "an arc of the curve ends inside the domain without a V-point (inconsistent subdivision)";
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
            ++pr.ends_on_faces;
            pr.ends_on_identified_faces += seam[n];
          } else
            ++pr.ends_at_points;
        }
    }
    for (const auto& [c, e] : ends) {
      if (e == 0) ++pr.loops;
      else if (e == 2) ++pr.arcs;
      else {
        pr.undecided_reason = "a V-curve with " + std::to_string(e) + " ends (inconsistent subdivision)";
        return false;
      }
    }
    return true;
  };

  const T fractions[3] = {T(1) / T(2), T(7) / T(16), T(13) / T(32)};
  for (std::size_t i = 0; i < nl; ++i)
    for (std::size_t j = i + 1; j < nl; ++j) {
      bool meet = false;
      for (const auto& p : pieces) meet = meet || (detail::bern_sign(p.G[i]) == 0 && detail::bern_sign(p.G[j]) == 0);
      if (!meet) continue;
      typename TrimmedCurves<T>::Pair pr;
      pr.i = i;
      pr.j = j;
      std::string reasons;
      for (const T& f : fractions) {
        pr.undecided_reason.clear();
        if (attempt(i, j, f, pr)) {
          pr.decided = true;
          pr.split = f;
          break;
        }
        reasons = pr.undecided_reason;
        if (permanent(reasons)) break;  // another split fraction cannot help
      }
      if (!pr.decided) {
        pr.undecided_reason = reasons;
        out.decided = false;
      } else {
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
