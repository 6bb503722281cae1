// Trimming by freeform solids (vrep/freeform/freeform.hpp), instantiated for Rational and double.
#include "vrep/freeform/freeform.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <memory>
#include <numeric>
#include <queue>
#include <sstream>
#include <type_traits>

#include "base/errors.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/knots.hpp"
#include "vrep/boolean/boolean_impl.hpp"
#include "vrep/model/regularity_impl.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/freeform/cell_checks_impl.hpp"
#include "vrep/topology/box_components.hpp"

namespace splinex {

namespace {

using vrep_detail::corner_set;
using vrep_detail::join_identified;
using vrep_detail::join_touching;
using vrep_detail::UnionFind;
template <class T>
using H4 = std::array<Bernstein<T>, 4>;  // W, wx, wy, wz

/// Bounds (x_lo, y_lo, z_lo, x_hi, y_hi, z_hi) of the points of a homogeneous Bezier form: the
/// control points' (weights positive: every point is a convex combination of them).
template <class T>
std::array<T, 6> bounds_of(const H4<T>& h) {
  std::array<T, 6> b;
  const T one(1);
  for (std::size_t i = 0; i < h[0].c.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const bool unit = h[0].c[i] == one;  // polynomial: no division
      const T x = unit ? h[k + 1].c[i] : T(h[k + 1].c[i] / h[0].c[i]);
      if (i == 0 || x < b[k]) b[k] = x;
      if (i == 0 || b[k + 3] < x) b[k + 3] = x;
    }
  return b;
}

template <class T>
bool overlap(const std::array<T, 6>& a, const std::array<T, 6>& b) {
  for (int k = 0; k < 3; ++k)
    if (a[k + 3] < b[k] || b[k + 3] < a[k]) return false;
  return true;
}

template <class T>
T extent(const std::array<T, 6>& a) {
  T e = a[3] - a[0];
  for (int k = 1; k < 3; ++k) e = std::max(e, T(a[k + 3] - a[k]));
  return e;
}

template <class T>
H4<T> homogeneous_form(const BSpline<T>& piece) {
  H4<T> h;
  h[0] = bern_coordinate(piece, piece.q);
  for (int k = 0; k < 3; ++k) h[k + 1] = bern_coordinate(piece, k);
  return h;
}

template <class T>
std::pair<H4<T>, H4<T>> split_h(const H4<T>& h, int dir) {
  std::pair<H4<T>, H4<T>> out;
  for (int k = 0; k < 4; ++k) std::tie(out.first[k], out.second[k]) = vrep_detail::split_half(h[k], dir);
  return out;
}

}  // namespace

template <class T>
FreeformSolid<T> freeform_solid(std::string name, std::vector<BSpline<T>> cells, const Limits& limits) {
  if (cells.empty()) throw ValidationError(name + ".cells", "is empty", "give at least one trivariate");
  FreeformSolid<T> S;
  S.name = std::move(name);
  std::size_t pieces = 0;
  for (std::size_t c = 0; c < cells.size(); ++c)  // every cell's numbers before any cell's work
    vrep_detail::require_short_numbers(cells[c], S.name + ".cells[" + std::to_string(c) + "]", limits);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    vrep_detail::require_valid_shape(cells[c], S.name + ".cells[" + std::to_string(c) + "]", limits);
    std::size_t n = 1;
    for (int d = 0; d < 3; ++d) n = checked_product(n, cells[c].knots[d].size(), limits, "solid pieces");
    pieces += n;
    limits.check_count(pieces, "solid pieces");
  }
  // Faces and which of them another face covers.
  struct Face {
    std::size_t cell;
    int d, side;
    BSpline<T> F;
    std::vector<std::array<T, 3>> corners;
    bool inner = false;
  };
  std::vector<Face> faces;
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (int d = 0; d < 3; ++d)
      for (int s = 0; s < 2; ++s) {
        Face f{c, d, s, face(cells[c], d, s), {}, false};
        f.corners = corner_set(f.F);
        faces.push_back(std::move(f));
      }
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      if (faces[i].corners != faces[j].corners) continue;
      if (same_surface(faces[i].F, faces[j].F, T(0), limits)) faces[i].inner = faces[j].inner = true;
    }
  S.faces = faces.size();
  for (const auto& f : faces) {
    if (f.inner) {
      ++S.inner_faces;
      continue;
    }
    const BezierForm<T> B = bezier_form(f.F, limits);
    for (std::size_t k = 0; k < B.size(); ++k) {
      typename FreeformSolid<T>::Patch p;
      p.h = homogeneous_form(B.piece(k).spline);
      p.box = bounds_of(p.h);
      S.boundary.push_back(std::move(p));
    }
  }
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const BezierForm<T> B = bezier_form(cells[c], limits);
    for (std::size_t k = 0; k < B.size(); ++k) {
      const auto pc = B.piece(k);
      typename FreeformSolid<T>::Piece p;
      p.cell = c;
      p.h = homogeneous_form(pc.spline);
      p.box = bounds_of(p.h);
      for (int d = 0; d < 3; ++d) {
        p.lo.push_back(pc.box[d].first);
        p.hi.push_back(pc.box[d].second);
        for (int s = 0; s < 2; ++s) {
          const T at = s ? cells[c].domain_hi(d) : cells[c].domain_lo(d);
          const bool on_face = (s ? pc.box[d].second : pc.box[d].first) == at;
          p.on_boundary[d][s] = on_face && !faces[c * 6 + d * 2 + s].inner;
        }
      }
      S.pieces.push_back(std::move(p));
    }
  }
  S.box = S.pieces.front().box;
  for (const auto& p : S.pieces)
    for (int k = 0; k < 3; ++k) {
      S.box[k] = std::min(S.box[k], p.box[k]);
      S.box[k + 3] = std::max(S.box[k + 3], p.box[k + 3]);
    }
  S.cells = std::move(cells);
  return S;
}

