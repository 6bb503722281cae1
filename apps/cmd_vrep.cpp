// splinex vrep: volumetric models of papers/002 (vrep/): trivariate constructors, primitives,
// gluing into a V-model, its topology and invariants, certified regularity per cell.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include "apps/command.hpp"
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "io/trimmed_io.hpp"
#include "io/vmodel_io.hpp"
#include "io/vtk_io.hpp"
#include "experiments/vrep_figures.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/vrep_ssi.hpp"
#include "experiments/vrep_teapot.hpp"
#include <fstream>
#include "vrep/blend.hpp"
#include "vrep/boolean.hpp"
#include "vrep/primitives.hpp"
#include "vrep/regularity.hpp"
#include "vrep/trimmed.hpp"
#include "vrep/trivariate.hpp"
#include "vrep/validate.hpp"

namespace splinex::app {

namespace {

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

}  // namespace


namespace {

struct ConstructOptions {
  std::string kind, arith = "exact", surface, first, second, faces, surfaces, vector, at, axis = "z";
  int quarters = 4, degree = 3;
};

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

BSpline<Rational> read_spline(const std::string& path, const std::string& field, const Context& ctx) {
  return spline_from_json(read_json_file(path, ctx.read_limits), ctx.limits, field);
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    out.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

Json construct(const ConstructOptions& o, const Context& ctx) {
  const auto spec = ArithSpec::parse(o.arith);
  auto need = [](const std::string& value, const std::string& field, const std::string& kind) {
    if (value.empty()) throw UsageError(field, "vrep construct " + kind + " needs --" + field, "give --" + field);
  };
  if (o.kind == "extrude") {
    need(o.surface, "surface", o.kind);
    need(o.vector, "vector", o.kind);
    const auto S = read_spline(o.surface, "surface", ctx);
    const auto V = parse_number_list(o.vector, "vector");
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      std::vector<F> v;
      for (const auto& x : V) v.push_back(round_checked<F>(x, "vector"));
      return spline_to_json(extrude(round_spline<F>(S, "surface"), v, ctx.limits));
    });
  }
  if (o.kind == "ruled") {
    need(o.first, "first", o.kind);
    need(o.second, "second", o.kind);
    const auto A = read_spline(o.first, "first", ctx), B = read_spline(o.second, "second", ctx);
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return spline_to_json(ruled(round_spline<F>(A, "first"), round_spline<F>(B, "second"), ctx.limits));
    });
  }
  if (o.kind == "revolve") {
    need(o.surface, "surface", o.kind);
    const auto S = read_spline(o.surface, "surface", ctx);
    const int axis = o.axis == "x" ? 0 : o.axis == "y" ? 1 : 2;
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return spline_to_json(revolve(round_spline<F>(S, "surface"), axis, o.quarters, ctx.limits));
    });
  }
  if (o.kind == "boolean-sum") {
    need(o.faces, "faces", o.kind);
    const auto files = split_list(o.faces);
    if (files.size() != 6)
      throw UsageError("faces", "needs six files, got " + std::to_string(files.size()), "give --faces u0,u1,v0,v1,w0,w1");
    const char* names[6] = {"u0", "u1", "v0", "v1", "w0", "w1"};
    std::array<std::array<BSpline<Rational>, 2>, 3> F;
    for (int k = 0; k < 6; ++k) F[k / 2][k % 2] = read_spline(files[k], names[k], ctx);
    return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
      using T = typename decltype(tag)::type;
      std::array<std::array<BSpline<T>, 2>, 3> G;
      for (int k = 0; k < 6; ++k) G[k / 2][k % 2] = round_spline<T>(F[k / 2][k % 2], names[k]);
      return spline_to_json(boolean_sum(G, ctx.limits));
    });
  }
  // sweep
  need(o.surfaces, "surfaces", o.kind);
  need(o.at, "at", o.kind);
  std::vector<BSpline<Rational>> S;
  const auto files = split_list(o.surfaces);
  for (std::size_t k = 0; k < files.size(); ++k) S.push_back(read_spline(files[k], "surfaces[" + std::to_string(k) + "]", ctx));
  const auto at = parse_number_list(o.at, "at");
  return with_arith_except_flint(spec, "vrep construct", [&](auto tag) {
    using F = typename decltype(tag)::type;
    std::vector<BSpline<F>> s;
    for (std::size_t k = 0; k < S.size(); ++k) s.push_back(round_spline<F>(S[k], "surfaces[" + std::to_string(k) + "]"));
    std::vector<F> w;
    for (const auto& x : at) w.push_back(round_checked<F>(x, "at"));
    return spline_to_json(sweep(s, w, o.degree, ctx.limits));
  });
}

template <class F>
Json report_to_json(const RegularityReport<F>& r) {
  auto point = [](const std::vector<F>& x) {
    Json a = Json::array();
    for (const auto& v : x) a.push_back(ArithTraits<F>::to_json(v));
    return a;
  };
  Json j{{"verdict", to_string(r.verdict)}, {"reason", r.reason}, {"levels", r.levels}, {"boxes", r.boxes}};
  if (r.verdict == Regularity::regular) j["sign"] = r.sign;
  if (!r.point.empty()) j["point"] = point(r.point);
  if (r.verdict == Regularity::singular) {
    j["det_numerator_at_point"] = ArithTraits<F>::to_json(r.value);
    if (!r.other.empty()) {
      j["other"] = point(r.other);
      j["det_numerator_at_other"] = ArithTraits<F>::to_json(r.other_value);
    }
  }
  return j;
}

struct PrimitiveOptions {
  std::string name, arith = "exact", radius = "1", radius2 = "1/2", height = "2", major = "3", lo = "0,0,0", hi = "1,1,1", axis = "z",
              at = "0,0,0";
  int degree = 3, pieces = 4;
};

/// A primitive's cells and its exact region (vrep/trimmed.hpp) where it has one: the sphere of
/// seven cells has its piecewise one for patches of degree <= 4 (sphere_region: leaves of degree
/// 2 degree <= 8) and at most 11 pieces, in exact arithmetic; the singular trivariates are not
/// offered for Booleans.
template <class F>
struct Primitive {
  std::vector<BSpline<F>> cells;
  std::optional<Region<F>> region;
};

