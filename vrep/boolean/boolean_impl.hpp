// Booleans on V-models (vrep/boolean/boolean.hpp): the templates, instantiated in vrep/instances.cpp.
// The volumes of cells are in vrep/boolean/volume_impl.hpp.
#pragma once
#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "base/errors.hpp"
#include "base/point.hpp"
#include "compose/affine.hpp"
#include "compose/compose.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/knots.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/boolean/boolean_junctions_impl.hpp"  // vrep_detail::find_corner_junctions
#include "vrep/boolean/volume_impl.hpp"  // cell_volume, volume_enclosure, vrep_detail::box_integral_bounds
#include "vrep/model/planted.hpp"
#include "vrep/model/trivariate_impl.hpp"  // vrep_detail::greville
#include "vrep/model/vmodel_impl.hpp"      // vrep_detail::magnitude, centre_of

namespace splinex {

namespace vrep_detail {

template <class T>
T plane_at(const HalfSpace<T>& H, const T* x) { return H.n[0] * x[0] + H.n[1] * x[1] + H.n[2] * x[2] + H.d; }

/// Whether half-space k of a cell's six is tested when a point is classified (always; the planted
/// bug of vrep/model/planted.hpp skips the second, the face u = end, in tests only).
inline bool plane_tested(std::size_t k) { return !(k == 1 && vrep_testing::is_planted(vrep_testing::Plant::classify_skips_plane)); }

/// The tolerance of a plane's values: eps times |n|_1 (a point moved by eps per coordinate moves
/// the value by at most that); 0 in exact mode.
template <class T>
T plane_tol(const HalfSpace<T>& H, const T& eps) {
  return eps == T(0) ? T(0) : eps * (magnitude(H.n[0]) + magnitude(H.n[1]) + magnitude(H.n[2]));
}

/// How a half-space meets a trivariate (see vrep/boolean/boolean.hpp).
template <class T>
struct PlaneOnCell {
  enum Kind { inside, outside, split, curved } kind = inside;
  int dir = 0;
  T at{0};
};

template <class T>
PlaneOnCell<T> plane_on(const BSpline<T>& V, const HalfSpace<T>& H, const T& eps) {
  // The plane's values at the Euclidean control points: L(T(u)) is their convex combination with
  // the positive weights w_i N_i / W, so their signs decide inside and outside.
  const std::size_t n = V.size();
  std::vector<T> c(n);
  for (std::size_t i = 0; i < n; ++i) c[i] = plane_at(H, &V.points[i * V.q]);
  const T tol = plane_tol(H, eps);
  bool all_in = true, all_out = true;
  for (const auto& x : c) {
    all_in = all_in && !(x < -tol);
    all_out = all_out && !(tol < x);
  }
  PlaneOnCell<T> r;
  if (all_in && all_out)
    throw DomainError("trivariate", "lies in a plane of another cell (det J = 0)", "give regular cells (vrep certify)");
  if (all_in) return r;
  if (all_out) {
    r.kind = PlaneOnCell<T>::outside;
    return r;
  }
  const std::size_t cnt[3] = {V.count(0), V.count(1), V.count(2)};
  auto flat = [&](std::size_t i0, std::size_t i1, std::size_t i2) { return i0 + cnt[0] * (i1 + cnt[1] * i2); };
  for (int d = 0; d < 3; ++d) {
    // Depends on direction d only?
    bool only_d = true;
    for (std::size_t i2 = 0; i2 < cnt[2] && only_d; ++i2)
      for (std::size_t i1 = 0; i1 < cnt[1] && only_d; ++i1)
        for (std::size_t i0 = 0; i0 < cnt[0] && only_d; ++i0) {
          std::size_t ref[3] = {0, 0, 0}, idx[3] = {i0, i1, i2};
          ref[d] = idx[d];
          only_d = !(tol < magnitude(T(c[flat(i0, i1, i2)] - c[flat(ref[0], ref[1], ref[2])])));
        }
    // The weights may not vary along d (then L(T) = sum_k N_k(u_d) c_k: the weights cancel).
    if (only_d && V.is_rational())
      for (std::size_t i2 = 0; i2 < cnt[2] && only_d; ++i2)
        for (std::size_t i1 = 0; i1 < cnt[1] && only_d; ++i1)
          for (std::size_t i0 = 0; i0 < cnt[0] && only_d; ++i0) {
            std::size_t ref[3] = {i0, i1, i2};
            ref[d] = 0;
            only_d = V.weights[flat(i0, i1, i2)] == V.weights[flat(ref[0], ref[1], ref[2])];
          }
    if (!only_d) continue;
    // Linear in the parameter: c_k = alpha + beta g_k on the Greville abscissae.
    const int p = V.degrees[d];
    if (p == 0) break;
    const std::vector<T> g = greville(V.knots[d], p, cnt[d]);
    std::vector<T> ck(cnt[d]);
    for (std::size_t k = 0; k < cnt[d]; ++k) {
      std::size_t idx[3] = {0, 0, 0};
      idx[d] = k;
      ck[k] = c[flat(idx[0], idx[1], idx[2])];
    }
    if (!(g.front() < g.back())) break;
    const T beta = (ck.back() - ck.front()) / (g.back() - g.front()), alpha = ck.front() - beta * g.front();
    bool linear = true;
    for (std::size_t k = 0; k < cnt[d] && linear; ++k) linear = !(tol < magnitude(T(alpha + beta * g[k] - ck[k])));
    if (!linear || beta == T(0)) break;
    r.kind = PlaneOnCell<T>::split;
    r.dir = d;
    r.at = -alpha / beta;
    return r;
  }
  r.kind = PlaneOnCell<T>::curved;
  return r;
}

/// A piece of a cell cut by the planes of the other model's cells: its trivariate and the cell of
/// the other model it lies in, if any.
template <class T>
struct Piece {
  BSpline<T> V;
  std::optional<std::size_t> in;
};

/// The planes of every cell of a model (nothing for a cell that is not convex with planar faces).
template <class T>
std::vector<std::optional<std::vector<HalfSpace<T>>>> model_planes(const VModel<T>& M, const T& eps) {
  std::vector<std::optional<std::vector<HalfSpace<T>>>> out;
  for (const auto& c : M.cells) out.push_back(convex_planes(M.trivariates[c.trivariates.front()], eps));
  return out;
}

template <class T>
std::vector<Piece<T>> pieces_of(const BSpline<T>& V, const std::string& vname, const VModel<T>& other, const std::string& oname,
                                const std::vector<std::optional<std::vector<HalfSpace<T>>>>& planes,
                                const std::vector<HalfSpace<T>>& forced, const T& eps, const Limits& limits, std::size_t& cut_count,
                                std::vector<HalfSpace<T>>& splitting) {
  std::vector<std::size_t> overlapping;
  std::vector<T> cuts[3];
  splitting.clear();
  for (const auto& H : forced) {
    const auto h = plane_on(V, H, eps);
    if (h.kind == PlaneOnCell<T>::curved)
      throw NotPlanarError(vname, "needs a cut by a plane of a neighbour's tiling that is not a parameter plane of its trivariate",
                           "cut it as a trimmed cell on the models' exact regions (vrep/trimmed/trimmed.hpp; vrep boolean --trim auto)");
    if (h.kind == PlaneOnCell<T>::split) {
      cuts[h.dir].push_back(h.at);
      splitting.push_back(H);
    }
  }
  for (std::size_t b = 0; b < other.cells.size(); ++b) {
    if (!planes[b])
      throw NotPlanarError(oname + ".cells[" + std::to_string(b) + "]", "is not a convex cell with planar faces: the planar path cannot cut with it",
                           "cut as trimmed cells on the models' exact regions (vrep/trimmed/trimmed.hpp; vrep boolean --trim auto)");
    bool outside = false;
    std::vector<PlaneOnCell<T>> how;
    for (const auto& H : *planes[b]) {
      how.push_back(plane_on(V, H, eps));
      outside = outside || how.back().kind == PlaneOnCell<T>::outside;
    }
    if (outside) continue;
    overlapping.push_back(b);
    for (const auto& h : how) {
      if (h.kind == PlaneOnCell<T>::curved)
        throw NotPlanarError(vname, "is cut by a face plane of " + oname + ".cells[" + std::to_string(b) +
                                        "] along a surface that is not a parameter plane of its trivariate",
                             "cut it as a trimmed cell on the models' exact regions (vrep/trimmed/trimmed.hpp; vrep boolean --trim auto)");
    }
    for (std::size_t k = 0; k < how.size(); ++k)
      if (how[k].kind == PlaneOnCell<T>::split) {
        cuts[how[k].dir].push_back(how[k].at);
        splitting.push_back((*planes[b])[k]);
      }
  }
  // The grid: cuts strictly inside the domain, sorted, those within eps of each other merged.
  for (int d = 0; d < 3; ++d) {
    std::sort(cuts[d].begin(), cuts[d].end());
    std::vector<T> kept;
    const T lo = V.domain_lo(d), hi = V.domain_hi(d);
    for (const auto& x : cuts[d]) {
      if (!(lo + eps < x) || !(x + eps < hi)) continue;
      if (!kept.empty() && !(kept.back() + eps < x)) continue;
      kept.push_back(x);
    }
    cuts[d] = kept;
    cut_count += kept.size();
  }
  limits.check_count((cuts[0].size() + 1) * (cuts[1].size() + 1) * (cuts[2].size() + 1) * V.size(), "pieces");
  std::vector<BSpline<T>> slabs{V};
  for (int d = 0; d < 3; ++d) {
    std::vector<BSpline<T>> next;
    for (auto S : slabs) {
      for (const auto& x : cuts[d]) {
        auto [left, right] = split_at(S, d, x, limits);
        next.push_back(std::move(left));
        S = std::move(right);
      }
      next.push_back(std::move(S));
    }
    slabs = std::move(next);
  }
  std::vector<Piece<T>> out;
  for (auto& S : slabs) {
    Piece<T> p{std::move(S), std::nullopt};
    const auto x = evaluate(p.V, centre_of(p.V));
    for (std::size_t b : overlapping) {
      bool inside = true;
      for (std::size_t k = 0; k < planes[b]->size(); ++k) {
        const auto& H = (*planes[b])[k];
        inside = inside && (!plane_tested(k) || plane_tol(H, eps) < plane_at(H, x.data()));
      }
      if (!inside) continue;
      if (p.in)
        throw DomainError(oname, "has cells " + std::to_string(*p.in) + " and " + std::to_string(b) + " that overlap",
                          "give a V-model whose cells meet only at their boundaries");
      p.in = b;
    }
    out.push_back(std::move(p));
  }
  return out;
}

template <class T>
void merge_constants(Attributes<T>& into, const Attributes<T>& from, Blend blend) {
  for (const auto& [name, v] : from.constants) {
    auto it = into.constants.find(name);
    if (it == into.constants.end()) {
      into.constants[name] = v;
      continue;
    }
    if (blend == Blend::first) continue;
    auto& w = it->second;
    if (w.size() != v.size())
      throw ValidationError("attributes." + name, "has values of different lengths in the two models", "give the same number of values");
    for (std::size_t i = 0; i < w.size(); ++i) {
      w[i] += v[i];
      if (blend == Blend::sum_clipped && T(1) < w[i]) w[i] = T(1);
    }
  }
}

/// The inverse of an affine cell: for a polynomial trivariate with one Bezier piece whose three
/// coordinates are affine in the parameters, x = alpha + B s, the map x -> B^-1 (x - alpha).
template <class T>
struct AffineInverse {
  std::array<T, 3> alpha;
  std::array<std::array<T, 3>, 3> inv;  // B^-1
  /// The parameters s = B^-1 (x - alpha) of the point x (three coordinates).
  std::array<T, 3> operator()(const T* x) const {
    const T d[3] = {x[0] - alpha[0], x[1] - alpha[1], x[2] - alpha[2]};
    std::array<T, 3> s;
    for (int r = 0; r < 3; ++r) s[r] = inv[r][0] * d[0] + inv[r][1] * d[1] + inv[r][2] * d[2];
    return s;
  }
};
template <class T>
std::optional<AffineInverse<T>> affine_inverse(const BSpline<T>& V) {
  if (V.is_rational() || V.dim() != 3 || V.q < 3) return std::nullopt;
  for (int d = 0; d < 3; ++d)
    if (breakpoints(V.knots[d], V.degrees[d], V.count(d)).size() != 2 || !is_clamped(V.knots[d], V.degrees[d], V.count(d))) return std::nullopt;
  std::array<std::array<T, 3>, 3> B;
  AffineInverse<T> r;
  for (int c = 0; c < 3; ++c) {
    const auto f = affine_form(V, c);
    if (!f) return std::nullopt;
    r.alpha[c] = f->alpha;
    for (int l = 0; l < 3; ++l) B[c][l] = f->beta[l];
  }
  const T det = B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1]) - B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0]) +
                B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0]);
  if (det == T(0)) return std::nullopt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // inv[i][j] = cofactor(j, i) / det
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      r.inv[i][j] = (B[r0][c0] * B[r1][c1] - B[r0][c1] * B[r1][c0]) / det;
    }
  return r;
}