template <class T>
Truth classify_point_freeform(const FreeformSolid<T>& S, const std::vector<T>& x, const SolveOptions& options, std::size_t* systems) {
  if (x.size() != 3) throw ValidationError("point", "has " + std::to_string(x.size()) + " coordinates", "give x, y, z");
  const std::array<T, 6> at{x[0], x[1], x[2], x[0], x[1], x[2]};
  if (!overlap(S.box, at)) return Truth::out;
  bool doubtful = false;
  for (const auto& p : S.pieces) {
    if (!overlap(p.box, at)) continue;
    std::vector<Bernstein<T>> f(3);
    for (int k = 0; k < 3; ++k) {
      f[k] = p.h[k + 1];
      for (std::size_t i = 0; i < f[k].c.size(); ++i) f[k].c[i] -= x[k] * p.h[0].c[i];
    }
    const SolveResult<T> r = solve_system(f, p.lo, p.hi, options);
    if (systems) ++*systems;
    if (!r.undecided.empty()) doubtful = true;
    for (const auto& root : r.roots) {
      // A root on (or within its box of) a boundary face: x may lie on the boundary.
      bool touches = false;
      for (int d = 0; d < 3; ++d) {
        const T lo = root.exact ? root.point[d] : root.lo[d], hi = root.exact ? root.point[d] : root.hi[d];
        if ((p.on_boundary[d][0] && !(p.lo[d] < lo)) || (p.on_boundary[d][1] && !(hi < p.hi[d]))) touches = true;
      }
      if (!touches && (root.unique || root.exact)) return Truth::in;
      doubtful = true;
    }
  }
  if (!doubtful) return Truth::out;
  // A root exactly on a piece's face at an inner knot plane, with irrational coordinates, stays
  // undecided for the solver (its box cannot reach across the face). Common case: a symmetry plane
  // of the data at a patch boundary, where one coordinate vanishes identically on the face. Then
  // the other two equations on the face decide: a certified root there, away from the solid's
  // boundary, puts x in the solid.
  for (const auto& p : S.pieces) {
    if (!overlap(p.box, at)) continue;
    for (int d = 0; d < 3; ++d)
      for (int side = 0; side < 2; ++side) {
        const T& plane = side ? p.hi[d] : p.lo[d];
        const auto& cell = S.cells[p.cell];
        if (plane == cell.domain_lo(d) || plane == cell.domain_hi(d)) continue;  // a face of the cell, not an inner knot plane
        std::vector<Bernstein<T>> f, zero;
        for (int k = 0; k < 3; ++k) {
          Bernstein<T> g = bern_face(p.h[k + 1], d, side);
          const Bernstein<T> w = bern_face(p.h[0], d, side);
          for (std::size_t i = 0; i < g.c.size(); ++i) g.c[i] -= x[k] * w.c[i];
          (std::all_of(g.c.begin(), g.c.end(), [](const T& v) { return v == T(0); }) ? zero : f).push_back(std::move(g));
        }
        if (zero.size() != 1) continue;
        std::vector<T> lo, hi;
        std::vector<int> dirs;
        for (int e = 0; e < 3; ++e)
          if (e != d) {
            lo.push_back(p.lo[e]);
            hi.push_back(p.hi[e]);
            dirs.push_back(e);
          }
        const SolveResult<T> r = solve_system(f, lo, hi, options);
        if (systems) ++*systems;
        for (const auto& root : r.roots) {
          if (!(root.unique || root.exact)) continue;
          bool touches = false;
          for (int i = 0; i < 2; ++i) {
            const int e = dirs[static_cast<std::size_t>(i)];
            const T rl = root.exact ? root.point[i] : root.lo[i], rh = root.exact ? root.point[i] : root.hi[i];
            if ((p.on_boundary[e][0] && !(p.lo[e] < rl)) || (p.on_boundary[e][1] && !(rh < p.hi[e]))) touches = true;
          }
          if (!touches) return Truth::in;
        }
      }
  }
  return Truth::mixed;
}

