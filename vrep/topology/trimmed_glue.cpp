// The gluing of a trimmed V-model (vrep/trimmed/trimmed.hpp: trimmed_glue), instantiated for Rational and
// double.
//
// Every count here is a certified subdivision count of vrep/topology/curve_graph.hpp (count_region on a face
// of a cell's domain, count_surface on a trimming surface) of one formula: the cell's trim and a
// second formula read on the other side of the half-V-surface (the model's region, or a
// neighbouring cell's trim). Equal surfaces of the two formulas are one leaf of the subdivision
// (Region::alias), so that coincident surfaces (a cut and its complement, coplanar box faces) do
// not stop it.
#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <type_traits>

#include "base/errors.hpp"
#include "bernstein/subdivide.hpp"
#include "spline/evaluate.hpp"
#include "vrep/boolean/boolean_impl.hpp"
#include "vrep/freeform/freeform.hpp"
#include "vrep/model/planted.hpp"
#include "vrep/topology/box_components.hpp"
#include "vrep/topology/curve_graph.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/trimmed/trimmed_impl.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_glue.hpp"

namespace splinex {

namespace {

using namespace vrep_detail;

/// h = lambda g for a rational lambda != 0: the sign of lambda; 0 if not proportional.
template <class T>
int proportional(const Poly3<T>& g, const Poly3<T>& h) {
  if (g.terms.size() != h.terms.size() || g.terms.empty()) return 0;
  auto it = g.terms.begin();
  auto jt = h.terms.begin();
  if (it->first != jt->first || it->second == T(0)) return 0;
  const T lambda = jt->second / it->second;
  for (; it != g.terms.end(); ++it, ++jt)
    if (it->first != jt->first || !(it->second * lambda == jt->second)) return 0;
  return T(0) < lambda ? 1 : -1;
}

/// The distinct surfaces of a formula built from several regions (collect order), each read from
/// inside or, on a face of the domain, from outside (`outside`: the other cell's side).
template <class T>
struct LeafTable {
  std::vector<Poly3<T>> g;
  std::vector<char> outside;
  /// The entry of h read from `out` (its sign relative to the entry), if there is one.
  std::optional<std::pair<std::size_t, int>> find(const Poly3<T>& h, bool out) const {
    for (std::size_t i = 0; i < g.size(); ++i)
      if (static_cast<bool>(outside[i]) == out)
        if (const int s = proportional(g[i], h)) return std::make_pair(i, s);
    return std::nullopt;
  }
  std::vector<const Poly3<T>*> pointers() const {
    std::vector<const Poly3<T>*> p;
    for (const auto& x : g) p.push_back(&x);
    return p;
  }
};

/// R with its leaves made entries of `table` (appended in collect order, so that the final formula's
/// non-alias leaves are the table in order): a leaf proportional to an entry becomes an alias.
/// `read_outside(h)`: read h from the other side of the face; `flip(h)`: read h across the
/// trimming surface the count is about (the other side of it).
template <class T, class Outside, class Flip>
Region<T> aliased(const Region<T>& R, LeafTable<T>& table, const Outside& read_outside, const Flip& flip) {
  if (R.kind != Region<T>::leaf) {
    Region<T> out = R;
    for (auto& p : out.parts) p = aliased(p, table, read_outside, flip);
    return out;
  }
  if (R.alias >= 0) throw std::logic_error("trimmed_glue: a region with alias leaves");
  const bool out = read_outside(R.g);
  const bool f = flip(R.g);
  Region<T> leaf = R;
  if (const auto hit = table.find(R.g, out)) {
    leaf.alias = static_cast<int>(hit->first);
    leaf.flip = (hit->second < 0) != f;
    return leaf;
  }
  if (f) {  // a first occurrence read across: the negated polynomial, same zero set
    for (auto& [e, c] : leaf.g.terms) c = -c;
  }
  table.g.push_back(leaf.g);
  table.outside.push_back(out ? 1 : 0);
  return leaf;
}

template <class T>
Region<T> conj(Region<T> a, Region<T> b) {
  return region_and<T>({std::move(a), std::move(b)});
}

void take(RegionCount c, bool& decided, std::size_t& pieces, std::string& reason) {
  decided = c.decided;
  pieces = c.decided ? c.pieces : 0;
  if (!c.decided && reason.empty()) reason = c.undecided_reason;
}

template <class T>
class Gluer {
 public:
  Gluer(const TrimmedModel<T>& M, const TrimmedGlueOptions& options, const Limits& limits) : M_(M), opt_(options), limits_(limits) {
    // Cells of one source cell carry equal copies of its trivariate (documents store one per
    // cell): the first equal one stands for all.
    for (std::size_t t = 0; t < M.trivariates.size(); ++t) {
      std::size_t r = t;
      for (std::size_t u = 0; u < t && r == t; ++u)
        if (canon_[u] == u && equal(M.trivariates[u], M.trivariates[t])) r = u;
      canon_.push_back(r);
    }
  }