/// The field F of an affine cell b pulled back onto the parameters of a piece P lying in b:
/// F o (T_b^-1 o P), exact (T_b^-1 o P has P's weights and the control points B^-1 (P_i - alpha);
/// the composition of papers/000). Nothing when a Bezier piece of the map crosses a knot line of F
/// (that would need the trimmed composition, Algorithm 1).
template <class T>
std::optional<BSpline<T>> pull_back_field(const BSpline<T>& F, const AffineInverse<T>& Ainv, const BSpline<T>& P, const Limits& limits) {
  BSpline<T> phi = P;
  phi.q = 3;
  phi.points.assign(3 * P.size(), T(0));
  for (std::size_t i = 0; i < P.size(); ++i) {
    const auto s = Ainv(&P.points[i * P.q]);
    std::copy(s.begin(), s.end(), phi.points.begin() + 3 * i);
  }
  try {
    return compose(F, phi, CompositionOptions{}, limits);
  } catch (const SizeLimitError&) {
    throw;
  } catch (const DomainError&) {
    return std::nullopt;
  }
}

/// Fields of a source cell onto a cell: `into` holds the cell's own (restricted) fields; `from`
/// are the other model's, already on the cell's parameters. Same names are blended like the
/// constants: first keeps the cell's own, sum adds them (one spline: make_compatible), and the
/// clipped sum is not a spline (ValidationError naming the field).
template <class T>
void merge_fields(std::map<std::string, BSpline<T>>& into, std::map<std::string, BSpline<T>> from, Blend blend, const Limits& limits) {
  for (auto& [name, F] : from) {
    auto it = into.find(name);
    if (it == into.end()) {
      into.emplace(name, std::move(F));
      continue;
    }
    if (blend == Blend::first) continue;
    if (blend == Blend::sum_clipped)
      throw ValidationError("attributes." + name, "is a field in both models: its clipped sum min(1, F1 + F2) is not a spline",
                            "give --blend sum (the fields added) or --blend first (the first model's)");
    if (it->second.q != F.q)
      throw ValidationError("attributes." + name, "has fields of different lengths in the two models", "give fields with the same number of components");
    auto [a, b] = make_compatible(it->second, F, limits);
    if (a.is_rational() || b.is_rational())
      throw DomainError("attributes." + name, "is a rational field in both models: their sum is not built", "give polynomial fields or --blend first");
    for (std::size_t i = 0; i < a.points.size(); ++i) a.points[i] += b.points[i];
    it->second = std::move(a);
  }
}

}  // namespace vrep_detail