namespace {

template <class T>
using PatchPtr = std::shared_ptr<const typename FreeformSolid<T>::Patch>;

/// A parameter box of the trimmed cell (freeform_cell): its piece's homogeneous net and det J's
/// numerator, its parameters, the share of the piece's volume it holds, its image's bounds and its
/// candidates.
template <class T>
struct CellBox {
  H4<T> h;
  Bernstein<T> N;
  std::array<T, 3> lo, hi;
  T vol;
  std::array<T, 6> image;
  std::vector<std::vector<PatchPtr<T>>> cand;  // per condition: boundary pieces whose bounds meet the image's
  std::vector<char> clear;                     // per condition: no candidate left
};

// Settled: clear of every boundary, and det J's coefficients of one sign (then the box's volume
// is exact for a polynomial V, Jensen / chord bounds for a rational one: see box_integral_bounds).
template <class T>
bool settled(const CellBox<T>& b) {
  if (!std::all_of(b.clear.begin(), b.clear.end(), [](char c) { return c != 0; })) return false;
  bool pos = false, neg = false;
  for (const auto& x : b.N.c) {
    pos |= T(0) < x;
    neg |= x < T(0);
  }
  return !(pos && neg);
}

// The direction in which a box's image is longest: the largest step between neighbouring
// control points along it (L1, times the degree: a bound on the speed), where halving helps most.
template <class T>
int longest_direction(const CellBox<T>& b) {
  int best = 0;
  T top(-1);
  const auto& deg = b.h[0].deg;
  for (int d = 0; d < 3; ++d) {
    if (deg[d] == 0) continue;
    const std::size_t stride = detail::tensor_stride(deg, d);
    T m(0);
    std::vector<int> idx(deg.size());
    for (std::size_t i = 0; i < b.h[0].c.size(); ++i) {
      detail::unflatten(i, deg, idx);
      if (idx[d] == deg[d]) continue;
      const std::size_t j = i + stride;
      T step(0);
      for (int k = 1; k < 4; ++k) {
        const T a = b.h[k].c[i] / b.h[0].c[i], c = b.h[k].c[j] / b.h[0].c[j];
        step += c < a ? T(a - c) : T(c - a);
      }
      if (m < step) m = step;
    }
    m *= T(deg[d]);
    if (top < m) {
      top = m;
      best = d;
    }
  }
  return best;
}

// The volume a box may hold: the upper bound of |det J| over it (the order of splitting).
template <class T>
T split_weight(const CellBox<T>& b) {
  T l, h;
  vrep_detail::box_integral_bounds(b.N, b.h[0], b.vol, l, h, 4, true);
  return std::max(T(l < T(0) ? T(-l) : l), T(h < T(0) ? T(-h) : h));
}

template <class T>
struct Queued {
  T weight;
  std::size_t at;
  bool operator<(const Queued& o) const { return weight < o.weight; }
};

/// freeform_cell's steps on what they share: V's boxes are halved (subdivide), then decided by the
/// conditions and measured (classify).
template <class T>
class CellTrimming {
 public:
  CellTrimming(const BSpline<T>& V, const std::vector<FreeformCondition<T>>& conditions, const FreeformOptions& options,
               const Limits& limits)
      : V_(V), conditions_(conditions), options_(options), limits_(limits), nc_(conditions.size()), roots_(nc_) {
    for (std::size_t j = 0; j < nc_; ++j)
      for (const auto& p : conditions_[j].solid->boundary) roots_[j].push_back(std::make_shared<typename FreeformSolid<T>::Patch>(p));
  }