  TrimmedGluing<T> run() {
    TrimmedGluing<T> out;
    add_halves(out);
    surface_twins(out);
    glued_face_twins(out);
    unmatched_parts(out);
    Contacts contacts = locate_contacts(out);
    contact_twins(out, contacts);
    totals(out, contacts.partners);
    return out;
  }

 private:
  /// Where the face halves' unmatched parts met halves of other trivariates at witness points.
  struct Contacts {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> met;  // (face half, surface half) -> witnesses
    std::map<std::size_t, std::set<std::size_t>> partners;
  };

  /// The halves: every cell's faces (not collapsed) and distinct trimming surfaces.
  void add_halves(TrimmedGluing<T>& out) const {
    for (std::size_t c = 0; c < M_.cells.size(); ++c) {
      const auto& V = M_.trivariates.at(M_.cells[c].trivariate);
      for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 2; ++s) {
          const BSpline<T> F = face(V, d, s);
          if (collapsed(F, 0) || collapsed(F, 1)) continue;
          typename TrimmedGluing<T>::Half h;
          h.cell = c;
          h.dir = d;
          h.side = s;
          h.what = std::string("face ") + "uvw"[d] + " = " + (s ? "end" : "start");
          face_half(h);
          out.halves.push_back(h);
        }
      std::vector<const Poly3<T>*> leaves;
      collect_leaves(M_.cells[c].trim, leaves);
      std::vector<std::string> labels;
      label_leaves(M_.cells[c].trim, labels);
      std::vector<const Poly3<T>*> distinct;
      for (std::size_t k = 0; k < leaves.size(); ++k) {
        bool seen = false;
        for (const auto* g : distinct) seen = seen || proportional(*g, *leaves[k]) != 0;
        if (seen) continue;
        distinct.push_back(leaves[k]);
        typename TrimmedGluing<T>::Half h;
        h.cell = c;
        h.leaf = static_cast<int>(k);
        h.what = "surface " + std::to_string(k) + (labels[k].empty() ? "" : " (" + labels[k] + ")");
        leaf_half(h);
        out.halves.push_back(h);
      }
    }
  }

  /// The half of cell c on its face (d, s) (g null) or on its trimming surface g, if there is one.
  std::optional<std::size_t> half_of(const TrimmedGluing<T>& out, std::size_t c, int d, int s, const Poly3<T>* g) const {
    for (std::size_t i = 0; i < out.halves.size(); ++i) {
      const auto& h = out.halves[i];
      if (h.cell != c) continue;
      if (g ? (h.leaf >= 0 && proportional(poly(h), *g) != 0) : (h.leaf < 0 && h.dir == d && h.side == s)) return i;
    }
    return std::nullopt;
  }

  /// Exact twins (1): two cells of one trivariate on the two sides of one trimming surface.
  void surface_twins(TrimmedGluing<T>& out) const {
    for (std::size_t i = 0; i < out.halves.size(); ++i) {
      const auto& h = out.halves[i];
      if (h.leaf < 0 || (h.decided && h.internal == 0)) continue;
      for (std::size_t c2 = h.cell + 1; c2 < M_.cells.size(); ++c2) {
        if (tri(c2) != tri(h.cell)) continue;
        const auto j = half_of(out, c2, -1, -1, &poly(h));
        if (!j) continue;
        typename TrimmedGluing<T>::Twin t;
        t.a = i;
        t.b = *j;
        t.how = "one trivariate, the two sides of a trimming surface";
        std::string reason;
        take(count_leaf(h.cell, poly(h), &M_.cells[c2].trim, {}), t.decided, t.pieces, reason);
        t.undecided_reason = reason;
        if (t.decided && t.pieces == 0) continue;
        out.twins.push_back(t);
      }
    }
  }

