// splinex vrep: volumetric models of papers/002 (vrep/): trivariate constructors, primitives,
// gluing into a V-model, its topology and invariants, certified regularity per cell.
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "apps/command.hpp"
#include "experiments/svg_plot.hpp"
#include "experiments/vrep_figures.hpp"
#include "experiments/vrep_ssi.hpp"
#include "experiments/vrep_teapot.hpp"
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "float/rounding.hpp"
#include "io/trimmed_io.hpp"
#include "io/vmodel_io.hpp"
#include "io/vtk_io.hpp"
#include <fstream>
#include "vrep/boolean/boolean.hpp"
#include "vrep/io/api.hpp"
#include "vrep/io/documents.hpp"
#include "vrep/model/regularity.hpp"
#include "vrep/model/trivariate.hpp"
#include "vrep/model/validate.hpp"
#include "vrep/primitives/blend.hpp"
#include "vrep/primitives/catalog.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex::app {

namespace {

struct ConstructOptions {
  std::string kind, arith = "exact", surface, first, second, faces, curves, surfaces, vector, at, axis = "z";
  int quarters = 4, degree = 3;
};

BSpline<Rational> read_spline(const std::string& path, const std::string& field, const Context& ctx) {
  return splinex::read_spline(path, ctx.limits, ctx.read_limits, field);
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

/// 2N spline files from a comma list (`field`, `count` the number in words for the message), read
/// as pairs [k / 2][k % 2] under `names`: boolean-sum's six faces, coons' four curves.
template <std::size_t N>
std::array<std::array<BSpline<Rational>, 2>, N> read_pairs(const std::string& list, const std::string& field, const std::string& count,
                                                         const std::array<const char*, 2 * N>& names, const Context& ctx) {
  const auto files = split_list(list);
  if (files.size() != 2 * N) {
    std::string fix = "give --" + field + " ";
    for (std::size_t k = 0; k < 2 * N; ++k) {
      if (k) fix += ',';
      fix += names[k];
    }
    throw UsageError(field, "needs " + count + " files, got " + std::to_string(files.size()), fix);
  }
  std::array<std::array<BSpline<Rational>, 2>, N> out;
  for (std::size_t k = 0; k < 2 * N; ++k) out[k / 2][k % 2] = read_spline(files[k], names[k], ctx);
  return out;
}

/// read_pairs' splines in the arithmetic T.
template <class T, std::size_t N>
std::array<std::array<BSpline<T>, 2>, N> round_pairs(const std::array<std::array<BSpline<Rational>, 2>, N>& S,
                                                     const std::array<const char*, 2 * N>& names) {
  std::array<std::array<BSpline<T>, 2>, N> out;
  for (std::size_t k = 0; k < 2 * N; ++k) out[k / 2][k % 2] = round_spline<T>(S[k / 2][k % 2], names[k]);
  return out;
}

auto construct(const ConstructOptions& o, const Context& ctx) {
  const auto spec = ArithSpec::parse(o.arith);
  auto need = [](const std::string& value, const std::string& field, const std::string& kind) {
    if (value.empty()) throw UsageError(field, "vrep construct " + kind + " needs --" + field, "give --" + field);
  };
  if (o.kind == "extrude") {
    need(o.surface, "surface", o.kind);
    need(o.vector, "vector", o.kind);
    const auto S = read_spline(o.surface, "surface", ctx);
    const auto V = parse_number_list(o.vector, "vector");
    return with_arith<VrepArithmetics>(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      std::vector<F> v;
      for (const auto& x : V) v.push_back(round_checked<F>(x, "vector"));
      return document(extrude(round_spline<F>(S, "surface"), v, ctx.limits));
    });
  }
  if (o.kind == "ruled") {
    need(o.first, "first", o.kind);
    need(o.second, "second", o.kind);
    const auto A = read_spline(o.first, "first", ctx), B = read_spline(o.second, "second", ctx);
    return with_arith<VrepArithmetics>(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return document(ruled(round_spline<F>(A, "first"), round_spline<F>(B, "second"), ctx.limits));
    });
  }
  if (o.kind == "revolve") {
    need(o.surface, "surface", o.kind);
    const auto S = read_spline(o.surface, "surface", ctx);
    const int axis = o.axis == "x" ? 0 : o.axis == "y" ? 1 : 2;
    return with_arith<VrepArithmetics>(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return document(revolve(round_spline<F>(S, "surface"), axis, o.quarters, ctx.limits));
    });
  }
  if (o.kind == "boolean-sum") {
    need(o.faces, "faces", o.kind);
    const auto F = read_pairs<3>(o.faces, "faces", "six", {"u0", "u1", "v0", "v1", "w0", "w1"}, ctx);
    return with_arith<VrepArithmetics>(spec, "vrep construct", [&](auto tag) {
      return document(boolean_sum(round_pairs<typename decltype(tag)::type>(F, {"u0", "u1", "v0", "v1", "w0", "w1"}), ctx.limits));
    });
  }
  if (o.kind == "tube") {
    need(o.surface, "surface", o.kind);
    const auto S = read_spline(o.surface, "surface", ctx);
    return with_arith<VrepArithmetics>(spec, "vrep construct", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return document(tube_boolean_sum(round_spline<F>(S, "surface"), ctx.limits));
    });
  }
  if (o.kind == "coons") {
    need(o.curves, "curves", o.kind);
    const auto C = read_pairs<2>(o.curves, "curves", "four", {"u0", "u1", "v0", "v1"}, ctx);
    return with_arith<VrepArithmetics>(spec, "vrep construct", [&](auto tag) {
      return document(coons_surface(round_pairs<typename decltype(tag)::type>(C, {"u0", "u1", "v0", "v1"}), ctx.limits));
    });
  }
  // sweep
  need(o.surfaces, "surfaces", o.kind);
  need(o.at, "at", o.kind);
  std::vector<BSpline<Rational>> S;
  const auto files = split_list(o.surfaces);
  for (std::size_t k = 0; k < files.size(); ++k) S.push_back(read_spline(files[k], "surfaces[" + std::to_string(k) + "]", ctx));
  const auto at = parse_number_list(o.at, "at");
  return with_arith<VrepArithmetics>(spec, "vrep construct", [&](auto tag) {
    using F = typename decltype(tag)::type;
    std::vector<BSpline<F>> s;
    for (std::size_t k = 0; k < S.size(); ++k) s.push_back(round_spline<F>(S[k], "surfaces[" + std::to_string(k) + "]"));
    std::vector<F> w;
    for (const auto& x : at) w.push_back(round_checked<F>(x, "at"));
    return document(sweep(s, w, o.degree, ctx.limits));
  });
}