  /// The boxes, split until each is settled or the budget is spent: the settled ones, then the live
  /// mixed ones.
  void subdivide() {
    require_box_limits();
    start_boxes();
    auto clock = std::chrono::steady_clock::now();
    // Halve the boxes that are not settled, the one that may hold the most volume first, across the direction of its image's longest
    // extent, until none is left or the budget is spent.
    live_ = todo_.size();
    while (live_ > 0 && live_ + done_.size() < options_.max_boxes) {
      const std::size_t at = order_.top().at;
      order_.pop();
      split(at);
      if (options_.progress && std::chrono::steady_clock::now() - clock > std::chrono::seconds(2)) {
        clock = std::chrono::steady_clock::now();
        options_.progress("freeform cell: " + std::to_string(done_.size() + live_) + " of " + std::to_string(options_.max_boxes) +
                          " boxes, " + std::to_string(live_) + " near a boundary or not yet integrated");
      }
    }
    boxes_ = std::move(done_);
    while (!order_.empty()) {  // the live mixed boxes (a slot emptied by a split that left none is not queued)
      boxes_.push_back(std::move(todo_[order_.top().at]));
      order_.pop();
    }
    const std::size_t n = boxes_.size();
    lo_.resize(n);
    hi_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      lo_[i] = boxes_[i].lo;
      hi_[i] = boxes_[i].hi;
    }
  }

  /// The boxes decided (point queries per group of clear boxes, Kleene's and), the volume enclosed
  /// and the components of the cover.
  FreeformCell<T> classify() {
    box_truths(condition_truths());
    enclose_volume();
    cover_components();
    return std::move(out_);
  }

 private:
  // Filters a box's candidates to those meeting its image's bounds; pieces larger than the image
  // are halved in both directions (exact de Casteljau) first.
  void filter_candidates(CellBox<T>& b) const {
    b.image = bounds_of(b.h);
    const T size = extent(b.image);
    b.clear.assign(nc_, 0);
    for (std::size_t j = 0; j < nc_; ++j) {
      std::vector<PatchPtr<T>> keep, todo = std::move(b.cand[j]);
      while (!todo.empty()) {
        PatchPtr<T> p = std::move(todo.back());
        todo.pop_back();
        if (!overlap(p->box, b.image)) continue;
        if (size < extent(p->box) && keep.size() + todo.size() < options_.max_candidates) {
          auto [a, c] = split_h(p->h, 0);
          for (auto* half : {&a, &c}) {
            auto [e, f] = split_h(*half, 1);
            for (auto* quarter : {&e, &f}) {
              auto q = std::make_shared<typename FreeformSolid<T>::Patch>();
              q->h = std::move(*quarter);
              q->box = bounds_of(q->h);
              todo.push_back(std::move(q));
            }
          }
          continue;
        }
        keep.push_back(std::move(p));
      }
      b.cand[j] = std::move(keep);
      b.clear[j] = b.cand[j].empty();
    }
  }

  // Limits before the work: every box holds its homogeneous net and det J's numerator.
  void require_box_limits() const {
    std::size_t h = 1, n = 1;
    for (int d = 0; d < 3; ++d) {
      h = checked_product(h, static_cast<std::size_t>(V_.degrees[d] + 1), limits_, "trivariate piece");
      n = checked_product(n, static_cast<std::size_t>((V_.is_rational() ? 4 : 3) * V_.degrees[d]), limits_, "det J's numerator");
    }
    checked_product(4 * h + n, options_.max_boxes, limits_, "subdivision boxes of the cell (boxes times coefficients per box)");
  }