template <class F>
Primitive<F> primitive_cells(const PrimitiveOptions& o) {
  auto num = [](const std::string& text, const std::string& field) { return round_checked<F>(parse_number(text, field), field); };
  auto list = [](const std::string& text, const std::string& field) {
    std::vector<F> v;
    for (const auto& x : parse_number_list(text, field)) v.push_back(round_checked<F>(x, field));
    return v;
  };
  if (o.name == "cylinder") return {cylinder_cells(num(o.radius, "radius"), num(o.height, "height")), cylinder_region(num(o.radius, "radius"), num(o.height, "height"))};
  if (o.name == "cone")
    return {cone_cells(num(o.radius, "radius"), num(o.radius2, "radius2"), num(o.height, "height")),
            cone_region(num(o.radius, "radius"), num(o.radius2, "radius2"), num(o.height, "height"))};
  if (o.name == "torus") return {torus_cells(num(o.major, "major"), num(o.radius, "radius")), torus_region(num(o.major, "major"), num(o.radius, "radius"))};
  if (o.name == "box") return {box_cells(list(o.lo, "lo"), list(o.hi, "hi")), box_region(list(o.lo, "lo"), list(o.hi, "hi"))};
  if (o.name == "sphere") {
    auto cells = sphere_cells(num(o.radius, "radius"), o.degree, o.pieces);  // checks degree and pieces
    // In floating point the rounded region would not describe the rounded cells exactly; above 11
    // pieces its 30 pieces^2 + 6 leaves pass the documents' 4096.
    if (o.degree > 4 || o.pieces > 11 || !ArithTraits<F>::exact) return {std::move(cells), std::nullopt};
    return {std::move(cells), sphere_region(num(o.radius, "radius"), o.degree, o.pieces)};
  }
  if (o.name == "singular-cylinder") return {{singular_cylinder(num(o.radius, "radius"), num(o.height, "height"))}, std::nullopt};
  return {{singular_sphere(num(o.radius, "radius"))}, std::nullopt};
}