namespace vrep_detail {

/// face_plane with the trivariate's centre point c given (convex_planes asks for six faces).
template <class T>
std::optional<HalfSpace<T>> face_plane_towards(const BSpline<T>& V, int d, int s, const T& eps, const std::vector<T>& c) {
  const BSpline<T> F = face(V, d, s);
  const std::size_t n = F.size();
  auto pt = [&](std::size_t i) { return &F.points[i * F.q]; };
  const T* p0 = pt(0);
  HalfSpace<T> H{{T(0), T(0), T(0)}, T(0)};
  bool found = false;
  for (std::size_t i = 1; i < n && !found; ++i)
    for (std::size_t j = i + 1; j < n && !found; ++j) {
      const Point3<T> a{pt(i)[0] - p0[0], pt(i)[1] - p0[1], pt(i)[2] - p0[2]};
      const Point3<T> b{pt(j)[0] - p0[0], pt(j)[1] - p0[1], pt(j)[2] - p0[2]};
      H.n = cross(a, b);
      const T size = magnitude(H.n[0]) + magnitude(H.n[1]) + magnitude(H.n[2]);
      const T amax = std::max({magnitude(a[0]), magnitude(a[1]), magnitude(a[2])}), bmax = std::max({magnitude(b[0]), magnitude(b[1]), magnitude(b[2])});
      found = eps * (amax + bmax) < size && !(size == T(0));
    }
  if (!found) return std::nullopt;
  H.d = -(H.n[0] * p0[0] + H.n[1] * p0[1] + H.n[2] * p0[2]);
  const T tol = plane_tol(H, eps);
  for (std::size_t i = 0; i < n; ++i)
    if (tol < magnitude(plane_at(H, pt(i)))) return std::nullopt;
  const T at_centre = plane_at(H, c.data());
  if (!(tol < magnitude(at_centre))) return std::nullopt;
  if (at_centre < T(0)) {
    for (auto& x : H.n) x = -x;
    H.d = -H.d;
  }
  return H;
}

}  // namespace vrep_detail