  /// Exact twins (2): faces of the trivariates glued exactly (seams of one trivariate included).
  void glued_face_twins(TrimmedGluing<T>& out) const {
    const auto glued = glued_faces();
    for (const auto& [fa, fb] : glued) {
      for (std::size_t c1 = 0; c1 < M_.cells.size(); ++c1) {
        if (tri(c1) != static_cast<std::size_t>(fa[0])) continue;
        const auto i = half_of(out, c1, fa[1], fa[2], nullptr);
        if (!i || (out.halves[*i].decided && out.halves[*i].internal == 0)) continue;
        for (std::size_t c2 = 0; c2 < M_.cells.size(); ++c2) {
          if (tri(c2) != static_cast<std::size_t>(fb[0])) continue;
          const auto j = half_of(out, c2, fb[1], fb[2], nullptr);
          if (!j) continue;
          typename TrimmedGluing<T>::Twin t;
          t.a = *i;
          t.b = *j;
          t.how = c1 == c2 ? "a seam of the cell's trivariate" : "faces of the trivariates glued exactly";
          std::string reason;
          take(count_face(c1, fa[1], fa[2], {&M_.cells[c2].trim}, false), t.decided, t.pieces, reason);
          t.undecided_reason = reason;
          if (t.decided && t.pieces == 0) continue;
          out.twins.push_back(t);
        }
      }
    }
  }

  /// What the exact twins leave of each half's internal part: contacts with cells of other
  /// trivariates across a surface that is not a parameter face of both.
  void unmatched_parts(TrimmedGluing<T>& out) const {
    for (std::size_t i = 0; i < out.halves.size(); ++i) {
      auto& h = out.halves[i];
      if (!h.decided || h.internal == 0) continue;
      const auto others = twin_trims(i, out);
      if (others.empty()) {
        h.unmatched = h.internal;
        continue;
      }
      bool decided = false;
      std::size_t n = 0;
      std::string reason;
      if (h.leaf >= 0) take(count_leaf(h.cell, poly(h), nullptr, others), decided, n, reason);
      else take(count_face(h.cell, h.dir, h.side, others, true), decided, n, reason);
      if (!decided) {
        h.decided = false;
        h.undecided_reason = "its part not on an exact twin: " + reason;
      }
      h.unmatched = n;
    }
  }

  /// Contacts, matched at witness points: rational points of a face half's unmatched part, located
  /// on the trimming surfaces of cells of other trivariates, or on their faces (affine
  /// trivariates: faces that overlap in part, which exact face gluing does not pair).
  Contacts locate_contacts(const TrimmedGluing<T>& out) const {
    Contacts contacts;
    auto& met = contacts.met;
    auto& partners = contacts.partners;
    for (std::size_t i = 0; i < out.halves.size(); ++i) {
      const auto& h = out.halves[i];
      if (h.leaf >= 0 || !h.decided || h.unmatched == 0) continue;
      for (const auto& x : witnesses(i, out)) {
        for (std::size_t j = 0; j < out.halves.size(); ++j) {
          const auto& h2 = out.halves[j];
          if (tri(h2.cell) == tri(h.cell) || !h2.decided || h2.unmatched == 0) continue;
          if (!(h2.leaf >= 0 ? on_surface_part(h2, x) : on_face_part(h2, x))) continue;
          ++met[{std::min(i, j), std::max(i, j)}];
          partners[i].insert(j);
          partners[j].insert(i);
        }
      }
    }
    return contacts;
  }