  // The first boxes: V's Bezier pieces, each with every boundary piece of every condition as candidates.
  void start_boxes() {
    const BezierForm<T> F = bezier_form(V_, limits_);
    for (std::size_t k = 0; k < F.size(); ++k) {
      const auto pc = F.piece(k);
      CellBox<T> b;
      b.h = homogeneous_form(pc.spline);
      b.N = vrep_detail::jacobian_numerator(pc.spline);
      for (int d = 0; d < 3; ++d) {
        b.lo[d] = pc.box[d].first;
        b.hi[d] = pc.box[d].second;
      }
      b.vol = T(1);
      b.cand = roots_;
      filter_candidates(b);
      if (settled(b))
        done_.push_back(std::move(b));
      else {
        order_.push({split_weight(b), todo_.size()});
        todo_.push_back(std::move(b));
      }
    }
  }

  // The box in slot `at` halved across the direction in which its image is longest; a settled half
  // is done, a mixed one queued.
  void split(std::size_t at) {
    CellBox<T> b = std::move(todo_[at]);
    --live_;
    const int dir = longest_direction(b);
    auto [h0, h1] = split_h(b.h, dir);
    auto [n0, n1] = vrep_detail::split_half(b.N, dir);
    const T mid = (b.lo[dir] + b.hi[dir]) / T(2);
    CellBox<T> c[2];
    c[0].h = std::move(h0);
    c[1].h = std::move(h1);
    c[0].N = std::move(n0);
    c[1].N = std::move(n1);
    for (int s = 0; s < 2; ++s) {
      c[s].lo = b.lo;
      c[s].hi = b.hi;
      c[s].vol = b.vol / T(2);
      c[s].cand = b.cand;
    }
    c[0].hi[dir] = mid;
    c[1].lo[dir] = mid;
    bool reuse = true;  // the first mixed half takes the parent's slot
    for (auto& x : c) {
      filter_candidates(x);
      if (settled(x)) {
        done_.push_back(std::move(x));
        continue;
      }
      const std::size_t slot = reuse ? at : todo_.size();
      order_.push({split_weight(x), slot});
      if (reuse)
        todo_[at] = std::move(x);
      else
        todo_.push_back(std::move(x));
      reuse = false;
      ++live_;
    }
  }

  // Per condition: the clear boxes in groups that touch, one point query per group.
  std::vector<std::vector<Truth>> condition_truths() {
    const std::size_t n = boxes_.size();
    std::vector<std::vector<Truth>> truth(nc_, std::vector<Truth>(n, Truth::mixed));
    for (std::size_t j = 0; j < nc_; ++j) {
      std::vector<std::size_t> ids;
      for (std::size_t i = 0; i < n; ++i)
        if (boxes_[i].clear[j]) ids.push_back(i);
      UnionFind uf(n);
      join_touching(lo_, hi_, ids, uf);
      std::vector<std::vector<std::size_t>> groups;
      std::vector<long> group_of(n, -1);
      for (std::size_t i : ids) {
        const std::size_t r = uf.find(i);
        if (group_of[r] < 0) {
          group_of[r] = static_cast<long>(groups.size());
          groups.emplace_back();
        }
        groups[static_cast<std::size_t>(group_of[r])].push_back(i);
      }
      for (const auto& g : groups) {
        const Truth t = group_truth(j, g);
        for (std::size_t i : g) truth[j][i] = t;
      }
    }
    return truth;
  }