template <class T>
std::optional<HalfSpace<T>> face_plane(const BSpline<T>& V, int d, int s, const T& eps) {
  if (V.dim() != 3 || V.q < 3) throw ValidationError("trivariate", "is not a trivariate in R^3", "give a trivariate with q >= 3");
  return vrep_detail::face_plane_towards(V, d, s, eps, evaluate(V, vrep_detail::centre_of(V)));
}

template <class T>
std::optional<std::vector<HalfSpace<T>>> convex_planes(const BSpline<T>& V, const T& eps) {
  using namespace vrep_detail;
  if (V.dim() != 3 || V.q < 3) throw ValidationError("trivariate", "is not a trivariate in R^3", "give a trivariate with q >= 3");
  const auto c = evaluate(V, centre_of(V));
  std::vector<HalfSpace<T>> out;
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) {
      const auto H = face_plane_towards(V, d, s, eps, c);
      if (!H) return std::nullopt;
      out.push_back(*H);
    }
  for (const auto& H : out) {
    const T tol = plane_tol(H, eps);
    for (std::size_t i = 0; i < V.size(); ++i)
      if (plane_at(H, &V.points[i * V.q]) < -tol) return std::nullopt;
  }
  return out;
}

template <class T>
std::vector<std::vector<T>> face_corners(const BSpline<T>& V, int dir, int side) {
  const int a = dir == 0 ? 1 : 0, b = dir == 2 ? 1 : 2;
  std::vector<std::vector<T>> out;
  for (int k = 0; k < 4; ++k) {
    std::vector<T> x(3);
    x[dir] = side ? V.domain_hi(dir) : V.domain_lo(dir);
    x[a] = (k == 1 || k == 2) ? V.domain_hi(a) : V.domain_lo(a);
    x[b] = k >= 2 ? V.domain_hi(b) : V.domain_lo(b);
    auto p = evaluate(V, x);
    p.resize(3);
    out.push_back(std::move(p));
  }
  return out;
}