  /// A contact between two halves that met only each other: one set (sampled), equal piece
  /// counts. A half that met several (one part of a cell against the trimming surfaces of several
  /// cells of the other operand, or the other way round), each of which met only it: its part is
  /// split among them, and the V-surfaces are theirs (each of its pieces holds at least one).
  static void contact_twins(TrimmedGluing<T>& out, Contacts& contacts) {
    auto& partners = contacts.partners;
    for (const auto& [ij, n] : contacts.met) {
      typename TrimmedGluing<T>::Twin t;
      t.a = ij.first;
      t.b = ij.second;
      t.how = "contact between cells of different trivariates, located at witness points";
      t.witnesses = n;
      const auto& ha = out.halves[t.a];
      const auto& hb = out.halves[t.b];
      const std::size_t pa = partners[t.a].size(), pb = partners[t.b].size();
      auto star_ok = [&](std::size_t centre) {
        std::size_t sum = 0;
        for (std::size_t j : partners[centre]) {
          if (partners[j].size() != 1) return false;
          sum += out.halves[j].unmatched;
        }
        return out.halves[centre].unmatched <= sum;
      };
      // (Planted, tests only: vrep/model/planted.hpp ignores the piece counts.)
      if (pa == 1 && pb == 1 && (ha.unmatched == hb.unmatched || vrep_testing::is_planted(vrep_testing::Plant::glue_counts_ignored))) {
        t.decided = true;
        t.pieces = ha.unmatched;
      } else if (pa == 1 && pb > 1 && star_ok(t.b)) {
        t.decided = true;
        t.pieces = ha.unmatched;
      } else if (pb == 1 && pa > 1 && star_ok(t.a)) {
        t.decided = true;
        t.pieces = hb.unmatched;
      } else {
        t.undecided_reason = "the unmatched parts (" + std::to_string(ha.unmatched) + " and " + std::to_string(hb.unmatched) + " pieces, " +
                             std::to_string(pa) + " and " + std::to_string(pb) +
                             " partners) are neither one set nor one part split among parts that meet only it";
      }
      out.twins.push_back(t);
    }
  }

  /// Totals.
  static void totals(TrimmedGluing<T>& out, const std::map<std::size_t, std::set<std::size_t>>& partners) {
    out.decided = true;
    for (const auto& h : out.halves) {
      out.decided = out.decided && h.decided;
      out.boundary_v_surfaces += h.boundary;
      out.part_pieces += h.internal + h.boundary;
      if (!h.decided || h.unmatched == 0) continue;
      const bool matched = partners.count(static_cast<std::size_t>(&h - out.halves.data())) > 0;
      if (!matched) {
        out.decided = false;
        ++out.unmatched_halves;
      }
    }
    for (const auto& t : out.twins) {
      out.decided = out.decided && t.decided;
      out.internal_v_surfaces += t.pieces;
      if (t.how.rfind("contact", 0) == 0) {
        out.contacts += t.pieces;
        out.witness_points += t.witnesses;
      }
    }
    out.half_v_surfaces = out.boundary_v_surfaces + 2 * out.internal_v_surfaces;
  }
  const TrimmedModel<T>& M_;
  TrimmedGlueOptions opt_;
  Limits limits_;
  std::vector<std::size_t> canon_;
  mutable std::map<std::size_t, FreeformSolid<T>> solids_;  // one-cell solids for point location, per trivariate

  static bool equal(const BSpline<T>& a, const BSpline<T>& b) {
    return a.degrees == b.degrees && a.knots == b.knots && a.q == b.q && a.points == b.points && a.weights == b.weights;
  }
  /// The cell's trivariate, equal copies identified.
  std::size_t tri(std::size_t c) const { return canon_[M_.cells[c].trivariate]; }

  /// The trims of the cells on the other side of half i's exact twins.
  std::vector<const Region<T>*> twin_trims(std::size_t i, const TrimmedGluing<T>& G) const {
    std::vector<const Region<T>*> others;
    for (const auto& t : G.twins)
      if (t.a == i || t.b == i) others.push_back(&M_.cells[G.halves[t.a == i ? t.b : t.a].cell].trim);
    return others;
  }

  /// The trimming surface of a half (leaf >= 0: collect order in its cell's trim).
  const Poly3<T>& poly(const typename TrimmedGluing<T>::Half& h) const {
    std::vector<const Poly3<T>*> leaves;
    collect_leaves(M_.cells[h.cell].trim, leaves);
    return *leaves.at(static_cast<std::size_t>(h.leaf));
  }

  static void label_leaves(const Region<T>& R, std::vector<std::string>& out) {
    if (R.kind == Region<T>::leaf) {
      if (R.alias < 0) out.push_back(R.label);
      return;
    }
    for (const auto& p : R.parts) label_leaves(p, out);
  }

  CurveOptions curve_options() const {
    CurveOptions o;
    o.max_boxes = opt_.max_boxes;
    o.max_total_boxes = 3 * opt_.max_boxes;
    return o;
  }