  // Condition j on a group of clear boxes that touch: one point query decides them all.
  Truth group_truth(std::size_t j, const std::vector<std::size_t>& g) {
    Truth t = Truth::mixed;
    // Corners of up to eight of its boxes (spread over the group) until one is decided.
    const std::size_t tries = std::min<std::size_t>(g.size(), 8);
    for (std::size_t a = 0; a < tries && t == Truth::mixed; ++a) {
      const CellBox<T>& b = boxes_[g[a * g.size() / tries]];
      for (int s = 0; s < 8 && t == Truth::mixed; s += 7) {
        // Corner s of the box: its control point (an exact point of the image).
        const int i0 = s & 1 ? b.h[0].deg[0] : 0, i1 = (s >> 1) & 1 ? b.h[0].deg[1] : 0, i2 = s >> 2 ? b.h[0].deg[2] : 0;
        const std::size_t idx = static_cast<std::size_t>(i0 + (b.h[0].deg[0] + 1) * (i1 + (b.h[0].deg[1] + 1) * i2));
        std::vector<T> x(3);
        for (int k = 0; k < 3; ++k) x[k] = b.h[k + 1].c[idx] / b.h[0].c[idx];
        ++out_.queries;
        t = classify_point_freeform(*conditions_[j].solid, x, options_.solve, &out_.systems);
        if (t == Truth::mixed) ++out_.undecided_queries;
      }
    }
    return t;
  }

  // Each box: in when every condition holds, out when one fails (Kleene's and).
  void box_truths(const std::vector<std::vector<Truth>>& truth) {
    const std::size_t n = boxes_.size();
    box_truth_ = std::vector<Truth>(n);
    bool has_in = false, has_out = false;
    std::size_t mixed = 0;
    for (std::size_t i = 0; i < n; ++i) {
      Truth t = Truth::in;
      for (std::size_t j = 0; j < nc_; ++j) {
        Truth c = truth[j][i];
        if (!conditions_[j].inside) c = c == Truth::in ? Truth::out : c == Truth::out ? Truth::in : Truth::mixed;
        if (c == Truth::out) {
          t = Truth::out;
          break;
        }
        if (c == Truth::mixed) t = Truth::mixed;
      }
      box_truth_[i] = t;
      has_in |= t == Truth::in;
      has_out |= t == Truth::out;
      mixed += t == Truth::mixed;
    }
    out_.cls.boxes = n;
    out_.cls.mixed = mixed;
    out_.cls.kind = cell_kind<T>(mixed == 0, has_in, has_out);
  }

  // Volume: in-boxes' integral of det J, mixed boxes between none and all.
  void enclose_volume() {
    const std::size_t n = boxes_.size();
    auto& v = out_.volume;
    for (std::size_t i = 0; i < n; ++i) {
      if (box_truth_[i] == Truth::out) continue;
      T l, h;
      vrep_detail::box_integral_bounds(boxes_[i].N, boxes_[i].h[0], boxes_[i].vol, l, h, 4, box_truth_[i] == Truth::mixed);
      if (box_truth_[i] == Truth::mixed) {
        l = std::min(T(0), l);
        h = std::max(T(0), h);
      }
      v.lower += l;
      v.upper += h;
    }
    if (v.upper < T(0) || (v.upper == T(0) && v.lower < T(0))) {
      const T l = -v.upper;
      v.upper = -v.lower;
      v.lower = l;
    }
    v.boxes = n;
  }

  // Components of the cover (the boxes that are not out), with V's own identifications.
  void cover_components() {
    const std::size_t n = boxes_.size();
    std::vector<std::size_t> cover;
    for (std::size_t i = 0; i < n; ++i)
      if (box_truth_[i] != Truth::out) cover.push_back(i);
    UnionFind uf(n);
    join_touching(lo_, hi_, cover, uf);
    join_identified(V_, lo_, hi_, cover, uf, limits_);
    std::vector<long> comp(n, -1);
    std::vector<char> comp_has_in;
    for (std::size_t i : cover) {
      const std::size_t r = uf.find(i);
      if (comp[r] < 0) {
        comp[r] = static_cast<long>(comp_has_in.size());
        comp_has_in.push_back(0);
      }
      if (box_truth_[i] == Truth::in) comp_has_in[static_cast<std::size_t>(comp[r])] = 1;
    }
    out_.cover_components = comp_has_in.size();
    out_.components = static_cast<std::size_t>(std::count(comp_has_in.begin(), comp_has_in.end(), 1));
    for (std::size_t i : cover) {
      typename FreeformCell<T>::Box b;
      b.lo = lo_[i];
      b.hi = hi_[i];
      b.truth = box_truth_[i];
      b.component = static_cast<int>(comp[uf.find(i)]);
      out_.boxes.push_back(b);
      if (b.truth == Truth::in && out_.cls.inside.empty()) out_.cls.inside = {lo_[i][0], lo_[i][1], lo_[i][2]};
    }
    for (std::size_t i = 0; i < n && out_.cls.outside.empty(); ++i)
      if (box_truth_[i] == Truth::out) out_.cls.outside = {lo_[i][0], lo_[i][1], lo_[i][2]};
  }