struct PrimitiveOptions {
  std::string name, arith = "exact", radius = "1", radius2 = "1/2", height = "2", major = "3", lo = "0,0,0", hi = "1,1,1", axis = "z",
              at = "0,0,0";
  int degree = 3, pieces = 4;
};

/// The primitive's parameters as given: those its row reads (vrep/primitives/catalog.hpp), parsed
/// in that order; the others keep their defaults.
PrimitiveParameters parameters(const PrimitiveOptions& o) {
  PrimitiveParameters p;
  std::istringstream reads(primitive_row<Rational>(o.name).reads);
  for (std::string field; reads >> field;) {
    if (field == "radius") p.radius = parse_number(o.radius, "radius");
    if (field == "radius2") p.radius2 = parse_number(o.radius2, "radius2");
    if (field == "height") p.height = parse_number(o.height, "height");
    if (field == "major") p.major = parse_number(o.major, "major");
    if (field == "lo") p.lo = parse_number_list(o.lo, "lo");
    if (field == "hi") p.hi = parse_number_list(o.hi, "hi");
  }
  p.degree = o.degree;
  p.pieces = o.pieces;
  return p;
}

struct GlueOptions {
  std::vector<std::string> files;
  std::string eps;
  int levels = 6;
};

struct BooleanOptions {
  std::string op, a, b, eps, blend = "sum-clipped", at, trim = "auto";
  std::size_t boxes = 256;
  bool centroid = false;
  std::string field;
  int component = 0;
  std::string rel_width = "1/100";
};

