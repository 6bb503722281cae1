// The V-rep results as documents (vrep/io/documents.hpp), moved here from the command line
// (apps/cmd_vrep.cpp) unchanged.
#include "vrep/io/documents.hpp"

#include <chrono>

#include "float/mpfr.hpp"
#include "vrep/boolean/boolean.hpp"
#include "vrep/primitives/blend.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_euler.hpp"
#include "vrep/topology/trimmed_glue.hpp"
#include "vrep/topology/trimmed_topology.hpp"

namespace splinex::vrep {

/// A certified enclosure lo <= x <= hi into j: `exact_key` when lo == hi, else "lower" and "upper"
/// (and, with `approx`, their doubles as "approximately").
void put_enclosure(Json& j, const char* exact_key, const Rational& lo, const Rational& hi, bool approx) {
  if (lo == hi) {
    j[exact_key] = to_fraction_string(lo);
    return;
  }
  j["lower"] = to_fraction_string(lo);
  j["upper"] = to_fraction_string(hi);
  if (approx) j["approximately"] = {approx_json(to_double(lo)), approx_json(to_double(hi))};
}

/// (hi - lo) / lo as a decimal rounded up to two significant digits ("0" when exact, "unbounded"
/// when lo <= 0 < hi), exactly: never narrower than the enclosure.
std::string relative_width_text(const Rational& lo, const Rational& hi) {
  if (lo == hi) return "0";
  if (!(Rational(0) < lo)) return "unbounded";
  const Rational x = (hi - lo) / lo;
  // 10^k <= x < 10^(k+1), then m = ceil(x 10^(1-k)) in [10, 100].
  int k = 0;
  Rational p(1);
  while (!(x < p * 10)) {
    p *= 10;
    ++k;
  }
  while (x < p) {
    p /= 10;
    --k;
  }
  const Rational scaled = x * 10 / p;
  Integer m = numerator(scaled) / denominator(scaled);
  if (Rational(m) < scaled) m += 1;
  int e = k - 1;  // x <= m 10^e
  if (m == 100) {
    m = 10;
    ++e;
  }
  std::string digits = m.str();
  if (e >= 0) return digits + std::string(static_cast<std::size_t>(e), '0');
  const std::size_t point = static_cast<std::size_t>(-e);
  std::string text = digits.size() <= point ? "0." + std::string(point - digits.size(), '0') + digits
                                            : digits.substr(0, digits.size() - point) + "." + digits.substr(digits.size() - point);
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}


/// An Euler characteristic as JSON: decided or the reason, chi in the parameters and in space,
/// the interior's chi_c and whether duality holds (the only case in which chi is the regularized
/// cell's for sure).
Json euler_json(const TrimmedEuler<Rational>& e) {
  if (!e.decided) return Json{{"decided", false}, {"reason", e.undecided_reason}, {"cells_visited", e.cells}};
  return Json{{"decided", true},
              {"chi_parameters", e.chi},
              {"chi", e.image_chi},
              {"interior_chi_c", e.interior_chi_c},
              {"dual", e.duality},
              {"coplanar_contacts_read_from_inside", e.resolved_contacts},
              {"coplanar_contacts_unresolved", e.unresolved_contacts},
              {"cells_visited", e.cells},
              {"verdict", e.duality ? "exact: a 3-manifold's chi (chi_c of the open set is -chi)"
                                    : "the closed and open readings disagree: thin parts, cracks or non-manifold points; chi of the closed set only"}};
}

/// The V-curves between two trimming surfaces as JSON: per pair of leaves, arcs and loops or the
/// reason it is undecided.
Json curves_json(const TrimmedCurves<Rational>& c) {
  Json pairs = Json::array();
  for (const auto& p : c.pairs) {
    Json x{{"leaves", {p.i, p.j}}, {"decided", p.decided}};
    if (p.decided) {
      x["arcs"] = p.arcs;
      x["loops"] = p.loops;
      x["ends_on_faces"] = p.ends_on_faces;
      x["ends_at_v_points"] = p.ends_at_points;
      x["ends_on_identified_faces"] = p.ends_on_identified_faces;
      x["boxes"] = p.boxes;
      x["split_fraction"] = to_fraction_string(p.split);
    } else
      x["reason"] = p.undecided_reason;
    pairs.push_back(x);
  }
  return Json{{"decided", c.decided}, {"arcs", c.arcs}, {"loops", c.loops}, {"pairs", pairs},
              {"verdict", c.decided ? "exact: certified graph of the curves (counts in the trivariate's parameters)"
                                    : "undecided for some pair (reason given); the totals count the decided pairs only"}};
}


template <class F>
Json report_to_json(const RegularityReport<F>& r) {
  auto point = [](const std::vector<F>& x) {
    Json a = Json::array();
    for (const auto& v : x) a.push_back(ArithTraits<F>::to_json(v));
    return a;
  };
  Json j{{"verdict", regularity_name(r.verdict)}, {"reason", r.verdict.reason()}, {"levels", r.levels}, {"boxes", r.boxes}};
  if (r.verdict.is_proved()) j["sign"] = r.sign;
  if (!r.point.empty()) j["point"] = point(r.point);
  if (r.verdict.is_refuted()) {
    j["det_numerator_at_point"] = ArithTraits<F>::to_json(r.value);
    if (!r.other.empty()) {
      j["other"] = point(r.other);
      j["det_numerator_at_other"] = ArithTraits<F>::to_json(r.other_value);
    }
  }
  return j;
}

template Json report_to_json(const RegularityReport<Rational>&);
template Json report_to_json(const RegularityReport<double>&);
template Json report_to_json(const RegularityReport<Mpfr>&);

/// trimmed_glue's result as JSON (halves, twins, the V-surface counts, the time taken).
Json gluing_json(const TrimmedGluing<Rational>& G, const TrimmedModel<Rational>& M, double seconds) {
  Json halves = Json::array(), twins = Json::array();
  for (std::size_t i = 0; i < G.halves.size(); ++i) {
    const auto& h = G.halves[i];
    if (h.decided && h.internal == 0 && h.boundary == 0) continue;  // absent
    Json j{{"half", i}, {"cell", h.cell}, {"name", M.cells[h.cell].name}, {"what", h.what}, {"decided", h.decided}};
    if (h.decided) {
      j["internal_pieces"] = h.internal;
      j["boundary_pieces"] = h.boundary;
      j["unmatched_pieces"] = h.unmatched;
    } else j["reason"] = h.undecided_reason;
    halves.push_back(j);
  }
  for (const auto& t : G.twins) {
    Json j{{"halves", {t.a, t.b}}, {"how", t.how}, {"decided", t.decided}};
    if (t.decided) j["v_surfaces"] = t.pieces;
    else j["reason"] = t.undecided_reason;
    if (t.witnesses) j["witness_points"] = t.witnesses;
    twins.push_back(j);
  }
  return Json{{"decided", G.decided},
              {"half_v_surfaces", G.half_v_surfaces},
              {"part_pieces", G.part_pieces},
              {"boundary_v_surfaces", G.boundary_v_surfaces},
              {"internal_v_surfaces", G.internal_v_surfaces},
              {"v_surfaces", G.boundary_v_surfaces + G.internal_v_surfaces},
              {"internal_matched_at_witness_points", G.contacts},
              {"witness_points", G.witness_points},
              {"halves_unmatched", G.unmatched_halves},
              {"seconds", seconds},
              {"halves", halves},
              {"twins", twins},
              {"verdict", G.contacts == 0 ? "exact where decided: certified subdivision counts, twins by identity and exact face gluing"
                                          : "exact where decided, except contacts between operands: matched at witness points (checked at " +
                                                std::to_string(G.witness_points) + " points), not proved one set"}};
}

/// The V-model's summary: counts, Euler characteristic, invariants, per cell its neighbours and
/// regularity verdict (computed by the validation, vrep/model/validate.hpp), and the model's validity.
Json info_document(const VModel<Rational>& M, const ValidityReport& v) {
  Json doc = vmodel_to_json(M);
  Json cells = Json::array();
  for (std::size_t c = 0; c < M.cells.size(); ++c)
    cells.push_back({{"name", M.cells[c].name}, {"neighbours", M.neighbours_of_cell(c)}, {"regularity", report_to_json(v.regularity.at(c))}});
  const Json& t = doc["topology"];
  Json validity{{"verdict", v.verdict()}, {"decided", v.decided()}, {"cells", v.cells}, {"cell_pairs_with_overlapping_boxes", v.pairs_tested}};
  if (!v.undecided.empty()) validity["undecided"] = v.undecided;
  if (!v.not_checked.empty()) validity["not_checked"] = v.not_checked;
  if (!v.degenerate.empty()) validity["degenerate_cells"] = v.degenerate;
  return Json{{"counts", t["counts"]}, {"euler_characteristic", t["euler_characteristic"]}, {"invariants", t["invariants"]}, {"cells", cells},
              {"validity", validity}};
}

Json topology_document(const TrimmedModel<Rational>& M, const ValidityReport& validity, std::size_t boxes, bool glue,
                       const Limits& limits) {
  Json cells = Json::array();
  const char* status[] = {"curve", "collapsed", "on_trimming_surface"};
  for (std::size_t k = 0; k < M.cells.size(); ++k) {
    const auto t = trimmed_topology(M.trivariates[M.cells[k].trivariate], M.cells[k].trim, boxes, limits);
    Json edges = Json::array(), surfaces = Json::array();
    std::size_t pieces = 0, points = 0, faces = 0, trims = 0;
    for (const auto& e : t.edges) {
      Json cuts = Json::array();
      for (const auto& [lo, hi] : e.cuts) {
        Json c;
        put_enclosure(c, "exact", lo, hi, false);
        cuts.push_back(c);
      }
      edges.push_back({{"along", e.along}, {"sides", e.sides}, {"status", e.status.is_certain() ? status[e.status.make_certain("edge status")] : "undecided"}, {"v_curves", e.pieces}, {"v_points", e.points}, {"cuts", cuts}});
      pieces += e.pieces;
      points += e.points;
    }
    std::size_t face_pieces = 0, trim_pieces = 0;
    bool face_pieces_decided = true, trim_pieces_decided = true;
    for (const auto& sf : t.surfaces) {
      Json j{{"what", sf.what}, {"collapsed", sf.collapsed}, {"absent", sf.absent}, {"at_least", sf.at_least}, {"cover_components", sf.cover}};
      if (!sf.collapsed) {
        j["decided"] = sf.decided;
        if (sf.decided) {
          j["pieces"] = sf.pieces;
          j[sf.leaf < 0 ? "pieces_on_identified_edges" : "pieces_on_identified_faces"] = sf.on_identified_edges;
          (sf.leaf < 0 ? face_pieces : trim_pieces) += sf.pieces;
        } else {
          j["reason"] = sf.undecided_reason;
          (sf.leaf < 0 ? face_pieces_decided : trim_pieces_decided) = false;
        }
      }
      surfaces.push_back(j);
      (sf.leaf < 0 ? faces : trims) += sf.at_least;
    }
    Json face_curves = Json::array();
    std::size_t curves = 0, exact_curves = 0;
    bool curves_decided = true;
    for (const auto& fc : t.face_curves) {
      if (fc.absent) continue;
      Json f{{"face", {fc.dir, fc.side}}, {"leaf", fc.leaf}, {"at_least", fc.at_least}, {"cover_components", fc.cover}, {"decided", fc.decided}};
      if (fc.decided) {
        f["arcs"] = fc.arcs;
        f["loops"] = fc.loops;
        f["ends_on_edges"] = fc.ends_on_edges;
        f["ends_at_face_v_points"] = fc.ends_at_points;
        exact_curves += fc.arcs + fc.loops;
      } else {
        f["reason"] = fc.undecided_reason;
        curves_decided = false;
      }
      face_curves.push_back(f);
      curves += fc.at_least;
    }
    cells.push_back({{"cell", k},
                     {"name", M.cells[k].name},
                     {"corners", t.corners},
                     {"corners_on_trimming_surface", t.corners_on_trimming},
                     {"edge_v_curves", pieces},
                     {"edge_v_points", points},
                     {"face_half_v_surfaces_at_least", faces},
                     {"face_half_v_surfaces", face_pieces_decided ? Json(face_pieces) : Json("undecided (see surfaces)")},
                     {"trimming_half_v_surfaces_at_least", trims},
                     {"trimming_half_v_surfaces", trim_pieces_decided ? Json(trim_pieces) : Json("undecided (see surfaces)")},
                     {"edges", edges},
                     {"surfaces", surfaces},
                     {"face_curves", face_curves},
                     {"trimming_curves_on_faces_at_least", curves},
                     {"trimming_curves_on_faces", curves_decided ? Json(exact_curves) : Json("undecided (see face_curves)")},
                     {"face_v_points", t.face_points},
                     {"interior_v_points", t.interior_points},
                     {"v_points_undecided", t.points_undecided},
                     {"v_curves_between_trimming_surfaces", curves_json(trimmed_curves(M.trivariates[M.cells[k].trivariate], M.cells[k].trim, {}, limits))},
                     {"euler", euler_json(trimmed_euler(M.trivariates[M.cells[k].trivariate], M.cells[k].trim, {}, limits))}});
  }
  const Json model = euler_json(model_euler(M, {}, limits));
  Json out_doc{{"cells", cells}, {"model_euler", model}};
  if (!validity.complete()) out_doc["validity"] = validity.verdict();
  if (glue) {
    TrimmedGlueOptions go;
    go.max_boxes = std::max<std::size_t>(512, boxes);
    const auto t0 = std::chrono::steady_clock::now();
    const auto G = trimmed_glue(M, go, limits);
    out_doc["gluing"] = gluing_json(G, M, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  out_doc["note"] = std::string( "exact: corners, edge V-curves and V-points (certified roots), V-points off the edges (two trimming "
                             "surfaces meeting on a face, three inside; exact where v_points_undecided is 0, else lower bounds), the "
                             "Euler characteristic of every cell (in its trivariate's parameters and in space) and of the model (its "
                             "region), trusted where dual (the open set's chi_c is -chi); exact where decided: the pieces of the cell's part of "
                             "each face of the domain and of each trimming surface (face_half_v_surfaces, trimming_half_v_surfaces, in the "
                             "trivariate's parameters; parts touching at one point count apart); lower bounds (certified): half-V-surfaces "
                             "and the trimming surfaces' boundary curves on the faces (face_curves, present ones listed), which are also counted exactly "
                             "where decided (trimming_curves_on_faces: arcs and loops); exact where decided: "
                             "V-curves between two trimming surfaces (arcs and closed loops per pair of trimming surfaces, in the "
                             "trivariate's parameters)");
  return out_doc;
}

Json volume_document(const Operand& O, const VolumeRequest& rq, const Limits& limits) {
  const Rational rel = rq.rel_width;
  if (rel < Rational(0)) throw ValidationError("rel-width", "is negative", "give a fraction >= 0 (0: spend the whole budget)");
  // Every cell in one adaptive run (its widest boxes refined first, over all cells); with
  // --centroid the moments of x, y, z come from the same run.
  const Region<Rational> whole = region_and<Rational>({});
  std::vector<IntegrandCell<Rational>> in;
  std::vector<std::string> names;
  if (O.model)
    for (const auto& cell : O.model->cells) {
      in.push_back({&O.model->trivariates[cell.trivariates.front()], &whole, nullptr});
      names.push_back(cell.name);
    }
  else
    for (const auto& x : O.trimmed->cells) {
      in.push_back({&O.trimmed->trivariates[x.trivariate], &x.trim, nullptr});
      names.push_back(x.name);
    }
  const std::vector<int> xyz{0, 1, 2};
  // With the centroid, half the width for the volume and the moments: the quotient's
  // width is then within the target of the model's extent (checked below).
  const auto R = integral_enclosures(in, rq.centroid ? xyz : std::vector<int>{}, rq.centroid ? Rational(rel / 2) : rel,
                                     rq.boxes, limits);
  // The status is read off the widths reported, not the engine's own test.
  bool reached = R.total.upper - R.total.lower <= rel * R.total.lower;
  bool exact = R.total.upper == R.total.lower;
  Json cells = Json::array();
  for (std::size_t c = 0; c < in.size(); ++c) {
    const auto& e = R.volume[c];
    Json j{{"cell", c}, {"name", names[c]}};
    put_enclosure(j, "volume", e.lower, e.upper, false);
    if (e.lower != e.upper) {
      j["boxes"] = e.boxes;
      j["relative_width"] = relative_width_text(e.lower, e.upper);
    }
    cells.push_back(j);
  }
  const Rational lo = R.total.lower, hi = R.total.upper;
  Json out{{"cells", cells}};
  put_enclosure(out, "volume", lo, hi, true);
  Json acc{{"target", to_fraction_string(rel)}, {"boxes", R.total.boxes}, {"relative_width", relative_width_text(lo, hi)}};
  if (!O.validity.complete()) out["validity"] = O.validity.verdict();
  if (!rq.field.empty()) {
    // Per cell that has the field: its integral (exact or a certified enclosure); the
    // model's sum when every cell has it.
    std::vector<IntegrandCell<Rational>> fin;
    std::vector<std::size_t> which;
    std::vector<std::string> missing;
    auto add_field = [&](std::size_t c, const std::map<std::string, BSpline<Rational>>& fields) {
      const auto it = fields.find(rq.field);
      if (it == fields.end()) {
        missing.push_back(names[c]);
        return;
      }
      fin.push_back({in[c].trivariate, in[c].trim, &it->second});
      which.push_back(c);
    };
    for (std::size_t c = 0; c < in.size(); ++c) add_field(c, O.model ? O.model->cells[c].attributes.fields : O.trimmed->cells[c].fields);
    if (fin.empty())
      throw ValidationError("field", "\"" + rq.field + "\" is on no cell of the model", "give the name of an attribute field of its cells");
    const auto F = integral_enclosures(fin, {rq.component}, rel, rq.boxes, limits);
    const auto& fm = F.total_moment[0];
    reached = reached && fm.upper - fm.lower <= rel * F.total.lower * F.scale[0];
    exact = exact && fm.upper == fm.lower;
    Json fc = Json::array();
    for (std::size_t i = 0; i < fin.size(); ++i) {
      Json j{{"cell", which[i]}, {"name", names[which[i]]}};
      put_enclosure(j, "integral", F.moment[i][0].lower, F.moment[i][0].upper, true);
      fc.push_back(j);
    }
    Json f{{"name", rq.field}, {"component", rq.component}, {"cells", fc}};
    const auto& t = F.total_moment[0];
    if (missing.empty()) put_enclosure(f, "integral", t.lower, t.upper, true);
    else f["cells_without"] = missing;
    out["field"] = f;
    // The integral's width relative to its scale: the volume's lower bound times the
    // field component's largest |value| (of the control points).
    acc["field_relative_width"] = relative_width_text(F.total.lower * F.scale[0], F.total.lower * F.scale[0] + (t.upper - t.lower));
  }
  if (rq.centroid) {
    // The model's centroid: per coordinate the enclosure of the summed moments over the
    // enclosure of the summed volumes (one subdivision gives all).
    Json c = Json::array(), approx = Json::array();
    const Rational vl = R.total.lower, vh = R.total.upper;
    if (!(Rational(0) < vl)) throw DomainError("centroid", "needs a volume enclosure away from 0", "raise --boxes");
    Rational worst(0);
    for (int a = 0; a < 3; ++a) {
      const Rational ml = R.total_moment[a].lower, mh = R.total_moment[a].upper;
      // m / v over m in [ml, mh], v in [vl, vh], v > 0.
      const Rational lo_c = std::min(ml / vl, ml / vh), hi_c = std::max(mh / vl, mh / vh);
      if (lo_c == hi_c) c.push_back(to_fraction_string(lo_c));
      else c.push_back({to_fraction_string(lo_c), to_fraction_string(hi_c)});
      approx.push_back({to_double(lo_c), to_double(hi_c)});
      if (Rational(0) < R.scale[a]) worst = std::max(worst, Rational((hi_c - lo_c) / R.scale[a]));
    }
    out["centroid"] = c;
    out["centroid_approximately"] = approx;
    // The widest coordinate's width relative to the model's extent (its largest |coordinate|).
    acc["centroid_relative_width"] = relative_width_text(Rational(1), Rational(1) + worst);
    reached = reached && worst <= rel;
    exact = exact && worst == Rational(0);
  }
  acc["status"] = exact ? "exact"
                  : reached          ? "target reached"
                                     : "target not reached: budget of " + std::to_string(rq.boxes) + " boxes per cell (" +
                                           std::to_string(R.budget) + " in all) spent; raise --boxes or --rel-width";
  out["enclosure"] = acc;
  return out;
}

template <class F>
Json vmodel_document(const VModel<F>& M, const std::optional<Region<F>>& implicit) {
  Json doc = vmodel_to_json(M);
  if (implicit) doc["implicit"] = region_to_json(*implicit);
  return doc;
}
template Json vmodel_document(const VModel<Rational>&, const std::optional<Region<Rational>>&);
template Json vmodel_document(const VModel<double>&, const std::optional<Region<double>>&);
template Json vmodel_document(const VModel<Mpfr>&, const std::optional<Region<Mpfr>>&);

Json glued_document(const LoadedModel& r) {
  Json doc = vmodel_to_json(r.model);
  doc["topology"]["validity"] = r.validity.verdict();  // for the reader; ignored on input
  return doc;
}

Json cell_value_document(std::size_t cell, const CellValue<Rational>& r) {
  Json out{{"cell", cell}, {"point", point_to_json(r.point)}, {"coordinates", point_to_json(r.coordinates)}};
  Json f = Json::object(), c = Json::object();
  for (const auto& [n, v] : r.fields) f[n] = point_to_json(v);
  for (const auto& [n, v] : r.constants) c[n] = point_to_json(v);
  out["fields"] = f;
  out["constants"] = c;
  return out;
}

Json classify_document(const Operand& O, const std::vector<Rational>& x) {
  // Cells with planar faces: which cells contain x. Otherwise the model's exact region.
  std::optional<std::vector<std::size_t>> in_cells;
  if (O.model && planar_region(*O.model)) in_cells = cells_containing(*O.model, x);
  if (in_cells) {
    Json cells = Json::array();
    for (std::size_t c : *in_cells) cells.push_back({{"cell", c}, {"name", O.model->cells[c].name}});
    Json out{{"inside", !cells.empty()}, {"cells", cells}};
    if (!O.validity.complete()) out["validity"] = O.validity.verdict();
    return out;
  }
  if (!O.trimmed)
    throw DomainError("file", "has curved cells and no exact region (\"implicit\"): point classification needs one",
                      "build the model with vrep primitive or vrep boolean, which write it");
  const Truth t = classify_point(O.trimmed->region, x);
  Json out{{"truth", t == Truth::in ? "inside" : t == Truth::out ? "outside" : "on a surface"}};
  if (t != Truth::mixed) out["inside"] = t == Truth::in;
  else out["note"] = "x lies on the zero set of a polynomial that decides it: the boundary, or inside where two pieces touch";
  if (!O.validity.complete()) out["validity"] = O.validity.verdict();
  return out;
}

Json blend_document(const VModel<Rational>& V1, const VModel<Rational>& V2, const std::vector<Rational>& x, const std::string& attribute,
                    int k, int bits) {
  const DistanceBlend D(V1, V2);
  const bool in1 = D.in_first(x), in2 = D.in_second(x);
  std::vector<Rational> A1, A2;
  Json out{{"in_first", in1}, {"in_second", in2}};
  if (in1) out["A1"] = point_to_json(A1 = attribute_at(V1, x, attribute));
  if (in2) out["A2"] = point_to_json(A2 = attribute_at(V2, x, attribute));
  if (!in1) A1 = A2;
  if (!in2) A2 = A1;
  const auto r = D.at(x, A1, A2, k, bits);
  if (in1 && in2) {
    out["d1_squared"] = to_fraction_string(r.d1_squared);
    out["d2_squared"] = to_fraction_string(r.d2_squared);
  }
  out["singular"] = r.singular;
  if (r.singular) out["note"] = "d1 = d2 = 0: the blend is undefined here (the point r of Figure 6)";
  Json value = Json::array(), approx = Json::array();
  for (const auto& e : r.value) {
    if (e.exact()) value.push_back(to_fraction_string(e.lo));
    else value.push_back({to_fraction_string(e.lo), to_fraction_string(e.hi)});
    approx.push_back(approx_json(to_double(e.lo)));
  }
  if (!r.singular) {
    out["value"] = value;
    out["approximately"] = approx;
  }
  return out;
}

}  // namespace splinex::vrep