  const BSpline<T>& V_;
  const std::vector<FreeformCondition<T>>& conditions_;
  const FreeformOptions& options_;
  const Limits& limits_;
  const std::size_t nc_;
  std::vector<std::vector<PatchPtr<T>>> roots_;  // per condition: its solid's boundary pieces
  std::vector<CellBox<T>> todo_;                 // mixed boxes, split largest weight first
  std::priority_queue<Queued<T>> order_;
  std::vector<CellBox<T>> done_;
  std::size_t live_ = 0;                   // the queued (mixed) boxes
  std::vector<CellBox<T>> boxes_;          // after subdivide: the settled boxes, then the live mixed ones
  std::vector<std::array<T, 3>> lo_, hi_;  // their parameter bounds
  std::vector<Truth> box_truth_;
  FreeformCell<T> out_;
};

}  // namespace

template <class T>
FreeformCell<T> freeform_cell(const BSpline<T>& V, const std::vector<FreeformCondition<T>>& conditions, const FreeformOptions& options,
                              const Limits& limits) {
  vrep_detail::require_cell(V, "trivariate", limits);
  if (options.max_boxes < 1) throw ValidationError("boxes", "must be at least 1", "give a positive box budget");
  for (std::size_t j = 0; j < conditions.size(); ++j)
    if (!conditions[j].solid) throw ValidationError("conditions[" + std::to_string(j) + "].solid", "is null", "give a solid");
  CellTrimming<T> cell(V, conditions, options, limits);
  cell.subdivide();
  return cell.classify();
}