  /// The model's region and none of the cells' trims `minus`, over `table`'s surfaces (read as
  /// `aliased` says), localized to `box` (localized_by_box: where the count reads them).
  template <class Outside, class Flip>
  Region<T> model_minus(LeafTable<T>& table, const std::vector<const Region<T>*>& minus, const Outside& read_outside, const Flip& flip,
                        const std::array<T, 6>& box) const {
    Region<T> other = aliased(local(M_.region, box), table, read_outside, flip);
    if (minus.empty()) return other;
    std::vector<Region<T>> any;
    for (const auto* r : minus) any.push_back(aliased(local(*r, box), table, read_outside, flip));
    return conj(std::move(other), region_not(region_or(std::move(any))));
  }

  /// A formula of the model (its region, another cell's trim) read on or next to the control-point
  /// box `box` of a face or a cell: its leaves of strict sign on the box fixed (exact arithmetic),
  /// so that a count costs what the cell meets, not what the model holds (issue 47: a grid of
  /// boxes); in double, as it is.
  static Region<T> local(const Region<T>& R, const std::array<T, 6>& box) {
    if constexpr (std::is_same_v<T, double>) return R;
    else return localized_by_box(R, box);
  }

  /// The formula on face (d, s) of cell c: its trim and, read just outside the face, the model's
  /// region (minus the cells' trims `extra` when `model_minus_extra`; without it, `extra`'s trims
  /// instead of the region), or its complement; with its distinct surfaces.
  struct FaceFormula {
    Region<T> formula;
    LeafTable<T> table;
  };
  FaceFormula face_formula(std::size_t c, int d, int s, const std::vector<const Region<T>*>& extra, bool model_minus_extra, bool complement) const {
    const auto& cell = M_.cells[c];
    const auto& V = M_.trivariates.at(cell.trivariate);
    // The model's formulas near the face: the leaves of strict sign on its control-point box
    // have that sign on and just outside the face (a neighbourhood of a compact set).
    const auto box = control_bounds(face(V, d, s));
    const Region<T> region = local(M_.region, box);
    std::vector<Region<T>> extra_local;
    for (const auto* r : extra) extra_local.push_back(local(*r, box));
    // Which surfaces vanish on the face: those of all formulas, composed once.
    std::vector<const Poly3<T>*> all;
    collect_leaves(cell.trim, all);
    collect_leaves(region, all);
    for (const auto& r : extra_local) collect_leaves(r, all);
    const auto probe = leaf_pieces(V, all, limits_);
    const T at = s ? V.domain_hi(d) : V.domain_lo(d);
    std::vector<char> vanish(all.size(), 0);
    for (const auto& p : probe) {
      if (!((s ? p.hi[d] : p.lo[d]) == at)) continue;
      std::vector<int> m;
      leaves_on_face(V, p, d, s, nullptr, &m);
      for (std::size_t l = 0; l < all.size(); ++l) vanish[l] = vanish[l] || m[l] > 0;
    }
    auto vanishes = [&](const Poly3<T>& h) {
      for (std::size_t l = 0; l < all.size(); ++l)
        if (vanish[l] && proportional(*all[l], h) != 0) return true;
      return false;
    };
    FaceFormula out;
    const auto no = [](const Poly3<T>&) { return false; };
    Region<T> formula = aliased(cell.trim, out.table, no, no);
    Region<T> other;
    if (extra.empty() || model_minus_extra) other = model_minus(out.table, extra, vanishes, no, box);
    else {
      std::vector<Region<T>> all_of;
      for (const auto& r : extra_local) all_of.push_back(aliased(r, out.table, vanishes, no));
      other = region_and(std::move(all_of));
    }
    out.formula = conj(std::move(formula), complement ? region_not(std::move(other)) : std::move(other));
    return out;
  }

  /// The 2D problem of a face formula (its `trim` set by the caller: the formula moves).
  CurveProblem<T, 2> face_problem(std::size_t c, int d, int s, const FaceFormula& f) const {
    const auto& V = M_.trivariates.at(M_.cells[c].trivariate);
    const auto pieces = leaf_pieces(V, f.table.pointers(), limits_);
    CurveProblem<T, 2> problem = face_curve_problem(V, pieces, d, s, face_edges(V, d, s, limits_), &f.table.outside);
    problem.options = curve_options();
    return problem;
  }