// Models and operands are read by the V-rep facade (vrep/io/api.hpp): glued, attributes applied,
// an "implicit" region checked against the cells, validated.
VModelCells read_cells(const std::vector<std::string>& files, const Context& ctx) {
  return vrep::read_cells(files, ctx.limits, ctx.read_limits);
}
vrep::LoadedModel read_model(const std::vector<std::string>& files, const Context& ctx, int levels = 6) {
  return vrep::load_model(files, ctx.limits, ctx.read_limits, levels);
}
VModel<Rational> exact_model(const std::vector<std::string>& files, const Context& ctx) { return read_model(files, ctx).model; }
vrep::Operand operand(const std::string& file, const Context& ctx) { return vrep::load_operand(file, ctx.limits, ctx.read_limits); }


/// `splinex vrep construct`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_construct(CLI::App* v) {
  auto o = std::make_shared<ConstructOptions>();
  auto* c = v->add_subcommand("construct", "a trivariate from surfaces: extrude, ruled, revolve, boolean-sum, tube or sweep; or a "
                                             "surface from four curves: coons");
  c->add_option("kind", o->kind, "extrude, ruled, revolve, boolean-sum, tube, sweep or coons")
      ->required()
      ->check(CLI::IsMember({"extrude", "ruled", "revolve", "boolean-sum", "tube", "sweep", "coons"}));
  add_arith_option(c, o->arith, "exact (GMP), double or mpfr:BITS");
  c->add_option("--surface", o->surface, "extrude, revolve, tube: the surface document (points in R^3, attributes after; tube: "
                                         "closed around u, polynomial)");
  c->add_option("--vector", o->vector, "extrude: the vector V, comma-separated (one entry per point coordinate)");
  c->add_option("--first", o->first, "ruled: the surface at w = 0");
  c->add_option("--second", o->second, "ruled: the surface at w = 1");
  c->add_option("--axis", o->axis, "revolve: the coordinate axis")->check(CLI::IsMember({"x", "y", "z"}))->capture_default_str();
  c->add_option("--quarters", o->quarters, "revolve: the angle in quarter turns (exact rational circle arcs)")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  c->add_option("--faces", o->faces, "boolean-sum: six surface files u0,u1,v0,v1,w0,w1 (u faces in (v, w), v faces in (u, w), "
                                     "w faces in (u, v))");
  c->add_option("--curves", o->curves, "coons: four curve files u0,u1,v0,v1 (the boundaries at u = 0, 1, curves in v; at v = 0, 1, "
                                       "curves in u), meeting at the corners");
  c->add_option("--surfaces", o->surfaces, "sweep: the surface files S_0,...,S_m");
  c->add_option("--at", o->at, "sweep: the parameters w_0 < ... < w_m, comma-separated");
  c->add_option("--degree", o->degree, "sweep: the degree in w (at most m)")->check(CLI::Range(1, 64))->capture_default_str();

  return {c, [o](const Context& ctx) {
    print_document(construct(*o, ctx));
    return 0;
  }};
}

/// `splinex vrep certify`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_certify(CLI::App* v) {
  struct CertifyOptions {
    std::string arith = "exact", file;
    int levels = 6;
  };
  auto co = std::make_shared<CertifyOptions>();
  auto* cert = v->add_subcommand("certify", "certified regularity of a trivariate: the sign of det J from exact Bernstein coefficients");
  add_arith_option(cert, co->arith, "exact (GMP) decides exactly; double or mpfr:BITS run the same test in floats");
  cert->add_option("file", co->file, "the trivariate document")->required();
  cert->add_option("--levels", co->levels, "subdivision levels before \"undecided\"")->check(CLI::Range(0, 12))->capture_default_str();
  return {cert, [co](const Context& ctx) {
    const auto V = read_spline(co->file, "trivariate", ctx);
    const auto spec = ArithSpec::parse(co->arith);
    print_document(with_arith<VrepArithmetics>(spec, "vrep certify", [&](auto tag) {
      using F = typename decltype(tag)::type;
      return vrep::document(certify_regularity(round_spline<F>(V, "trivariate"), co->levels, ctx.limits));
    }), 2);
    return 0;
  }};
}