template <class T>
FreeformEdges<T> freeform_edges(const BSpline<T>& V, const std::vector<FreeformCondition<T>>& conditions, const FreeformOptions& options,
                                const Limits& limits) {
  vrep_detail::require_cell(V, "trivariate", limits);
  for (std::size_t j = 0; j < conditions.size(); ++j)
    if (!conditions[j].solid) throw ValidationError("conditions[" + std::to_string(j) + "].solid", "is null", "give a solid");
  FreeformEdges<T> out;
  // The cell's truth at a point: every condition by a point query (Kleene's and).
  auto truth_at_point = [&](const std::vector<T>& x) {
    Truth t = Truth::in;
    for (const auto& c : conditions) {
      Truth q = classify_point_freeform(*c.solid, x, options.solve, &out.systems);
      if (!c.inside) q = q == Truth::in ? Truth::out : q == Truth::out ? Truth::in : Truth::mixed;
      if (q == Truth::out) return Truth::out;
      if (q == Truth::mixed) t = Truth::mixed;
    }
    return t;
  };
  auto point_of = [&](const BSpline<T>& C, const T& t) {
    const auto p = evaluate(C, std::vector<T>{t});
    return std::vector<T>{p[0], p[1], p[2]};
  };
  for (int c = 0; c < 8; ++c) {
    std::vector<T> u;
    for (int d = 0; d < 3; ++d) u.push_back((c >> d) & 1 ? V.domain_hi(d) : V.domain_lo(d));
    const auto p = evaluate(V, u);
    const Truth t = truth_at_point({p[0], p[1], p[2]});
    out.corners += t == Truth::in;
    out.corners_undecided += t == Truth::mixed;
  }
  // An edge piece's homogeneous coordinates lifted to (s, t, tau), and a boundary piece's.
  auto lift = [](Bernstein<T> b, int dims_before) {
    std::vector<int> deg(static_cast<std::size_t>(dims_before), 0);
    deg.insert(deg.end(), b.deg.begin(), b.deg.end());
    while (deg.size() < 3) deg.push_back(0);
    b.deg = deg;
    return b;
  };
  for (int along = 0; along < 3; ++along)
    for (int s1 = 0; s1 < 2; ++s1)
      for (int s2 = 0; s2 < 2; ++s2) {
        typename FreeformEdges<T>::Edge e;
        e.along = along;
        const int a = along == 0 ? 1 : 0, b = along == 2 ? 1 : 2;
        e.sides[a] = s1;
        e.sides[b] = s2;
        const BSpline<T> C = edge_curve(V, along, e.sides);
        if (vrep_detail::curve_collapsed(C)) {
          e.status = FreeformEdges<T>::Edge::collapsed;
          out.edges.push_back(e);
          continue;
        }
        std::vector<std::pair<T, T>> events;
        const BezierForm<T> F = bezier_form(C, limits);
        for (std::size_t k = 0; k < F.size() && e.status == FreeformEdges<T>::Edge::curve; ++k) {
          const auto pc = F.piece(k);
          H4<T> h;
          h[0] = bern_coordinate(pc.spline, pc.spline.q);
          for (int c = 0; c < 3; ++c) h[c + 1] = bern_coordinate(pc.spline, c);
          const auto box = bounds_of(h);
          for (const auto& cond : conditions)
            for (const auto& P : cond.solid->boundary) {
              if (!overlap(P.box, box)) continue;
              std::vector<Bernstein<T>> f;
              const Bernstein<T> WE = lift(h[0], 2), WP = lift(P.h[0], 0);
              for (int c = 1; c < 4; ++c)
                f.push_back(bern_sub(bern_product(lift(P.h[c], 0), WE), bern_product(lift(h[c], 2), WP)));
              // An equation that vanishes identically (the edge and the piece in one coordinate plane):
              // no crossing if another one has one strict sign, else the solutions need not be isolated.
              bool zero = false, excluded = false;
              for (const auto& g : f) {
                zero = zero || std::all_of(g.c.begin(), g.c.end(), [](const T& x) { return x == T(0); });
                excluded = excluded || std::all_of(g.c.begin(), g.c.end(), [](const T& x) { return T(0) < x; }) ||
                           std::all_of(g.c.begin(), g.c.end(), [](const T& x) { return x < T(0); });
              }
              if (excluded) continue;
              if (zero) {
                e.status = Uncertain<typename FreeformEdges<T>::Edge::Status>::undecided("a condition vanishes identically on the edge");
                continue;
              }
              const SolveResult<T> r = solve_system(f, {T(0), T(0), pc.box[0].first}, {T(1), T(1), pc.box[0].second}, options.solve);
              ++out.systems;
              if (!r.undecided.empty())
                e.status = Uncertain<typename FreeformEdges<T>::Edge::Status>::undecided("the solver left boxes undecided (tangency, an edge on the boundary)");
              for (const auto& root : r.roots) events.push_back(root.exact ? std::pair<T, T>{root.point[2], root.point[2]} : std::pair<T, T>{root.lo[2], root.hi[2]});
            }
        }
        if (e.status == FreeformEdges<T>::Edge::curve) {
          const auto runs = vrep_detail::edge_runs(events, V.domain_lo(along), V.domain_hi(along),
                                                   [&](const T& t) { return static_cast<int>(truth_at_point(point_of(C, t))); });
          if (!runs.decided) e.status = Uncertain<typename FreeformEdges<T>::Edge::Status>::undecided("the truth between the events is not decided");
          e.pieces = runs.pieces;
          e.points = runs.points;
          e.cuts = runs.cuts;
        }
        out.edges.push_back(e);
      }
  return out;
}

#define SPLINEX_INSTANTIATE_FREEFORM(T)                                                                                                   \
  template FreeformSolid<T> freeform_solid(std::string, std::vector<BSpline<T>>, const Limits&);                                          \
  template Truth classify_point_freeform(const FreeformSolid<T>&, const std::vector<T>&, const SolveOptions&, std::size_t*);              \
  template FreeformCell<T> freeform_cell(const BSpline<T>&, const std::vector<FreeformCondition<T>>&, const FreeformOptions&, const Limits&); \
  template FreeformEdges<T> freeform_edges(const BSpline<T>&, const std::vector<FreeformCondition<T>>&, const FreeformOptions&, const Limits&);
SPLINEX_INSTANTIATE_FREEFORM(Rational)
SPLINEX_INSTANTIATE_FREEFORM(double)

}  // namespace splinex