namespace vrep_detail {

/// One round's tiling (boolean_op, Algorithms 1-3): the pieces the operation keeps, in order, with
/// their names, their source cells in A and B, and the planes that split each source cell.
template <class T>
struct Tiling {
  struct Source {
    std::optional<std::size_t> a, b;
  };
  std::vector<BSpline<T>> cells;
  std::vector<std::string> names;
  std::vector<Source> sources;
  std::vector<std::pair<int, std::size_t>> origin;  // (model, cell) whose tiling made the piece
  std::vector<std::vector<HalfSpace<T>>> splitting[2];
  std::size_t cut_count = 0;
};

/// The junctions a round's conformity pass found: pairs of source cells (model, cell) whose pieces
/// meet without being glued, and the first one found, in words.
struct Junctions {
  std::set<std::pair<std::pair<int, std::size_t>, std::pair<int, std::size_t>>> pairs;
  std::string first;
};

/// A boundary face of a piece that lies in a plane.
template <class T>
struct BoundaryFace {
  std::size_t cell;
  HalfSpace<T> H;  // the inner side of the piece's face plane
  std::vector<std::vector<T>> corners;
  std::string text;
};

/// Whether two boundary faces overlap with positive area in one plane from opposite sides.
template <class T>
bool boundary_faces_overlap(const BoundaryFace<T>& f, const BoundaryFace<T>& g, const T& eps) {
  if (!(f.H.n[0] * g.H.n[0] + f.H.n[1] * g.H.n[1] + f.H.n[2] * g.H.n[2] < T(0))) return false;
  const T tol = plane_tol(g.H, eps);
  for (const auto& c : f.corners)
    if (tol < magnitude(plane_at(g.H, c.data()))) return false;
  // Positive-area overlap of two convex quadrilaterals in the plane (projected along the
  // normal's largest coordinate): no edge of either separates them.
  int drop = 0;
  for (int d = 1; d < 3; ++d)
    if (magnitude(f.H.n[drop]) < magnitude(f.H.n[d])) drop = d;
  const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
  auto separates = [&](const std::vector<std::vector<T>>& P, const std::vector<std::vector<T>>& Q) {
    T cu(0), cv(0);
    for (const auto& p : P) {
      cu += p[u];
      cv += p[v];
    }
    cu /= T(4);
    cv /= T(4);
    for (int k = 0; k < 4; ++k) {
      const auto &A = P[k], &B = P[(k + 1) % 4];
      const T eu = B[u] - A[u], ev = B[v] - A[v];
      auto side = [&](const T& x, const T& y) { return eu * (y - A[v]) - ev * (x - A[u]); };
      const T inner = side(cu, cv);
      const T etol = eps * (magnitude(eu) + magnitude(ev));
      bool all_out = true;
      for (const auto& q : Q) all_out = all_out && !(etol < (inner < T(0) ? T(-side(q[u], q[v])) : side(q[u], q[v])));
      if (all_out) return true;
    }
    return false;
  };
  return !separates(f.corners, g.corners) && !separates(g.corners, f.corners);
}

/// The planar Boolean of two valid V-models (boolean_op), round by round: what its steps share are
/// the operands, the planes of their cells and the cuts forced on their cells by earlier rounds.
template <class T>
class PlanarBoolean {
 public:
  PlanarBoolean(const VModel<T>& A, const VModel<T>& B, BooleanOp op, const T& eps, Blend blend, const Limits& limits)
      : A(A), B(B), op(op), eps(eps), blend(blend), limits(limits), planesA(model_planes(A, eps)), planesB(model_planes(B, eps)),
        forced{std::vector<std::vector<HalfSpace<T>>>(A.cells.size()), std::vector<std::vector<HalfSpace<T>>>(B.cells.size())} {}