/// `splinex vrep primitive`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_primitive(CLI::App* v) {
  auto po = std::make_shared<PrimitiveOptions>();
  auto* prim = v->add_subcommand("primitive", "a glued primitive V-model (Figure 9) or a singular single trivariate (Figure 8)");
  prim->add_option("name", po->name, primitive_help())->required()->check(CLI::IsMember(primitive_names()));
  add_arith_option(prim, po->arith, "exact (GMP), double or mpfr:BITS");
  prim->add_option("--radius", po->radius, "radius (torus: the tube's)")->capture_default_str();
  prim->add_option("--radius2", po->radius2, "cone: the top radius")->capture_default_str();
  prim->add_option("--height", po->height, "cylinder, cone: the height")->capture_default_str();
  prim->add_option("--major", po->major, "torus: the distance of the tube's centre from the axis")->capture_default_str();
  prim->add_option("--degree", po->degree, "sphere: the patches' degree (radius approximate, direction exact; docs/vrep/primitives.md)")
      ->capture_default_str();
  prim->add_option("--pieces", po->pieces, "sphere: the patches' polynomial pieces per direction")->capture_default_str();
  prim->add_option("--lo", po->lo, "box: the low corner x,y,z")->capture_default_str();
  prim->add_option("--hi", po->hi, "box: the high corner x,y,z")->capture_default_str();
  prim->add_option("--axis", po->axis, "the primitive's axis (z: as built; x, y: the coordinates permuted cyclically)")
      ->check(CLI::IsMember({"x", "y", "z"}))
      ->capture_default_str();
  prim->add_option("--at", po->at, "a translation x,y,z applied after --axis")->capture_default_str();

  return {prim, [po](const Context& ctx) {
    const auto spec = ArithSpec::parse(po->arith);
    print_document(with_arith<VrepArithmetics>(spec, "vrep primitive", [&](auto tag) {
      using F = typename decltype(tag)::type;
      const int axis = po->axis == "x" ? 0 : po->axis == "y" ? 1 : 2;
      std::vector<F> at;
      for (const auto& x : parse_number_list(po->at, "at")) at.push_back(round_checked<F>(x, "at"));
      if (at.size() != 3) throw UsageError("at", "needs three coordinates", "give --at x,y,z");
      auto [cells, region] = build_primitive<F>(po->name, parameters(*po));
      for (auto& V : cells) V = place_trivariate(V, axis, at);
      std::vector<std::string> names;
      for (std::size_t k = 0; k < cells.size(); ++k) names.push_back(po->name + " " + std::to_string(k));
      std::optional<Region<F>> placed;
      if (region) placed = place_region(*region, axis, at);
      return vrep::vmodel_document(glue(cells, F(0), names, ctx.limits), placed);
    }));
    return 0;
  }};
}

/// `splinex vrep glue`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_glue(CLI::App* v) {
  auto go = std::make_shared<GlueOptions>();
  auto* glue_cmd = v->add_subcommand("glue", "glue trivariates and V-models into one V-model (exact; --eps: in double, IRIT's test)");
  glue_cmd->add_option("files", go->files, "trivariate or V-model documents")->required();
  glue_cmd->add_option("--eps", go->eps, "glue in double with control points equal within eps (default: exact)");
  return {glue_cmd, [go](const Context& ctx) {
    if (go->eps.empty()) {
      print_document(vrep::glued_document(read_model(go->files, ctx)));
      return 0;
    }
    const auto all = read_cells(go->files, ctx);
    validate_cells(all.trivariates, all.names, "vmodel", {}, ctx.limits);  // the exact cells, before rounding
    const double eps = to_double(parse_number(go->eps, "eps"));
    if (!(eps > 0) || !std::isfinite(eps)) throw UsageError("eps", "must be a positive double", "give e.g. --eps 1e-9");
    std::vector<BSpline<double>> d;
    for (std::size_t k = 0; k < all.trivariates.size(); ++k) d.push_back(round_spline<double>(all.trivariates[k], all.names[k]));
    print_document(vrep::vmodel_document(glue(d, eps, all.names, ctx.limits)));
    return 0;
  }};
}