/// trimmed_glue's result as JSON (halves, twins, the V-surface counts, the time taken).
template <class T>
Json gluing_json(const TrimmedGluing<T>& G, const TrimmedModel<T>& M, double seconds) {
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
/// regularity verdict (computed by the validation, vrep/validate.hpp), and the model's validity.
Json info_of(const VModel<Rational>& M, const ValidityReport& v) {
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

}  // namespace

Commands add_vrep(CLI::App& app) {
  auto* v = app.add_subcommand("vrep", "volumetric models (papers/002): trivariate constructors, certified regularity");
  v->require_subcommand(1);
  auto o = std::make_shared<ConstructOptions>();
  auto* c = v->add_subcommand("construct", "a trivariate from surfaces: extrude, ruled, revolve, boolean-sum or sweep");
  c->add_option("kind", o->kind, "extrude, ruled, revolve, boolean-sum or sweep")
      ->required()
      ->check(CLI::IsMember({"extrude", "ruled", "revolve", "boolean-sum", "sweep"}));
  add_arith_option(c, o->arith, "exact (GMP), double or mpfr:BITS");
  c->add_option("--surface", o->surface, "extrude, revolve: the surface document (points in R^3, attributes after)");
  c->add_option("--vector", o->vector, "extrude: the vector V, comma-separated (one entry per point coordinate)");
  c->add_option("--first", o->first, "ruled: the surface at w = 0");
  c->add_option("--second", o->second, "ruled: the surface at w = 1");
  c->add_option("--axis", o->axis, "revolve: the coordinate axis")->check(CLI::IsMember({"x", "y", "z"}))->capture_default_str();
  c->add_option("--quarters", o->quarters, "revolve: the angle in quarter turns (exact rational circle arcs)")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  c->add_option("--faces", o->faces, "boolean-sum: six surface files u0,u1,v0,v1,w0,w1 (u faces in (v, w), v faces in (u, w), "
                                     "w faces in (u, v))");
  c->add_option("--surfaces", o->surfaces, "sweep: the surface files S_0,...,S_m");
  c->add_option("--at", o->at, "sweep: the parameters w_0 < ... < w_m, comma-separated");
  c->add_option("--degree", o->degree, "sweep: the degree in w (at most m)")->check(CLI::Range(1, 64))->capture_default_str();

  struct CertifyOptions {
    std::string arith = "exact", file;
    int levels = 6;
  };
  auto co = std::make_shared<CertifyOptions>();
  auto* cert = v->add_subcommand("certify", "certified regularity of a trivariate: the sign of det J from exact Bernstein coefficients");
  add_arith_option(cert, co->arith, "exact (GMP) decides exactly; double or mpfr:BITS run the same test in floats");
  cert->add_option("file", co->file, "the trivariate document")->required();
  cert->add_option("--levels", co->levels, "subdivision levels before \"undecided\"")->check(CLI::Range(0, 12))->capture_default_str();
  auto po = std::make_shared<PrimitiveOptions>();
  auto* prim = v->add_subcommand("primitive", "a glued primitive V-model (Figure 9) or a singular single trivariate (Figure 8)");
  prim->add_option("name", po->name, "cylinder, cone, torus (five cells each), sphere (seven), box, singular-cylinder, singular-sphere")
      ->required()
      ->check(CLI::IsMember({"cylinder", "cone", "torus", "sphere", "box", "singular-cylinder", "singular-sphere"}));
  add_arith_option(prim, po->arith, "exact (GMP), double or mpfr:BITS");
  prim->add_option("--radius", po->radius, "radius (torus: the tube's)")->capture_default_str();
  prim->add_option("--radius2", po->radius2, "cone: the top radius")->capture_default_str();
  prim->add_option("--height", po->height, "cylinder, cone: the height")->capture_default_str();
  prim->add_option("--major", po->major, "torus: the distance of the tube's centre from the axis")->capture_default_str();
  prim->add_option("--degree", po->degree, "sphere: the patches' degree (radius approximate, direction exact; docs/vrep.md)")
      ->capture_default_str();
  prim->add_option("--pieces", po->pieces, "sphere: the patches' polynomial pieces per direction")->capture_default_str();
  prim->add_option("--lo", po->lo, "box: the low corner x,y,z")->capture_default_str();
  prim->add_option("--hi", po->hi, "box: the high corner x,y,z")->capture_default_str();
  prim->add_option("--axis", po->axis, "the primitive's axis (z: as built; x, y: the coordinates permuted cyclically)")
      ->check(CLI::IsMember({"x", "y", "z"}))
      ->capture_default_str();
  prim->add_option("--at", po->at, "a translation x,y,z applied after --axis")->capture_default_str();

  struct GlueOptions {
    std::vector<std::string> files;
    std::string eps;
    int levels = 6;
  };
  auto go = std::make_shared<GlueOptions>();
  auto* glue_cmd = v->add_subcommand("glue", "glue trivariates and V-models into one V-model (exact; --eps: in double, IRIT's test)");
  glue_cmd->add_option("files", go->files, "trivariate or V-model documents")->required();
  glue_cmd->add_option("--eps", go->eps, "glue in double with control points equal within eps (default: exact)");
  auto io = std::make_shared<GlueOptions>();
  auto* info = v->add_subcommand("info", "counts, Euler characteristic, invariants, neighbours and regularity per cell");
  info->add_option("files", io->files, "a V-model document (or trivariates, glued exactly)")->required();
  info->add_option("--levels", io->levels, "subdivision levels of the regularity test")->check(CLI::Range(0, 12))->capture_default_str();

  struct ExportOptions {
    std::vector<std::string> files;
    std::string vtk, svg;
    double explode = 0.35;
    bool singular = false;
  };
  auto eo = std::make_shared<ExportOptions>();
  auto* exp = v->add_subcommand("export", "the V-model for ParaView: Bezier hexahedra (VTK cell type 79, rational weights)");
  exp->add_option("files", eo->files, "a V-model document (or trivariates, glued exactly)")->required();
  exp->add_option("--vtk", eo->vtk, "the .vtu file to write (Bezier hexahedra for ParaView)")->check(output_file());
  exp->add_option("--svg", eo->svg, "an SVG figure: the cells exploded, flat-shaded")->check(output_file());
  exp->add_option("--explode", eo->explode, "--svg: how far cells move apart (0: not at all)")->check(CLI::Range(0.0, 5.0))->capture_default_str();
  exp->add_flag("--mark-singular", eo->singular, "--svg: mark sampled boundary points where det J = 0 exactly");

  struct EvalOptions {
    std::string file, at;
    std::size_t cell = 0;
  };
  auto vo = std::make_shared<EvalOptions>();
  auto* ev = v->add_subcommand("eval", "geometry and attributes of a cell at a parameter point, exactly");
  ev->add_option("file", vo->file, "a V-model document")->required();
  ev->add_option("--cell", vo->cell, "the cell (0-based)")->capture_default_str();
  ev->add_option("--at", vo->at, "the parameter point u,v,w")->required();

  struct BooleanOptions {
    std::string op, a, b, eps, blend = "sum-clipped", at, trim = "auto";
    std::size_t boxes = 256;
    bool centroid = false;
    std::string field;
    int component = 0;
    std::string rel_width = "1/100";
  };
  auto bo = std::make_shared<BooleanOptions>();
  bo->boxes = 4096;
  auto* boo = v->add_subcommand("boolean", "V-model Booleans (papers/002 Algorithms 1-3): cells cut exactly along parameter planes, or trimmed on exact regions");
  boo->add_option("operation", bo->op, "intersect, subtract or union")->required()->check(CLI::IsMember({"intersect", "subtract", "union"}));
  boo->add_option("first", bo->a, "the V-model A (or a trivariate)")->required();
  boo->add_option("second", bo->b, "the V-model B (or a trivariate)")->required();
  boo->add_option("--eps", bo->eps, "run in double with IRIT-style tolerance eps (default: exact); trimmed cells too");
  boo->add_option("--blend", bo->blend, "constants of cells in both models: sum-clipped (Figure 5), sum or first")
      ->check(CLI::IsMember({"sum-clipped", "sum", "first"}))
      ->capture_default_str();
  boo->add_option("--trim", bo->trim, "auto: planar cuts where they suffice, else trimmed cells on the models' exact regions; "
                                      "always: trimmed cells; never: planar cuts only")
      ->check(CLI::IsMember({"auto", "always", "never"}))
      ->capture_default_str();
  boo->add_option("--boxes", bo->boxes, "trimmed cells: the subdivision budget per cell before a contact counts as tangential")
      ->check(CLI::Range(8, 1 << 20))
      ->capture_default_str();
  auto volo = std::make_shared<BooleanOptions>();
  auto* vol = v->add_subcommand("volume", "every cell's volume and the model's: exact (polynomial cells) or a certified enclosure (rational)");
  vol->add_option("file", volo->a, "a V-model document")->required();
  vol->add_flag("--centroid", volo->centroid, "also the model's centroid: exact (polynomial cells, no curved cut) or a certified enclosure per coordinate");
  volo->boxes = 500;
  vol->add_option("--rel-width", volo->rel_width,
                  "rational or cut cells: refine adaptively until the enclosure's width is at most this fraction of its lower bound "
                  "(moments, field integrals: of the volume times the largest |coordinate| or |field value|), or the budget is spent; "
                  "0: spend the budget")
      ->capture_default_str();
  vol->add_option("--boxes", volo->boxes, "the subdivision budget: boxes per cell (in all: this times the cells), spent where the enclosure is widest")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  vol->add_option("--field", volo->field, "also the integral of this attribute field over every cell that has it (F det J over the trimmed domain)");
  vol->add_option("--component", volo->component, "the field's component to integrate (0-based)")->check(CLI::Range(0, 1 << 20))->capture_default_str();
  auto clo = std::make_shared<BooleanOptions>();
  auto* cls = v->add_subcommand("classify", "which cells contain a point (exact: planar cells; otherwise the model's exact region)");
  cls->add_option("file", clo->a, "a V-model document")->required();
  cls->add_option("--at", clo->at, "the point x,y,z")->required();

  auto read_cells = [](const std::vector<std::string>& files, const Context& ctx) {
    VModelCells all;
    for (std::size_t f = 0; f < files.size(); ++f)
      append_cells(all, vmodel_cells_from_json(read_json_file(files[f], ctx.read_limits), ctx.limits, files.size() == 1 ? "vmodel" : files[f]));
    return all;
  };
  // The exact V-model of documents: glued, with their attributes; an "implicit" region is checked
  // against the cells (vrep/trimmed.hpp: check_region) and refused when it does not describe them;
  // then validated (vrep/validate.hpp: a proved defect is a typed error naming the cells).
  struct ReadModel {
    VModel<Rational> model;
    std::optional<Region<Rational>> region;
    ValidityReport validity;
  };
  auto model_of = [](const VModelCells& all, const Context& ctx, int levels) {
    auto M = glue(all.trivariates, Rational(0), all.names, ctx.limits);
    apply_attributes(M, all, ctx.limits);
    if (all.region) {
      const auto fails = check_region(M, *all.region, TrimOptions{}, ctx.limits);
      if (!fails.empty())
        throw ValidationError("vmodel.implicit", "does not describe the cells: " + fails.front() + (fails.size() > 1 ? " (and " + std::to_string(fails.size() - 1) + " more)" : ""),
                              "remove \"implicit\" or give the model's exact region");
    }
    ValidityOptions vo;
    vo.levels = levels;
    auto validity = validate_vmodel(M, "vmodel", vo, ctx.limits);
    return ReadModel{std::move(M), all.region, std::move(validity)};
  };
  auto read_model = [read_cells, model_of](const std::vector<std::string>& files, const Context& ctx, int levels = 6) {
    return model_of(read_cells(files, ctx), ctx, levels);
  };
  auto exact_model = [read_model](const std::vector<std::string>& files, const Context& ctx) { return read_model(files, ctx).model; };
  // A Boolean operand: a trimmed V-model document as it is, a V-model with its region ("implicit",
  // or the half-spaces of convex planar cells), or the V-model alone (no region: planar cuts only).
  struct Operand {
    std::optional<VModel<Rational>> model;
    std::optional<TrimmedModel<Rational>> trimmed;
    ValidityReport validity;
  };
  auto operand = [model_of](const std::string& file, const Context& ctx) {
    Operand o;
    const Json doc = read_json_file(file, ctx.read_limits);
    if (doc.is_object() && doc.contains("type") && doc["type"] == "trimmed_vmodel") {
      o.trimmed = trimmed_from_json(doc, ctx.limits, file);
      o.validity = validate_trimmed(*o.trimmed, file, {}, ctx.limits);
      return o;
    }
    auto r = model_of(vmodel_cells_from_json(doc, ctx.limits, "vmodel"), ctx, 6);
    if (!r.region) r.region = planar_region(r.model);
    if (r.region) o.trimmed = as_trimmed(r.model, *r.region);
    o.model = std::move(r.model);
    o.validity = std::move(r.validity);
    return o;
  };
  struct TopologyCli {
    std::string file;
    std::size_t boxes = 1024;
    bool glue = false;
  };
  auto tco = std::make_shared<TopologyCli>();
  auto* topo = v->add_subcommand("topology", "the boundary structure of a trimmed V-model's cells: exact V-curves and V-points on the trivariates' "
                                             "edges, V-curves between trimming surfaces, half-V-surfaces (exact where decided), Euler characteristic");
  topo->add_option("file", tco->file, "a trimmed V-model document (the output of vrep boolean with trimmed cells)")->required();
  topo->add_option("--boxes", tco->boxes, "subdivision boxes per cell (the faces get an eighth each)")->check(CLI::Range(8, 1000000))->capture_default_str();
  topo->add_flag("--glue", tco->glue, "also glue the cells into one V-model: internal and boundary pieces of every half-V-surface, their twins, "
                                      "the V-surface counts (trimmed_glue)");
  struct TeapotCli {
    std::string arith = "exact", svg, vtk;
    std::size_t boxes = 4096;
  };
  auto tpo = std::make_shared<TeapotCli>();
  auto* tp = v->add_subcommand("teapot", "the teapot's V-model (Figure 14): body shell, handle and spout trimmed by each other and the cavity, "
                                         "from trivariates without an implicit form (certified in exact arithmetic)");
  tp->add_option("--arith", tpo->arith, "exact (certified) or double")->check(CLI::IsMember({"exact", "double"}))->capture_default_str();
  tp->add_option("--boxes", tpo->boxes, "subdivision boxes per cell")->check(CLI::Range(1, 1000000))->capture_default_str();
  tp->add_option("--svg", tpo->svg, "write an exploded view (exact run only) to this SVG file")->check(output_file());
  tp->add_option("--vtk", tpo->vtk, "write the cells' boxes as hexahedra (legacy VTK, exact run only) to this file")->check(output_file());
  struct SsiCli {
    std::string a, b, step = "1/16", tolerance = "1e-12", svg, obj;
    int grid = 48;
    bool judge = false;
  };
  auto so = std::make_shared<SsiCli>();
  auto* ssi = v->add_subcommand("ssi", "surface-surface intersection in double (seeds + marching), every point judged exactly with --judge");
  ssi->add_option("first", so->a, "a surface document, or teapot:body|handle|spout|lid")->required();
  ssi->add_option("second", so->b, "a surface document, or teapot:body|handle|spout|lid")->required();
  ssi->add_option("--step", so->step, "the marching chord in model units")->capture_default_str();
  ssi->add_option("--tolerance", so->tolerance, "Newton stops at |S1 - S2| <= tolerance")->capture_default_str();
  ssi->add_option("--grid", so->grid, "seed cells per direction of each surface")->check(CLI::Range(1, 128))->capture_default_str();
  ssi->add_flag("--judge", so->judge, "judge every point and segment midpoint exactly: gap |S1 - S2| and a Krawczyk certificate of the true intersection nearby");
  ssi->add_option("--svg", so->svg, "write the branches in both parameter planes to this SVG file")->check(output_file());
  ssi->add_option("--obj", so->obj, "write the branches as 3D polylines to this OBJ file")->check(output_file());
  struct BlendCli {
    std::string a, b, at, attribute;
    int k = 1, bits = 128;
  };
  auto blo = std::make_shared<BlendCli>();
  auto* bl = v->add_subcommand("blend", "Eq. 2's distance blend of an attribute of two models at a point of their union (certified enclosure)");
  bl->add_option("first", blo->a, "the V-model V1 (convex cells with planar faces)")->required();
  bl->add_option("second", blo->b, "the V-model V2 (convex cells with planar faces)")->required();
  bl->add_option("--at", blo->at, "the point x,y,z")->required();
  bl->add_option("--attribute", blo->attribute, "a constant or a field (on affine cells) both models carry")->required();
  bl->add_option("--k", blo->k, "the blend's order: d^k weights (1: Eq. 2)")->check(CLI::Range(1, 64))->capture_default_str();
  bl->add_option("--bits", blo->bits, "the MPFI enclosure's precision")->check(CLI::Range(16, 100000))->capture_default_str();
  auto teapot_json = [](const auto& M) {
    using T = std::decay_t<decltype(M.cells.front().cell.volume.lower)>;
    auto row = [](const auto& r) {
      Json v;
      if constexpr (std::is_same_v<T, Rational>) put_enclosure(v, "exact", r.cell.volume.lower, r.cell.volume.upper, true);
      else v = {{"lower", r.cell.volume.lower}, {"upper", r.cell.volume.upper}};
      std::size_t pieces = 0, points = 0, undecided = 0, collapsed = 0;
      for (const auto& e : r.edges.edges) {
        pieces += e.pieces;
        points += e.points;
        undecided += e.status == std::decay_t<decltype(e)>::undecided;
        collapsed += e.status == std::decay_t<decltype(e)>::collapsed;
      }
      return Json{{"name", r.name},
                  {"edges", {{"corners", r.edges.corners}, {"corners_undecided", r.edges.corners_undecided}, {"v_curves", pieces}, {"v_points", points},
                             {"undecided", undecided}, {"collapsed", collapsed}}},
                  {"trivariate", r.trivariate},
                  {"conditions", r.conditions},
                  {"kind", to_string<T>(r.cell.cls.kind)},
                  {"components_at_least", r.cell.components},
                  {"cover_components", r.cell.cover_components},
                  {"volume", v},
                  {"boxes", r.cell.cls.boxes},
                  {"boxes_near_trimming", r.cell.cls.mixed},
                  {"point_queries", r.cell.queries},
                  {"seconds", r.seconds}};
    };
    Json cells = Json::array(), removed = Json::array();
    std::size_t vcells = 0;
    for (const auto& r : M.cells) {
      cells.push_back(row(r));
      vcells += r.cell.components;
    }
    for (const auto& r : M.removed) removed.push_back(row(r));
    return Json{{"cells", cells},
                {"removed_by_subtraction", removed},
                {"v_cells_at_least", vcells},
                {"seconds", M.seconds},
                {"certified", std::is_same_v<T, Rational>},
                {"note", std::is_same_v<T, Rational>
                             ? "kinds, volume enclosures and the lower bounds on components are certified; (body + handle + spout) - cavity"
                             : "double: the same steps in floats, nothing certified; (body + handle + spout) - cavity"}};
  };
  return {{topo, [tco](const Context& ctx) {
             const Json doc = read_json_file(tco->file, ctx.read_limits);
             if (!doc.is_object() || !doc.contains("type") || doc["type"] != "trimmed_vmodel")
               throw ValidationError(tco->file, "is not a trimmed V-model document (type \"trimmed_vmodel\")",
                                     "give the output of vrep boolean with trimmed cells; a V-model's own topology is in vrep info");
             const auto M = trimmed_from_json(doc, ctx.limits, tco->file);
             const auto validity = validate_trimmed(M, tco->file, {}, ctx.limits);
             Json cells = Json::array();
             const char* status[] = {"curve", "collapsed", "on_trimming_surface", "undecided"};
             for (std::size_t k = 0; k < M.cells.size(); ++k) {
               const auto t = trimmed_topology(M.trivariates[M.cells[k].trivariate], M.cells[k].trim, tco->boxes, ctx.limits);
               Json edges = Json::array(), surfaces = Json::array();
               std::size_t pieces = 0, points = 0, faces = 0, trims = 0;
               for (const auto& e : t.edges) {
                 Json cuts = Json::array();
                 for (const auto& [lo, hi] : e.cuts) {
                   Json c;
                   put_enclosure(c, "exact", lo, hi, false);
                   cuts.push_back(c);
                 }
                 edges.push_back({{"along", e.along}, {"sides", e.sides}, {"status", status[e.status]}, {"v_curves", e.pieces}, {"v_points", e.points}, {"cuts", cuts}});
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
                                {"v_curves_between_trimming_surfaces", curves_json(trimmed_curves(M.trivariates[M.cells[k].trivariate], M.cells[k].trim, {}, ctx.limits))},
                                {"euler", euler_json(trimmed_euler(M.trivariates[M.cells[k].trivariate], M.cells[k].trim, {}, ctx.limits))}});
             }
             const Json model = euler_json(model_euler(M, {}, ctx.limits));
             Json out_doc{{"cells", cells}, {"model_euler", model}};
             if (!validity.complete()) out_doc["validity"] = validity.verdict();
             if (tco->glue) {
               TrimmedGlueOptions go;
               go.max_boxes = std::max<std::size_t>(512, tco->boxes);
               const auto t0 = std::chrono::steady_clock::now();
               const auto G = trimmed_glue(M, go, ctx.limits);
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
             std::cout << out_doc.dump() << "\n";
             return 0;
           }},
          {tp, [tpo, teapot_json](const Context&) {
             auto progress = [](const std::string& line) { std::cerr << "[vrep teapot] " << line << "\n"; };
             if (tpo->arith == "double") {
               if (!tpo->svg.empty() || !tpo->vtk.empty())
                 throw UsageError("svg", "figures are drawn from the exact run", "drop --svg/--vtk or use --arith exact");
               std::cout << teapot_json(teapot_vmodel<double>(tpo->boxes, progress)).dump() << "\n";
               return 0;
             }
             const auto M = teapot_vmodel<Rational>(tpo->boxes, progress);
             if (!tpo->svg.empty()) write_file_atomically(tpo->svg, teapot_vmodel_svg(M));
             if (!tpo->vtk.empty()) write_file_atomically(tpo->vtk, teapot_vmodel_vtk(M));
             std::cout << teapot_json(M).dump() << "\n";
             return 0;
           }},
          {bl, [blo, exact_model](const Context& ctx) {
             const auto V1 = exact_model({blo->a}, ctx), V2 = exact_model({blo->b}, ctx);
             const auto x = parse_number_list(blo->at, "at");
             if (x.size() != 3) throw UsageError("at", "needs three coordinates", "give --at x,y,z");
             const DistanceBlend D(V1, V2);
             const bool in1 = D.in_first(x), in2 = D.in_second(x);
             std::vector<Rational> A1, A2;
             Json out{{"in_first", in1}, {"in_second", in2}};
             auto strings = [](const std::vector<Rational>& v) {
               Json j = Json::array();
               for (const auto& y : v) j.push_back(to_fraction_string(y));
               return j;
             };
             if (in1) out["A1"] = strings(A1 = attribute_at(V1, x, blo->attribute));
             if (in2) out["A2"] = strings(A2 = attribute_at(V2, x, blo->attribute));
             if (!in1) A1 = A2;
             if (!in2) A2 = A1;
             const auto r = D.at(x, A1, A2, blo->k, blo->bits);
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
             std::cout << out.dump() << "\n";
             return 0;
           }},
          {ssi, [so](const Context& ctx) {
             const auto S1 = read_surface_argument(so->a, "first", ctx), S2 = read_surface_argument(so->b, "second", ctx);
             SsiOptions opt;
             opt.step = to_double(parse_number(so->step, "step"));
             opt.tolerance = to_double(parse_number(so->tolerance, "tolerance"));
             opt.grid = so->grid;
             auto progress = [](const std::string& line) { std::cerr << "[vrep ssi] " << line << "\n"; };
             const auto st = ssi_study(S1, S2, opt, so->judge, progress);
             Json branches = Json::array();
             for (const auto& b : st.result.branches) {
               Json pts = Json::array();
               for (const auto& x : b.points) pts.push_back({x[0], x[1], x[2], x[3]});
               branches.push_back({{"closed", b.closed}, {"ends_meet", b.ends_meet}, {"tangential_stop", b.tangential_stop}, {"points", pts}});
             }
             Json out{{"branches", branches},
                      {"candidates", st.result.candidates},
                      {"seeds", st.result.seeds},
                      {"newton_failures", st.result.newton_failures},
                      {"starts_skipped", st.result.skipped},
                      {"loops_in_space", loops_in_space(S1, st.result, opt.step / 4)},
                      {"seconds", st.seconds_float},
                      {"note", "computed in double on the surfaces rounded to double; points are (u, v, s, t)"}};
             std::size_t tangential = 0;
             for (const auto& b : st.result.branches) tangential += b.tangential_stop;
             if (tangential > 0)
               out["warning"] = std::to_string(tangential) + " branches stopped where the normals are parallel: tangential contact or surfaces "
                                "that coincide over a region, where the intersection is not a curve and this method does not apply";
             if (so->judge)
               out["judged"] = {{"vertices", st.vertices},
                                {"vertices_certified", st.vertices_certified},
                                {"midpoints", st.midpoints},
                                {"midpoints_certified", st.midpoints_certified},
                                {"max_vertex_gap_at_most", st.max_vertex_gap},
                                {"max_vertex_distance_at_most", st.max_vertex_distance},
                                {"max_midpoint_gap_at_most", st.max_mid_gap},
                                {"max_midpoint_distance_at_most", st.max_mid_distance},
                                {"uncertified", st.uncertified},
                                {"seconds", st.seconds_judge},
                                {"meaning", "gap: |S1(u,v) - S2(s,t)| exactly (rounded up); distance: certified bound of |S1(u,v) - q| for the "
                                            "unique true intersection point q Krawczyk proves in a box about the point (certified points only)"}};
             if (!so->svg.empty()) write_file_atomically(so->svg, ssi_svg(S1, S2, st.result, so->a, so->b, "vrep ssi: " + so->a + " and " + so->b));
             if (!so->obj.empty()) write_file_atomically(so->obj, ssi_obj(S1, st.result));
             std::cout << out.dump() << "\n";
             return 0;
           }},
          {c, [o](const Context& ctx) {
             std::cout << construct(*o, ctx).dump() << "\n";
             return 0;
           }},
          {prim, [po](const Context& ctx) {
             const auto spec = ArithSpec::parse(po->arith);
             const Json j = with_arith_except_flint(spec, "vrep primitive", [&](auto tag) {
               using F = typename decltype(tag)::type;
               const int axis = po->axis == "x" ? 0 : po->axis == "y" ? 1 : 2;
               std::vector<F> at;
               for (const auto& x : parse_number_list(po->at, "at")) at.push_back(round_checked<F>(x, "at"));
               if (at.size() != 3) throw UsageError("at", "needs three coordinates", "give --at x,y,z");
               auto [cells, region] = primitive_cells<F>(*po);
               for (auto& V : cells) V = place_trivariate(V, axis, at);
               std::vector<std::string> names;
               for (std::size_t k = 0; k < cells.size(); ++k) names.push_back(po->name + " " + std::to_string(k));
               Json doc = vmodel_to_json(glue(cells, F(0), names, ctx.limits));
               if (region) doc["implicit"] = region_to_json(place_region(*region, axis, at));
               return doc;
             });
             std::cout << j.dump() << "\n";
             return 0;
           }},
          {glue_cmd, [go, read_cells, read_model](const Context& ctx) {
             if (go->eps.empty()) {
               const auto r = read_model(go->files, ctx);
               Json doc = vmodel_to_json(r.model);
               doc["topology"]["validity"] = r.validity.verdict();  // for the reader; ignored on input
               std::cout << doc.dump() << "\n";
               return 0;
             }
             const auto all = read_cells(go->files, ctx);
             validate_cells(all.trivariates, all.names, "vmodel", {}, ctx.limits);  // the exact cells, before rounding
             const double eps = to_double(parse_number(go->eps, "eps"));
             if (!(eps > 0) || !std::isfinite(eps)) throw UsageError("eps", "must be a positive double", "give e.g. --eps 1e-9");
             std::vector<BSpline<double>> d;
             for (std::size_t k = 0; k < all.trivariates.size(); ++k) d.push_back(round_spline<double>(all.trivariates[k], all.names[k]));
             std::cout << vmodel_to_json(glue(d, eps, all.names, ctx.limits)).dump() << "\n";
             return 0;
           }},
          {exp, [eo, read_model, operand](const Context& ctx) {
             if (eo->vtk.empty() && eo->svg.empty()) throw UsageError("vtk", "vrep export needs --vtk or --svg", "give --vtk FILE.vtu or --svg FILE.svg");
             std::optional<Operand> O;
             if (eo->files.size() == 1) O = operand(eo->files.front(), ctx);
             std::optional<VModel<Rational>> glued;
             ValidityReport validity;
             if (O) validity = O->validity;
             else {
               auto r = read_model(eo->files, ctx);
               glued = std::move(r.model);
               validity = std::move(r.validity);
             }
             auto write = [&validity](const std::string& path, const std::string& field, const std::string& text) {
               std::ofstream out(path);
               if (!out) throw UsageError(field, "cannot write " + path, "give a writable file path");
               out << text;
               if (!out) throw UsageError(field, "writing " + path + " failed", "check the disk space and the path");
               std::cerr << "splinex vrep export: wrote " << path << (validity.complete() ? std::string() : " (model validity " + validity.verdict() + ")") << "\n";
             };
             if (O && !O->model) {  // a trimmed V-model: its cells sampled on parameter voxels (a figure)
               const auto& T = *O->trimmed;
               if (!eo->vtk.empty()) write(eo->vtk, "vtk", trimmed_vtu(T));
               if (!eo->svg.empty()) write(eo->svg, "svg", trimmed_svg(T, eo->explode, "trimmed V-model: " + std::to_string(T.cells.size()) + " cells"));
               return 0;
             }
             const auto& M = O ? *O->model : *glued;
             if (!eo->vtk.empty()) write(eo->vtk, "vtk", vmodel_to_vtu(M));
             if (!eo->svg.empty()) write(eo->svg, "svg", vmodel_svg(M, eo->explode, "V-model: " + std::to_string(M.cells.size()) + " cells", eo->singular));
             return 0;
           }},
          {boo, [bo, operand](const Context& ctx) {
             const auto A = operand(bo->a, ctx), B = operand(bo->b, ctx);
             const BooleanOp op = parse_boolean_op(bo->op);
             const Blend blend = parse_blend(bo->blend);
             TrimOptions topt;
             topt.max_boxes = bo->boxes;
             // Curved cuts need both models' exact regions.
             const std::string region_fix =
                 "curved cuts need both models' exact regions (\"implicit\"): vrep primitive writes one for box, cylinder, cone, "
                 "torus and sphere (patch degree <= 4); glued or constructed models of curved cells have none: place such a model so "
                 "that every cut is a parameter plane of its cells, or give its region";
             auto need_regions = [&]() {
               if (!A.trimmed || !B.trimmed)
                 throw DomainError(A.trimmed ? "second" : "first", "has curved cells and no exact region, and its cells are cut along curved surfaces",
                                   region_fix);
             };
             // A planar cut that is not a parameter plane where an operand has no region.
             auto no_region = [&](const NotPlanarError& e) {
               return DomainError(A.trimmed ? "second" : "first",
                                  "has no exact region, and the Boolean cuts a cell along a surface that is not a parameter plane of its "
                                  "trivariate (" + e.field() + ")",
                                  region_fix);
             };
             // Trimmed cells (curved cuts), exactly.
             auto trimmed = [&]() {
               need_regions();
               std::cout << trimmed_to_json(trimmed_boolean(*A.trimmed, *B.trimmed, op, blend, topt, Rational(0), ctx.limits)).dump() << "\n";
               return 0;
             };
             const bool planar_possible = A.model && B.model && bo->trim != "always";
             if (bo->eps.empty()) {
               if (!planar_possible) {
                 if (bo->trim == "never") throw DomainError("trim", "is never, but an operand is a trimmed V-model", "give --trim auto");
                 return trimmed();
               }
               try {
                 std::cout << vmodel_to_json(boolean_op(*A.model, *B.model, op, Rational(0), blend, ctx.limits)).dump() << "\n";
                 return 0;
               } catch (const NotPlanarError& e) {
                 // A cut that is not a parameter plane: trimmed cells, where both regions are known.
                 if (bo->trim == "never") throw;
                 if (!A.trimmed || !B.trimmed) throw no_region(e);
               }
               return trimmed();
             }
             const double eps = to_double(parse_number(bo->eps, "eps"));
             if (!(eps > 0) || !std::isfinite(eps)) throw UsageError("eps", "must be a positive double", "give e.g. --eps 1e-9");
             // Trimmed cells in double: the models and regions rounded, coefficients within eps count as 0.
             auto trimmed_in_double = [&]() {
               need_regions();
               std::cout << trimmed_to_json(trimmed_boolean(trimmed_to_double(*A.trimmed), trimmed_to_double(*B.trimmed), op, blend, topt, eps, ctx.limits)).dump()
                         << "\n";
               return 0;
             };
             if (!planar_possible) {
               if (bo->trim == "never") throw DomainError("trim", "is never, but an operand is a trimmed V-model", "give --trim auto");
               return trimmed_in_double();
             }
             auto in_double = [&](const VModel<Rational>& M, const std::string& field) {
               std::vector<BSpline<double>> d;
               std::vector<std::string> names;
               for (std::size_t c = 0; c < M.cells.size(); ++c) {
                 d.push_back(round_spline<double>(M.trivariates[M.cells[c].trivariates.front()], field + ".cells[" + std::to_string(c) + "]"));
                 names.push_back(M.cells[c].name);
               }
               auto G = glue(d, eps, names, ctx.limits);
               // The attributes rounded as well (a value beyond double's range is a typed error).
               for (std::size_t c = 0; c < M.cells.size(); ++c) {
                 const std::string w = field + ".cells[" + std::to_string(c) + "].attributes.";
                 for (const auto& [n, v] : M.cells[c].attributes.constants)
                   for (const auto& y : v) G.cells[c].attributes.constants[n].push_back(round_checked<double>(y, w + n));
                 for (const auto& [n, F] : M.cells[c].attributes.fields) G.cells[c].attributes.fields.emplace(n, round_spline<double>(F, w + n));
               }
               return G;
             };
             try {
               std::cout << vmodel_to_json(boolean_op(in_double(*A.model, "first"), in_double(*B.model, "second"), op, eps, blend, ctx.limits)).dump() << "\n";
               return 0;
             } catch (const NotPlanarError& e) {
               if (bo->trim == "never") throw;
               if (!A.trimmed || !B.trimmed) throw no_region(e);
             }
             return trimmed_in_double();
           }},
          {vol, [volo, operand](const Context& ctx) {
             const auto O = operand(volo->a, ctx);
             const Rational rel = parse_number(volo->rel_width, "rel-width");
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
             const auto R = integral_enclosures(in, volo->centroid ? xyz : std::vector<int>{}, volo->centroid ? Rational(rel / 2) : rel,
                                                volo->boxes, ctx.limits);
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
             if (!volo->field.empty()) {
               // Per cell that has the field: its integral (exact or a certified enclosure); the
               // model's sum when every cell has it.
               std::vector<IntegrandCell<Rational>> fin;
               std::vector<std::size_t> which;
               std::vector<std::string> missing;
               auto add_field = [&](std::size_t c, const std::map<std::string, BSpline<Rational>>& fields) {
                 const auto it = fields.find(volo->field);
                 if (it == fields.end()) {
                   missing.push_back(names[c]);
                   return;
                 }
                 fin.push_back({in[c].trivariate, in[c].trim, &it->second});
                 which.push_back(c);
               };
               for (std::size_t c = 0; c < in.size(); ++c) add_field(c, O.model ? O.model->cells[c].attributes.fields : O.trimmed->cells[c].fields);
               if (fin.empty())
                 throw ValidationError("field", "\"" + volo->field + "\" is on no cell of the model", "give the name of an attribute field of its cells");
               const auto F = integral_enclosures(fin, {volo->component}, rel, volo->boxes, ctx.limits);
               const auto& fm = F.total_moment[0];
               reached = reached && fm.upper - fm.lower <= rel * F.total.lower * F.scale[0];
               exact = exact && fm.upper == fm.lower;
               Json fc = Json::array();
               for (std::size_t i = 0; i < fin.size(); ++i) {
                 Json j{{"cell", which[i]}, {"name", names[which[i]]}};
                 put_enclosure(j, "integral", F.moment[i][0].lower, F.moment[i][0].upper, true);
                 fc.push_back(j);
               }
               Json f{{"name", volo->field}, {"component", volo->component}, {"cells", fc}};
               const auto& t = F.total_moment[0];
               if (missing.empty()) put_enclosure(f, "integral", t.lower, t.upper, true);
               else f["cells_without"] = missing;
               out["field"] = f;
               // The integral's width relative to its scale: the volume's lower bound times the
               // field component's largest |value| (of the control points).
               acc["field_relative_width"] = relative_width_text(F.total.lower * F.scale[0], F.total.lower * F.scale[0] + (t.upper - t.lower));
             }
             if (volo->centroid) {
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
                                                : "target not reached: budget of " + std::to_string(volo->boxes) + " boxes per cell (" +
                                                      std::to_string(R.budget) + " in all) spent; raise --boxes or --rel-width";
             out["enclosure"] = acc;
             std::cout << out.dump() << "\n";
             return 0;
           }},
          {cls, [clo, operand](const Context& ctx) {
             const auto O = operand(clo->a, ctx);
             const auto x = parse_number_list(clo->at, "at");
             if (x.size() != 3) throw UsageError("at", "needs three coordinates", "give --at x,y,z");
             // Cells with planar faces: which cells contain x. Otherwise the model's exact region.
             std::optional<std::vector<std::size_t>> in_cells;
             if (O.model && planar_region(*O.model)) in_cells = cells_containing(*O.model, x);
             if (in_cells) {
               Json cells = Json::array();
               for (std::size_t c : *in_cells) cells.push_back({{"cell", c}, {"name", O.model->cells[c].name}});
               Json out{{"inside", !cells.empty()}, {"cells", cells}};
               if (!O.validity.complete()) out["validity"] = O.validity.verdict();
               std::cout << out.dump() << "\n";
               return 0;
             }
             if (!O.trimmed)
               throw DomainError("file", "has curved cells and no exact region (\"implicit\"): point classification needs one",
                                 "build the model with vrep primitive or vrep boolean, which write it");
             const Truth t = classify_point(O.trimmed->region, x);
             Json out{{"truth", t == Truth::in ? "inside" : t == Truth::out ? "outside" : "on a surface"}};
             if (t != Truth::mixed) out["inside"] = t == Truth::in;
             else out["note"] = "x lies on the zero set of a polynomial that decides it: the boundary, or inside where two pieces touch";
             if (!O.validity.complete()) out["validity"] = O.validity.verdict();
             std::cout << out.dump() << "\n";
             return 0;
           }},
          {info, [io, read_model](const Context& ctx) {
             const auto r = read_model(io->files, ctx, io->levels);
             std::cout << info_of(r.model, r.validity).dump(2) << "\n";
             return 0;
           }},
          {ev, [vo, exact_model](const Context& ctx) {
             const auto M = exact_model({vo->file}, ctx);
             const auto x = parse_number_list(vo->at, "at");
             if (x.size() != 3) throw UsageError("at", "needs three parameters", "give --at u,v,w");
             const auto r = evaluate_cell(M, vo->cell, x);
             auto list = [](const std::vector<Rational>& v) {
               Json a = Json::array();
               for (const auto& y : v) a.push_back(to_fraction_string(y));
               return a;
             };
             Json out{{"cell", vo->cell}, {"point", list(r.point)}, {"coordinates", list(r.coordinates)}};
             Json f = Json::object(), c = Json::object();
             for (const auto& [n, v] : r.fields) f[n] = list(v);
             for (const auto& [n, v] : r.constants) c[n] = list(v);
             out["fields"] = f;
             out["constants"] = c;
             std::cout << out.dump() << "\n";
             return 0;
           }},
          {cert, [co](const Context& ctx) {
             const auto V = read_spline(co->file, "trivariate", ctx);
             const auto spec = ArithSpec::parse(co->arith);
             const Json j = with_arith_except_flint(spec, "vrep certify", [&](auto tag) {
               using F = typename decltype(tag)::type;
               return report_to_json(certify_regularity(round_spline<F>(V, "trivariate"), co->levels, ctx.limits));
             });
             std::cout << j.dump(2) << "\n";
             return 0;
           }}};
}

}  // namespace splinex::app
