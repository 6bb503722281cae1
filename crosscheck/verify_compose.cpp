// Judging Algorithm 1's trimmed patches and Algorithm 2's tensor-product tiles (papers/000) handed
// in as `splinex compose --method trimmed|tensor` writes them (crosscheck/verify.hpp).
#include <algorithm>
#include <optional>

#include "compose/compose.hpp"
#include "crosscheck/verify.hpp"
#include "spline/evaluate.hpp"
#include "untrim/algorithm2.hpp"

namespace splinex {

namespace {

using Box = std::vector<std::pair<Rational, Rational>>;

std::string idx(const std::string& base, std::size_t i) { return base + "[" + std::to_string(i) + "]"; }

const Json& field(const Json& obj, const std::string& key, const std::string& where, const std::string& fix) {
  if (!obj.is_object() || !obj.contains(key)) throw ValidationError(where + "." + key, "is missing", fix);
  return obj[key];
}

std::size_t index_field(const Json& j, const std::string& where) {
  const Rational v = json_number(j, where);
  if (v < 0 || denominator(v) != 1 || v > Rational(1L << 30))
    throw ValidationError(where, "is not a non-negative integer index", "give the index as written by splinex compose");
  return static_cast<std::size_t>(numerator(v).convert_to<unsigned long>());
}

Box box_from_json(const Json& j, int dims, const std::string& where) {
  if (!j.is_array() || j.size() != static_cast<std::size_t>(dims))
    throw ValidationError(where, "is not a box of " + std::to_string(dims) + " intervals", "give [[lo, hi], ...], one per direction of S");
  Box b;
  for (std::size_t l = 0; l < j.size(); ++l) {
    if (!j[l].is_array() || j[l].size() != 2) throw ValidationError(idx(where, l), "is not an interval", "write [lo, hi]");
    b.emplace_back(json_number(j[l][0], idx(where, l) + "[0]"), json_number(j[l][1], idx(where, l) + "[1]"));
    if (!(b.back().first < b.back().second)) throw ValidationError(idx(where, l), "is empty", "give lo < hi");
  }
  return b;
}

std::vector<Rational> numbers(const Json& j, const std::string& where) {
  if (!j.is_array()) throw ValidationError(where, "is not a list of numbers", "write [x0, x1, ...]");
  std::vector<Rational> v;
  for (std::size_t i = 0; i < j.size(); ++i) v.push_back(json_number(j[i], idx(where, i)));
  return v;
}

/// x equals r exactly or is r rounded to the candidate's precision.
bool matches(const Rational& x, const Rational& r, int precision) { return x == r || x == rounded_to_precision(r, precision); }

bool box_matches(const Box& c, const Box& r, int precision) {
  if (c.size() != r.size()) return false;
  for (std::size_t l = 0; l < c.size(); ++l)
    if (!matches(c[l].first, r[l].first, precision) || !matches(c[l].second, r[l].second, precision)) return false;
  return true;
}

bool in_box(const Box& b, const std::vector<Rational>& r) {
  for (std::size_t l = 0; l < b.size(); ++l)
    if (r[l] < b[l].first || b[l].second < r[l]) return false;
  return true;
}

/// A candidate patch: (w R, w) when `weighted`, read from {"homogeneous": ..., "patch": ...}.
Homogeneous<Rational> patch_from_json(const Json& pc, int q, const std::string& where, const Limits& limits) {
  Homogeneous<Rational> h;
  const Json& w = field(pc, "homogeneous", where, "say whether the patch holds (w R, w): \"homogeneous\": true|false");
  if (!w.is_boolean()) throw ValidationError(where + ".homogeneous", "is not true or false", "write true or false");
  h.weighted = w.get<bool>();
  h.net = spline_from_json(field(pc, "patch", where, "give the composed patch as a spline document"), limits, where + ".patch");
  if (h.net.is_rational())
    throw ValidationError(where + ".patch", "has weights", "give a homogeneous patch as points (w R, w) with \"homogeneous\": true");
  if (h.q() != q)
    throw ValidationError(where + ".patch", "has points with " + std::to_string(h.q()) + " coordinates, T(S) has " + std::to_string(q),
                          "hand in the composition of the same T and S");
  return h;
}

/// The patch's Cartesian value at x (NaN-free: a zero weight is reported as nullopt).
std::optional<std::vector<Rational>> patch_value(const Homogeneous<Rational>& h, const std::vector<Rational>& x) {
  auto v = evaluate(h.net, x);
  if (!h.weighted) return v;
  if (v.back() == 0) return std::nullopt;
  return divide_by_weight(v);
}

/// Options for one part of a composition: a smaller refinement budget (the parts are high-degree
/// tensor patches, and a bound per part within a few times the witness is enough for the worst).
VerifyOptions part_options(VerifyOptions o) {
  o.budget = std::min<std::size_t>(o.budget, 4);
  return o;
}

/// Candidate patch C against reference patch R (same parameter box) as functions: rational when
/// every weight of both is positive (then the Cartesian error is bounded); otherwise the
/// homogeneous coordinates compared as polynomials (the weight may vanish off the region).
FunctionError patch_error(const Homogeneous<Rational>& C, const Homogeneous<Rational>& R, const VerifyOptions& options,
                          const Limits& limits) {
  auto cartesian = [](const Homogeneous<Rational>& h, BSpline<Rational>& out) {
    if (!h.weighted) {
      out = h.net;
      return true;
    }
    const std::size_t n = h.net.size(), q = h.q(), Q = h.net.q;
    out = h.net;
    out.q = static_cast<int>(q);
    out.points.assign(n * q, Rational(0));
    out.weights.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Rational& w = h.net.points[i * Q + q];
      if (!(w > 0)) return false;
      out.weights[i] = w;
      for (std::size_t c = 0; c < q; ++c) out.points[i * q + c] = h.net.points[i * Q + c] / w;
    }
    return true;
  };
  BSpline<Rational> c, r;
  if (C.weighted == R.weighted && cartesian(C, c) && cartesian(R, r)) return function_error(c, r, options, limits);
  if (C.weighted != R.weighted) {
    FunctionError fe;
    fe.method = "not compared: one patch is homogeneous, the other not";
    return fe;
  }
  FunctionError fe = function_error(C.net, R.net, options, limits);
  fe.method = "homogeneous coordinates (w R, w) compared as polynomials (a weight is not positive on the whole box): " + fe.method;
  return fe;
}

/// Accumulates per-part function errors into the report: the worst one, certified only if all are.
struct Worst {
  bool any = false, certified = true, within = true;
  void offer(VerifyReport& rep, FunctionError fe, const std::string& what) {
    certified = certified && fe.certified;
    within = within && fe.within_factor;
    if (!any || rep.function.upper < fe.upper) {
      rep.function = std::move(fe);
      rep.function.method += " (worst part: " + what + ")";
    }
    any = true;
  }
  void finish(VerifyReport& rep) {
    if (!any) {
      rep.function = FunctionError{};
      rep.function.method = "not compared: no part pairs up with the reference";
      return;
    }
    rep.function.certified = certified;
    rep.function.within_factor = within;
  }
};

Json fe_brief(const FunctionError& fe) {
  return Json{{"upper", to_double(fe.upper)}, {"lower", to_double(fe.lower)}, {"certified", fe.certified}};
}

/// Sample points of S's domain: g per direction (17 for surfaces, 65 for curves, 7 for trivariates).
std::vector<std::vector<Rational>> domain_grid(const BSpline<Rational>& S) {
  const int k = S.dim();
  const int g = k == 1 ? 65 : k == 2 ? 17 : 7;
  std::vector<std::vector<Rational>> pts;
  std::vector<int> i(k, 0);
  for (;;) {
    std::vector<Rational> r(k);
    for (int l = 0; l < k; ++l) r[l] = S.domain_lo(l) + (S.domain_hi(l) - S.domain_lo(l)) * Rational(i[l], g - 1);
    pts.push_back(std::move(r));
    int l = 0;
    while (l < k && ++i[l] == g) i[l++] = 0;
    if (l == k) break;
  }
  return pts;
}

/// An empty report for a composition: the scale of the function errors is the largest
/// coefficient of the exact patches.
VerifyReport composition_report(const std::string& operation, const TrimmedComposition<Rational>& ref, std::size_t results,
                                const VerifyOptions& options) {
  VerifyReport rep;
  rep.operation = operation;
  rep.precision = options.precision;
  rep.results = results;
  for (const auto& p : ref.patches)
    for (const auto& x : p.patch.net.points) rep.reference_scale = std::max(rep.reference_scale, Rational(abs(x)));
  return rep;
}

void add_value_error(VerifyReport& rep, const std::vector<Rational>& exact, const std::vector<Rational>& cand) {
  for (std::size_t c = 0; c < exact.size(); ++c) rep.values.add(exact[c], cand[c]);
}

}  // namespace