  /// Pieces of the cell's part of face (d, s) where the other formula of face_formula holds just
  /// outside the face.
  RegionCount count_face(std::size_t c, int d, int s, const std::vector<const Region<T>*>& extra, bool model_minus_extra,
                         bool complement = false) const {
    const FaceFormula f = face_formula(c, d, s, extra, model_minus_extra, complement);
    CurveProblem<T, 2> problem = face_problem(c, d, s, f);
    problem.trim = &f.formula;
    return count_region(problem);
  }

  /// Pieces of the cell's trimming surface g where the other side is in the model (`pair`: in that
  /// cell of the same trivariate instead; `minus`: in the model but none of these cells;
  /// `complement`: out of the model).
  RegionCount count_leaf(std::size_t c, const Poly3<T>& g, const Region<T>* pair, const std::vector<const Region<T>*>& minus,
                         bool complement = false) const {
    const auto& cell = M_.cells[c];
    const auto& V = M_.trivariates.at(cell.trivariate);
    LeafTable<T> table;
    const auto no = [](const Poly3<T>&) { return false; };
    const auto across = [&](const Poly3<T>& h) { return proportional(g, h) != 0; };
    Region<T> formula = aliased(cell.trim, table, no, no);
    // Read inside V only (on both sides of g): localized to V's control-point box.
    const auto box = control_bounds(V);
    Region<T> other = pair ? aliased(local(*pair, box), table, no, across) : model_minus(table, minus, no, across, box);
    formula = conj(std::move(formula), complement ? region_not(std::move(other)) : std::move(other));
    std::size_t k = table.g.size();
    for (std::size_t i = 0; i < table.g.size() && k == table.g.size(); ++i)
      if (proportional(table.g[i], g) != 0) k = i;
    const CurveProblem<T, 3> problem = cell_problem(V, formula, table.pointers(), curve_options(), limits_);
    return count_surface(problem, k);
  }

  void face_half(typename TrimmedGluing<T>::Half& h) const {
    std::string reason;
    bool d1 = false, d2 = false;
    take(count_face(h.cell, h.dir, h.side, {}, true, false), d1, h.internal, reason);
    take(count_face(h.cell, h.dir, h.side, {}, true, true), d2, h.boundary, reason);
    h.decided = d1 && d2;
    h.undecided_reason = reason;
  }

  void leaf_half(typename TrimmedGluing<T>::Half& h) const {
    std::string reason;
    bool d1 = false, d2 = false;
    take(count_leaf(h.cell, poly(h), nullptr, {}, false), d1, h.internal, reason);
    take(count_leaf(h.cell, poly(h), nullptr, {}, true), d2, h.boundary, reason);
    h.decided = d1 && d2;
    h.undecided_reason = reason;
  }

  /// Pairs of faces (trivariate, dir, side) equal as surfaces, each pair once.
  std::vector<std::pair<std::array<int, 3>, std::array<int, 3>>> glued_faces() const {
    struct F {
      std::array<int, 3> id;
      BSpline<T> S;
      std::vector<std::array<T, 3>> corners;
    };
    std::vector<F> faces;
    for (std::size_t t = 0; t < M_.trivariates.size(); ++t)
      if (canon_[t] == t)
      for (int d = 0; d < 3; ++d)
        for (int s = 0; s < 2; ++s) {
          BSpline<T> S = face(M_.trivariates[t], d, s);
          if (collapsed(S, 0) || collapsed(S, 1)) continue;
          auto cs = corner_set(S);
          faces.push_back({{static_cast<int>(t), d, s}, std::move(S), std::move(cs)});
        }
    std::vector<std::pair<std::array<int, 3>, std::array<int, 3>>> out;
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j) {
        if (faces[i].corners != faces[j].corners) continue;
        if (!same_surface(faces[i].S, faces[j].S, T(0), limits_)) continue;
        out.push_back({faces[i].id, faces[j].id});
      }
    return out;
  }

