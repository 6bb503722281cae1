// Trimmed V-cells on exact implicit regions (vrep/trimmed/trimmed.hpp): the templates, instantiated in
// vrep/instances.cpp.
#pragma once
#include "vrep/trimmed/compose_leaf_impl.hpp"
#include "vrep/trimmed/primitive_regions_impl.hpp"

namespace splinex {

namespace vrep_detail {

/// The classification of one trivariate against a region by a refinement of its Bezier pieces
/// (bernstein/subdivide.hpp: refine, breadth first): a box is decided where every leaf the formula
/// depends on has Bernstein coefficients of one sign (beyond eps), and mixed boxes are halved across
/// their widest parameter side until none is left, the budget is spent or both sides are
/// certified (an in- or out-box, or an exact witness at a corner).
template <class T>
CellClass<T> run_trim(const BSpline<T>& V, const Region<T>& trim, std::size_t max_boxes, const T& eps, const Limits& limits) {
  require_jacobian_input(V, limits);
  if (max_boxes < 1) throw ValidationError("boxes", "must be at least 1", "give a positive box budget");
  require_positive_weights(V);
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(trim, leaves);
  // Limits before the work: all leaves composed on one piece; the boxes' compositions are counted
  // as they are made (a box carries only the leaves that can still change its truth).
  composed_leaves_size(V, leaves, limits);
  struct Box {
    std::vector<Bernstein<T>> G;  // per leaf: its composition, or empty where it is not carried
    std::vector<Truth> lt;        // per leaf: its truth on the box (not carried: its last one)
    std::array<T, 3> lo, hi;      // in the trivariate's parameters
    Truth truth = Truth::mixed;
  };
  CellClass<T> cls;
  bool has_in = false, has_out = false;
  CarriedCoefficients carried{limits};
  auto evaluate = [&](Box& b) {
    for (std::size_t l = 0; l < b.G.size(); ++l)
      if (!b.G[l].c.empty()) b.lt[l] = coefficient_truth(b.G[l], eps);
    std::size_t k = 0;
    b.truth = combine(trim, b.lt, k);
    if (b.truth == Truth::in) has_in = true;
    if (b.truth == Truth::out) has_out = true;
    if (b.truth != Truth::mixed) {
      b.G.clear();  // decided: its leaves are not needed again (an in-box stays in)
      return;
    }
    // Exact witnesses at the corners (the corner coefficients are G's values there; a leaf not
    // carried has one strict sign on the box, or does not change the formula's truth).
    for (int s = 0; s < 8; ++s) {
      if (!cls.inside.empty() && !cls.outside.empty()) break;
      std::vector<Truth> pt(b.lt);
      for (std::size_t l = 0; l < b.G.size(); ++l)
        if (!b.G[l].c.empty()) pt[l] = value_truth(corner(b.G[l], s & 1, (s >> 1) & 1, s >> 2), eps);
      std::size_t j = 0;
      const Truth t = combine(trim, pt, j);
      if (t == Truth::mixed) continue;
      auto& w = t == Truth::in ? cls.inside : cls.outside;
      if (!w.empty()) continue;
      w = {s & 1 ? b.hi[0] : b.lo[0], (s >> 1) & 1 ? b.hi[1] : b.lo[1], s >> 2 ? b.hi[2] : b.lo[2]};
    }
    // Release the leaves that no longer matter on the box and its parts: those the formula does not
    // depend on any more, and those of one strict sign (every corner value has that sign too).
    std::vector<char> live;
    live_leaves(trim, b.lt, live);
    // (A leaf decided with a zero coefficient keeps its values: a corner may lie on its surface.)
    for (std::size_t l = 0; l < b.G.size(); ++l) {
      if (b.G[l].c.empty() || live[l]) continue;
      if (b.lt[l] == Truth::mixed || strictly_signed(b.G[l], eps)) b.G[l] = Bernstein<T>{};
    }
  };
  auto examine = [&](Box& b) {
    evaluate(b);
    carried.add(CarriedCoefficients::of(b.G));
    return b.truth == Truth::mixed ? Examined::split : Examined::settled;
  };
  // Halves across the widest parameter side (exact de Casteljau on the leaves it carries).
  auto split = [&](Box&& b, int, auto&& emit) {
    carried.remove(CarriedCoefficients::of(b.G));
    Box c[2];
    halve_widest(std::move(b), c);
    emit(std::move(c[0]));
    emit(std::move(c[1]));
  };
  const BezierForm<T> F = bezier_form(V, limits);
  // The roots, each examined as it is made: every Bezier piece.
  auto roots = [&](auto&& emit) {
    for (std::size_t k = 0; k < F.size(); ++k) {
      const auto pc = F.piece(k);
      Box b;
      // The planes first (cheap); then only the leaves the formula may still depend on.
      b.G.resize(leaves.size());
      b.lt.assign(leaves.size(), Truth::mixed);
      PiecePowers<T> powers(pc.spline);
      for (std::size_t l = 0; l < leaves.size(); ++l)
        if (leaves[l]->degree() <= 1) {
          b.G[l] = compose_leaf(*leaves[l], powers);
          b.lt[l] = coefficient_truth(b.G[l], eps);
        }
      std::vector<char> live;
      live_leaves(trim, b.lt, live);
      for (std::size_t l = 0; l < leaves.size(); ++l)
        if (leaves[l]->degree() > 1 && live[l]) b.G[l] = compose_leaf(*leaves[l], powers);
      for (int d = 0; d < 3; ++d) {
        b.lo[d] = pc.box[d].first;
        b.hi[d] = pc.box[d].second;
      }
      emit(std::move(b));
    }
  };
  Budget budget;
  budget.max_boxes = max_boxes;
  // Classification only: both sides certified ends it.
  auto both_sides = [&]() { return (has_in || !cls.inside.empty()) && (has_out || !cls.outside.empty()); };
  const Subdivision run = refine_from<Box>(roots, Order::breadth_first, budget, examine, split, both_sides, [](Box&&, bool) {});
  cls.boxes = run.boxes;
  cls.mixed = run.left;
  const bool some_in = has_in || !cls.inside.empty(), some_out = has_out || !cls.outside.empty();
  cls.kind = run.left == 0 ? cell_kind<T>(true, has_in, has_out) : cell_kind<T>(false, some_in, some_out);
  return cls;
}

template <class T>
bool trivially_true(const Region<T>& R) {
  return R.kind == Region<T>::all_of && R.parts.empty();
}

/// trim and extra, flattened into one all_of.
template <class T>
Region<T> conjoin(const Region<T>& trim, Region<T> extra) {
  if (trivially_true(trim)) return extra;
  std::vector<Region<T>> parts;
  if (trim.kind == Region<T>::all_of) parts = trim.parts;
  else parts.push_back(trim);
  parts.push_back(std::move(extra));
  return region_and(std::move(parts));
}

}  // namespace vrep_detail

template <class T>
const char* to_string(const Uncertain<typename CellClass<T>::Kind>& k) {
  using K = typename CellClass<T>::Kind;
  return k == K::whole ? "whole" : k == K::empty ? "empty" : k == K::cut ? "cut" : status_name(Status::undecided);
}

template <class T>
T poly_at(const Poly3<T>& g, const T* x) {
  T s(0);
  for (const auto& [e, c] : g.terms) {
    T t = c;
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < e[a]; ++i) t *= x[a];
    s += t;
  }
  return s;
}