  /// The rounds: tiling, gluing and conformity, until no junction is left; then the result's
  /// invariants, the statistics and the sources and attributes of its cells.
  VModel<T> run(BooleanStats<T>* stats) {
    for (int round = 0;; ++round) {
      const Tiling<T> tiling = tile();
      if (tiling.cells.empty())
        throw DomainError("result", "is empty (the models do not overlap where the operation keeps anything)", "check the operands and the operation");
      VModel<T> M = glue(tiling.cells, eps, tiling.names, limits);
      // No T-junctions: two boundary faces of different pieces may not overlap in one plane (with
      // opposite sides). Where they do (a cut that splits one face and not the other, or two cells
      // touching on faces that overlap in part), both source cells take each other's planes and the
      // round is repeated.
      Junctions junctions = face_junctions(M, tiling);
      if (junctions.pairs.empty()) find_corner_junctions(M, tiling.origin, tiling.names, eps, junctions.pairs, junctions.first);
      if (!junctions.pairs.empty()) {
        if (take_each_others_planes(junctions, tiling) && round < 16) continue;
        throw NotPlanarError("result", junctions.first + " (a T-junction the cuboid tiling could not resolve)",
                             "cut as trimmed cells on the models' exact regions (vrep/trimmed/trimmed.hpp; vrep boolean --trim auto)");
      }
      const auto result_check = check_invariants(M, limits);
      if (!result_check.ok())
        throw DomainError("result", "fails the V-model invariants: " + result_check.failures.front(),
                          "check that the inputs' cells are regular (vrep certify); please report it if they are");
      if (stats) {
        stats->pieces = tiling.cells.size();
        stats->cuts = tiling.cut_count;
        stats->rounds = static_cast<std::size_t>(round) + 1;
      }
      add_sources_and_attributes(M, tiling);
      return M;
    }
  }

 private:
  /// Algorithms 1-3: each cell of A cut by the planes of the cells of B that overlap it (and by the
  /// cuts forced on it), the pieces the operation keeps; in a union also B's pieces outside A.
  Tiling<T> tile() const {
    Tiling<T> tiling;
    tiling.splitting[0] = std::vector<std::vector<HalfSpace<T>>>(A.cells.size());
    tiling.splitting[1] = std::vector<std::vector<HalfSpace<T>>>(B.cells.size());
    for (std::size_t a = 0; a < A.cells.size(); ++a) {
      const auto& V = A.trivariates[A.cells[a].trivariates.front()];
      for (auto& p : pieces_of(V, "A.cells[" + std::to_string(a) + "]", B, "B", planesB, forced[0][a], eps, limits, tiling.cut_count,
                               tiling.splitting[0][a])) {
        const bool keep = p.in ? op != BooleanOp::subtract : op != BooleanOp::intersect;
        if (!keep) continue;
        tiling.names.push_back("A" + std::to_string(a) + (p.in ? "*B" + std::to_string(*p.in) : std::string()));
        tiling.sources.push_back({a, p.in});
        tiling.origin.push_back({0, a});
        tiling.cells.push_back(std::move(p.V));
      }
    }
    if (op == BooleanOp::unite)
      for (std::size_t b = 0; b < B.cells.size(); ++b) {
        const auto& V = B.trivariates[B.cells[b].trivariates.front()];
        for (auto& p : pieces_of(V, "B.cells[" + std::to_string(b) + "]", A, "A", planesA, forced[1][b], eps, limits, tiling.cut_count,
                                 tiling.splitting[1][b])) {
          if (p.in) continue;  // the intersection came from A's side
          tiling.names.push_back("B" + std::to_string(b));
          tiling.sources.push_back({std::nullopt, b});
          tiling.origin.push_back({1, b});
          tiling.cells.push_back(std::move(p.V));
        }
      }
    return tiling;
  }