  /// Rational points (in space) strictly inside the unmatched part of a face half: centres of
  /// subdivision boxes of the face decided in (every leaf strictly signed there).
  std::vector<std::vector<T>> witnesses(std::size_t i, const TrimmedGluing<T>& G) const {
    const auto& h = G.halves[i];
    const auto& cell = M_.cells[h.cell];
    const auto& V = M_.trivariates.at(cell.trivariate);
    const int d = h.dir, s = h.side, a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
    const auto others = twin_trims(i, G);
    // The same formula as count_face's "model minus twins", on boxes.
    const FaceFormula f = face_formula(h.cell, d, s, others, true, false);
    const Region<T>& formula = f.formula;
    const CurveProblem<T, 2> problem = face_problem(h.cell, d, s, f);
    const T at = s ? V.domain_hi(d) : V.domain_lo(d);
    struct Box {
      std::vector<Bernstein<T>> G;
      std::array<T, 2> lo, hi;
      int level = 0;
    };
    // Breadth first: a box touching the part's boundary is never strict, so the witnesses come from
    // the largest boxes decided in; the walk ends when enough are found or the budget is spent.
    std::vector<Box> roots;
    for (const auto& p : problem.pieces) roots.push_back({p.G, p.lo, p.hi, 0});
    std::vector<std::vector<T>> out;
    Budget budget;
    budget.max_boxes = opt_.max_boxes;
    auto examine = [&](const Box& x, int) {
      std::vector<Truth> t;
      for (const auto& G : x.G) t.push_back(coefficient_truth(G, T(0)));
      bool strict = true;
      for (const auto& G : x.G) strict = strict && bern_sign(G) != 0;
      std::size_t k = 0;
      const Truth f = combine(formula, t, k);
      if (f == Truth::out) return Examined::settled;
      if (f == Truth::in && strict) {
        std::vector<T> u(3);
        u[static_cast<std::size_t>(d)] = at;
        u[static_cast<std::size_t>(a)] = (x.lo[0] + x.hi[0]) / 2;
        u[static_cast<std::size_t>(b)] = (x.lo[1] + x.hi[1]) / 2;
        out.push_back(evaluate(V, u));
        return Examined::settled;
      }
      return Examined::split;
    };
    auto split = [&](Box&& x, int, auto&& emit) {
      Box c[2];
      split_box(x, widest(x.lo, x.hi), T(1) / T(2), c);
      emit(std::move(c[0]));
      emit(std::move(c[1]));
    };
    subdivide(std::move(roots), Walk{Order::breadth_first, 2, false}, budget, examine, split, [](Box&&, Left) {},
              [&]() { return out.size() >= opt_.witnesses; });
    return out;
  }

  /// The point x (exact, in space) lies in the relative interior of the face half's part, for an
  /// affine trivariate (else false: not located): its exact parameters on the face, strictly inside
  /// the face's other two ranges; every leaf of the trim read just inside (a leaf vanishing at x by
  /// the sign of its gradient along the inward parameter direction, which must not be 0) and the
  /// trim in.
  bool on_face_part(const typename TrimmedGluing<T>::Half& h, const std::vector<T>& x) const {
    const auto& cell = M_.cells[h.cell];
    const auto& V = M_.trivariates.at(cell.trivariate);
    const auto inv = affine_inverse(V);
    if (!inv) return false;
    const auto u = (*inv)(x.data());
    for (int d = 0; d < 3; ++d) {
      const T& ud = u[static_cast<std::size_t>(d)];
      if (d == h.dir) {
        if (!(ud == (h.side ? V.domain_hi(d) : V.domain_lo(d)))) return false;
      } else if (!(V.domain_lo(d) < ud && ud < V.domain_hi(d)))
        return false;
    }
    // The inward direction in space: +-dT/du_dir (T affine: the difference of two points).
    const std::vector<T> a = u_point(V, u, h.dir, false), b = u_point(V, u, h.dir, true);
    std::array<T, 3> inward;
    for (int k = 0; k < 3; ++k) inward[static_cast<std::size_t>(k)] = (b[static_cast<std::size_t>(k)] - a[static_cast<std::size_t>(k)]) * (h.side ? T(-1) : T(1));
    std::vector<const Poly3<T>*> leaves;
    collect_leaves(cell.trim, leaves);
    std::vector<Truth> t;
    for (const auto* l : leaves) {
      T v = poly_at(*l, x.data());
      if (v == T(0)) {
        v = T(0);
        for (int k = 0; k < 3; ++k) v += poly_at(partial(*l, k), x.data()) * inward[static_cast<std::size_t>(k)];
        if (v == T(0)) return false;
      }
      t.push_back(T(0) < v ? Truth::in : Truth::out);
    }
    std::size_t k = 0;
    return combine(cell.trim, t, k) == Truth::in;
  }