// ---- Algorithm 1: trimmed patches ------------------------------------------------------------------

namespace {

// A trimmed patch's region as the candidate gives it: conditions on S's coordinates (q of them),
// each with "at_least", and "at_most" or "below"; numbers read exactly.
std::vector<CellCondition<Rational>> region_from_json(const Json& reg, int q, const std::string& where) {
  if (!reg.is_array()) throw ValidationError(where + ".region", "is not an array", "give a list of conditions");
  std::vector<CellCondition<Rational>> out;
  for (std::size_t c = 0; c < reg.size(); ++c) {
    const std::string w = idx(where + ".region", c);
    CellCondition<Rational> cc;
    cc.coord = static_cast<int>(index_field(field(reg[c], "coordinate", w, "give the coordinate of S"), w + ".coordinate"));
    if (cc.coord >= q) throw ValidationError(w + ".coordinate", "is beyond S's coordinates", "give 0.." + std::to_string(q - 1));
    cc.check_lo = reg[c].contains("at_least");
    if (cc.check_lo) cc.lo = json_number(reg[c]["at_least"], w + ".at_least");
    cc.hi_closed = reg[c].contains("at_most");
    cc.check_hi = cc.hi_closed || reg[c].contains("below");
    if (cc.check_hi) cc.hi = json_number(reg[c][cc.hi_closed ? "at_most" : "below"], w + (cc.hi_closed ? ".at_most" : ".below"));
    out.push_back(cc);
  }
  return out;
}

}  // namespace