  /// Conformity, the faces (find_corner_junctions looks at corners): a curved boundary face on a
  /// face of its source cell that was glued in the input, and two planar boundary faces of
  /// different pieces that overlap in part.
  Junctions face_junctions(const VModel<T>& M, const Tiling<T>& tiling) const {
    Junctions junctions;
    std::vector<BoundaryFace<T>> faces;
    for (const auto& h : M.half_surfaces) {
      if (h.twin) continue;
      const auto& V = M.trivariates[h.trivariate];
      const std::string text = "face (" + std::to_string(h.dir) + ", " + std::to_string(h.side) + ") of piece " + tiling.names[h.cell];
      const auto H = face_plane(V, h.dir, h.side, eps);
      if (H) {
        faces.push_back({h.cell, *H, face_corners(V, h.dir, h.side), text});
        continue;
      }
      // A curved face (of a curved cell of A; B's cells are planar): a part of its source cell's
      // face, since cuts are planar. If that face was internal in A, the neighbour's pieces must
      // have the same part: a face left unglued here is a junction between the two source cells.
      const auto [model, src] = tiling.origin[h.cell];
      const VModel<T>& S = model == 0 ? A : B;
      const auto& SV = S.trivariates[S.cells[src].trivariates.front()];
      const T end = h.side ? SV.domain_hi(h.dir) : SV.domain_lo(h.dir);
      const T here = h.side ? V.domain_hi(h.dir) : V.domain_lo(h.dir);
      if (!(end == here)) continue;
      for (const auto& sh : S.half_surfaces)
        if (sh.cell == src && sh.dir == h.dir && sh.side == h.side && sh.twin) {
          junctions.pairs.insert({tiling.origin[h.cell], {model, S.half_surfaces[*sh.twin].cell}});
          if (junctions.first.empty()) junctions.first = text + " lies on a face that was glued in the input and is not glued in the result";
        }
    }
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j) {
        if (faces[i].cell == faces[j].cell || !boundary_faces_overlap(faces[i], faces[j], eps)) continue;
        junctions.pairs.insert({tiling.origin[faces[i].cell], tiling.origin[faces[j].cell]});
        if (junctions.first.empty()) junctions.first = faces[i].text + " overlaps " + faces[j].text + " without being glued to it";
      }
    return junctions;
  }

  /// The two source cells of each junction take each other's planes (forced on them from the next
  /// round on). Whether any forced plane is new.
  bool take_each_others_planes(const Junctions& junctions, const Tiling<T>& tiling) {
    bool grew = false;
    // The planes of a source cell's tiling: its splitting planes and its own face planes (two
    // cells touching on faces that overlap only in part are cut to the common part).
    auto give = [&](std::pair<int, std::size_t> from, std::pair<int, std::size_t> to) {
      auto& f = forced[to.first][to.second];
      std::vector<HalfSpace<T>> planes = tiling.splitting[from.first][from.second];
      const auto& own = (from.first == 0 ? planesA : planesB)[from.second];
      if (own) planes.insert(planes.end(), own->begin(), own->end());
      for (const auto& H : planes) {
        bool have = false;
        for (const auto& G : f) have = have || (G.n == H.n && G.d == H.d);
        if (!have) {
          f.push_back(H);
          grew = true;
        }
      }
    };
    for (const auto& [x, y] : junctions.pairs) {
      give(x, y);
      give(y, x);
    }
    return grew;
  }