  /// The point of V at the parameters u with u[dir] set to the domain's start or end.
  static std::vector<T> u_point(const BSpline<T>& V, std::array<T, 3> u, int dir, bool end) {
    u[static_cast<std::size_t>(dir)] = end ? V.domain_hi(dir) : V.domain_lo(dir);
    return evaluate(V, std::vector<T>(u.begin(), u.end()));
  }

  /// d g / d x_k.
  static Poly3<T> partial(const Poly3<T>& g, int k) {
    Poly3<T> out;
    for (const auto& [e, c] : g.terms) {
      if (e[static_cast<std::size_t>(k)] == 0) continue;
      auto f = e;
      --f[static_cast<std::size_t>(k)];
      out.terms[f] += c * T(e[static_cast<std::size_t>(k)]);
    }
    return out;
  }

  /// The point x (exact, in space) lies in the relative interior of the half's part: on its
  /// surface, every other leaf of the cell's trim strictly signed at x, the trim depending on the
  /// surface's sign there, and x strictly inside the image of the cell's trivariate.
  bool on_surface_part(const typename TrimmedGluing<T>::Half& h, const std::vector<T>& x) const {
    const Poly3<T>& g = poly(h);
    if (!(poly_at(g, x.data()) == T(0))) return false;
    const auto& cell = M_.cells[h.cell];
    std::vector<const Poly3<T>*> leaves;
    collect_leaves(cell.trim, leaves);
    std::vector<Truth> plus, minus;
    for (const auto* l : leaves) {
      if (const int sgn = proportional(g, *l)) {
        plus.push_back(sgn > 0 ? Truth::in : Truth::out);
        minus.push_back(sgn > 0 ? Truth::out : Truth::in);
        continue;
      }
      const T v = poly_at(*l, x.data());
      if (v == T(0)) return false;
      plus.push_back(T(0) < v ? Truth::in : Truth::out);
      minus.push_back(plus.back());
    }
    std::size_t k1 = 0, k2 = 0;
    if (combine(cell.trim, plus, k1) == combine(cell.trim, minus, k2)) return false;
    const auto& V = M_.trivariates.at(cell.trivariate);
    if (const auto inv = affine_inverse(V)) {
      const auto u = (*inv)(x.data());
      for (int d = 0; d < 3; ++d)
        if (!(V.domain_lo(d) < u[static_cast<std::size_t>(d)] && u[static_cast<std::size_t>(d)] < V.domain_hi(d))) return false;
      return true;
    }
    auto it = solids_.find(tri(h.cell));
    if (it == solids_.end()) it = solids_.emplace(tri(h.cell), freeform_solid<T>("cell", {V}, limits_)).first;
    return classify_point_freeform(it->second, x) == Truth::in;
  }
};

}  // namespace

template <class T>
TrimmedGluing<T> trimmed_glue(const TrimmedModel<T>& M, const TrimmedGlueOptions& options, const Limits& limits) {
  if (options.max_boxes < 8) throw ValidationError("boxes", "must be at least 8", "give --boxes 8 or more");
  for (const auto& c : M.cells)
    if (c.trivariate >= M.trivariates.size())
      throw ValidationError("cells[].trivariate", "names no trivariate of the model", "give an index below the number of trivariates");
  // The model's region as the counts read it near each trivariate (localized to its
  // control-point box in exact arithmetic; every face's box lies in it).
  for (const auto& V : M.trivariates) {
    if constexpr (std::is_same_v<T, double>) checked_trim_leaves(V, M.region, options.max_boxes, limits);
    else checked_trim_leaves(V, localized_by_box(M.region, control_bounds(V)), options.max_boxes, limits);
  }
  for (const auto& c : M.cells) checked_trim_leaves(M.trivariates[c.trivariate], c.trim, options.max_boxes, limits);
  return Gluer<T>(M, options, limits).run();
}

template TrimmedGluing<Rational> trimmed_glue(const TrimmedModel<Rational>&, const TrimmedGlueOptions&, const Limits&);
template TrimmedGluing<double> trimmed_glue(const TrimmedModel<double>&, const TrimmedGlueOptions&, const Limits&);

}  // namespace splinex