VerifyReport verify_trimmed_composition(const BSpline<Rational>& T, const BSpline<Rational>& S, const Json& candidate,
                                        const VerifyOptions& options, const Limits& limits) {
  const auto ref = compose_trimmed(T, S, {}, limits);
  const Json& pieces = field(candidate, "pieces", "candidate", "give the output of splinex compose --method trimmed");
  if (!pieces.is_array()) throw ValidationError("candidate.pieces", "is not an array", "give a list of trimmed patches");
  struct Piece {
    Box box;
    std::size_t cell = 0;
    std::vector<CellCondition<Rational>> region;
    Homogeneous<Rational> patch;
  };
  std::vector<Piece> cand;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::string where = idx("candidate.pieces", i);
    const Json& pc = pieces[i];
    Piece p;
    p.box = box_from_json(field(pc, "inner_box", where, "give the inner piece's parameter box"), S.dim(), where + ".inner_box");
    p.cell = index_field(field(pc, "outer_cell", where, "give the index of T's polynomial piece"), where + ".outer_cell");
    p.region = region_from_json(field(pc, "region", where, "give the region's conditions (an empty list for an untrimmed piece)"), S.q, where);
    p.patch = patch_from_json(pc, T.q, where, limits);
    if (p.patch.net.dim() != S.dim())
      throw ValidationError(where + ".patch", "has " + std::to_string(p.patch.net.dim()) + " parameters, S has " + std::to_string(S.dim()),
                            "hand in the composition of the same T and S");
    cand.push_back(std::move(p));
  }

  VerifyReport rep = composition_report("compose --method trimmed", ref, cand.size(), options);
  int verdict = 0;
  if (cand.size() != ref.patches.size()) {
    verdict = 2;
    rep.structure_notes.push_back("the candidate has " + std::to_string(cand.size()) + " trimmed patches, the reference " +
                                  std::to_string(ref.patches.size()));
  }
  // Pair by (inner box, outer cell); compare regions and patches.
  std::vector<char> used(ref.patches.size(), 0);
  bool unpaired = false;
  Worst worst;
  for (std::size_t i = 0; i < cand.size(); ++i) {
    if (options.progress) options.progress("patch " + std::to_string(i + 1) + " of " + std::to_string(cand.size()));
    const auto& c = cand[i];
    Json part{{"candidate", i}};
    std::size_t k = ref.patches.size();
    for (std::size_t j = 0; j < ref.patches.size() && k == ref.patches.size(); ++j)
      if (!used[j] && ref.patches[j].outer_cell == c.cell && box_matches(c.box, ref.inner_pieces[ref.patches[j].inner_piece].box, options.precision))
        k = j;
    if (k == ref.patches.size()) {
      verdict = 2;
      unpaired = true;
      rep.structure_notes.push_back(idx("pieces", i) + ": no reference patch has this inner box and outer cell " + std::to_string(c.cell));
      part["reference"] = nullptr;
      rep.parts.push_back(part);
      continue;
    }
    used[k] = 1;
    part["reference"] = k;
    const auto& r = ref.patches[k];
    const Box& rbox = ref.inner_pieces[r.inner_piece].box;
    bool exact_box = true;
    for (std::size_t l = 0; l < rbox.size(); ++l) exact_box = exact_box && c.box[l] == rbox[l];
    if (!exact_box) verdict = std::max(verdict, 1);
    // The regions: the same conditions (coordinate, bounds, closedness), in any order.
    bool same_region = c.region.size() == r.region.size();
    bool rounded_region = false;
    for (const auto& rc : r.region) {
      bool found = false;
      for (const auto& cc : c.region)
        if (cc.coord == rc.coord && cc.check_lo == rc.check_lo && cc.check_hi == rc.check_hi && (!rc.check_hi || cc.hi_closed == rc.hi_closed) &&
            (!rc.check_lo || matches(cc.lo, rc.lo, options.precision)) && (!rc.check_hi || matches(cc.hi, rc.hi, options.precision))) {
          found = true;
          rounded_region = rounded_region || (rc.check_lo && !(cc.lo == rc.lo)) || (rc.check_hi && !(cc.hi == rc.hi));
        }
      same_region = same_region && found;
    }
    if (!same_region) {
      verdict = 2;
      rep.structure_notes.push_back(idx("pieces", i) + ": the region's conditions differ from the reference's");
    } else if (rounded_region) {
      verdict = std::max(verdict, 1);
    }
    part["region"] = same_region ? (rounded_region ? "equal after rounding" : "equal") : "different";
    // The patch on the whole inner box (a bound there bounds the region, which lies inside it).
    Homogeneous<Rational> R = r.patch;
    if (c.patch.net.degrees == R.net.degrees && c.patch.net.points.size() == R.net.points.size() && c.patch.weighted == R.weighted) {
      rep.coefficients_compared = true;
      for (std::size_t m = 0; m < R.net.points.size(); ++m) rep.control_points.add(R.net.points[m], c.patch.net.points[m]);
    } else {
      verdict = 2;
      rep.structure_notes.push_back(idx("pieces", i) + ": the patch's degrees or form differ from the reference's");
    }
    try {
      FunctionError fe = patch_error(c.patch, R, part_options(options), limits);
      part["function"] = fe_brief(fe);
      worst.offer(rep, std::move(fe), idx("pieces", i));
    } catch (const DomainError&) {
      verdict = 2;
      rep.structure_notes.push_back(idx("pieces", i) + ": the patch's domain is not the inner box, so it is not compared");
      part["function"] = nullptr;
    }
    rep.parts.push_back(part);
  }
  for (std::size_t j = 0; j < ref.patches.size(); ++j)
    if (!used[j]) {
      verdict = 2;
      unpaired = true;
      rep.structure_notes.push_back("reference patch " + std::to_string(j) + " (outer cell " + std::to_string(ref.patches[j].outer_cell) +
                                    ") has no candidate");
    }
  worst.finish(rep);
  if (unpaired) rep.function.certified = false;  // a missing or unpaired patch is not bounded

  // Sampled: at a grid of S's domain, every candidate patch that claims the point (its box holds r
  // and its region holds at S(r), read exactly with the candidate's bounds) against T(S(r)).
  for (const auto& r : domain_grid(S)) {
    ++rep.points_checked;
    const auto exact = ref.evaluate(r);
    const auto s = evaluate(S, r);
    const std::size_t truth = ref.locate(r);
    bool claimed = false;
    for (std::size_t i = 0; i < cand.size(); ++i) {
      const auto& c = cand[i];
      if (!in_box(c.box, r)) continue;
      bool in = true;
      for (const auto& cc : c.region) in = in && cc.holds(s[cc.coord]);
      if (!in) continue;
      claimed = true;
      const auto v = patch_value(c.patch, r);
      if (!v) {
        ++rep.points_failed;
        continue;
      }
      add_value_error(rep, exact, *v);
      // S(r) outside the claimed cell's closed box (on a knot line it belongs to both cells).
      if (c.cell != ref.patches[truth].outer_cell && (c.cell >= ref.outer_pieces.size() || !in_box(ref.outer_pieces[c.cell].box, s)))
        ++rep.points_misassigned;
    }
    if (!claimed) ++rep.points_unclaimed;
  }
  rep.structure = verdict == 0 ? "equal" : verdict == 1 ? "equal after rounding" : "different";
  return rep;
}