  /// Each result cell holds its piece first and then the trivariates of its sources (Section 4), and
  /// its sources' attributes by category (Figures 4, 5).
  void add_sources_and_attributes(VModel<T>& M, const Tiling<T>& tiling) const {
    // The source trivariates, each once, and the attributes by category.
    std::map<std::pair<int, std::size_t>, std::size_t> added;
    auto source_index = [&](int model, std::size_t t) {
      const auto key = std::make_pair(model, t);
      const auto it = added.find(key);
      if (it != added.end()) return it->second;
      M.trivariates.push_back(model == 0 ? A.trivariates[t] : B.trivariates[t]);
      added[key] = M.trivariates.size() - 1;
      return M.trivariates.size() - 1;
    };
    for (std::size_t k = 0; k < M.cells.size(); ++k) {
      auto& cell = M.cells[k];
      // (By index: source_index below appends to M.trivariates.)
      const std::size_t piece = cell.trivariates.front();
      std::array<T, 3> lo, hi;
      for (int d = 0; d < 3; ++d) {
        lo[d] = M.trivariates[piece].domain_lo(d);
        hi[d] = M.trivariates[piece].domain_hi(d);
      }
      // Fields: the piece's own model's restricted to the piece (the same parameters), the other
      // model's pulled back where its cell is affine (else named in not_carried).
      const int own = tiling.origin[k].first;
      const VModel<T>& O = own == 0 ? A : B;
      for (const auto& [name, F] : O.cells[tiling.origin[k].second].attributes.fields)
        cell.attributes.fields.emplace(name, restrict_to_box(F, lo.data(), hi.data(), limits));
      if (tiling.sources[k].a) {
        for (std::size_t t : A.cells[*tiling.sources[k].a].trivariates) cell.trivariates.push_back(source_index(0, t));
        merge_constants(cell.attributes, A.cells[*tiling.sources[k].a].attributes, blend);
      }
      if (tiling.sources[k].b) {
        for (std::size_t t : B.cells[*tiling.sources[k].b].trivariates) cell.trivariates.push_back(source_index(1, t));
        merge_constants(cell.attributes, B.cells[*tiling.sources[k].b].attributes, blend);
      }
      if (tiling.sources[k].a && tiling.sources[k].b) {
        const VModel<T>& X = own == 0 ? B : A;
        const std::size_t xc = own == 0 ? *tiling.sources[k].b : *tiling.sources[k].a;
        const auto& fields = X.cells[xc].attributes.fields;
        if (fields.empty()) continue;
        const auto inv = affine_inverse(X.trivariates[X.cells[xc].trivariates.front()]);
        std::map<std::string, BSpline<T>> pulled;
        for (const auto& [name, F] : fields) {
          std::optional<BSpline<T>> G;
          if (inv) G = pull_back_field(F, *inv, M.trivariates[piece], limits);
          if (G) pulled.emplace(name, std::move(*G));
          else cell.attributes.not_carried.push_back(name);
        }
        merge_fields(cell.attributes.fields, std::move(pulled), blend, limits);
      }
    }
  }

  const VModel<T>& A;
  const VModel<T>& B;
  const BooleanOp op;
  const T& eps;
  const Blend blend;
  const Limits& limits;
  const std::vector<std::optional<std::vector<HalfSpace<T>>>> planesA, planesB;
  // Cuts forced on a source cell by a neighbour's tiling (a T-junction found in an earlier round):
  // the planes that split the cell on the other side of the junction, and its face planes. They only grow, and there
  // are finitely many planes, so the rounds end.
  std::vector<std::vector<HalfSpace<T>>> forced[2];
};

}  // namespace vrep_detail

template <class T>
VModel<T> boolean_op(const VModel<T>& A, const VModel<T>& B, BooleanOp op, const T& eps, Blend blend, const Limits& limits,
                     BooleanStats<T>* stats) {
  using namespace vrep_detail;
  if (eps < T(0)) throw ValidationError("eps", "must not be negative", "give eps >= 0");
  // Only valid V-models in, only valid V-models out: a degenerate or inconsistent input is a
  // typed error here, not an invalid result later.
  for (const auto* X : {&A, &B}) {
    const auto chk = check_invariants(*X, limits);
    if (!chk.ok())
      throw DomainError(X == &A ? "A" : "B", "is not a valid V-model: " + chk.failures.front(),
                        "give regular cells glued face to face (vrep info shows the invariants)");
  }
  return PlanarBoolean<T>(A, B, op, eps, blend, limits).run(stats);
}

template <class T>
std::vector<std::size_t> cells_containing(const VModel<T>& M, const std::vector<T>& x, const T& eps) {
  using namespace vrep_detail;
  if (x.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto P = convex_planes(M.trivariates[M.cells[c].trivariates.front()], eps);
    if (!P)
      throw DomainError("cells[" + std::to_string(c) + "]", "is not a convex cell with planar faces: point classification in curved cells is not built yet",
                        "classify in models of boxes or planar hexahedra for now");
    bool in = true;
    for (std::size_t k = 0; k < P->size(); ++k) in = in && (!plane_tested(k) || !(plane_at((*P)[k], x.data()) < -plane_tol((*P)[k], eps)));
    if (in) out.push_back(c);
  }
  return out;
}

}  // namespace splinex