/// `splinex vrep info`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_info(CLI::App* v) {
  auto io = std::make_shared<GlueOptions>();
  auto* info = v->add_subcommand("info", "counts, Euler characteristic, invariants, neighbours and regularity per cell");
  info->add_option("files", io->files, "a V-model document (or trivariates, glued exactly)")->required();
  info->add_option("--levels", io->levels, "subdivision levels of the regularity test")->check(CLI::Range(0, 12))->capture_default_str();

  return {info, [io](const Context& ctx) {
    const auto r = read_model(io->files, ctx, io->levels);
    std::cout << vrep::info_document(r.model, r.validity).dump(2) << "\n";
    return 0;
  }};
}

/// `splinex vrep export`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_export(CLI::App* v) {
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

  return {exp, [eo](const Context& ctx) {
    if (eo->vtk.empty() && eo->svg.empty()) throw UsageError("vtk", "vrep export needs --vtk or --svg", "give --vtk FILE.vtu or --svg FILE.svg");
    std::optional<vrep::Operand> O;
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
  }};
}

/// `splinex vrep eval`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_eval(CLI::App* v) {
  struct EvalOptions {
    std::string file, at;
    std::size_t cell = 0;
  };
  auto vo = std::make_shared<EvalOptions>();
  auto* ev = v->add_subcommand("eval", "geometry and attributes of a cell at a parameter point, exactly");
  ev->add_option("file", vo->file, "a V-model document")->required();
  ev->add_option("--cell", vo->cell, "the cell (0-based)")->capture_default_str();
  ev->add_option("--at", vo->at, "the parameter point u,v,w")->required();

  return {ev, [vo](const Context& ctx) {
    const auto M = exact_model({vo->file}, ctx);
    const auto x = parse_number_list(vo->at, "at");
    if (x.size() != 3) throw UsageError("at", "needs three parameters", "give --at u,v,w");
    const auto r = evaluate_cell(M, vo->cell, x);
    print_document(vrep::cell_value_document(vo->cell, r));
    return 0;
  }};
}

/// `splinex vrep boolean`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_boolean(CLI::App* v) {
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
  return {boo, [bo](const Context& ctx) {
    const auto A = operand(bo->a, ctx), B = operand(bo->b, ctx);
    vrep::BooleanRequest rq;
    rq.op = parse_boolean_op(bo->op);
    rq.blend = parse_blend(bo->blend);
    rq.trim = vrep::parse_trim_mode(bo->trim);
    rq.boxes = bo->boxes;
    if (!bo->eps.empty()) rq.eps = to_double(parse_number(bo->eps, "eps"));
    print_document(vrep::document(vrep::boolean(A, B, rq, ctx.limits)));
    return 0;
  }};
}

/// `splinex vrep volume`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_volume(CLI::App* v) {
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
  return {vol, [volo](const Context& ctx) {
    const auto O = operand(volo->a, ctx);
    vrep::VolumeRequest rq;
    rq.rel_width = parse_number(volo->rel_width, "rel-width");
    rq.boxes = volo->boxes;
    rq.centroid = volo->centroid;
    rq.field = volo->field;
    rq.component = volo->component;
    print_document(vrep::volume_document(O, rq, ctx.limits));
    return 0;
  }};
}