// ---- Algorithm 2: tensor-product tiles -------------------------------------------------------------

namespace {

// A tile as the candidate gives it: its chains (x, y_bottom, y_top: one entry per slab boundary)
// and, for curved chains, the Bernstein ordinates of each piece; numbers read exactly.
Tile<Rational> tile_from_json(const Json& tile, const std::string& where) {
  Tile<Rational> t;
  t.x = numbers(field(tile, "x", where + ".tile", "give the slab abscissae"), where + ".tile.x");
  t.yb = numbers(field(tile, "y_bottom", where + ".tile", "give the bottom chain"), where + ".tile.y_bottom");
  t.yt = numbers(field(tile, "y_top", where + ".tile", "give the top chain"), where + ".tile.y_top");
  if (t.x.size() < 2 || t.yb.size() != t.x.size() || t.yt.size() != t.x.size())
    throw ValidationError(where + ".tile", "has chains of different lengths or fewer than two abscissae",
                          "give x, y_bottom and y_top with one entry per slab boundary");
  for (std::size_t m = 0; m + 1 < t.x.size(); ++m)
    if (!(t.x[m] < t.x[m + 1])) throw ValidationError(where + ".tile.x", "is not increasing", "give increasing abscissae");
  if (tile.contains("bottom_pieces") || tile.contains("top_pieces")) {
    for (const char* side : {"bottom_pieces", "top_pieces"}) {
      const Json& ps = field(tile, side, where + ".tile", "give both bottom_pieces and top_pieces");
      if (!ps.is_array() || ps.size() + 1 != t.x.size())
        throw ValidationError(where + ".tile." + side, "needs one piece per slab", "give the Bernstein ordinates of each chain piece");
      auto& dst = std::string(side) == "bottom_pieces" ? t.bottom : t.top;
      for (std::size_t m = 0; m < ps.size(); ++m) {
        dst.push_back(numbers(ps[m], idx(where + ".tile." + side, m)));
        if (dst.back().size() < 2) throw ValidationError(idx(where + ".tile." + side, m), "has fewer than two ordinates", "give degree >= 1");
      }
    }
  }
  return t;
}

}  // namespace