template <class T>
Truth classify_point(const Region<T>& R, const std::vector<T>& x, const T& eps) {
  if (x.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  std::vector<const Poly3<T>*> leaves;
  vrep_detail::collect_leaves(R, leaves);
  std::vector<Truth> t;
  for (const auto* g : leaves) t.push_back(vrep_detail::value_truth(poly_at(*g, x.data()), eps));
  std::size_t k = 0;
  return vrep_detail::combine(R, t, k);
}

template <class T>
std::optional<Region<T>> planar_region(const VModel<T>& M, const T& eps) {
  using vrep_detail::poly_linear;
  std::vector<Region<T>> cells;
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto P = convex_planes(M.trivariates[M.cells[c].trivariates.front()], eps);
    if (!P) return std::nullopt;
    std::vector<Region<T>> faces;
    for (const auto& H : *P) faces.push_back(region_leaf(poly_linear(H.d, H.n[0], H.n[1], H.n[2]), M.cells[c].name + ": face"));
    cells.push_back(region_and(std::move(faces)));
  }
  return cells.size() == 1 ? cells.front() : region_or(std::move(cells));
}

template <class T>
Region<T> place_region(const Region<T>& R, int axis, const std::vector<T>& offset) {
  using namespace vrep_detail;
  if (axis < 0 || axis > 2) throw ValidationError("axis", "must be x, y or z", "give --axis x, y or z");
  if (offset.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  Region<T> out = R;
  if (R.kind != Region<T>::leaf) {
    for (auto& p : out.parts) p = place_region(p, axis, offset);
    return out;
  }
  // new = P old + t with (P old)_j = old_{(j + s) % 3}, s = (2 - axis) mod 3 (s = 0: identity);
  // old_i = (new - t)_{(i - s) mod 3}.
  const int s = (5 - axis) % 3;  // new_axis = old_z
  std::array<Poly3<T>, 3> old;
  for (int i = 0; i < 3; ++i) {
    const int j = (i - s + 3) % 3;
    T e[3] = {T(0), T(0), T(0)};
    e[j] = T(1);
    old[i] = poly_linear(T(-offset[j]), e[0], e[1], e[2]);
  }
  Poly3<T> g;
  for (const auto& [e, c] : R.g.terms) {
    Poly3<T> t = poly_mul(poly_mul(poly_pow(old[0], e[0]), poly_pow(old[1], e[1])), poly_pow(old[2], e[2]));
    g = poly_add(g, t, c);
  }
  out.g = std::move(g);
  return out;
}

template <class T>
BSpline<T> place_trivariate(const BSpline<T>& V, int axis, const std::vector<T>& offset) {
  if (axis < 0 || axis > 2) throw ValidationError("axis", "must be x, y or z", "give --axis x, y or z");
  if (offset.size() != 3) throw ValidationError("at", "needs three coordinates", "give x,y,z");
  if (V.q < 3) throw ValidationError("trivariate", "has points with fewer than three coordinates", "give points in R^3");
  const int s = (5 - axis) % 3;  // new_axis = old_z
  BSpline<T> out = V;
  for (std::size_t i = 0; i < V.size(); ++i)
    for (int j = 0; j < 3; ++j) out.points[i * V.q + j] = V.points[i * V.q + (j + s) % 3] + offset[j];
  return out;
}

template <class T>
TrimmedModel<T> placed_primitive(std::vector<BSpline<T>> cells, const Region<T>& region, int axis, const std::vector<T>& offset) {
  for (auto& V : cells) V = place_trivariate(V, axis, offset);
  return as_trimmed(glue(cells), place_region(region, axis, offset));
}

template <class T>
TrimmedModel<T> as_trimmed(const VModel<T>& M, Region<T> region) {
  TrimmedModel<T> out;
  out.trivariates = M.trivariates;
  out.region = std::move(region);
  for (const auto& c : M.cells) {
    typename TrimmedModel<T>::Cell x;
    x.trivariate = c.trivariates.front();
    x.trim = region_and<T>({});
    x.name = c.name;
    x.inherited.assign(c.trivariates.begin() + 1, c.trivariates.end());
    x.constants = c.attributes.constants;
    x.fields = c.attributes.fields;
    x.not_carried = c.attributes.not_carried;
    out.cells.push_back(std::move(x));
  }
  return out;
}

namespace vrep_detail {

template <class T>
bool has_alias(const Region<T>& R) {
  if (R.kind == Region<T>::leaf) return R.alias >= 0;
  for (const auto& p : R.parts)
    if (has_alias(p)) return true;
  return false;
}

/// R with the leaves fixed in `fixed` (collect order; mixed: kept) replaced by constants (true: an
/// all_of without parts, false: an any_of without parts) and the constants folded.
template <class T>
Region<T> fold_constants(const Region<T>& R, const std::vector<Truth>& fixed, std::size_t& k) {
  auto constant = [](bool t) { return t ? region_and<T>({}) : region_or<T>({}); };
  auto value = [](const Region<T>& x) -> int {  // 1 true, 0 false, -1 not a constant
    if (x.kind != Region<T>::all_of && x.kind != Region<T>::any_of) return -1;
    if (!x.parts.empty()) return -1;
    return x.kind == Region<T>::all_of ? 1 : 0;
  };
  switch (R.kind) {
    case Region<T>::leaf: {
      const Truth t = fixed[k++];
      return t == Truth::mixed ? R : constant(t == Truth::in);
    }
    case Region<T>::complement: {
      Region<T> x = fold_constants(R.parts.front(), fixed, k);
      const int v = value(x);
      return v < 0 ? region_not(std::move(x)) : constant(v == 0);
    }
    case Region<T>::all_of:
    case Region<T>::any_of: {
      const bool all = R.kind == Region<T>::all_of;
      std::vector<Region<T>> kept;
      bool absorbed = false;  // a false part of an all_of, a true part of an any_of
      for (const auto& p : R.parts) {
        Region<T> x = fold_constants(p, fixed, k);  // (every part: k must pass all leaves)
        const int v = value(x);
        if (v < 0) kept.push_back(std::move(x));
        else if (v == (all ? 0 : 1)) absorbed = true;
      }
      if (absorbed) return constant(!all);
      if (kept.size() == 1) return std::move(kept.front());
      Region<T> out = all ? region_and<T>(std::move(kept)) : region_or<T>(std::move(kept));
      out.label = R.label;
      return out;
    }
    case Region<T>::cases: {
      // Cases whose piece is out drop; a piece that is all there is leaves its formula; formulas
      // that are one constant on every piece left are that constant (the pieces cover).
      std::vector<std::pair<Region<T>, Region<T>>> kept;
      int common = -2;
      for (std::size_t i = 0; i + 1 < R.parts.size(); i += 2) {
        Region<T> c = fold_constants(R.parts[i], fixed, k);
        Region<T> f = fold_constants(R.parts[i + 1], fixed, k);
        const int cv = value(c);
        if (cv == 0) continue;
        const int fv = value(f);
        common = common == -2 ? fv : common == fv ? fv : -1;
        kept.emplace_back(std::move(c), std::move(f));
      }
      if (kept.empty()) return constant(false);
      if (common >= 0) return constant(common == 1);
      if (kept.size() == 1 && value(kept.front().first) == 1) return std::move(kept.front().second);
      Region<T> out = region_cases<T>(std::move(kept));
      out.label = R.label;
      return out;
    }
  }
  return R;
}

/// Bounds lo <= g <= hi of a polynomial on the box b = {min x, min y, min z, max x, max y, max z}
/// (interval arithmetic per monomial, exact in exact arithmetic; wider than g's range in general).
template <class T>
std::pair<T, T> poly_bounds(const Poly3<T>& g, const std::array<T, 6>& b) {
  T lo(0), hi(0);
  for (const auto& [e, c] : g.terms) {
    T mlo(1), mhi(1);
    for (int a = 0; a < 3; ++a) {
      if (e[a] == 0) continue;
      T plo(1), phi(1);  // x^e on [b[a], b[a + 3]]
      for (int k = 0; k < e[a]; ++k) {
        plo *= b[a];
        phi *= b[a + 3];
      }
      if (phi < plo) std::swap(plo, phi);
      if (e[a] % 2 == 0 && b[a] < T(0) && T(0) < b[a + 3]) plo = T(0);
      // [mlo, mhi] * [plo, phi]
      const T p[4] = {mlo * plo, mlo * phi, mhi * plo, mhi * phi};
      mlo = *std::min_element(p, p + 4);
      mhi = *std::max_element(p, p + 4);
    }
    if (c < T(0)) {
      lo += c * mhi;
      hi += c * mlo;
    } else {
      lo += c * mlo;
      hi += c * mhi;
    }
  }
  return {lo, hi};
}

/// R with every leaf of strict sign on the box b (poly_bounds) replaced by its truth and the
/// formula folded: the same set on any set of points whose closure lies in the box, and just
/// outside that set too when it lies in the box's interior or the sign is strict on a
/// neighbourhood (a strict sign on a compact set holds on a neighbourhood of it). Exact arithmetic
/// only; regions with alias leaves are returned as they are.
template <class T>
Region<T> localized_by_box(const Region<T>& R, const std::array<T, 6>& b) {
  if (has_alias(R)) return R;
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(R, leaves);
  std::map<std::map<std::array<int, 3>, T>, Truth> seen;
  std::vector<Truth> fixed;
  for (const auto* g : leaves) {
    auto it = seen.find(g->terms);
    if (it == seen.end()) {
      const auto [lo, hi] = poly_bounds(*g, b);
      it = seen.emplace(g->terms, T(0) < lo ? Truth::in : hi < T(0) ? Truth::out : Truth::mixed).first;
    }
    fixed.push_back(it->second);
  }
  std::size_t k = 0;
  return fold_constants(R, fixed, k);
}

/// The region on one trivariate V (exact arithmetic): every leaf that has one truth on all of V
/// is replaced by it and the formula folded, where "one truth" is either (a) g > 0 or g < 0 on
/// V's control-point box (interval bounds; V lies in it by the convex hull property), so g o T
/// has that strict sign everywhere on the cell, or (b) the composition's Bernstein coefficients
/// have one weak sign with the same coefficient_truth on every Bezier piece of V, which the
/// subdivision boxes of a piece keep (their coefficients are convex combinations of the piece's,
/// and a polynomial that is 0 on a box is 0 on the piece). Either way the leaf's truth on every
/// part of the cell is the fixed one as a set, so the classification stays sound, and with (b)
/// alone it is unchanged. Equal leaves are decided once. The localized formula holds the leaves V
/// meets: the cost of a cell of a model of many cells (a grid of boxes with the union of their
/// regions, issue 47) is that of its neighbourhood, not of the model. Float arithmetic and regions
/// with alias leaves (built by trimmed_glue) are returned as they are.
template <class T>
Region<T> localized_region(const BSpline<T>& V, const Region<T>& R, const T& eps, const Limits& limits) {
  if (!(eps == T(0)) || has_alias(R)) return R;
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(R, leaves);
  if (leaves.empty()) return R;
  require_jacobian_input(V, limits);
  require_positive_weights(V);
  const auto box = control_bounds(V);
  std::vector<Truth> fixed(leaves.size(), Truth::mixed);
  std::map<std::map<std::array<int, 3>, T>, Truth> seen;
  std::vector<std::size_t> open;  // leaves (first of equal ones) the bounds do not decide
  std::vector<const Poly3<T>*> open_leaves;
  for (std::size_t l = 0; l < leaves.size(); ++l) {
    const auto it = seen.find(leaves[l]->terms);
    if (it != seen.end()) continue;
    const auto [lo, hi] = poly_bounds(*leaves[l], box);
    const Truth t = T(0) < lo ? Truth::in : hi < T(0) ? Truth::out : Truth::mixed;
    seen.emplace(leaves[l]->terms, t);
    if (t == Truth::mixed) {
      open.push_back(l);
      open_leaves.push_back(leaves[l]);
    }
  }
  // (b) for the planes always; for curved leaves only when they are few (a piecewise region's many
  // pieces are left to the subdivision, which composes a leaf only where it may matter).
  std::size_t curved = 0;
  for (const auto* g : open_leaves) curved += g->degree() > 1;
  if (curved > 16) {
    std::vector<std::size_t> o;
    std::vector<const Poly3<T>*> ol;
    for (std::size_t q = 0; q < open.size(); ++q)
      if (open_leaves[q]->degree() <= 1) {
        o.push_back(open[q]);
        ol.push_back(open_leaves[q]);
      }
    open = std::move(o);
    open_leaves = std::move(ol);
  }
  if (!open.empty()) {
    const std::size_t per_piece = composed_leaves_size(V, open_leaves, limits);
    const BezierForm<T> F = bezier_form(V, limits);
    checked_product(per_piece, F.size(), limits, "region composed with the trivariate's pieces");
    std::vector<Truth> t(open.size(), Truth::mixed);
    std::vector<char> alive(open.size(), 1);
    // Planted (tests only, vrep/model/planted.hpp): the first Bezier piece decides for all.
    const std::size_t pieces =
        vrep_testing::is_planted(vrep_testing::Plant::classify_first_piece_only) ? std::min<std::size_t>(1, F.size()) : F.size();
    for (std::size_t k = 0; k < pieces; ++k) {
      const auto pc = F.piece(k);
      PiecePowers<T> powers(pc.spline);
      for (std::size_t q = 0; q < open.size(); ++q) {
        if (!alive[q]) continue;
        const Truth here = coefficient_truth(compose_leaf(*open_leaves[q], powers), eps);
        if (here == Truth::mixed || (k > 0 && here != t[q])) {
          alive[q] = 0;
          t[q] = Truth::mixed;
          continue;
        }
        t[q] = here;
      }
    }
    for (std::size_t q = 0; q < open.size(); ++q) seen[leaves[open[q]]->terms] = t[q];
  }
  for (std::size_t l = 0; l < leaves.size(); ++l) fixed[l] = seen.at(leaves[l]->terms);
  std::size_t k = 0;
  return fold_constants(R, fixed, k);
}

}  // namespace vrep_detail

template <class T>
CellClass<T> classify_cell(const BSpline<T>& V, const Region<T>& trim, const TrimOptions& options, const T& eps, const Limits& limits) {
  // On the region localized to V: a cell of a large model costs what it meets (issue 47).
  return vrep_detail::run_trim(V, vrep_detail::localized_region(V, trim, eps, limits), options.max_boxes, eps, limits);
}

// trimmed_volume, trimmed_moment, trimmed_field_integral: vrep/trimmed/enclosure_impl.hpp.

template <class T>
TrimmedModel<T> trimmed_boolean(const TrimmedModel<T>& A, const TrimmedModel<T>& B, BooleanOp op, Blend blend, const TrimOptions& options,
                                const T& eps, const Limits& limits) {
  using namespace vrep_detail;
  TrimmedModel<T> out;
  std::vector<std::size_t> tb;  // B's trivariates in out
  out.trivariates = A.trivariates;
  for (const auto& V : B.trivariates) {
    tb.push_back(out.trivariates.size());
    out.trivariates.push_back(V);
  }
  std::vector<std::array<T, 6>> boundsA, boundsB;
  for (const auto& c : A.cells) boundsA.push_back(control_bounds(A.trivariates[c.trivariate]));
  for (const auto& c : B.cells) boundsB.push_back(control_bounds(B.trivariates[c.trivariate]));
  auto meets = [](const std::array<T, 6>& a, const std::array<T, 6>& b) {
    for (int k = 0; k < 3; ++k)
      if (a[k + 3] < b[k] || b[k + 3] < a[k]) return false;
    return true;
  };
  // One side's cells restricted to `with` (the other model's region or its complement).
  auto pass = [&](const TrimmedModel<T>& M, bool from_a, const Region<T>& with, const std::string& category) {
    for (std::size_t c = 0; c < M.cells.size(); ++c) {
      const auto& cell = M.cells[c];
      const auto& V = M.trivariates[cell.trivariate];
      const std::string who = std::string(from_a ? "first" : "second") + ".cells[" + std::to_string(c) + "] (" + cell.name + ")";
      // The new condition alone first: a cell wholly inside it needs no new trim.
      using K = typename CellClass<T>::Kind;
      const auto alone = classify_cell(V, with, options, eps, limits);
      auto refuse = [&](const CellClass<T>& k) {
        throw DomainError(who, "meets the other model's boundary tangentially or nearly so: " + std::to_string(k.mixed) + " of " +
                                   std::to_string(k.boxes) + " subdivision boxes stay undecided and no exact witness of both sides was found",
                          "the paper excludes tangential contact; move the models apart or through each other, or raise --boxes");
      };
      if (!alone.kind.is_certain()) refuse(alone);
      if (alone.kind == K::empty) continue;
      Region<T> trim = alone.kind == K::whole ? cell.trim : conjoin(cell.trim, with);
      auto cls = alone;
      if (!trivially_true(trim)) cls = classify_cell(V, trim, options, eps, limits);
      if (!cls.kind.is_certain()) refuse(cls);
      if (cls.kind == K::empty) continue;
      typename TrimmedModel<T>::Cell x;
      x.trivariate = from_a ? cell.trivariate : tb[cell.trivariate];
      x.trim = std::move(trim);
      x.status = cls.kind == K::whole ? Truth::in : Truth::mixed;
      // A subtraction only trims A's cells: they keep the category an earlier Boolean gave them.
      x.category = op == BooleanOp::subtract && !cell.category.empty() ? cell.category : category;
      for (std::size_t t : cell.inherited) x.inherited.push_back(from_a ? t : tb[t]);
      x.constants = cell.constants;
      // Trimming keeps the trivariate and its parameters: the cell's fields stay as they are.
      x.fields = cell.fields;
      x.not_carried = cell.not_carried;
      x.name = cell.name.empty() ? (from_a ? "A" : "B") + std::to_string(c) : cell.name;
      if (category == "both") {
        const auto& mine = from_a ? boundsA[c] : boundsB[c];
        const auto& other = from_a ? B : A;
        const auto& ob = from_a ? boundsB : boundsA;
        for (std::size_t o = 0; o < other.cells.size(); ++o) {
          if (!meets(mine, ob[o])) continue;
          x.inherited.push_back(from_a ? tb[other.cells[o].trivariate] : other.cells[o].trivariate);
          Attributes<T> into, from;
          into.constants = std::move(x.constants);
          from.constants = other.cells[o].constants;
          merge_constants(into, from, blend);
          x.constants = std::move(into.constants);
          // The other cell's fields live on its trivariate's parameters; on this cell they would
          // need that trivariate's inverse (only the part inside it is known by the region).
          for (const auto& [n, F] : other.cells[o].fields)
            if (std::find(x.not_carried.begin(), x.not_carried.end(), n) == x.not_carried.end()) x.not_carried.push_back(n);
          x.name += "*" + (other.cells[o].name.empty() ? std::string(from_a ? "B" : "A") + std::to_string(o) : other.cells[o].name);
        }
      }
      out.cells.push_back(std::move(x));
    }
  };
  if (op == BooleanOp::intersect || op == BooleanOp::unite) pass(A, true, B.region, "both");
  if (op == BooleanOp::subtract || op == BooleanOp::unite) pass(A, true, region_not(B.region), "A");
  if (op == BooleanOp::unite) pass(B, false, region_not(A.region), "B");
  out.region = op == BooleanOp::intersect ? region_and<T>({A.region, B.region})
               : op == BooleanOp::subtract ? region_and<T>({A.region, region_not(B.region)})
                                           : region_or<T>({A.region, B.region});
  if (out.cells.empty())
    throw DomainError(std::string(to_string(op)), "gives an empty model (no cell has a part of positive volume)", "check the operands' placement");
  // Keep only the trivariates the cells use.
  std::vector<std::size_t> map(out.trivariates.size(), SIZE_MAX);
  std::vector<BSpline<T>> used;
  auto use = [&](std::size_t t) {
    if (map[t] == SIZE_MAX) {
      map[t] = used.size();
      used.push_back(out.trivariates[t]);
    }
    return map[t];
  };
  for (auto& c : out.cells) {
    c.trivariate = use(c.trivariate);
    for (auto& t : c.inherited) t = use(t);
  }
  out.trivariates = std::move(used);
  return out;
}

template <class T>
std::optional<std::vector<T>> cases_cover_gap(const Region<T>& R, const std::vector<BSpline<T>>& cells, int n) {
  if (n < 1) throw ValidationError("samples", "must be at least 1", "give n >= 1");
  std::vector<const Region<T>*> nodes;
  std::function<void(const Region<T>&)> walk = [&](const Region<T>& x) {
    if (x.kind == Region<T>::cases) nodes.push_back(&x);
    for (const auto& p : x.parts) walk(p);
  };
  walk(R);
  // The box of the cells' control points (those in R^3).
  std::optional<std::array<T, 6>> bounds;
  for (const auto& V : cells) {
    if (V.q < 3 || V.points.empty()) continue;
    const auto b = control_bounds(V);
    if (!bounds) bounds = b;
    for (int d = 0; d < 3; ++d) {
      (*bounds)[d] = std::min((*bounds)[d], b[d]);
      (*bounds)[d + 3] = std::max((*bounds)[d + 3], b[d + 3]);
    }
  }
  if (nodes.empty() || !bounds) return std::nullopt;
  const auto& box = *bounds;
  std::vector<T> x(3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const int at[3] = {i, j, k};
        for (int d = 0; d < 3; ++d) x[d] = box[d] + (box[d + 3] - box[d]) * T(at[d]) / T(n);
        for (const auto* c : nodes) {
          bool covered = false;
          for (std::size_t q = 0; q + 1 < c->parts.size() && !covered; q += 2) covered = classify_point(c->parts[q], x) != Truth::out;
          if (!covered) return x;
        }
      }
  return std::nullopt;
}

template <class T>
std::vector<std::string> check_region(const VModel<T>& M, const Region<T>& R, const TrimOptions& options, const Limits& limits) {
  using namespace vrep_detail;
  std::vector<std::string> fails;
  // The cover a piecewise region claims, at a grid of points over the cells (sampled).
  if (const auto gap = cases_cover_gap(R, M.trivariates, 8))
    fails.push_back("its cases' pieces do not cover the point (" + ArithTraits<T>::to_string((*gap)[0]) + ", " + ArithTraits<T>::to_string((*gap)[1]) +
                    ", " + ArithTraits<T>::to_string((*gap)[2]) + ") (the cover checked at 729 points over the cells)");
  std::vector<const Poly3<T>*> leaves;
  collect_leaves(R, leaves);
  for (std::size_t c = 0; c < M.cells.size(); ++c) {
    const auto cls = classify_cell(M.trivariates[M.cells[c].trivariates.front()], R, options, T(0), limits);
    if (cls.kind != CellClass<T>::whole)
      fails.push_back("cells[" + std::to_string(c) + "] (" + M.cells[c].name + ") is " + to_string<T>(cls.kind) + " against the region, not whole");
  }
  for (std::size_t h = 0; h < M.half_surfaces.size(); ++h) {
    const auto& hs = M.half_surfaces[h];
    if (hs.twin) continue;
    const BSpline<T> S = face(M.trivariates[hs.trivariate], hs.dir, hs.side);
    // Each Bezier piece of the face on the zero set of some leaf (a piecewise surface, such as the
    // sphere's patches, has one leaf per piece).
    bool on = true;
    std::size_t last = 0;  // the leaf the previous piece lies on: neighbouring pieces' leaves are near it
    for (const auto& pc : extract_bezier(S, limits)) {
      const auto box = control_bounds(pc.spline);
      // The piece as a degenerate trivariate: g o S vanishes iff every coefficient of W^k g(X/W, ...) does.
      BSpline<T> P = pc.spline;
      P.degrees.push_back(0);
      P.knots.push_back({T(0), T(1)});
      bool here = false;
      // The piece's corner (its first control point, a point of the face).
      const T* corner_point = pc.spline.points.data();
      for (std::size_t q = 0; q < leaves.size() && !here; ++q) {
        const std::size_t l = (last + q) % leaves.size();
        const Poly3<T>& g = *leaves[l];
        // A leaf that is not 0 at the corner, or whose bounds on the piece's control-point box
        // exclude 0, does not vanish on it.
        if (!(poly_at(g, corner_point) == T(0))) continue;
        if (const auto [lo, hi] = poly_bounds(g, box); T(0) < lo || hi < T(0)) continue;
        const Bernstein<T> G = compose_leaf(g, P);
        if (std::all_of(G.c.begin(), G.c.end(), [](const T& x) { return x == T(0); })) {
          here = true;
          last = l;
        }
      }
      if (!here) {
        on = false;
        break;
      }
    }
    if (!on)
      fails.push_back("boundary face (" + std::to_string(hs.dir) + ", " + std::to_string(hs.side) + ") of cells[" + std::to_string(hs.cell) +
                      "] lies on no surface g = 0 of the region");
  }
  return fails;
}

}  // namespace splinex