/// `splinex vrep classify`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_classify(CLI::App* v) {
  auto clo = std::make_shared<BooleanOptions>();
  auto* cls = v->add_subcommand("classify", "which cells contain a point (exact: planar cells; otherwise the model's exact region)");
  cls->add_option("file", clo->a, "a V-model document")->required();
  cls->add_option("--at", clo->at, "the point x,y,z")->required();

  return {cls, [clo](const Context& ctx) {
    const auto O = operand(clo->a, ctx);
    const auto x = parse_number_list(clo->at, "at");
    if (x.size() != 3) throw UsageError("at", "needs three coordinates", "give --at x,y,z");
    print_document(vrep::classify_document(O, x));
    return 0;
  }};
}

/// `splinex vrep topology`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_topology(CLI::App* v) {
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
  return {topo, [tco](const Context& ctx) {
    const auto M = vrep::read_trimmed_model(tco->file, ctx.limits, ctx.read_limits);
    const auto validity = validate_trimmed(M, tco->file, {}, ctx.limits);
    print_document(vrep::topology_document(M, validity, tco->boxes, tco->glue, ctx.limits));
    return 0;
  }};
}

/// `splinex vrep teapot`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_teapot(CLI::App* v) {
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
  return {tp, [tpo](const Context&) {
    auto progress = [](const std::string& line) { std::cerr << "[vrep teapot] " << line << "\n"; };
    if (tpo->arith == "double") {
      if (!tpo->svg.empty() || !tpo->vtk.empty())
        throw UsageError("svg", "figures are drawn from the exact run", "drop --svg/--vtk or use --arith exact");
      print_document(teapot_document(teapot_vmodel<double>(tpo->boxes, progress)));
      return 0;
    }
    const auto M = teapot_vmodel<Rational>(tpo->boxes, progress);
    if (!tpo->svg.empty()) write_file_atomically(tpo->svg, teapot_vmodel_svg(M));
    if (!tpo->vtk.empty()) write_file_atomically(tpo->vtk, teapot_vmodel_vtk(M));
    print_document(teapot_document(M));
    return 0;
  }};
}

/// `splinex vrep ssi`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_ssi(CLI::App* v) {
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
  return {ssi, [so](const Context& ctx) {
    const auto S1 = read_surface_argument(so->a, "first", ctx), S2 = read_surface_argument(so->b, "second", ctx);
    SsiOptions opt;
    opt.step = to_double(parse_number(so->step, "step"));
    opt.tolerance = to_double(parse_number(so->tolerance, "tolerance"));
    opt.grid = so->grid;
    auto progress = [](const std::string& line) { std::cerr << "[vrep ssi] " << line << "\n"; };
    const auto st = ssi_study(S1, S2, opt, so->judge, progress);
    if (!so->svg.empty()) write_file_atomically(so->svg, ssi_svg(S1, S2, st.result, so->a, so->b, "vrep ssi: " + so->a + " and " + so->b));
    if (!so->obj.empty()) write_file_atomically(so->obj, ssi_obj(S1, st.result));
    print_document(ssi_document(S1, st, opt, so->judge));
    return 0;
  }};
}

/// `splinex vrep blend`: its options, and what it runs (the work is in vrep/ and vrep/io/).
Command vrep_blend(CLI::App* v) {
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
  return {bl, [blo](const Context& ctx) {
    const auto V1 = exact_model({blo->a}, ctx), V2 = exact_model({blo->b}, ctx);
    const auto x = parse_number_list(blo->at, "at");
    if (x.size() != 3) throw UsageError("at", "needs three coordinates", "give --at x,y,z");
    print_document(vrep::blend_document(V1, V2, x, blo->attribute, blo->k, blo->bits));
    return 0;
  }};
}

}  // namespace

Commands add_vrep(CLI::App& app) {
  auto* v = app.add_subcommand("vrep", "volumetric models (papers/002): trivariate constructors, certified regularity");
  v->require_subcommand(1);
  // In the order of --help.
  return {vrep_construct(v), vrep_certify(v), vrep_primitive(v), vrep_glue(v), vrep_info(v), vrep_export(v), vrep_eval(v), vrep_boolean(v), vrep_volume(v), vrep_classify(v), vrep_topology(v), vrep_teapot(v), vrep_ssi(v), vrep_blend(v)};
}

}  // namespace splinex::app