VerifyReport verify_tensor_composition(const BSpline<Rational>& T, const BSpline<Rational>& S, const Json& candidate,
                                       const VerifyOptions& options, const Limits& limits) {
  if (S.dim() != 2)
    throw ValidationError("inner", "has " + std::to_string(S.dim()) + " parameters; tiles (Algorithm 2) are made for inner surfaces",
                          "verify compose --method trimmed for curves and trivariates");
  const auto ref = compose_trimmed(T, S, {}, limits);
  // The exact tiling exists where every trimming curve is straight; otherwise only the tiles'
  // own compositions and sampled values are judged.
  std::optional<TensorComposition<Rational>> exact_tiles;
  std::string no_exact_tiling;
  try {
    exact_tiles = compose_tensor(T, S, {}, limits);
  } catch (const DomainError& e) {
    no_exact_tiling = e.what();
  }
  const Json& tiles = field(candidate, "tiles", "candidate", "give the output of splinex compose --method tensor");
  if (!tiles.is_array()) throw ValidationError("candidate.tiles", "is not an array", "give a list of tiles");

  VerifyReport rep = composition_report("compose --method tensor", ref, tiles.size(), options);
  int verdict = 0;
  if (exact_tiles && exact_tiles->tiles.size() != tiles.size()) {
    verdict = 2;
    rep.structure_notes.push_back("the candidate has " + std::to_string(tiles.size()) + " tiles, the exact tiling " +
                                  std::to_string(exact_tiles->tiles.size()));
  }
  if (!exact_tiles)
    rep.structure_notes.push_back("no exact tiling to compare the tiles with (" + no_exact_tiling +
                                  "); each tile's patch is judged against the exact composition of its own Coons patch");
  // Area per region (patch index of the reference): candidate tiles' exact areas against the
  // exact tiling's (what the trimming tolerance moved from one region to another).
  std::vector<Rational> area_cand(ref.patches.size(), Rational(0)), area_ref(ref.patches.size(), Rational(0));
  if (exact_tiles)
    for (const auto& t : exact_tiles->tiles) area_ref[t.patch] += t.area;
  bool unpaired = false;
  Worst worst;
  CompositionOptions co;
  co.expand = true;  // Q may stray off the piece's box by the tolerance: T_j^e is a polynomial there
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    if (options.progress) options.progress("tile " + std::to_string(i + 1) + " of " + std::to_string(tiles.size()));
    const std::string where = idx("candidate.tiles", i);
    const Json& tj = tiles[i];
    const Box box = box_from_json(field(tj, "inner_box", where, "give the inner piece's parameter box"), 2, where + ".inner_box");
    const std::size_t cell = index_field(field(tj, "outer_cell", where, "give the index of T's polynomial piece"), where + ".outer_cell");
    const Tile<Rational> t = tile_from_json(field(tj, "tile", where, "give the tile's chains {\"x\", \"y_bottom\", \"y_top\"}"), where);
    const BSpline<Rational> Q = spline_from_json(field(tj, "coons_patch", where, "give the tile's Coons patch"), limits, where + ".coons_patch");
    if (Q.dim() != 2 || Q.q != 2 || Q.is_rational())
      throw ValidationError(where + ".coons_patch", "is not a polynomial surface in the plane", "give Q(x, l) with points in S's parameters");
    const Homogeneous<Rational> P = patch_from_json(tj, T.q, where, limits);
    if (P.net.dim() != 2) throw ValidationError(where + ".patch", "is not a surface", "give the tile's patch R(x, l)");
    Json part{{"candidate", i}};
    // The tile's own composition: R against T_j^e(S_i(Q)) exactly, with the candidate's Q.
    std::size_t k = ref.patches.size();
    for (std::size_t j = 0; j < ref.patches.size() && k == ref.patches.size(); ++j)
      if (ref.patches[j].outer_cell == cell && box_matches(box, ref.inner_pieces[ref.patches[j].inner_piece].box, options.precision)) k = j;
    if (k == ref.patches.size()) {
      verdict = 2;
      unpaired = true;
      rep.structure_notes.push_back(idx("tiles", i) + ": no region of the exact trimmed composition has this inner box and outer cell " +
                                    std::to_string(cell));
      part["reference"] = nullptr;
      rep.parts.push_back(part);
      continue;
    }
    part["reference"] = k;
    area_cand[k] += tile_area(t);
    if (exact_tiles && exact_tiles->tiles.size() == tiles.size()) {
      // The same tiling: tile i's region, chains and their rounding.
      const auto& et = exact_tiles->tiles[i];
      auto chain = [&](const std::vector<Rational>& c, const std::vector<Rational>& e) {
        if (c.size() != e.size()) return 2;
        int v = 0;
        for (std::size_t m = 0; m < c.size(); ++m) v = std::max(v, c[m] == e[m] ? 0 : matches(c[m], e[m], options.precision) ? 1 : 2);
        return v;
      };
      const int v = et.patch != k || t.curved() != et.tile.curved()
                        ? 2
                        : std::max({chain(t.x, et.tile.x), chain(t.yb, et.tile.yb), chain(t.yt, et.tile.yt)});
      if (v == 2) rep.structure_notes.push_back(idx("tiles", i) + ": region or chains differ from the exact tiling's tile " + std::to_string(i));
      verdict = std::max(verdict, v);
      part["tile"] = v == 0 ? "equal" : v == 1 ? "equal after rounding" : "different";
    }
    const auto& rp = ref.patches[k].patch;
    const Homogeneous<Rational> Rref{compose(rp.net, Q, co, limits), rp.weighted};
    if (P.net.degrees == Rref.net.degrees && P.net.points.size() == Rref.net.points.size() && P.weighted == Rref.weighted) {
      rep.coefficients_compared = true;
      for (std::size_t m = 0; m < Rref.net.points.size(); ++m) rep.control_points.add(Rref.net.points[m], P.net.points[m]);
    }
    try {
      FunctionError fe = patch_error(P, Rref, part_options(options), limits);
      part["function"] = fe_brief(fe);
      worst.offer(rep, std::move(fe), idx("tiles", i));
    } catch (const DomainError&) {
      verdict = 2;
      rep.structure_notes.push_back(idx("tiles", i) + ": the patch's domain is not the Coons patch's, so it is not compared");
      part["function"] = nullptr;
    }
    // Sampled: 25 points (x, l) of the tile; r = Q(x, l) in S's parameters; R(x, l) against
    // T(S(r)) with the true region of r (what the trimming tolerance does).
    // A 5 x 5 grid of the tile, its sides included: a tolerance shows at the sides.
    const Rational x0 = Q.domain_lo(0), x1 = Q.domain_hi(0);
    for (int a = 0; a < 5; ++a)
      for (int b = 0; b < 5; ++b) {
        const std::vector<Rational> xl{x0 + (x1 - x0) * Rational(a, 4), Rational(b, 4)};
        const auto r = evaluate(Q, xl);
        ++rep.points_checked;
        bool inside = true;
        for (int l = 0; l < 2; ++l) inside = inside && !(r[l] < S.domain_lo(l)) && !(S.domain_hi(l) < r[l]);
        if (!inside) {
          ++rep.points_unclaimed;  // the tile leaves S's domain: no true value there
          continue;
        }
        const auto v = patch_value(P, xl);
        if (!v) {
          ++rep.points_failed;
          continue;
        }
        add_value_error(rep, ref.evaluate(r), *v);
        // S(r) outside the tile's cell's closed box (on a knot line it belongs to both cells).
        if (ref.patches[ref.locate(r)].outer_cell != cell && !in_box(ref.outer_pieces[cell].box, evaluate(S, r)))
          ++rep.points_misassigned;
      }
    rep.parts.push_back(part);
  }
  worst.finish(rep);
  if (unpaired) rep.function.certified = false;  // an unpaired tile is not bounded
  if (exact_tiles) {
    Rational moved(0);
    for (std::size_t k = 0; k < area_ref.size(); ++k) moved += abs(Rational(area_cand[k] - area_ref[k]));
    rep.area_moved = moved;
    rep.area_compared = true;
  }
  rep.structure = verdict == 0 ? "equal" : verdict == 1 ? "equal after rounding" : "different";
  return rep;
}

}  // namespace splinex
